"""Verification: J2 plasticity in homogeneous uniaxial compression and
unloading (tests/j2_uniaxial.prm) against the 1D integration of the same
law: in logarithmic strain, uniaxial Kirchhoff stress tau = E (ln(lambda)
- eps_p), von Mises |tau| <= sigma_y(alpha) with the hardening (36),
backward-Euler return; the nominal force is tau / lambda on the unit
section. Loading, elastic unloading and reverse yielding must agree within
0.1 % (measured to ~1e-9)."""

import math
import sys

from tribos_test import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
E, s0, sinf, delta, H = 206.9, 0.45, 0.715, 16.93, 0.12924
run(tribos, tests + "/j2_uniaxial.prm", out)
rows = read_csv(out + "/history.csv")


def yield_stress(a):
    return s0 + (sinf - s0) * (1 - math.exp(-delta * a)) + H * a


eps_p, alpha, worst, phases = 0.0, 0.0, 0.0, set()
previous_tau = 0.0
for row in rows:
    u = -0.2 * min(row["time"], 1) + 0.02 * max(row["time"] - 1, 0)
    stretch = 1 + u
    eps = math.log(stretch)
    trial = E * (eps - eps_p)
    da = 0.0
    if abs(trial) > yield_stress(alpha):
        for _ in range(60):
            r = abs(trial) - E * da - yield_stress(alpha + da)
            slope = E + (sinf - s0) * delta * math.exp(-delta * (alpha + da)) + H
            da += r / slope
        eps_p += math.copysign(da, trial)
        alpha += da
        phases.add("plastic, tension" if trial > 0 else "plastic, compression")
    elif row["time"] > 1:
        phases.add("elastic unloading")
    tau = E * (eps - eps_p)
    force = tau / stretch
    error = abs(row["RF5_z"] - force) / abs(force)
    worst = max(worst, error)
print("phases: " + ", ".join(sorted(phases)) + "; final plastic strain %.4f"
      % alpha)
check(worst < 1e-3, "force vs 1D integration: max relative error %.2e"
      % worst)
check(len(phases) == 3, "loading, elastic unloading and reverse yielding")
finish()
