"""Verification: J2 plasticity in homogeneous uniaxial compression and
unloading (tests/data/j2_uniaxial.prm) against the 1D integration of the same
law: in logarithmic strain, uniaxial Kirchhoff stress tau = E (ln(lambda)
- eps_p), von Mises |tau| <= sigma_y(alpha) with the hardening (36),
backward-Euler return; the nominal force is tau / lambda on the unit
section. Loading, elastic unloading and reverse yielding must agree within
0.1 % (measured to ~1e-9)."""
# ctest: labels quick

import sys

from tribos_testing.analytic import J2Uniaxial
from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
run(tribos, tests + "/j2_uniaxial.prm", out)
rows = read_csv(out + "/history.csv")

material, worst, phases = J2Uniaxial(), 0.0, set()
for row in rows:
    u = -0.2 * min(row["time"], 1) + 0.02 * max(row["time"] - 1, 0)
    stretch = 1 + u
    tau = material.update(stretch)
    if material.phase != "elastic":
        phases.add(material.phase)
    elif row["time"] > 1:
        phases.add("elastic unloading")
    force = tau / stretch
    error = abs(row["RF5_z"] - force) / abs(force)
    worst = max(worst, error)
print("phases: " + ", ".join(sorted(phases)) + "; final plastic strain %.4f"
      % material.alpha)
check(worst < 1e-3, "force vs 1D integration: max relative error %.2e"
      % worst)
check(len(phases) == 3, "loading, elastic unloading and reverse yielding")
finish()
