"""The paper's cylinder compression (parameters/cylinder_compression.prm:
one eighth, J2 plasticity with the hardening (36), frictionless rigid
plate, 25 x 0.2 mm) with penalties 10 E, 100 E, 1000 E and the augmented
Lagrangian. The compression is homogeneous, so the plate force is known:
the 1D integration of the law in logarithmic strain (tau = E(ln lambda -
eps_p), |tau| <= sigma_y(alpha)) divided by lambda, times the meshed
section (a polygon of 8 chords). Asserts, for every method, the force at
the stretch it reaches (plate position plus the uniform penetration) to
1e-6, and that the penalty error against the nominal plate stretch falls
with eps_N; writes the force-vs-displacement table doc-style to stdout."""

import math
import sys

from tribos_testing.analytic import j2_forces, polygon_section
from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
r = 6.35
area = polygon_section(r, 8)


def forces(stretches):
    """Nominal forces of monotonic compression through the stretches."""
    return j2_forces(stretches, area)


prm = PARAMETERS + "/cylinder_compression.prm"
final_errors = {}
# The paper's penalties 10 E, 100 E, 1000 E: absolute values in its units
# (E = 206.9, lengths in mm).
for method, sets in (("penalty 10E", ["Contact/Penalty factor=2069"]),
                     ("penalty 100E", ["Contact/Penalty factor=20690"]),
                     ("penalty 1000E", ["Contact/Penalty factor=206900"]),
                     ("augmented lagrangian",
                      ["Contact/Method=augmented lagrangian",
                       "Contact/Augmentation tolerance=1e-6"])):
    folder = out + "/" + method.replace(" ", "_")
    run(tribos, prm, folder, sets + ["Output/Write VTU=false"])
    rows = read_csv(folder + "/history.csv")
    check(len(rows) == 25, "%s: all 25 steps" % method)
    reached = forces([(r - 0.2 * row["time"] + row["max_penetration"]) / r
                      for row in rows])
    nominal = forces([(r - 0.2 * row["time"]) / r for row in rows])
    worst = max(abs(abs(row["pair0_Fz"]) - abs(f)) / abs(f)
                for row, f in zip(rows, reached))
    check(worst < 1e-6, "%s: force at the reached stretch within %.1e"
          % (method, worst))
    final_errors[method] = abs(abs(rows[-1]["pair0_Fz"]) - abs(nominal[-1])) / abs(nominal[-1])
    print("%s: final force %.4f kN, analytic %.4f kN, error %.2e, Newton "
          "iterations %d" % (method, abs(rows[-1]["pair0_Fz"]), abs(nominal[-1]),
                             final_errors[method],
                             sum(row["newton_iterations"] for row in rows)))
e = final_errors
check(e["penalty 10E"] > e["penalty 100E"] > e["penalty 1000E"] >
      e["augmented lagrangian"],
      "error falls with eps_N and is smallest with the augmented Lagrangian")
finish()
