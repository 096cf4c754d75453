"""Linear solvers: GMRES with AMG and the MUMPS direct solver give the
same history as the default (KLU) reference of regression/cylinder_3d.
Type = auto chooses by the size and the number of processes: iterative
above Iterative above (one process) or Iterative above under MPI
(several), direct below, and summary.txt says which ran."""

import sys

from tribos_test import (setup, run, strip_columns, numdiff, check, finish,
                         mpi_available, solver_line)

tribos, tests, out = setup(sys.argv)
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all")
strip_columns(tests + "/cylinder_3d.reference.csv", out + "/reference.csv",
              drop=noisy)
for name, sets in (("gmres_amg", ["Linear solver/Type=iterative",
                                  "Linear solver/Tolerance=1e-12"]),
                   ("mumps", ["Linear solver/Direct solver=Amesos_Mumps"])):
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
if mpi_available():
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
