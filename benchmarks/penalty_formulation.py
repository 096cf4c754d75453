#!/usr/bin/env python3
"""Contact/Penalty formulation: the penalty law solved primal (forces of the
displacements) or mixed (the slave tractions as unknowns, the same
solution). The static scenes of benchmarks/extrapolation.py, plus the 3D
upsetting on its structured mesh, run with both, alternating, one
process, the other settings as the files have them (penalty pairs only
change): Newton iterations (accepted, and with the failed attempts),
cutbacks, wall time (median of --runs), and the largest relative
difference of the last step's contact forces and reactions between the
two. Writes doc/data/penalty_formulation.csv.

    python3 benchmarks/penalty_formulation.py [--tribos build/tribos]
        [--runs 1] [--out doc/data/penalty_formulation.csv] [--only NAME ...]
"""

import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
from extrapolation import CASES as SCENES  # noqa: E402

CASES = dict(SCENES)
CASES["upsetting_structured"] = (
    "parameters/upsetting.prm",
    ["Scene/Cylinder compression/Mesh=structured",
     "Scene/Cylinder compression/Radial refinements=2"])


def history(folder):
    path = folder + "/history.csv"
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def summary(folder, key):
    path = folder + "/summary.txt"
    if not os.path.exists(path):
        return ""
    m = re.search("^" + re.escape(key) + r"\s+(\S+)", open(path).read(),
                  re.MULTILINE)
    return m.group(1) if m else ""


def one_run(tribos, prm, sets, formulation, folder):
    command = [tribos, os.path.join(ROOT, prm),
               "--set", "Output/Directory=" + folder,
               "--set", "Output/Write VTU=false",
               "--set", "Contact/Penalty formulation=" + formulation]
    for s in sets:
        command += ["--set", s]
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    return result.returncode, time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--out", default=os.path.join(
        ROOT, "doc", "data", "penalty_formulation.csv"))
    parser.add_argument("--only", nargs="*", default=[])
    args = parser.parse_args()

    rows = []
    for name, (prm, sets) in CASES.items():
        if args.only and name not in args.only:
            continue
        walls = {"primal": [], "mixed": []}
        results = {}
        with tempfile.TemporaryDirectory() as tmp:
            for _ in range(args.runs):
                for formulation in ("primal", "mixed"):
                    folder = os.path.join(tmp, formulation)
                    code, wall = one_run(args.tribos, prm, sets, formulation,
                                         folder)
                    walls[formulation].append(wall)
                    h = history(folder)
                    results[formulation] = {
                        "exit": code,
                        "newton": summary(folder, "newton iterations"),
                        "newton_all": summary(
                            folder, "newton iterations (all attempts)"),
                        "cutbacks": summary(folder, "cutbacks"),
                        "last": h[-1] if h else {}}
        # The largest relative difference of the forces of the last row.
        a, b = results["primal"]["last"], results["mixed"]["last"]
        columns = [c for c in a if c.startswith("RF") or
                   c.endswith("_normal_force") or
                   c.endswith("_tangential_force")]
        scale = max([abs(float(a[c])) for c in columns] + [1e-300])
        difference = max([abs(float(a[c]) - float(b.get(c, "nan")))
                          for c in columns] + [0]) / scale
        row = {"case": name}
        for formulation in ("primal", "mixed"):
            r = results[formulation]
            row[formulation + "_exit"] = r["exit"]
            row[formulation + "_newton"] = r["newton"]
            row[formulation + "_newton_all"] = r["newton_all"]
            row[formulation + "_cutbacks"] = r["cutbacks"]
            row[formulation + "_wall"] = "%.2f" % statistics.median(
                walls[formulation])
        row["force_difference"] = "%.1e" % difference
        rows.append(row)
        print(row, flush=True)

    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]),
                                lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    print("wrote " + args.out)


if __name__ == "__main__":
    main()
