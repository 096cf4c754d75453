"""MPI: MUMPS gets the workspace it asks for. A 2 x 2 x 1 block on a rigid
plane with friction and Lagrange multipliers (tests/data/
block_on_plane_3d.prm, Refinement 1) under mpirun -np 2: the pivoting on
the multipliers' zero diagonal outgrows the workspace MUMPS's analysis
estimates with ICNTL(14) = 20 % (INFOG(1) = -9), and every increment was
cut back as "the direct solver Amesos_Mumps failed (singular system?)"
until the run exited 2. Now the factorization is retried with the
workspace doubled: the run completes without a cutback, with KLU's
history (1e-8)."""
# ctest: mpirun

import sys

from tribos_testing import (require_mpi, setup, run, read_csv, check, finish,
                            strip_columns, numdiff)

tribos, tests, out = setup(sys.argv)
require_mpi()
prm = tests + "/block_on_plane_3d.prm"
mumps = run(tribos, prm, out + "/mumps", mpi_ranks=2, expect_success=False)
cutbacks = sum(r["cutbacks"] for r in read_csv(out + "/mumps/history.csv")) \
    if mumps.returncode == 0 else -1
# The retry happened (on a machine where MUMPS's estimate sufficed this
# test would prove nothing): the solver's name in the log says so.
check("Amesos_Mumps (workspace ICNTL(14) = 140 %)" in mumps.stdout,
      "the factorization was retried with the workspace raised to 140 %")
check(mumps.returncode == 0 and cutbacks == 0 and
      "Amesos_Mumps : ERROR" not in mumps.stderr,
      "Amesos_Mumps at -np 2: exit %d, %d cutbacks, Amesos's report of the "
      "factorization that the retry replaced %s" % (
          mumps.returncode, cutbacks,
          "not shown" if "Amesos_Mumps : ERROR" not in mumps.stderr else
          "shown"))
if mumps.returncode == 0:
    run(tribos, prm, out + "/klu", ["Linear solver/Direct solver=Amesos_Klu"],
        mpi_ranks=2)
    noisy = ("wall_time", "residual", "newton_iterations",
             "newton_iterations_all")
    for name in ("mumps", "klu"):
        strip_columns(out + "/%s/history.csv" % name,
                      out + "/%s/h.csv" % name, drop=noisy)
    numdiff(out + "/mumps/h.csv", out + "/klu/h.csv", relative=1e-8,
            absolute=1e-12)
    print("ok      MUMPS's history equals KLU's")
    check(read_csv(out + "/mumps/history.csv")[-1]["time"] == 3,
          "the drag completes (t = 3)")
finish()
