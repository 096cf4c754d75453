"""Penalties and contact tolerances are free of the units: the frictional
ironing of tests/data/ironing_2d.prm (neo-Hookean cylinder slid over a block,
mu = 0.3, penalty 10 E/h) in its own units and scaled to metres and pascal
from millimetres and megapascal (lengths x 1e-3, moduli x 1e6) gives, at
every converged increment, the same Newton iterations and the same
dimensionless forces F / (E L) and, at every slave node, the same
dimensionless pressure CPRESS / E and gap COPEN / L to 1e-8; with penalty
and with Lagrange multipliers (whose semismooth parameters are E/h too)."""

import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
L, S = 1e-3, 1e6   # length and stress scales
# 31 block cells: no slave node sits exactly on a master vertex (with 32
# the indenter's lowest node does at t = 0 and after every 0.125 of
# sliding, and which of the two faces it is paired with in the first
# iteration is then decided by round-off, which differs between the unit
# systems; the converged states agree either way).
common = ["Scene/Cylinder over block/Block subdivisions=31, 4",
          "Output/Frequency=1"]
scaled = [
    "Scene/Cylinder over block/Radius=%g" % L,
    "Scene/Cylinder over block/Block width=%g" % (4 * L),
    "Scene/Cylinder over block/Block height=%g" % L,
    "Materials/Young's modulus=%g, %g" % (S, 10 * S),
    "Boundary conditions/Dirichlet=11 : xy : if(t < 1, 0, %g*(t - 1)), "
    "-%g*min(t, 1) ; 2 : xy : 0, 0" % (0.25 * L, 0.05 * L),
    # The absolute residual floor is a force (per thickness): scaled too.
    "Nonlinear solver/Absolute residual tolerance=%g" % (1e-12 * S * L),
]
for method in ("penalty", "lagrange multiplier"):
    folders = []
    for name, sets in (("model", []), ("metres", scaled)):
        folder = "%s/%s_%s" % (out, method.split()[0], name)
        run(tribos, tests + "/ironing_2d.prm", folder,
            common + sets + ["Contact/Method=" + method])
        folders.append(folder)
    a, b = (read_csv(f + "/history.csv") for f in folders)
    check(len(a) == len(b) and all(
        x["newton_iterations"] == y["newton_iterations"] for x, y in zip(a, b)),
        "%s: the same increments and Newton iterations (%d in all)"
        % (method, sum(x["newton_iterations"] for x in a)))
    worst = max(abs(x["pair0_normal_force"] - y["pair0_normal_force"] /
                    (S * L)) / abs(x["pair0_normal_force"])
                for x, y in zip(a, b) if x["pair0_normal_force"] != 0)
    check(worst < 1e-8, "%s: normal force F / (E L) equal to %.1e"
          % (method, worst))
    worst_p, worst_g, n = 0.0, 0.0, 0
    for step in range(1, 13):
        name = "/contact-%05d.csv" % step
        for x, y in zip(read_csv(folders[0] + name),
                        read_csv(folders[1] + name)):
            scale_p = max(abs(x["CPRESS"]), 1e-3)
            worst_p = max(worst_p, abs(x["CPRESS"] - y["CPRESS"] / S) / scale_p)
            worst_g = max(worst_g, abs(x["COPEN"] - y["COPEN"] / L) /
                          max(abs(x["COPEN"]), 1e-6))
            n += 1
    check(worst_p < 1e-8 and worst_g < 1e-8,
          "%s: CPRESS / E and COPEN / L equal at %d node-steps to %.1e, %.1e"
          % (method, n, worst_p, worst_g))
finish()
