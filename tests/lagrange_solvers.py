"""Lagrange multipliers through the three linear solves: UMFPACK's LU of
the whole saddle-point system (Linear solver/Eliminate multipliers =
false, the reference), the multipliers eliminated from a regularized copy
with CHOLMOD and iterative refinement (the default), and FGMRES on the
saddle-point system preconditioned by the elimination with GMRES + ML on
the displacement-only matrix (Linear solver/Type = iterative). Each must
give the reference's history within 1e-6 (Newton iterations may differ:
the iterative solve is inexact Newton) and report the solve it used; on
a frictional case the elimination must hand the unsymmetric system to LU.
Also checks that a run under MPI with Type = iterative and multipliers is
refused with a clear message."""

import os
import sys

from tribos_test import (setup, run, strip_columns, numdiff, check, finish)

tribos, tests, out = setup(sys.argv)
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
    "hertz_3d": (os.path.join(os.path.dirname(tests), "parameters",
                              "hertz_3d.prm"), HERTZ_3D,
                 "CHOLMOD, multipliers eliminated"),
    # friction: unsymmetric, the direct solve stays LU of the whole system
    "sliding_blocks_3d": (tests + "/sliding_blocks_3d.prm", [], "UMFPACK"),
}
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all", "chattering_nodes")


def solver_line(folder):
    with open(folder + "/summary.txt") as f:
        for line in f:
            if line.startswith("linear solver"):
                return line.split(None, 2)[2].strip()
    return ""


for case, (prm, sets, direct) in CASES.items():
    for solve, extra in SOLVES.items():
        folder = "%s/%s_%s" % (out, case, solve)
        run(tribos, prm, folder, sets + LM + extra)
        strip_columns(folder + "/history.csv", folder + "/h.csv", drop=noisy)
        used = solver_line(folder)
        expected = {"lu": "UMFPACK (SuiteSparse)",
                    "eliminated": direct + " (SuiteSparse)",
                    "iterative": "FGMRES + eliminated multipliers "
                                 "(GMRES + ML)"}[solve]
        check(used == expected, "%s, %s: solved with <%s> (expected <%s>)"
              % (case, solve, used, expected))
        if solve != "lu":
            numdiff(folder + "/h.csv", "%s/%s_lu/h.csv" % (out, case),
                    relative=1e-6, absolute=1e-10)
            print("ok      %s, %s: the LU history within 1e-6" % (case,
                                                                  solve))

# Under MPI the iterative solve with multipliers is refused.
if os.environ.get("MPIEXEC") or any(
        os.access(os.path.join(p, "mpirun"), os.X_OK)
        for p in os.environ.get("PATH", "").split(os.pathsep)):
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    result = run(tribos, tests + "/sliding_blocks_3d.prm", out + "/mpi",
                 LM + ["Linear solver/Type=iterative"], mpi_ranks=2,
                 expect_success=False)
    check(result.returncode != 0 and "under MPI use Linear solver/Type = "
          "direct" in result.stderr,
          "mpirun -np 2 with multipliers and Type = iterative is refused "
          "(exit %d)" % result.returncode)
finish()
