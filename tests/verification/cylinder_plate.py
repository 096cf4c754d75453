"""Rigid-plate contact in 3D: parameters/cylinder_compression.prm (one
eighth of the paper's cylinder, frictionless rigid plate moved 25 x 0.2 mm)
run with the neo-Hookean solid of the same E, nu (set here). Frictionless
compression is homogeneous, so the plate force
is P_zz(stretch) x A0 with the lateral stretch from P_rr = 0, A0 the area of
the meshed quarter section (its arc is a polygon of 2^(refinements + 1)
chords: 0.64 % less than pi r^2 / 4 with 2 refinements). At the
stretch the penalty solution reaches (plate position plus the uniform
penetration) the force must match to 1e-6 at every step; against the
nominal plate stretch the penalty error is reported and bounded by 0.5 %."""

import sys

from tribos_testing.analytic import neo_hookean_stress, polygon_section
from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
E, nu, r, half = 206.9, 0.29, 6.35, 6.35
area = polygon_section(r, 2 ** (2 + 1))


def force(stretch):
    return neo_hookean_stress(stretch, E, nu, 2) * area


run(tribos, PARAMETERS + "/cylinder_compression.prm", out,
    ["Output/Write VTU=false", "Materials/Model=neo-Hookean"])
rows = read_csv(out + "/history.csv")
check(len(rows) == 25 and rows[-1]["time"] == 25, "all 25 steps")
worst, worst_nominal = 0.0, 0.0
for row in rows:
    plate = 0.2 * row["time"]
    reached = (half - plate + row["max_penetration"]) / half
    exact = force(reached)
    error = abs(row["pair0_Fz"] - exact) / abs(exact)
    nominal = abs(row["pair0_Fz"] - force((half - plate) / half)) / abs(
        force((half - plate) / half))
    worst, worst_nominal = max(worst, error), max(worst_nominal, nominal)
check(worst < 1e-6, "force at the reached stretch: max relative error %.2e"
      % worst)
check(worst_nominal < 5e-3, "force at the nominal plate stretch (penalty "
      "error): max %.2e" % worst_nominal)
check(all(r["n_active"] == rows[0]["n_active"] for r in rows),
      "every top node stays in contact (%d)" % rows[0]["n_active"])
finish()
