#!/usr/bin/python3
"""Paired wall time of tribos against GetFEM on the shallow ironing
(parameters/ironing.prm; GetFEM: getfem_ironing.py, the same mesh,
material, friction and loading): the two programs run alternately
(tribos, GetFEM, tribos, ...), each as the process a user starts, for 150
and 600 steps, and the medians of each and their ratio are written per
case, with both codes' Newton iterations, cutbacks and punch forces.

    /usr/bin/python3 benchmarks/peers/paired_ironing.py build/tribos \\
        [--runs 3] [--steps 150,600] [--out doc/data/paired_ironing.csv]
        [--set "Section/Entry=value"]... [--getfem-args "--r 3448"]

tribos: parameters/ironing.prm with --set "Time stepping/Number of
steps=N", "Output/Directory=<temporary>", "Output/Write VTU=false" (GetFEM
writes no fields either) and the --set items given here. GetFEM:
getfem_ironing.py --steps N (its defaults: large-sliding augmented
Lagrangian contact, full Newton steps, halving cutbacks; --getfem-args
adds options). Needs `import getfem` (README.md).

Columns: case (ironing_N), runs, tribos_wall, getfem_wall (medians of the
whole processes, s), ratio (tribos / GetFEM), tribos_newton_all (the sum
of history.csv's newton_iterations_all: every linear solve, failed
attempts included), getfem_newton (the same count), tribos_cutbacks
(summary.txt), getfem_cutbacks, tribos_increments, getfem_increments,
tribos_t_end, getfem_t_end (the last converged time: 6 unless a run
stopped), then tribos_V_<t>, tribos_H_<t>, getfem_V_<t>, getfem_H_<t> for
t = 0.5, 1, 1.5, 3.5: the punch's vertical and horizontal force (V =
-RF13_y, H = RF13_x, the reaction of the punch top), linear between the
increments around t. Counts and forces are those of the last run (they do
not change between runs).
"""

import argparse
import csv
import os
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from getfem_ironing import REPORT_TIMES, interpolate  # noqa: E402
from peer_runs import summary_value  # noqa: E402

PRM = os.path.join(ROOT, "parameters", "ironing.prm")


def forces(prefix, times, fx, fy):
    """{prefix_V_t, prefix_H_t} at REPORT_TIMES."""
    row = {}
    for t in REPORT_TIMES:
        row["%s_V_%g" % (prefix, t)] = "%.2f" % -interpolate(times, fy, t)
        row["%s_H_%g" % (prefix, t)] = "%.2f" % interpolate(times, fx, t)
    return row


def run_tribos(tribos, steps, folder, sets):
    command = [tribos, PRM, "--set", "Time stepping/Number of steps=%d"
               % steps, "--set", "Output/Directory=" + folder, "--set",
               "Output/Write VTU=false"]
    for s in sets:
        command += ["--set", s]
    start = time.time()
    result = subprocess.run(command, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    history = os.path.join(folder, "history.csv")
    # exit 2: no convergence after the cutbacks; the converged steps and
    # the summary are kept, and the run counts
    if result.returncode not in (0, 2) or not os.path.exists(history):
        sys.exit("tribos failed (exit status %d):\n%s"
                 % (result.returncode, result.stderr[-2000:]))
    rows = list(csv.DictReader(open(history)))
    times = [0.0] + [float(r["time"]) for r in rows]
    row = {"tribos_newton_all": sum(int(float(r["newton_iterations_all"]))
                                    for r in rows),
           "tribos_cutbacks": summary_value(folder, "cutbacks"),
           "tribos_increments": len(rows),
           "tribos_t_end": "%.4f" % times[-1]}
    row.update(forces("tribos", times,
                      [0.0] + [float(r["RF13_x"]) for r in rows],
                      [0.0] + [float(r["RF13_y"]) for r in rows]))
    return wall, row


def run_getfem(steps, folder, extra):
    results = os.path.join(folder, "getfem.csv")
    history = os.path.join(folder, "getfem_history.csv")
    start = time.time()
    result = subprocess.run(["/usr/bin/python3",
                             os.path.join(HERE, "getfem_ironing.py"),
                             "--steps", str(steps), "--csv", results,
                             "--history", history] + extra,
                            stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    # exit 1 after writing its row: stopped after its cutbacks (counts)
    if result.returncode not in (0, 1) or not os.path.exists(results):
        sys.exit("GetFEM failed (exit status %d):\n%s"
                 % (result.returncode, result.stderr[-2000:]))
    last = list(csv.DictReader(open(results)))[-1]
    rows = list(csv.DictReader(open(history)))
    times = [float(r["time"]) for r in rows]
    row = {"getfem_newton": last["newton_total"],
           "getfem_cutbacks": last["cutbacks"],
           "getfem_increments": last["increments"],
           "getfem_t_end": last["t_end"]}
    row.update(forces("getfem", times, [float(r["RF_x"]) for r in rows],
                      [float(r["RF_y"]) for r in rows]))
    return wall, row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--steps", default="150,600")
    parser.add_argument("--out", default="")
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--getfem-args", default="",
                        help="options for getfem_ironing.py, one string")
    args = parser.parse_args()
    try:
        import getfem  # noqa: F401
    except ImportError:
        sys.exit("GetFEM is missing: apt-get install python3-getfem, and "
                 "run with /usr/bin/python3 (benchmarks/peers/README.md)")
    fields = ["case", "runs", "tribos_wall", "getfem_wall", "ratio",
              "tribos_newton_all", "getfem_newton", "tribos_cutbacks",
              "getfem_cutbacks", "tribos_increments", "getfem_increments",
              "tribos_t_end", "getfem_t_end"]
    for t in REPORT_TIMES:
        fields += ["%s_%s_%g" % (code, force, t)
                   for code in ("tribos", "getfem") for force in "VH"]
    rows = []
    print(",".join(fields), flush=True)
    with tempfile.TemporaryDirectory() as work:
        for steps in [int(s) for s in args.steps.split(",")]:
            row = {"case": "ironing_%d" % steps, "runs": args.runs}
            walls = {"tribos": [], "getfem": []}
            for k in range(args.runs):
                folder = os.path.join(work, "%d_%d" % (steps, k))
                os.makedirs(folder)
                wall, values = run_tribos(os.path.abspath(args.tribos), steps,
                                          folder, args.set)
                walls["tribos"].append(wall)
                row.update(values)
                wall, values = run_getfem(steps, folder,
                                          shlex.split(args.getfem_args))
                walls["getfem"].append(wall)
                row.update(values)
            for code in walls:
                row[code + "_wall"] = "%.2f" % statistics.median(walls[code])
            row["ratio"] = "%.3f" % (statistics.median(walls["tribos"]) /
                                     statistics.median(walls["getfem"]))
            print(",".join(str(row.get(f, "")) for f in fields), flush=True)
            rows.append(row)
    if args.out:
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=fields)
            writer.writeheader()
            for row in rows:
                writer.writerow(row)


if __name__ == "__main__":
    sys.exit(main())
