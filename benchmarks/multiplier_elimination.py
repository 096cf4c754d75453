#!/usr/bin/env python3
"""Lagrange multiplier solves with the multipliers eliminated (SparseDirect:
regularized elimination, CHOLMOD or UMFPACK of the displacement-only
matrix, iterative refinement on the exact system) against UMFPACK's LU of
the whole saddle-point system (Linear solver/Eliminate multipliers =
false), same build, alternating runs, medians; the penalty method's time
beside them for the Lagrange / penalty ratio of issue 16.

    python3 benchmarks/multiplier_elimination.py [--tribos build/tribos]
        [--runs 3] [--out doc/data/multiplier_elimination.csv]
        [--only NAME ...]

Per case and variant: Newton iterations, median wall time, linear solve
time and ms per solve, the solver the log names, and the largest relative
difference of the final contact force (history.csv) to the LU run's.

    python3 benchmarks/multiplier_elimination.py --iterative
        [--out doc/data/multiplier_iterative.csv]

runs instead the 3D Hertz with multipliers and Linear solver/Type =
iterative (GMRES preconditioned by the elimination, one ML V-cycle inside)
at Contact refinements 3, 4 and 5, once each: unknowns, Newton
iterations, GMRES iterations, AMG setups, wall time, peak memory."""

import argparse
import csv
import os
import statistics
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
from solver_speed import hertz2d, hertz3d, run_once, summary  # noqa: E402

LAGRANGE = "Contact/Method=lagrange multiplier"
CASES = [
    ("hertz2d_L5", hertz2d(5, 0.005)),
    ("hertz2d_L6", hertz2d(6, 0.005)),
    ("hertz3d_L4", hertz3d(4, 0.005)),
    ("hertz3d_L4r23", hertz3d(4, 0.005, radius=0.23)),
    ("cylinder", ("parameters/cylinder_compression.prm", [])),
    ("ring", ("parameters/ring_on_foundation.prm", [])),
    ("upsetting_5_steps", ("parameters/upsetting.prm",
                           ["Time stepping/End time=5",
                            "Time stepping/Number of steps=5"])),
    ("sliding_block_mu03", ("tests/data/sliding_block.prm", [])),
    ("cattaneo_mindlin_mu03", ("tests/data/cattaneo_mindlin.prm", [])),
    ("sliding_blocks_3d_mortar", ("tests/data/sliding_blocks_3d.prm",
                                  ["Contact/Discretization=mortar"])),
]
VARIANTS = [
    ("eliminated", [LAGRANGE, "Linear solver/Eliminate multipliers=true"]),
    ("lu", [LAGRANGE, "Linear solver/Eliminate multipliers=false"]),
    ("penalty", []),
]


def final_forces(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    last = rows[-1]
    return {k: float(v) for k, v in last.items()
            if k.startswith("pair") and k.endswith(("_Fx", "_Fy", "_Fz",
                                                    "_normal_force"))}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(
        ROOT, "doc", "data", "multiplier_elimination.csv"))
    parser.add_argument("--only", nargs="*", default=[])
    parser.add_argument("--iterative", action="store_true")
    args = parser.parse_args()
    if args.iterative:
        if args.out.endswith("multiplier_elimination.csv"):
            args.out = args.out.replace("multiplier_elimination.csv",
                                        "multiplier_iterative.csv")
        iterative(args)
        return
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name, (prm, sets) in CASES:
            if args.only and name not in args.only:
                continue
            walls = {v: [] for v, _ in VARIANTS}
            for _ in range(args.runs):
                for variant, extra in VARIANTS:
                    # The penalty runs keep the scene's own penalty method
                    # unless the scene is a Lagrange one by default.
                    folder = os.path.join(work, name + "_" + variant)
                    w, _ = run_once(args.tribos, prm, list(sets) + extra,
                                    folder)
                    walls[variant].append(w)
            reference = final_forces(os.path.join(work, name + "_lu"))
            for variant, _ in VARIANTS:
                folder = os.path.join(work, name + "_" + variant)
                sections, values = summary(folder)
                calls, solve = sections.get("linear solve", (0, 0.0))
                forces = final_forces(folder)
                difference = max(
                    (abs(forces[k] - reference[k]) /
                     max(abs(reference[k]), 1e-300)
                     for k in reference if abs(reference[k]) > 1e-12),
                    default=0.0)
                row = {
                    "case": name, "variant": variant, "runs": args.runs,
                    "unknowns": values.get("dofs", 0) +
                    values.get("multipliers", 0),
                    "multipliers": values.get("multipliers", 0),
                    "solver": values.get("linear solver", ""),
                    "newton_iterations": values.get(
                        "newton iterations (all attempts)", 0),
                    "wall_median": statistics.median(walls[variant]),
                    "t_linear_solve": solve,
                    "ms_per_solve": 1e3 * solve / max(calls, 1),
                    "force_difference_to_lu": difference,
                }
                rows.append(row)
                print("%-26s %-10s %7d unknowns %4d Newton %8.2f s  solve "
                      "%7.2f s %8.1f ms/solve  dF %.1e  [%s]" % (
                          name, variant, row["unknowns"],
                          row["newton_iterations"], row["wall_median"],
                          solve, row["ms_per_solve"], difference,
                          row["solver"]), flush=True)
            by = {r["variant"]: r for r in rows if r["case"] == name}
            print("%-26s eliminated / lu %.2f, eliminated / penalty %.2f, "
                  "lu / penalty %.2f" % (
                      name,
                      by["eliminated"]["wall_median"] / by["lu"]["wall_median"],
                      by["eliminated"]["wall_median"] /
                      by["penalty"]["wall_median"],
                      by["lu"]["wall_median"] / by["penalty"]["wall_median"]),
                  flush=True)
    if rows:
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            for r in rows:
                writer.writerow({k: ("%.4g" % v if isinstance(v, float)
                                     else v) for k, v in r.items()})


def iterative(args):
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for level in (3, 4, 5):
            prm, sets = hertz3d(level, 0.005)
            folder = os.path.join(work, "L%d" % level)
            w, rss = run_once(args.tribos, prm, list(sets) + [
                LAGRANGE, "Linear solver/Type=iterative"], folder)
            sections, values = summary(folder)
            counters = {}
            with open(os.path.join(folder, "summary.txt")) as f:
                for line in f:
                    for key in ("linear iterations", "AMG setups"):
                        if line.startswith(key):
                            counters[key] = int(line.split()[-1])
            calls, solve = sections.get("linear solve", (0, 0.0))
            newton = values.get("newton iterations (all attempts)", 0)
            row = {
                "level": level, "dofs": values.get("dofs", 0),
                "multipliers": values.get("multipliers", 0),
                "newton_iterations": newton,
                "gmres_iterations": counters.get("linear iterations", 0),
                "amg_setups": counters.get("AMG setups", 0),
                "wall": w, "t_linear_solve": solve,
                "s_per_solve": solve / max(calls, 1),
                "peak_rss_mb": rss,
                "solver": values.get("linear solver", ""),
            }
            rows.append(row)
            print("L%d %7d dofs + %5d multipliers: %2d Newton, %.1f GMRES "
                  "iterations per solve, %d AMG setups, "
                  "%.1f s (%.2f s per solve), %.0f MB  [%s]" % (
                      level, row["dofs"], row["multipliers"], newton,
                      row["gmres_iterations"] / max(newton, 1),
                      row["amg_setups"], w, row["s_per_solve"], rss,
                      row["solver"]), flush=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for r in rows:
            writer.writerow({k: ("%.4g" % v if isinstance(v, float) else v)
                             for k, v in r.items()})


if __name__ == "__main__":
    main()
