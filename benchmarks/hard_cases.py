#!/usr/bin/env python3
"""The hard cases of large frictional sliding (issue 55, doc/robustness.md):
one CSV row per run with the increments, cutbacks, Newton iterations of the
accepted increments and of every attempt (failed ones included), the mean
per nominal step, the wall time and the forces at the times the case
compares.

    python3 benchmarks/hard_cases.py [--tribos build/tribos]
        [--baseline OTHER/tribos] [--runs 1] [--cases ironing_600 ...]
        [--out doc/data/hard_cases.csv] [--timeout 3600]

--cases runs the cases whose name contains one of the words (their rows
replace the same rows of an existing file). With --baseline every case also
runs with that binary, alternating with --tribos run by run (the same
machine state for both), and the rows carry its numbers in columns
base_*; wall times are medians over --runs alternating pairs.

Columns: case, runs, status, steps, increments, cutbacks, rejected
(increments rejected for accuracy, Time stepping/Maximum contact changes), newton,
newton_all, newton_per_step (newton_all over the nominal steps), median_order
(Newton's observed order near convergence, the median over the
increments), wall (median, s), then the force columns of the case at its times
(e.g. V@1 and H@1 for the ironing: the punch's vertical and horizontal
reaction), and with --baseline the same prefixed base_.
"""

import argparse
import csv
import math
import os
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The parameter files (--parameters: those of another checkout, for a
# baseline binary that does not know this one's entries).
PRM = os.path.join(ROOT, "parameters")

# The ironing's forces: the punch top's reactions, vertical (V) and
# horizontal (H), at the times issue 55 compares.
IRONING_TIMES = (0.5, 1, 1.5, 3.5)
IRONING_2D = {"V": "RF13_y", "H": "RF13_x"}
IRONING_3D = {"V": "RF15_z", "H": "RF15_x"}
LM = ["Contact/Method=lagrange multiplier"]
MORTAR = ["Contact/Discretization=mortar"]
# The 3D ironing without symmetry planes: a punch 1 deep in the middle of
# a foundation 3 deep, both coarser across.
NARROW = ["Scene/Two blocks/Lower block size=12, 3, 4",
          "Scene/Two blocks/Lower subdivisions=40, 6, 12",
          "Scene/Two blocks/Upper subdivisions=8, 4, 8",
          "Scene/Two blocks/Upper block offset=0.2, 1",
          "Boundary conditions/Symmetry=",
          "Contact/Pairs=10, 11, 12, 13, 14 : 5"]
UPSETTING_STRUCTURED = ["Scene/Cylinder compression/Mesh=structured",
                        "Scene/Cylinder compression/Radial refinements=2"]


LANDING = ["Time stepping/Output times=0.5, 1, 1.5, 3.5"]
CONTROL = ["Time stepping/Maximum contact changes=0.25"]


def steps(n):
    return ["Time stepping/Number of steps=%d" % n]


# name, parameter file, --set entries, force columns, times
PRIMAL = ["Contact/Penalty formulation=primal"]

CASES = [
    ("ironing_600_penalty", "ironing", [], IRONING_2D, IRONING_TIMES),
    ("ironing_600_penalty_primal", "ironing", PRIMAL, IRONING_2D,
     IRONING_TIMES),
    ("ironing_600_lagrange", "ironing", LM, IRONING_2D, IRONING_TIMES),
    ("ironing_600_mortar_penalty", "ironing", MORTAR, IRONING_2D,
     IRONING_TIMES),
    ("ironing_600_mortar_lagrange", "ironing", MORTAR + LM, IRONING_2D,
     IRONING_TIMES),
    ("ironing_150_penalty", "ironing", steps(150), IRONING_2D, IRONING_TIMES),
    ("ironing_150_lagrange", "ironing", steps(150) + LM, IRONING_2D,
     IRONING_TIMES),
    ("ironing_150_mortar_penalty", "ironing", steps(150) + MORTAR,
     IRONING_2D, IRONING_TIMES),
    ("ironing_150_mortar_lagrange", "ironing", steps(150) + MORTAR + LM,
     IRONING_2D, IRONING_TIMES),
    # The stretch target: one increment per output time (every 0.1), so
    # 60 increments for the whole run.
    ("ironing_60_penalty", "ironing", steps(60) + ["Output/Frequency=1"],
     IRONING_2D, IRONING_TIMES),
    # Issue 74, automatic incrementation: 10 nominal steps landing on the
    # compared times, with the accuracy control (the default) and without.
    ("ironing_10_auto", "ironing", steps(10) + LANDING + CONTROL,
     IRONING_2D, IRONING_TIMES),
    ("ironing_10_no_control", "ironing", steps(10) + LANDING, IRONING_2D,
     IRONING_TIMES),
    ("ironing_30_auto", "ironing", steps(30) + LANDING + CONTROL,
     IRONING_2D, IRONING_TIMES),
    ("ironing_150_auto", "ironing", steps(150) + LANDING + CONTROL,
     IRONING_2D, IRONING_TIMES),
    ("ironing_3d_penalty", "ironing_3d", [], IRONING_3D, IRONING_TIMES),
    # Issue 74: the file keeps the defaults (automatic: mixed penalty,
    # smoothed master); the defaults before it (primal, faceted).
    ("ironing_3d_old_defaults", "ironing_3d",
     PRIMAL + ["Contact/Master smoothing=none"], IRONING_3D, IRONING_TIMES),
    ("ironing_3d_lagrange", "ironing_3d", LM, IRONING_3D, IRONING_TIMES),
    ("ironing_3d_mortar_penalty", "ironing_3d",
     MORTAR + ["Contact/Master smoothing=none"], IRONING_3D, IRONING_TIMES),
    ("ironing_3d_narrow_penalty", "ironing_3d", NARROW, IRONING_3D,
     IRONING_TIMES),
    ("slide_off_edge_penalty", "slide_off_edge", [], {}, ()),
    ("slide_off_edge_lagrange", "slide_off_edge",
     ["Contact/Method=lagrange multiplier"], {}, ()),
    # benchmarks/mortar_3d_hertz.py's sphere on a block at level 3.
    ("mortar_hertz_3d_level3", "hertz_3d",
     ["Scene/Cylinder over block/With block=true",
      "Scene/Cylinder over block/Contact refinements=3",
      "Contact/Pairs=10 : 5",
      "Boundary conditions/Symmetry=12, 13, 0, 2",
      "Boundary conditions/Dirichlet=11 : z : -0.02*t ; 4 : xyz : 0, 0, 0",
      "Contact/Penalty factor=1000*E/h"] + MORTAR, {}, ()),
    # The same with the penalty in mixed form (hertz_3d.prm keeps the
    # default primal form).
    ("mortar_hertz_3d_level3_mixed", "hertz_3d",
     ["Scene/Cylinder over block/With block=true",
      "Scene/Cylinder over block/Contact refinements=3",
      "Contact/Pairs=10 : 5",
      "Boundary conditions/Symmetry=12, 13, 0, 2",
      "Boundary conditions/Dirichlet=11 : z : -0.02*t ; 4 : xyz : 0, 0, 0",
      "Contact/Penalty factor=1000*E/h",
      "Contact/Penalty formulation=mixed"] + MORTAR, {}, ()),
    ("upsetting_structured_penalty", "upsetting", UPSETTING_STRUCTURED, {},
     ()),
    ("upsetting_structured_lagrange", "upsetting",
     UPSETTING_STRUCTURED + ["Contact/Method=lagrange multiplier"], {}, ()),
    ("upsetting_split_penalty", "upsetting", [], {}, ()),
    ("upsetting_split_lagrange", "upsetting",
     ["Contact/Method=lagrange multiplier"], {}, ()),
]


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) if v not in ("", "nan") else math.nan
                 for k, v in r.items()} for r in csv.DictReader(f)]


def nominal_steps(prm, sets):
    for s in reversed(sets):
        if s.startswith("Time stepping/Number of steps="):
            return int(s.split("=")[1])
    text = open(os.path.join(PRM, prm + ".prm")).read()
    return int(text.split("Number of steps")[1].split("=")[1].split()[0])


def run_once(tribos, prm, sets, forces, times, timeout, keep=None):
    """One run: its counters and forces (its output kept in @p keep)."""
    with tempfile.TemporaryDirectory() as temporary:
        folder = keep or temporary
        command = [tribos, os.path.join(PRM, prm + ".prm"),
                   "--set", "Output/Directory=" + folder,
                   "--set", "Output/Write VTU=false"]
        for s in sets:
            command += ["--set", s]
        start = time.time()
        try:
            result = subprocess.run(command, capture_output=True, text=True,
                                    timeout=timeout)
            status = "completed" if result.returncode == 0 else \
                "failed (exit %d)" % result.returncode
        except subprocess.TimeoutExpired:
            status = "stopped after %d s" % timeout
        wall = time.time() - start
        h = read_csv(os.path.join(folder, "history.csv"))
        rejected = 0
        if os.path.exists(os.path.join(folder, "summary.txt")):
            for line in open(os.path.join(folder, "summary.txt")):
                if line.startswith("rejected for accuracy"):
                    rejected = int(line.split()[-1])
        order = median_order(read_csv(os.path.join(folder,
                                                   "convergence.csv")))
        if keep:
            with open(os.path.join(folder, "stdout.txt"), "w") as f:
                f.write(result.stdout + result.stderr
                        if not status.startswith("stopped") else "")
    n = nominal_steps(prm, sets)
    last_step = int(h[-1]["step"]) if h else 0
    # history.csv counts a step's cutbacks so far: its last row has them.
    cutbacks = sum(int(max(r["cutbacks"] for r in h if r["step"] == s))
                   for s in set(r["step"] for r in h))
    row = {"status": status,
           "steps": "%d/%d" % (last_step if status == "completed"
                               else max(0, last_step - 1), n),
           "increments": len(h),
           "cutbacks": cutbacks,
           "rejected": rejected,
           "newton": int(sum(r["newton_iterations"] for r in h)),
           "newton_all": int(sum(r["newton_iterations_all"] for r in h)),
           "wall": wall}
    row["newton_per_step"] = "%.2f" % (row["newton_all"] / n)
    row["median_order"] = "%.2f" % order if order is not None else ""
    for label, column in forces.items():
        for t in times:
            value = interpolate(h, column, t)
            row["%s@%g" % (label, t)] = \
                "%.4f" % abs(value) if value is not None else ""
    return row


def median_order(convergence):
    """Newton's observed order near convergence: per increment the larger
    of the last two finite orders above round-off (as
    benchmarks/robustness_study.py), the median over the increments."""
    orders = []
    for increment in sorted(set(r["increment"] for r in convergence)):
        o = [r["order"] for r in convergence
             if r["increment"] == increment and math.isfinite(r["order"])
             and r["relative_residual"] > 1e-13]
        if o:
            orders.append(max(o[-2:]))
    return statistics.median(orders) if orders else None


def interpolate(rows, column, t):
    """The column at time t, linear between the increments around it (a
    run whose steps miss t, e.g. 150 steps at 0.5); None beyond the run."""
    for before, after in zip(rows, rows[1:]):
        if before["time"] <= t + 1e-9 and t <= after["time"] + 1e-9:
            if abs(after["time"] - t) < 1e-9:
                return after[column]
            s = (t - before["time"]) / (after["time"] - before["time"])
            return (1 - s) * before[column] + s * after[column]
    return None


def summarize(rows):
    """The counters of the first run, the median wall time of all."""
    result = dict(rows[0])
    result["wall"] = "%.2f" % statistics.median(r["wall"] for r in rows)
    return result


def main():
    global PRM
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--baseline", default=None)
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--cases", nargs="*", default=[])
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "data",
                                                      "hard_cases.csv"))
    parser.add_argument("--timeout", type=int, default=3600)
    parser.add_argument("--keep", default=None,
                        help="keep each case's output in KEEP/<case>")
    parser.add_argument("--parameters", default=PRM,
                        help="the folder of the parameter files")
    args = parser.parse_args()
    PRM = args.parameters

    rows = []
    for name, prm, sets, forces, times in CASES:
        if args.cases and not any(word in name for word in args.cases):
            continue
        ours, theirs = [], []
        for _ in range(args.runs):
            ours.append(run_once(args.tribos, prm, sets, forces, times,
                                 args.timeout,
                                 os.path.join(args.keep, name)
                                 if args.keep else None))
            if args.baseline:
                theirs.append(run_once(args.baseline, prm, sets, forces,
                                       times, args.timeout))
        row = {"case": name, "runs": args.runs}
        row.update(summarize(ours))
        if theirs:
            for key, value in summarize(theirs).items():
                row["base_" + key] = value
        rows.append(row)
        print(row, flush=True)

    if os.path.exists(args.out) and args.cases:
        with open(args.out) as f:
            old = list(csv.DictReader(f))
        new = {r["case"]: r for r in rows}
        rows = [new.pop(r["case"], r) for r in old] + list(new.values())
    columns = []
    for r in rows:
        for key in r:
            if key not in columns:
                columns.append(key)
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, lineterminator="\n",
                                restval="")
        writer.writeheader()
        writer.writerows(rows)
    print("wrote " + args.out)


if __name__ == "__main__":
    main()
