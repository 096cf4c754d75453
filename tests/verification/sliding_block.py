"""Verification: Coulomb friction on a block dragged over a rigid plane
(mu = 0.3). Pressing: every node sticks, no slip, no tangential force.
Dragging: while all nodes stick the tangential force grows linearly and
stays below mu N; once all slip, it equals mu N to 1e-6 (node by node the
return mapping puts |T| = mu t_N); the transition happens at the drag
predicted by the stick stiffness; the accumulated slip equals the drag
beyond that point, independent of the number of steps (CSV and VTU)."""
# ctest: cases penalty lagrange
# ctest: quick-cases penalty lagrange

import os
import sys

from tribos_testing import setup, run, read_csv, check, finish

from vtu import nodal_values  # noqa: E402

tribos, tests, out = setup(sys.argv)
# The case (argv[4]): the enforcement, penalty or lagrange (multipliers).
method = {"penalty": "penalty", "lagrange": "lagrange multiplier"}[
    sys.argv[4] if len(sys.argv) > 4 else "penalty"]
mu = 0.3
run(tribos, tests + "/sliding_block.prm", out,
    ["Time stepping/Number of steps=24", "Output/Frequency=4",
     "Contact/Method=" + method])
rows = read_csv(out + "/history.csv")

press = [r for r in rows if r["time"] <= 1 + 1e-12]
check(all(r["n_stick"] == r["n_active"] > 0 for r in press),
      "pressing: all %d nodes stick" % press[-1]["n_active"])
check(all(abs(r["pair0_tangential_force"]) < 1e-12 for r in press),
      "pressing: no tangential force")
contact = read_csv(out + "/contact-00008.csv")
check(max(r["CSLIP"] for r in contact) == 0.0, "pressing: CSLIP = 0")

drag = [r for r in rows if r["time"] > 1 + 1e-12]
stick = [r for r in drag if r["n_slip"] == 0]
slip = [r for r in drag if r["n_slip"] == r["n_active"]]
check(len(stick) >= 2 and len(slip) >= 5,
      "%d all-stick and %d all-slip drag steps" % (len(stick), len(slip)))
for r in stick:
    ratio = r["pair0_tangential_force"] / r["pair0_normal_force"]
    check(ratio < mu, "t = %.3f stick: T/N = %.6f < mu" % (r["time"], ratio))
worst = max(abs(r["pair0_tangential_force"] / r["pair0_normal_force"] - mu)
            / mu for r in slip)
check(worst < 1e-6, "slip: |T/N - mu| / mu = %.2e < 1e-6" % worst)
worst = max(abs(-r["pair0_Fx"] / r["pair0_Fy"] - mu) / mu for r in slip)
check(worst < 1e-6, "slip: resultant -Fx/Fy = mu within %.2e" % worst)

# Transition: the stick stiffness predicts the drag d* at which T = mu N.
drag_of = lambda r: 0.01 * (r["time"] - 1)
slope = stick[-1]["pair0_tangential_force"] / drag_of(stick[-1])
d_star = mu * stick[-1]["pair0_normal_force"] / slope
first_slip = min(drag_of(r) for r in slip)
check(drag_of(stick[-1]) <= d_star <= first_slip,
      "transition: last stick drag %.5f <= predicted %.5f <= first slip "
      "drag %.5f" % (drag_of(stick[-1]), d_star, first_slip))
final = read_csv(out + "/contact-00024.csv")
mean_slip = sum(r["CSLIP"] for r in final) / len(final)
expected = drag_of(rows[-1]) - d_star
check(abs(mean_slip - expected) < 0.02 * expected,
      "accumulated slip %.5f vs drag beyond d*: %.5f (d* from the last "
      "stick step's secant)" % (mean_slip, expected))

# The accumulated slip is a state, not a sum of increments counted twice:
# the same drag in twice as many steps gives the same CSLIP at every node
# (the return map's plastic slip telescopes while the block slips one
# way), in contact-*.csv and in the VTU.
fine = out + "/48_steps"
run(tribos, tests + "/sliding_block.prm", fine,
    ["Time stepping/Number of steps=48", "Output/Frequency=8",
     "Output/Write VTU=true", "Contact/Method=" + method])
fine_rows = read_csv(fine + "/contact-00048.csv")
worst = max(abs(a["CSLIP"] - b["CSLIP"]) / b["CSLIP"]
            for a, b in zip(final, fine_rows))
check(len(final) == len(fine_rows) and worst < 1e-6,
      "CSLIP with 24 and 48 steps: equal to %.1e at every node" % worst)
vtu = [values[0] for x, values, _ in
       nodal_values(fine + "/solution-00048.vtu", "CSLIP") if x[1] == 0]
vtu_mean = sum(vtu) / len(vtu)
check(abs(vtu_mean - mean_slip) < 1e-6 * mean_slip,
      "VTU CSLIP (48 steps, float32) equals the CSV's of 24 steps: mean "
      "%.7f vs %.7f" % (vtu_mean, mean_slip))
finish()
