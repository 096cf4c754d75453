"""Verification: Cattaneo-Mindlin partial slip in 2D. At every step of
the tangential loading (0 < Q < mu P) the stick zone, measured as the
half-distance between the midpoints of the stick/slip transitions on both
sides, must match c = a sqrt(1 - Q/(mu P)) within 10 %; a is the Hertz
half-width for the measured P (elastically similar bodies: E* = E/(2(1 -
nu^2)), no normal-tangential coupling)."""
# ctest: cases penalty lagrange
# ctest: quick-cases penalty

import math
import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
# The case (argv[4]): the enforcement, penalty or lagrange (multipliers).
method = {"penalty": "penalty", "lagrange": "lagrange multiplier"}[
    sys.argv[4] if len(sys.argv) > 4 else "penalty"]
E, nu, R, mu = 1.0, 0.3, 1.0, 0.3
e_star = E / (2 * (1 - nu * nu))
steps = 6
run(tribos, tests + "/cattaneo_mindlin.prm", out,
    ["Time stepping/Number of steps=%d" % steps, "Contact/Method=" + method])
history = read_csv(out + "/history.csv")


def transitions(nodes, inside):
    """Midpoints between the outermost nodes with inside() true and their
    outer neighbours, left and right."""
    nodes = sorted(nodes, key=lambda r: r["x"])
    flags = [inside(r) for r in nodes]
    first = flags.index(True)
    last = len(flags) - 1 - flags[::-1].index(True)
    left = 0.5 * (nodes[first]["x"] + nodes[first - 1]["x"])
    right = 0.5 * (nodes[last]["x"] + nodes[last + 1]["x"])
    return left, right


checked = 0
for step in range(steps // 2 + 1, steps + 1):
    row = [r for r in history if r["step"] == step][-1]
    P, Q = row["pair0_normal_force"], abs(row["pair0_Fx"])
    a = math.sqrt(4 * P * R / (math.pi * e_star))
    nodes = [r for r in read_csv(out + "/contact-%05d.csv" % step)
             if abs(r["x"]) < 3 * a]
    a_left, a_right = transitions(nodes, lambda r: r["CSTATUS"] > 0)
    c_left, c_right = transitions(nodes, lambda r: r["CSTATUS"] == 1)
    c = 0.5 * (c_right - c_left)
    expected = a * math.sqrt(1 - Q / (mu * P))
    print("step %d: Q/(mu P) = %.3f, a = %.5f (measured %.5f), c = %.5f, "
          "Cattaneo-Mindlin %.5f" % (step, Q / (mu * P), a,
                                     0.5 * (a_right - a_left), c, expected))
    check(abs(c - expected) < 0.1 * expected,
          "step %d: stick half-width within 10 %% (%.1f %%)"
          % (step, 100 * abs(c - expected) / expected))
    checked += 1
check(checked >= 3 and Q / (mu * P) > 0.5,
      "%d partial-slip states checked, up to Q/(mu P) = %.2f"
      % (checked, Q / (mu * P)))
finish()
