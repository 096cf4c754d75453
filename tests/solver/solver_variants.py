"""Linear solvers: GMRES with AMG and the MUMPS direct solver give the
same history as the default (KLU) reference of regression/cylinder_3d
(tests/regression/cylinder_3d.reference.csv).
Type = auto chooses by the size and the number of processes: iterative
above Iterative above (one process) or Iterative above under MPI
(several), direct below, and summary.txt says which ran.

Cases (argv[4]; without one, both run):
  serial  GMRES + AMG and MUMPS against the reference, Type = auto on one
          process
  mpi     Type = auto at -np 2, above and below the MPI threshold (two
          cores, one MPI test at a time)
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi

import os
import sys

from tribos_testing import (REPOSITORY, setup, run, strip_columns, numdiff, check, finish,
                            solver_line, parts, mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all")
strip_columns(os.path.join(REPOSITORY, "tests", "regression",
                           "cylinder_3d.reference.csv"),
              out + "/reference.csv", drop=noisy)
variants = (("gmres_amg", ["Linear solver/Type=iterative",
                           "Linear solver/Tolerance=1e-12"]),
            ("mumps", ["Linear solver/Direct solver=Amesos_Mumps"]))
for name, sets in variants if "serial" in selected else ():
    folder = out + "/" + name
    run(tribos, tests + "/cylinder_3d.prm", folder, sets)
    strip_columns(folder + "/history.csv", folder + "/h.csv", drop=noisy)
    numdiff(folder + "/h.csv", out + "/reference.csv", relative=1e-6,
            absolute=1e-8)
    print("ok      %s reproduces the KLU reference within 1e-6" % name)

# Type = auto: the thresholds decide (the scene has a few thousand
# unknowns, so 0 and 10^9 put it above and below).
cases = [("auto_serial_above", ["Linear solver/Iterative above=0"], 0,
          "GMRES + ML"),
         ("auto_serial_below", ["Linear solver/Iterative above=1000000000"],
          0, "(SuiteSparse)"),
         # one process ignores the MPI threshold
         ("auto_serial_mpi_threshold",
          ["Linear solver/Iterative above=1000000000",
           "Linear solver/Iterative above under MPI=0"], 0,
          "(SuiteSparse)")]
if "serial" not in selected:
    cases = []
if "mpi" in selected and mpi_part(selected):
    cases += [("auto_np2_above", ["Linear solver/Iterative above=1000000000",
                                  "Linear solver/Iterative above under MPI=0"],
               2, "GMRES + ML"),
              ("auto_np2_below", ["Linear solver/Iterative above=0",
                                  "Linear solver/Iterative above under "
                                  "MPI=1000000000"], 2, "Amesos_Mumps")]
for name, sets, ranks, expected in cases:
    folder = out + "/" + name
    run(tribos, tests + "/cylinder_3d.prm", folder,
        ["Linear solver/Type=auto"] + sets, mpi_ranks=ranks)
    used = solver_line(folder)
    check(used.endswith(expected), "%s: solved with <%s> (expected <%s>)"
          % (name, used, expected))
finish()
