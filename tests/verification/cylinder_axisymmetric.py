"""Axisymmetric 2D model of the cylinder compression
(parameters/cylinder_compression_axisymmetric.prm) against the analytic
homogeneous compression of the full cylinder (force = Kirchhoff stress of
the 1D integration of the J2 law / stretch x pi r^2): penalty 1000 E within
1e-4 at every step (the penalty's own error is 1.8e-5), Lagrange multipliers
within 1e-8. And against the 3D 1/8 model (parameters/cylinder_compression
.prm, default mesh): 4 x its plate force equals the axisymmetric force times
(section of the 3D mesh) / (pi r^2) within 1e-4 at every step, i.e. both
models are exact for this scene and the 3D one only pays for its polygonal
section (0.64 % smaller); the wall-time ratio is printed."""

import math
import sys
import time

from tribos_testing.analytic import cylinder_force
from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
r = 6.35


def analytic(k):
    """Full-section plate force after k steps of 0.2 mm."""
    return cylinder_force(k, math.pi * r * r)


prm2 = PARAMETERS + "/cylinder_compression_axisymmetric.prm"
times = {}
results = {}
for name, prm, sets in (
        ("axisymmetric", prm2, []),
        ("axisymmetric lagrange", prm2,
         ["Contact/Method=lagrange multiplier"]),
        ("3D", PARAMETERS + "/cylinder_compression.prm", [])):
    start = time.time()
    run(tribos, prm, out + "/" + name.replace(" ", "_"),
        sets + ["Output/Write VTU=false"])
    times[name] = time.time() - start
    results[name] = read_csv(out + "/" + name.replace(" ", "_") +
                             "/history.csv")

for name, bound in (("axisymmetric", 1e-4), ("axisymmetric lagrange", 1e-8)):
    rows = results[name]
    check(len(rows) == 25, "%s: 25 steps" % name)
    error = max(abs(abs(h["pair0_Fy"]) / analytic(int(h["step"])) - 1)
                for h in rows)
    check(error < bound, "%s: force within %.0e of the analytic curve at "
          "every step (max %.2e)" % (name, bound, error))

section = 4 * r * r * math.sin(math.pi / 16) / (math.pi * r * r / 4)
worst = max(abs(4 * abs(b["pair0_Fz"]) / (abs(a["pair0_Fy"]) * section) - 1)
            for a, b in zip(results["axisymmetric"], results["3D"]))
check(worst < 1e-4, "3D (x4) vs axisymmetric: equal up to the 3D mesh's "
      "section (%.4f) within %.1e" % (section, worst))
print("wall time: 3D %.2f s, axisymmetric %.2f s, ratio %.1f"
      % (times["3D"], times["axisymmetric"],
         times["3D"] / times["axisymmetric"]))
finish()
