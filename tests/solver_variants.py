"""Linear solvers: GMRES with AMG and the MUMPS direct solver give the
same history as the default (KLU) reference of regression/cylinder_3d."""

import sys

from tribos_test import setup, run, strip_columns, numdiff, check, finish

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
finish()
