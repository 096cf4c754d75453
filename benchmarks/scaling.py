#!/usr/bin/env python3
"""Distributed memory (issue 17): what MPI buys on this machine, from
summary.txt and the wall clock, written to doc/data/scaling.csv.

    python3 benchmarks/scaling.py [--tribos build/tribos] [--runs 3]
        [--out doc/data/scaling.csv] [--only CASE ...] [--large]

Cases (Parallel/Mesh = distributed unless the variant says shared):

* speedup: frictional sliding of two blocks (tests/data/sliding_blocks_3d.prm,
  mu = 0.3, penalty, refined to 245k dofs, GMRES + ML; pressed in 8 steps,
  then slid by two elements in one), one process (which
  assembles with both cores' threads) and one process with one thread
  against `mpirun -np 2`, alternating, medians of --runs;
* communication: the same scene at three sizes with Contact/Search
  distance = 0.05 (and the largest with no limit), np 2: the values each
  process receives per update of the ghosted solution, the contact's share
  of them (slave nodes beyond the process's cells), the master node values
  a process receives per search (the most in one search, and the mean),
  the slave nodes paired with another process's master face;
* memory: the paper's cylinder (J2, frictionless plate, penalty) at 314k
  dofs, the first step, np 2, shared against distributed mesh: peak memory
  per process and in all, and the ghost values;
* multipliers: the cylinder's first step at 42k and 314k dofs, np 2,
  penalty (GMRES + ML) against Lagrange multipliers (FGMRES, the
  multipliers eliminated across processes), and MUMPS at 42k;
* balance: the 3D mortar sphere on a block (parameters/hertz_3d.prm with
  the block, penalty 1000 E/h) at Contact refinements 2 and 3, np 2,
  METIS' plain partition against Parallel/Contact cell weight = 21 (what
  the plain run's summary.txt suggests) and Parallel/Rebalance threshold =
  2 (repartitioned by the measured work after step 1 of 2), alternating,
  medians of --runs; the contact time of the busiest and the idlest
  process (the rebalanced run: in its second step) and their slave nodes;
* large (only with --large, about 15 minutes): the cylinder at 1.2M dofs,
  its first two steps of 25 at np 2, for the whole stroke's projection;
  large_multipliers the same with Lagrange multipliers; large_full and
  large_multipliers_full (26 and 41 minutes, only with --only) the
  whole stroke of 25 steps, the issue's targets.

Each row: case, variant, processes, dofs, Newton iterations, median wall
time (and every run's), the assembly / contact / solve sections, linear
iterations, peak memory (largest process, all), ghost values (largest
process, contact's share), slave nodes paired across processes."""

import argparse
import csv
import os
import re
import statistics
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from solver_speed import run_once, summary, with_earlier_rows  # noqa: E402
from tribos_testing import sphere_on_block  # noqa: E402

BLOCKS = "tests/data/sliding_blocks_3d.prm"
CYLINDER = "parameters/cylinder_compression.prm"


def blocks(refinement):
    """Pressed in 8 steps, then slid by 0.0375 (two elements) in one."""
    return (BLOCKS, ["Scene/Two blocks/Lower subdivisions=8, 8, 2",
                     "Scene/Two blocks/Upper subdivisions=4, 4, 1",
                     "Scene/Refinement=%d" % refinement,
                     "Time stepping/End time=1.125",
                     "Time stepping/Number of steps=9"])


def cylinder(refinement, radial, steps):
    return (CYLINDER, ["Scene/Refinement=%d" % refinement,
                       "Scene/Cylinder compression/Radial refinements=%d"
                       % radial,
                       "Time stepping/End time=%d" % steps,
                       "Time stepping/Number of steps=%d" % steps])


SHARED = ["Parallel/Mesh=shared"]
ITERATIVE = ["Linear solver/Type=iterative"]
DIRECT = ["Linear solver/Type=direct"]
LM = ["Contact/Method=lagrange multiplier"]
# 2.7 elements of the lower block at refinement 3 (0.15 / 2^3).
SEARCH = ["Contact/Search distance=0.05"]
# One process without the assembly's second thread: the classic strong
# scaling baseline beside tribos' default one (both cores' threads).
ONE_THREAD = {"env": {"DEAL_II_NUM_THREADS": "1"}}


def mortar_sphere(level, weight, rebalance=0):
    return ("parameters/hertz_3d.prm",
            sphere_on_block(level, "mortar")
            + ["Parallel/Contact cell weight=%d" % weight,
               "Parallel/Rebalance threshold=%g" % rebalance])


def variant(case, extra):
    return (case[0], case[1] + extra)



# case: [(variant, (prm, sets), processes)]
CASES = {
    "speedup": [("np1", blocks(3), 1), ("np2", blocks(3), 2),
                ("np1 one thread", blocks(3), ONE_THREAD)],
    "communication": [("refinement %d" % r, variant(blocks(r), SEARCH), 2)
                      for r in (1, 2, 3)]
    + [("refinement 3 no limit", blocks(3), 2)],
    "memory": [("shared", (CYLINDER, cylinder(3, 2, 1)[1] + SHARED), 2),
               ("distributed", cylinder(3, 2, 1), 2)],
    "multipliers": [
        ("penalty 42k", variant(cylinder(2, 2, 1), ITERATIVE), 2),
        ("multipliers 42k", variant(cylinder(2, 2, 1), LM + ITERATIVE), 2),
        ("multipliers 42k MUMPS", variant(cylinder(2, 2, 1), LM + DIRECT),
         2),
        ("penalty 314k", variant(cylinder(3, 2, 1), ITERATIVE), 2),
        ("multipliers 314k", variant(cylinder(3, 2, 1), LM + ITERATIVE), 2)],
    "balance": [(name % level, mortar_sphere(level, weight, rebalance), 2)
                for level in (2, 3)
                for name, weight, rebalance in (
                    ("level %d weight 1", 1, 0),
                    ("level %d weight 21", 21, 0),
                    ("level %d rebalance 2", 1, 2))],
    "large": [("2 of 25 steps", cylinder(3, 3, 2), 2)],
    "large_full": [("25 steps", cylinder(3, 3, 25), 2)],
    "large_multipliers_full": [("25 steps",
                                variant(cylinder(3, 3, 25), LM + ITERATIVE),
                                2)],
    "large_multipliers": [("2 of 25 steps",
                           variant(cylinder(3, 3, 2), LM + ITERATIVE), 2)],
}


# summary.txt's lines: pattern, the columns of its groups, their type.
SUMMARY_VALUES = [
    (r"peak memory\s+([\d.e+]+) MB per process \(max\), ([\d.e+]+) MB in "
     r"all", ("peak_mb_process", "peak_mb_all"), float),
    (r"ghost values\s+max ([\d.e+]+) per process .* of which contact "
     r"([\d.e+]+)", ("ghost_values", "contact_ghost_values"), float),
    (r"master exchange\s+max ([\d.e+]+) values .* mean ([\d.e+]+)",
     ("exchange_values_max", "exchange_values_mean"), float),
    (r"contact across processes (\d+) slave nodes", ("paired_across",), int),
    (r"balance contact\s+min ([\d.e+-]+) s, max ([\d.e+-]+) s",
     ("contact_time_min", "contact_time_max"), float),
    (r"balance slave nodes min (\d+), max (\d+)",
     ("slave_nodes_min", "slave_nodes_max"), int),
    (r"linear iterations (\d+)", ("linear_iterations",), int),
    (r"refinement steps\s+(\d+)", ("outer_iterations",), int),
]


def as_launch(launch):
    """A case's launch: a number of processes or run_once's dictionary."""
    if isinstance(launch, dict):
        return launch
    return {"ranks": launch} if launch > 1 else {}


def extras(folder):
    """Peak memory, ghost values, contact across processes, the contact's
    balance and the linear iterations."""
    values = {}
    with open(folder + "/summary.txt") as f:
        text = f.read()
    for pattern, columns, kind in SUMMARY_VALUES:
        m = re.search(pattern, text)
        if m:
            for i, column in enumerate(columns):
                values[column] = kind(m.group(i + 1))
    return values


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "data",
                                                      "scaling.csv"))
    parser.add_argument("--only", nargs="*", default=[])
    parser.add_argument("--large", action="store_true")
    args = parser.parse_args()

    # The whole strokes (about 35 minutes each) only when asked by name.
    names = args.only or [n for n in CASES
                          if not n.startswith("large")
                          or (args.large and not n.endswith("_full"))]
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for name in names:
            variants = CASES[name]
            runs = args.runs if name in ("speedup", "balance") else 1
            walls = {v: [] for v, _, _ in variants}
            last = {}
            # Alternate the variants, so that the machine's noise hits all.
            for _ in range(runs):
                for variant, (prm, sets), launch in variants:
                    launch = as_launch(launch)
                    ranks = launch.get("ranks", 1)
                    folder = os.path.join(scratch, name, variant.replace(" ",
                                                                         "_"))
                    wall, _ = run_once(args.tribos, prm, sets, folder, launch)
                    walls[variant].append(wall)
                    last[variant] = folder
                    print("%-14s %-16s np %d  %.2f s" % (name, variant,
                                                         ranks, wall),
                          flush=True)
            for variant, (prm, sets), launch in variants:
                ranks = as_launch(launch).get("ranks", 1)
                sections, values = summary(last[variant])
                row = {"case": name, "variant": variant, "processes": ranks,
                       "dofs": values.get("dofs"),
                       "newton": values.get("newton iterations"),
                       "wall_median": statistics.median(walls[variant]),
                       "walls": " ".join("%.2f" % w for w in walls[variant])}
                for section in ("assembly", "contact assembly",
                                "contact search", "linear solve"):
                    row[section.replace(" ", "_")] = \
                        sections.get(section, (0, 0.))[1]
                row.update(extras(last[variant]))
                rows.append(row)

    columns = ["case", "variant", "processes", "dofs", "newton",
               "wall_median", "walls", "assembly", "contact_assembly",
               "contact_search", "linear_solve", "linear_iterations",
               "outer_iterations",
               "peak_mb_process", "peak_mb_all", "ghost_values",
               "contact_ghost_values", "exchange_values_max",
               "exchange_values_mean", "paired_across", "contact_time_min",
               "contact_time_max", "slave_nodes_min", "slave_nodes_max"]
    # The rows of the cases not run stay as they were.
    rows = with_earlier_rows(args.out, rows, names)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        for row in rows:
            writer.writerow({c: row.get(c, "") for c in columns})
    print("wrote " + args.out)

    by = {(r["case"], r["variant"]): r for r in rows}
    for baseline in ("np1", "np1 one thread"):
        if ("speedup", baseline) in by and ("speedup", "np2") in by:
            ratio = float(by["speedup", baseline]["wall_median"]) / \
                float(by["speedup", "np2"]["wall_median"])
            print("target: np 2 vs %s speed-up, frictional two blocks "
                  "(%s dofs): %.2f (target >= 1.7)"
                  % (baseline, by["speedup", "np2"]["dofs"], ratio))


if __name__ == "__main__":
    main()
