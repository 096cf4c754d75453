#!/usr/bin/env python3
"""Full runs of the robustness suite (doc/robustness.md) with penalty and
Lagrange multipliers: one CSV row per run with the steps completed,
increments, cutbacks, Newton iterations per step, the median observed
convergence order near convergence, the increments with chattering nodes
and the wall time.

    python3 benchmarks/robustness_study.py [--tribos build/tribos]
        [--timeout 1800] [--cases ironing upsetting] [--exact]

Writes doc/data/robustness.csv; with --cases only the cases whose name
contains one of the given words are run, and their rows replace the same
rows of the existing file. The whole suite takes about 40 min (the full
ironing with penalty alone about 10 min).
"""

import argparse
import csv
import math
import os
import statistics
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The upsetting file's mesh is the split corner (r = 3, 35-40 min a run);
# the structured rows use the 192-cell grid.
STRUCTURED = ["Scene/Cylinder compression/Mesh=structured",
              "Scene/Cylinder compression/Radial refinements=2"]

CASES = [
    ("stick-slip cycles", "stick_slip_cycles", []),
    ("release and re-contact", "bouncing_block", []),
    ("slide off a convex corner", "slide_off_edge", []),
    ("force control, initially apart", "force_control_apart", []),
    ("upsetting mu = 0.5", "upsetting", STRUCTURED),
    ("upsetting mu = 0.5, split-corner mesh, r = 3", "upsetting", []),
    ("upsetting mu = 0.2", "upsetting",
     STRUCTURED + ["Contact/Friction coefficient=0.2"]),
    ("upsetting mu = 0.5, axisymmetric 8 x 8", "cylinder_compression_axisymmetric",
     ["Finite element/F-bar=true", "Contact/Friction coefficient=0.5",
      "Contact/Pairs=3, 4 : plate", "Contact/Tangential penalty factor=5*E/h",
      "Scene/Cylinder compression/Radial refinements=3",
      "Scene/Cylinder compression/Axial cells=8"]),
    ("Hertz 2D, penalty 1e4 E/h", "hertz_2d", ["Contact/Penalty factor=1e4*E/h"]),
    ("Hertz 2D, penalty 1e6 E/h", "hertz_2d", ["Contact/Penalty factor=1e6*E/h"]),
    ("cylinder, penalty 1e4 E/h", "cylinder_compression",
     ["Contact/Penalty factor=1e4*E/h"]),
    ("cylinder, penalty 1e6 E/h", "cylinder_compression",
     ["Contact/Penalty factor=1e6*E/h"]),
    ("ring lift-off (paper)", "ring_on_foundation", []),
    ("ironing (full: 100 + 500 increments)", "ironing", []),
]

# Settings for one method only: the ironing's parameter file switches the
# line search off for penalty; Lagrange multipliers need it at first touch.
METHOD_SETS = {("ironing", "lagrange multiplier"):
               ["Nonlinear solver/Line search=true"]}


def read(path):
    with open(path) as f:
        return [{k: float(v) if v not in ("", "nan") else math.nan
                 for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--out", default="/tmp/tribos_robustness")
    parser.add_argument("--timeout", type=int, default=1800,
                        help="seconds after which a run is stopped")
    parser.add_argument("--cases", nargs="*", default=[],
                        help="run only the cases whose name contains one "
                        "of these words; their rows replace the old ones")
    parser.add_argument("--exact", action="store_true",
                        help="--cases are whole case names")
    args = parser.parse_args()
    rows = []
    for name, prm, sets in CASES:
        if args.cases and not any(
                (word == name if args.exact else word in name)
                for word in args.cases):
            continue
        for method in ("penalty", "lagrange multiplier"):
            if "penalty 1e" in name and method != "penalty":
                continue
            folder = os.path.join(args.out, prm + "_" + str(len(rows)))
            command = [args.tribos, os.path.join(ROOT, "parameters",
                                                 prm + ".prm"),
                       "--set", "Output/Directory=" + folder,
                       "--set", "Output/Write VTU=false",
                       "--set", "Contact/Method=" + method]
            for s in sets + METHOD_SETS.get((prm, method), []):
                command += ["--set", s]
            start = time.time()
            try:
                result = subprocess.run(command, capture_output=True,
                                        text=True, timeout=args.timeout)
                status = "completed" if result.returncode == 0 else "failed"
            except subprocess.TimeoutExpired:
                status = "stopped after %d s" % args.timeout
            wall = time.time() - start
            h = read(os.path.join(folder, "history.csv"))
            c = read(os.path.join(folder, "convergence.csv"))
            n_steps = int(open(os.path.join(ROOT, "parameters", prm + ".prm"))
                          .read().split("Number of steps")[1].split("=")[1]
                          .split()[0])
            steps = int(h[-1]["step"]) if h else 0
            done = status == "completed"
            orders = []
            for inc in sorted(set(r["increment"] for r in c)):
                o = [r["order"] for r in c if r["increment"] == inc and
                     math.isfinite(r["order"]) and r["relative_residual"] >
                     1e-13]
                if o:
                    orders.append(max(o[-2:]))
            iterations = sum(r["newton_iterations"] for r in h)
            rows.append({
                "case": name, "method": method,
                "status": status,
                "steps": "%d/%d" % (steps if done else steps - 1
                                    if steps else 0, n_steps),
                "increments": len(h),
                # history.csv counts the cutbacks of a step so far.
                "cutbacks": sum(int(max(r["cutbacks"] for r in h
                                        if r["step"] == step))
                                for step in set(r["step"] for r in h)),
                "newton_per_step": "%.2f" % (iterations / max(1, len(h))),
                "median_order": "%.2f" % statistics.median(orders)
                if orders else "",
                "chattering_increments": int(sum(
                    1 for r in h if r.get("chattering_nodes", 0) > 0)),
                "wall_time": "%.2f" % wall})
            print(rows[-1], flush=True)
    path = os.path.join(ROOT, "doc", "data", "robustness.csv")
    if args.cases and os.path.exists(path):
        with open(path) as f:
            old = list(csv.DictReader(f))
        new = {(r["case"], r["method"]): r for r in rows}
        merged = [new.pop((r["case"], r["method"]), r) for r in old]
        rows = merged + list(new.values())
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]),
                                lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    print("wrote " + path)


if __name__ == "__main__":
    main()
