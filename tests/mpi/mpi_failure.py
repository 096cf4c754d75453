"""MPI: a run that cannot converge because a cell inverts on one process
only ends as the serial run does (exit status 2, the same message, the
converged steps' outputs kept), instead of hanging; and a run whose
increments are cut back for such a cell takes the serial run's cutbacks
and ends on its history (1e-8).

A neo-Hookean strip 4 x 1 (16 x 4 cells) is crushed by a body force on
x < 0.5 only, so the inverted cells lie in one corner of the strip, on one
of the two processes. Before the fix the process whose cell inverted threw
alone and the other one waited for it in the next collective step: the run
hung (the Newton line search and the cutback alike). After that fix the
cut increments under MPI still started from another state than the serial
ones: the interrupted assembly had left entries for other processes in the
Trilinos vectors, and the next assembly and the next Newton update took
them in (np 2 cut back 3 times where the serial run cut twice)."""
# ctest: mpirun

import os
import re
import sys

from tribos_testing import (require_mpi, setup, run, run_or_hang, check, finish,
                         mpi_available, strip_columns, numdiff)

tribos, tests, out = setup(sys.argv)
prm = tests + "/neo_hookean_stretch.prm"
crush = ["Scene/Block/Upper corner=4, 1, 1",
         "Scene/Block/Subdivisions=16, 4, 1",
         "Boundary conditions/Dirichlet=",
         "Boundary conditions/Body force=0, -20*t*(x<0.5)",
         "Time stepping/Maximum cutbacks=2"]


def run_failing(folder, ranks):
    return run_or_hang(tribos, prm, folder, crush, ranks)


def status(folder):
    """summary.txt's status without det F's value (which cell is reported
    first depends on the partition)."""
    with open(folder + "/summary.txt") as f:
        line = f.readline().split(None, 1)[1].strip()
    return re.sub(r"det F = \S+", "det F = ...", line)


require_mpi()

serial = run_failing(out + "/serial", 0)
check(serial.returncode == 2 and "det F" in status(out + "/serial"),
      "serial: exit status %d, %s" % (serial.returncode,
                                      status(out + "/serial")))
for ranks in (2, 3):
    folder = out + "/np%d" % ranks
    result = run_failing(folder, ranks)
    check(result.returncode == 2,
          "np %d: ends with exit status %d (2 expected)"
          % (ranks, result.returncode))
    check(status(folder) == status(out + "/serial"),
          "np %d: summary.txt says what the serial run says: %s"
          % (ranks, status(folder)))
    check(os.path.isfile(folder + "/history.csv") and
          os.path.isfile(folder + "/convergence.csv"),
          "np %d: history.csv and convergence.csv are kept" % ranks)

# Recoverable: a milder load, the first two increments cut back.
mild = crush[:3] + ["Boundary conditions/Body force=0, -3*t*(x<0.5)",
                    "Time stepping/Number of steps=1"]


def cutbacks(result):
    return [line.strip() for line in result.stdout.splitlines()
            if line.strip().startswith("cutback")]


serial_run = run(tribos, prm, out + "/mild_serial", mild)
serial_cuts = cutbacks(serial_run)
check(len(serial_cuts) == 2, "serial, recoverable: %d cutbacks (2 expected)"
      % len(serial_cuts))
strip_columns(out + "/mild_serial/history.csv", out + "/mild_serial/h.csv")
for ranks in (2, 3):
    folder = out + "/mild_np%d" % ranks
    result = run(tribos, prm, folder, mild, mpi_ranks=ranks)
    check(cutbacks(result) == serial_cuts,
          "np %d, recoverable: the serial run's cutbacks (%s)"
          % (ranks, "; ".join(cutbacks(result))))
    strip_columns(folder + "/history.csv", folder + "/h.csv")
    numdiff(folder + "/h.csv", out + "/mild_serial/h.csv", relative=1e-8,
            absolute=1e-12)
    print("ok      np %d, recoverable: the serial history" % ranks)
finish()
