"""Friction chattering: a slipping node whose slip keeps reversing between
Newton iterations is held in stick (Contact/Chattering remedy = freeze).

parameters/ironing.prm with 2D mortar contact on the faceted master, the
primal penalty and full Newton steps, pressed down and 0.4 mm into the
slide (t in [0, 1.2]).
At t = 0.69 an edge node of the contact zone with a small pressure slipped
one way in one iterate and the other way in the next: the residual is
piecewise linear along the Newton direction, with the stick region in
between, and Newton cycled with period 2 for 20 iterations, 6 cutbacks in
a row, and the run stopped. Asserts: the run completes; every node that
sticks or slips at the outputs is within the Coulomb cone (a held node
ends inside it or is released); the punch force at t = 1 and its vertical
part at t = 1.2 are within 1 % of smoothed node to segment's (the same
scene, the other discretization), and in the slide Fx / |Fy| >= mu.

The same with the block as the slave (coarse slave, fine curved master):
it stopped at t = 0.77, where a closed node's element took or dropped a
master face by its distance from one iterate to the next and Newton
cycled even in increments of 1e-12 (the reach now decides whether a node
pairs, not which of its overlapping faces count). Asserts: it completes,
and its punch force at t = 1 is within 1 % of smoothed node to
segment's."""

import math
import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = PARAMETERS + "/ironing.prm"
mu = 0.3
# The case that cycled: the primal penalty with full Newton steps (what
# parameters/ironing.prm used then; it now solves the penalty in mixed
# form, where this cycling does not arise).
common = ["Time stepping/End time=1.2", "Time stepping/Number of steps=120",
          "Output/Write VTU=false", "Output/Frequency=10",
          "Contact/Penalty formulation=primal",
          "Nonlinear solver/Line search=false"]
mortar = run(tribos, prm, out + "/mortar",
             common + ["Contact/Discretization=mortar",
                       "Contact/Master smoothing=none"],
             expect_success=False)
check(mortar.returncode == 0,
      "mortar with full Newton steps completes (exit %d)" % mortar.returncode)
held = mortar.stdout.count("reversing slip")
print("        increments in which the remedy acted: %d" % held)

# The cone is checked on the pressures above the round-off of the
# tractions (1e-9 of the largest pressure): the file's penalty in mixed
# form has the tractions as unknowns, and a node that just touches
# converges to a pressure of 1e-12 and a shear of the same round-off.
worst = 0.0
for step in range(10, 121, 10):
    rows = read_csv(out + "/mortar/contact-%05d.csv" % step)
    floor = 1e-9 * max([r["CPRESS"] for r in rows] + [0])
    for row in rows:
        if row["CSTATUS"] >= 1 and row["CPRESS"] > floor:
            shear = math.sqrt(row["CSHEAR_x"] ** 2 + row["CSHEAR_y"] ** 2)
            worst = max(worst, shear / (mu * row["CPRESS"]))
check(worst <= 1 + 1e-6,
      "every closed node within the Coulomb cone: max |t_T| / (mu p) = %.9f"
      % worst)

block_slave = run(tribos, prm, out + "/block_slave",
                  common + ["Contact/Discretization=mortar",
                            "Contact/Master smoothing=none",
                            "Contact/Pairs=3 : 10, 11, 12"],
                  expect_success=False)
check(block_slave.returncode == 0,
      "mortar with the block as slave completes (exit %d)"
      % block_slave.returncode)

run(tribos, prm, out + "/nts", common)
forces = {}
for name in ("mortar", "nts", "block_slave"):
    forces[name] = {round(r["time"], 6): (r["RF13_x"], r["RF13_y"])
                    for r in read_csv(out + "/" + name + "/history.csv")}
for t in (1.0, 1.2):
    m, n = forces["mortar"][t], forces["nts"][t]
    for i, axis in enumerate("xy"):
        difference = abs(m[i] / n[i] - 1)
        line = ("t = %g: F%s mortar %.3f, smoothed node to segment %.3f "
                "(%.2f %%)" % (t, axis, m[i], n[i], 100 * difference))
        # In the slide the horizontal forces differ by the discretization
        # (ploughing; doc/mortar.md, 4-6 %): bounded below by friction.
        if t == 1.2 and axis == "x":
            check(m[0] / abs(m[1]) >= mu * (1 - 1e-6),
                  line + "; mortar Fx / |Fy| = %.4f >= mu"
                  % (m[0] / abs(m[1])))
        else:
            check(difference < 0.01, line)
for i, axis in enumerate("xy"):
    b, n = forces["block_slave"][1.0][i], forces["nts"][1.0][i]
    check(abs(b / n - 1) < 0.01,
          "t = 1: F%s mortar with the block as slave %.3f, smoothed node to "
          "segment %.3f (%.2f %%)" % (axis, b, n, 100 * abs(b / n - 1)))
finish()
