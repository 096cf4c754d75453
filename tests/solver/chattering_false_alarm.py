"""Regression: the chattering monitor must not mistake a converging active
set for chattering, and a freeze that leaves held nodes in tension must not
cost the increment.

The 3D Hertz quarter sphere of parameters/hertz_3d.prm under load control
(a traction of 0.005 on the flat top instead of the prescribed
displacement, the whole load in one increment): the contact zone grows
from one node to 265 in the first increment, and many slave nodes change
status on the way while the residual falls. Before, every status change
counted: nodes were held closed, ended in tension and the increment was
cut, again and again (before this test: the run failed after 6 cutbacks
with the direct solver). Counting only while Newton stalls left one cutback
(direct) and 6 with GMRES + ML (190 Newton iterations, 81 s). Now changes count only while
Newton stalls, held nodes in tension are released once, and a stalled
Newton step is solved tightly by the Krylov solver. Asserts, with the
direct and the iterative linear solver: one increment, no cutback, the
contact force equal to the applied load (the meshed top's area) and
Hertz's a and p0 within 5 % (as tests/verification/hertz.py does for the displacement-
controlled run)."""

import math
import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish, hertz_compare

tribos, tests, out = setup(sys.argv)
E, nu, R, traction = 1.0, 0.3, 1.0, 0.005
prm = PARAMETERS + "/hertz_3d.prm"
forces = {}
for solver in ("direct", "iterative"):
    folder = out + "/" + solver
    run(tribos, prm, folder, [
        "Boundary conditions/Dirichlet=",
        "Boundary conditions/Neumann=11 : 0, 0, -%g*t" % traction,
        "Time stepping/Number of steps=1",
        "Linear solver/Type=" + solver])
    history = read_csv(folder + "/history.csv")[-1]
    print("%s: %d increment(s), %d Newton iterations, %d cutbacks, "
          "%d chattering nodes" % (solver, history["increment"],
                                   history["newton_iterations_all"],
                                   history["cutbacks"],
                                   history["chattering_nodes"]))
    check(history["increment"] == 1 and history["cutbacks"] == 0,
          "%s: the load in one increment without cutback" % solver)
    # The top is a quarter disc of radius R meshed by straight-sided
    # faces: its area lies between the inscribed polygon's and pi/4.
    forces[solver] = history["pair0_normal_force"]
    area = forces[solver] / traction
    check(0.99 * math.pi / 4 < area <= math.pi / 4,
          "%s: contact force / traction = %.6f, the meshed top's area "
          "(pi/4 = %.6f, within 1 %%)" % (solver, area, math.pi / 4))
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(
        folder, 3, E / (1 - nu * nu), R, 4, step=1)
    check(abs(a_h - a) / a < 0.05 and abs(p0_h - p0) / p0 < 0.05,
          "%s: Hertz a and p0 within 5 %% (%.2f %%, %.2f %%; profile L2 "
          "error %.3f)" % (solver, 100 * abs(a_h - a) / a,
                           100 * abs(p0_h - p0) / p0, profile))
check(abs(forces["direct"] - forces["iterative"]) < 1e-6 * forces["direct"],
      "direct and iterative solutions carry the same force to 1e-6")
finish()
