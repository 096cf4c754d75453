"""The paper's ring on a foundation (parameters/ring_on_foundation.prm, the
full 81 steps): penalty (eps_N = 1e5) and augmented Lagrangian both
complete; at the last step the ring has lifted off in the middle (slave
nodes with |x| < 30 open) while nodes on both sides are in contact; the
augmented Lagrangian keeps every closed node's penetration below its
tolerance (1e-4 of the element size) and reduces the penalty's maximum
penetration; both give the same foundation reaction within 0.1 %."""

import math
import sys

from tribos_test import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = tests + "/../parameters/ring_on_foundation.prm"
final = {}
for method in ("penalty", "augmented lagrangian"):
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
difference = abs(penalty[-1]["RF12_y"] - augmented[-1]["RF12_y"]) / abs(
    augmented[-1]["RF12_y"])
check(difference < 1e-3, "final foundation reaction: penalty %.2f, augmented "
      "%.2f (%.2e relative)" % (penalty[-1]["RF12_y"], augmented[-1]["RF12_y"],
                                difference))
finish()
