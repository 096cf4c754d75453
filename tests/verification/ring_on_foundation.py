"""The paper's ring on a foundation (parameters/ring_on_foundation.prm, the
full 81 steps): penalty (eps_N = 1e5), augmented Lagrangian and Lagrange
multipliers all complete; at the last step the ring has lifted off in the
middle (slave nodes with |x| < 30 open) while nodes on both sides are in
contact; the Lagrange multipliers close every contact node exactly
(penetration < 1e-10 of the element size), the augmented Lagrangian below
its tolerance (1e-4 of the element size), both below the penalty's
penetration; penalty and augmented Lagrangian give the Lagrange foundation
reaction within 0.1 %, the augmented Lagrangian closer than the penalty."""

import math
import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = PARAMETERS + "/ring_on_foundation.prm"
final = {}
for method in ("penalty", "augmented lagrangian", "lagrange multiplier"):
    folder = out + "/" + method.replace(" ", "_")
    run(tribos, prm, folder, ["Contact/Method=" + method])
    history = read_csv(folder + "/history.csv")
    check(history[-1]["time"] == 81 and history[-1]["step"] == 81,
          "%s: all 81 steps completed (%d Newton iterations, %d cutbacks)"
          % (method, sum(h["newton_iterations"] for h in history),
             sum(1 for h in history if h["cutbacks"] > 0)))
    nodes = read_csv(folder + "/contact-00081.csv")
    middle = [n for n in nodes if abs(n["x"]) < 30]
    left = [n for n in nodes if n["x"] < -30 and n["CSTATUS"] > 0]
    right = [n for n in nodes if n["x"] > 30 and n["CSTATUS"] > 0]
    check(len(middle) > 5 and all(n["CSTATUS"] == 0 for n in middle) and
          min(n["COPEN"] for n in middle) > 1,
          "%s: lifted off in the middle (gap at x = 0: %.3f)"
          % (method, min(middle, key=lambda n: abs(n["x"]))["COPEN"]))
    check(len(left) >= 2 and len(right) >= 2,
          "%s: in contact on both sides (%d left, %d right)"
          % (method, len(left), len(right)))
    final[method] = history

penalty, augmented = final["penalty"], final["augmented lagrangian"]
size = math.pi * 100 / 64  # outer element length of the ring
penetration = max(h["max_penetration"] for h in augmented)
check(penetration <= 1e-4 * size * 1.01,
      "augmented lagrangian: max penetration %.3e <= 1e-4 x element size "
      "(%d augmentations in all)" % (penetration, sum(
          h["augmentations"] for h in augmented)))
check(penetration < max(h["max_penetration"] for h in penalty),
      "penalty max penetration %.3e is larger"
      % max(h["max_penetration"] for h in penalty))
exact = final["lagrange multiplier"]
penetration = max(h["max_penetration"] for h in exact)
check(penetration < 1e-10 * size,
      "lagrange multiplier: max penetration %.1e < 1e-10 x element size"
      % penetration)
reference = exact[-1]["RF12_y"]
differences = {}
for method in ("penalty", "augmented lagrangian"):
    value = final[method][-1]["RF12_y"]
    differences[method] = abs(value - reference) / abs(reference)
    check(differences[method] < 1e-3,
          "final foundation reaction: %s %.2f, Lagrange %.2f (%.2e relative)"
          % (method, value, reference, differences[method]))
check(differences["augmented lagrangian"] < differences["penalty"],
      "the augmented Lagrangian is closer to the Lagrange reaction than the "
      "penalty")
finish()
