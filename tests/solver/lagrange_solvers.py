"""Lagrange multipliers through the three linear solves: UMFPACK's LU of
the whole saddle-point system (Linear solver/Eliminate multipliers =
false, the reference), the multipliers eliminated from a regularized copy
with CHOLMOD and iterative refinement (the default), and GMRES on the
saddle-point system preconditioned by the elimination with an ML V-cycle
on the displacement-only matrix (Linear solver/Type = iterative). Each must
give the reference's history within 1e-6 (Newton iterations may differ:
the iterative solve is inexact Newton) and report the solve it used; on
a frictional case the elimination must hand the unsymmetric system to LU.
The iterative solve also under MPI (-np 2 and 3): the serial LU's
history within 1e-6.

Cases (argv[4]; without one, both run):
  serial  the three solves on one process
  mpi     the iterative solve at -np 2 and 3 against the serial LU runs,
          which it makes itself (two cores, one MPI test at a time)
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi

import os
import sys

from tribos_testing import (PARAMETERS, setup, run, strip_columns, numdiff,
                            check, finish, solver_line, parts, mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
LM = ["Contact/Method=lagrange multiplier"]
HERTZ_3D = ["Linear solver/Type=direct",
            "Scene/Cylinder over block/Indenter refinements=1",
            "Scene/Cylinder over block/Contact refinements=2",
            "Scene/Cylinder over block/Refinement radius=0.15",
            "Output/Write VTU=false"]
SOLVES = {
    "lu": ["Linear solver/Eliminate multipliers=false"],
    "eliminated": [],
    "iterative": ["Linear solver/Type=iterative",
                  "Linear solver/Tolerance=1e-12"],
}
CASES = {
    # frictionless: the eliminated matrix is symmetric positive definite
    "hertz_3d": (os.path.join(PARAMETERS,
                              "hertz_3d.prm"), HERTZ_3D,
                 "CHOLMOD, multipliers eliminated"),
    # friction: unsymmetric, the direct solve stays LU of the whole system
    "sliding_blocks_3d": (tests + "/sliding_blocks_3d.prm", [], "UMFPACK"),
}
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all", "chattering_nodes")



for case, (prm, sets, direct) in CASES.items():
    for solve, extra in SOLVES.items():
        if "serial" not in selected and solve != "lu":
            continue  # case mpi: the LU reference only
        folder = "%s/%s_%s" % (out, case, solve)
        run(tribos, prm, folder, sets + LM + extra)
        strip_columns(folder + "/history.csv", folder + "/h.csv", drop=noisy)
        used = solver_line(folder)
        expected = {"lu": "UMFPACK (SuiteSparse)",
                    "eliminated": direct + " (SuiteSparse)",
                    "iterative": "GMRES + eliminated multipliers "
                                 "(ML)"}[solve]
        check(used == expected, "%s, %s: solved with <%s> (expected <%s>)"
              % (case, solve, used, expected))
        if solve != "lu":
            numdiff(folder + "/h.csv", "%s/%s_lu/h.csv" % (out, case),
                    relative=1e-6, absolute=1e-10)
            print("ok      %s, %s: the LU history within 1e-6" % (case,
                                                                  solve))

# Under MPI the multipliers are eliminated across processes (each node's
# block on its owner, its columns gathered from the owners of the slave
# and master rows): the same history as the serial LU to 1e-6.
if "mpi" in selected and mpi_part(selected):
    for case, ranks in (("sliding_blocks_3d", 2), ("sliding_blocks_3d", 3),
                        ("hertz_3d", 2)):
        prm, sets, _ = CASES[case]
        folder = "%s/%s_iterative_np%d" % (out, case, ranks)
        run(tribos, prm, folder, sets + LM + SOLVES["iterative"],
            mpi_ranks=ranks)
        used = solver_line(folder)
        check(used == "GMRES + eliminated multipliers (ML)",
              "%s, iterative, mpirun -np %d: solved with <%s>"
              % (case, ranks, used))
        strip_columns(folder + "/history.csv", folder + "/h.csv",
                      drop=noisy)
        numdiff(folder + "/h.csv", "%s/%s_lu/h.csv" % (out, case),
                relative=1e-6, absolute=1e-10)
        print("ok      %s, iterative, mpirun -np %d: the serial LU history "
              "within 1e-6" % (case, ranks))
finish()
