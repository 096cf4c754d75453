#!/usr/bin/env python3
"""Cost of the sparse direct solvers (Linear solver/Direct solver) on the
same scenes: each case runs once per solver, and the 'linear solve' section
of the run's summary.txt (analysis, factorization and solve together) gives
the wall time per solve. Rows of the same case run the same Newton
iterations up to round-off, so their ratio is the solver's.

    python3 benchmarks/direct_solvers.py [--tribos build/tribos]
        [--output doc/data/direct_solvers.csv]

About 8 min on 2 cores (KLU on the finest 2D mesh alone about 2 min).
"""

import argparse
import csv
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLVERS = ["Amesos_Klu", "Amesos_Mumps"]
LAGRANGE = ["Contact/Method=lagrange multiplier"]
# Hertz 3D runs GMRES + AMG by default.
DIRECT = ["Linear solver/Type=direct"]
# The structured upsetting mesh (the file's own is the split corner).
STRUCTURED = ["Scene/Cylinder compression/Mesh=structured",
              "Scene/Cylinder compression/Radial refinements=2"]

CASES = [
    ("cylinder 3D, 8 steps", "upsetting", STRUCTURED +
     ["Time stepping/End time=8", "Time stepping/Number of steps=8"]),
    ("cylinder 3D refined, 1 step", "upsetting", STRUCTURED +
     ["Time stepping/End time=1", "Time stepping/Number of steps=1",
      "Scene/Cylinder compression/Radial refinements=3",
      "Scene/Cylinder compression/Axial cells=8"]),
    ("Hertz 3D, penalty", "hertz_3d", DIRECT),
    ("Hertz 3D, Lagrange", "hertz_3d", DIRECT + LAGRANGE),
    ("Hertz 2D, penalty", "hertz_2d", []),
    ("Hertz 2D, Lagrange", "hertz_2d", LAGRANGE),
    ("Hertz 2D refined, penalty", "hertz_2d", ["Scene/Refinement=1"]),
    ("ring, Lagrange", "ring_on_foundation", LAGRANGE),
]


def summary(path):
    """Scalar entries and the 'linear solve' row of a summary.txt."""
    values = {}
    with open(path) as f:
        for line in f:
            words = line.split()
            if line.startswith("linear solve"):
                values["solves"] = int(words[2])
                values["solve_wall"] = float(words[3])
            elif len(words) >= 2 and words[0] in ("dofs", "multipliers",
                                                  "status", "dimension"):
                values[words[0]] = words[-1]
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--output", default=os.path.join(
        ROOT, "doc", "data", "direct_solvers.csv"))
    args = parser.parse_args()

    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for name, prm, sets in CASES:
            for solver in SOLVERS:
                folder = os.path.join(scratch, "run")
                command = [args.tribos,
                           os.path.join(ROOT, "parameters", prm + ".prm")]
                for s in sets + ["Linear solver/Direct solver=" + solver,
                                 "Output/Directory=" + folder,
                                 "Output/Frequency=0"]:
                    command += ["--set", s]
                result = subprocess.run(command, capture_output=True,
                                        text=True)
                if result.returncode != 0:
                    raise SystemExit("failed: %s\n%s" % (" ".join(command),
                                                         result.stderr))
                s = summary(os.path.join(folder, "summary.txt"))
                rows.append({
                    "case": name, "dim": s["dimension"],
                    "dofs": s["dofs"], "multipliers": s["multipliers"],
                    "solver": solver, "solves": s["solves"],
                    "solve_wall": "%.3f" % s["solve_wall"],
                    "ms_per_solve": "%.2f" % (1e3 * s["solve_wall"] /
                                              s["solves"])})
                print(",".join(str(v) for v in rows[-1].values()),
                      flush=True)
    with open(args.output, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
