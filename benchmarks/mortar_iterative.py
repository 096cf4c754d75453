#!/usr/bin/env python3
"""The 3D mortar system with its multipliers eliminated, solved by Krylov
and AMG at three mesh sizes (issue 18: "condensed system solved by
AMG-preconditioned CG/GMRES on a 3D case of >= 1e5 dofs, with the
iteration count reported at 3 mesh sizes").

The 3D contact patch test (tests/data/patch_test_3d.prm: two stacked blocks,
uniform pressure 0.01 E on the top, non-matching meshes 3 : 2, the upper
block's bottom the slave) with mortar and dual Lagrange multipliers,
Linear solver/Type = iterative (GMRES on the saddle-point system,
preconditioned by the multipliers' elimination with one ML V-cycle on the
displacement-only matrix), at three refinements, on one process and with
`mpirun -np 2`. Per run: dofs, multipliers, Newton iterations, GMRES
iterations (V-cycles) per solve, wall time, linear solve
time, and the patch test's pressure spread (max - min) / mean, which the
iterative solve must keep at the direct solve's level (1e-10). Inexact
Newton stops at its own tolerances, not the linear solver's, and the
spread follows them (3e-8 at the default 1e-8): both are 1e-11 here.

    python3 benchmarks/mortar_iterative.py [--tribos build/tribos]
        [--out doc/data/mortar_iterative.csv]
"""

import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from tribos_testing import read_csv  # noqa: E402

# (lower, upper) subdivisions in x and y; z is half of them (blocks of
# height 0.5).
SIZES = [(9, 6), (18, 12), (36, 24)]


def summary_value(text, key):
    m = re.search(r"^%s\s+(\S+)" % re.escape(key), text, re.M)
    return m.group(1) if m else ""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--out", default=os.path.join(
        ROOT, "doc", "data", "mortar_iterative.csv"))
    args = parser.parse_args()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for lower, upper in SIZES:
            for ranks in (1, 2):
                folder = os.path.join(scratch, "L%d_np%d" % (lower, ranks))
                command = [args.tribos,
                           os.path.join(ROOT, "tests", "data", "patch_test_3d.prm")]
                for s in ("Output/Directory=" + folder,
                          "Scene/Two blocks/Lower subdivisions=%d, %d, %d"
                          % (lower, lower, lower // 2),
                          "Scene/Two blocks/Upper subdivisions=%d, %d, %d"
                          % (upper, upper, upper // 2),
                          "Contact/Method=lagrange multiplier",
                          "Linear solver/Type=iterative",
                          "Linear solver/Tolerance=1e-12",
                          "Nonlinear solver/Residual tolerance=1e-11",
                          "Nonlinear solver/Increment tolerance=1e-11"):
                    command += ["--set", s]
                if ranks > 1:
                    command = ["mpirun", "-np", str(ranks)] + command
                start = time.time()
                subprocess.run(command, check=True, env=env,
                               stdout=subprocess.DEVNULL)
                wall = time.time() - start
                with open(folder + "/summary.txt") as f:
                    text = f.read()
                solves = re.search(r"^linear solve\s+(\d+)\s+([\d.e+-]+)",
                                   text, re.M)
                n_solves = int(solves.group(1))
                pressures = [r["CPRESS"] for r in
                             read_csv(folder + "/contact-00001.csv")]
                mean = sum(pressures) / len(pressures)
                row = {
                    "lower": lower, "upper": upper, "processes": ranks,
                    "dofs": int(summary_value(text, "dofs")),
                    "multipliers": int(summary_value(text, "multipliers")),
                    "newton": int(summary_value(text, "newton iterations")),
                    "gmres_per_solve": int(summary_value(
                        text, "linear iterations")) / n_solves,
                    "wall": wall,
                    "linear_solve": float(solves.group(2)),
                    "pressure_spread": (max(pressures) - min(pressures))
                    / mean,
                }
                rows.append(row)
                print("lower %2d upper %2d np %d: %7d dofs + %5d "
                      "multipliers, %d Newton, GMRES %.1f per "
                      "solve, %.1f s (solve %.1f s), pressure spread %.1e"
                      % (lower, upper, ranks, row["dofs"],
                         row["multipliers"], row["newton"],
                         row["gmres_per_solve"],
                         wall, row["linear_solve"], row["pressure_spread"]),
                      flush=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: ("%.4g" % v if isinstance(v, float) else v)
                             for k, v in row.items()})
    print("wrote " + args.out)


if __name__ == "__main__":
    main()
