"""The nodal contact fields of the VTU are one physical value per node.

A block (tests/data/sliding_block.prm: nu = 0, pressed onto a rigid plane with
mu = 0.3) whose bottom (id 2) and left side (id 0) are two slave surfaces
against the same plane: the corner node (0, 0) is a slave of both pairs and
touches the plane in both with the same gap. Its CPRESS must be the
pressure of the pairs that hold it (their tributary-area-weighted mean:
the node's total normal force over its total area), not their sum; its
CSTATUS stick (1), not stick + stick (2, which reads as slip). Penalty and
multipliers must agree: with multipliers the second pair leaves the node
to the first, which takes over its tributary area. Frictionless, a closed
node reports CSTATUS 3 (closed, no tangential state), not stick."""
# ctest: labels quick

import os
import sys

from tribos_testing import setup, run, read_csv, check, finish

from vtu import nodal_values  # noqa: E402

tribos, tests, out = setup(sys.argv)
corner_pressure = {}
for method in ("penalty", "lagrange multiplier"):
    folder = out + "/" + method.split()[0]
    run(tribos, tests + "/sliding_block.prm", folder,
        ["Contact/Pairs=2 : plane ; 0 : plane", "Contact/Method=" + method,
         "Time stepping/End time=1", "Time stepping/Number of steps=2",
         "Output/Write VTU=true"])
    rows = read_csv(folder + "/contact-00002.csv")
    # Current positions: the corner sits at the plane within the penalty's
    # penetration.
    corner = [r for r in rows if abs(r["x"]) < 1e-6 and abs(r["y"]) < 1e-3]
    fields = {}
    for name in ("CPRESS", "CSTATUS"):
        fields[name] = [v for x, v, _ in nodal_values(
            folder + "/solution-00002.vtu", name)
            if abs(x[0]) < 1e-12 and abs(x[1]) < 1e-12][0]
    # Penalty: both pairs hold it (the same gap and eps_N); with
    # multipliers the second pair leaves it to the first (one constraint
    # per node and master), so the first pair's value is the node's.
    pressures = [r["CPRESS"] for r in corner if r["CSTATUS"] > 0]
    interior = [r["CPRESS"] for r in rows
                if r["pair"] == 0 and 0.3 < r["x"] < 0.7]
    check(len(corner) == 2 and len(pressures) >= 1,
          "%s: the corner is a slave node of both pairs (%d closed)"
          % (method, len(pressures)))
    check(all(abs(fields["CPRESS"][0] - p) <= 1e-6 * p for p in pressures),
          "%s: VTU CPRESS at the corner %.6g = its pressure in each pair "
          "holding it (%s), not their sum; interior nodes %.6g"
          % (method, fields["CPRESS"][0],
             ", ".join("%.6g" % p for p in pressures), interior[0]))
    check(fields["CSTATUS"][0] == 1,
          "%s: VTU CSTATUS at the corner = %g (stick)"
          % (method, fields["CSTATUS"][0]))
    corner_pressure[method] = fields["CPRESS"][0]

check(abs(corner_pressure["penalty"] / corner_pressure["lagrange multiplier"] -
        1) < 0.01,
      "the corner's CPRESS agrees between penalty and multipliers (%.5g, "
      "%.5g)" % tuple(corner_pressure.values()))

folder = out + "/frictionless"
run(tribos, tests + "/sliding_block.prm", folder,
    ["Contact/Friction coefficient=0", "Time stepping/End time=1",
     "Time stepping/Number of steps=2"])
rows = read_csv(folder + "/contact-00002.csv")
history = read_csv(folder + "/history.csv")[-1]
check(all(r["CSTATUS"] == 3 for r in rows) and history["n_active"] == 9 and
      history["n_stick"] == 0 and history["n_slip"] == 0,
      "frictionless: every closed node CSTATUS 3 (closed), counted active "
      "but neither stick nor slip")
finish()
