"""Hertz 3D on an elastic block, node to segment against mortar.

A quarter sphere (R = 1, parameters/hertz_3d.prm with With block = true)
pressed 0.02 into a block of the same material (E* = E / (2 (1 - nu^2))),
penalty 1000 E/h, Contact refinements 2 and 3 (--levels). The nodal
pressures are fitted at their reference positions (tests/tribos_testing/__init__.py,
hertz_compare) and compared with Hertz for the run's own force. Writes
doc/data/mortar_3d_hertz.csv (one run per row: level, discretization, dofs,
Newton iterations, wall time, contact assembly time, errors of a, p0 and
the profile) and prints it.

    python3 benchmarks/mortar_3d_hertz.py [--tribos build/tribos]
        [--levels 2,3] [--out /tmp/mortar_3d_hertz]
"""

import argparse
import csv
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from tribos_testing import hertz_compare, sphere_on_block  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--tribos", default=os.path.join(ROOT, "build/tribos"))
parser.add_argument("--levels", default="2,3")
parser.add_argument("--out", default="/tmp/mortar_3d_hertz")
parser.add_argument("--csv",
                    default=os.path.join(ROOT, "doc/data/mortar_3d_hertz.csv"))
args = parser.parse_args()

E, nu, R = 1.0, 0.3, 1.0
rows = []
for level in [int(x) for x in args.levels.split(",")]:
    for discretization in ("node to segment", "mortar"):
        folder = "%s/L%d_%s" % (args.out, level,
                                discretization.replace(" ", "_"))
        command = [args.tribos, os.path.join(ROOT, "parameters/hertz_3d.prm")]
        for s in (["Output/Directory=" + folder, "Output/Write VTU=false"]
                  + sphere_on_block(level, discretization)):
            command += ["--set", s]
        start = time.time()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        wall = time.time() - start
        summary = open(folder + "/summary.txt").read()

        def value(pattern):
            m = re.search(pattern, summary, re.MULTILINE)
            return m.group(1) if m else ""

        a, p0, a_h, p0_h, profile, n, P = hertz_compare(
            folder, 3, E / (2 * (1 - nu * nu)), R, 4, reference=True)
        rows.append({
            "level": level, "discretization": discretization,
            "dofs": value(r"^dofs\s+(\d+)"),
            "newton_iterations": value(r"^newton iterations\s+(\d+)$"),
            "cutbacks": value(r"^cutbacks\s+(\d+)"),
            "wall": "%.2f" % wall,
            "t_contact_assembly": value(r"^\s*contact assembly\s+\d+\s+([\d.e+-]+)"),
            "a_error": "%.4f" % (abs(a_h - a) / a),
            "p0_error": "%.4f" % (abs(p0_h - p0) / p0),
            "profile_error": "%.4f" % profile,
            "nodes_in_contact": n})
        print(rows[-1], flush=True)

with open(args.csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    writer.writeheader()
    writer.writerows(rows)
print("wrote", args.csv)
