#!/usr/bin/env python3
"""Time stepping/Extrapolation: where Newton starts an increment of a static
run (none: the converged state; linear: plus the last increment's change,
scaled by the increment sizes). Every static scene of parameters/ and the
test scenes with a moving load, run with both, alternating, one process:
Newton iterations (accepted, and with the failed attempts), cutbacks,
retries of an extrapolated start, wall time (median of --runs), and the
largest relative difference of the last step's contact force and
reactions between the two. Writes doc/data/extrapolation.csv.

    python3 benchmarks/extrapolation.py [--tribos build/tribos] [--runs 3]
        [--out doc/data/extrapolation.csv] [--only NAME ...]"""

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
sys.path.insert(0, os.path.join(ROOT, "tests"))
from tribos_testing import sphere_on_block  # noqa: E402

# name: (parameter file, overrides)
CASES = {
    "cylinder_compression": ("parameters/cylinder_compression.prm", []),
    "cylinder_compression_42k": ("parameters/cylinder_compression.prm",
                                 ["Scene/Refinement=2"]),
    "cylinder_axisymmetric": (
        "parameters/cylinder_compression_axisymmetric.prm", []),
    "cylinder_elastic_3d": ("parameters/cylinder_elastic_3d.prm", []),
    "hertz_2d": ("parameters/hertz_2d.prm", []),
    "hertz_3d": ("parameters/hertz_3d.prm", []),
    "ring_on_foundation": ("parameters/ring_on_foundation.prm", []),
    "necking_bar": ("parameters/necking_bar.prm", []),
    "ironing": ("parameters/ironing.prm", []),
    "stick_slip_cycles": ("parameters/stick_slip_cycles.prm", []),
    "slide_off_edge": ("parameters/slide_off_edge.prm", []),
    "force_control_apart": ("parameters/force_control_apart.prm", []),
    "ironing_2d": ("tests/data/ironing_2d.prm", []),
    "ironing_2d_frictionless": ("tests/data/ironing_2d.prm",
                                ["Contact/Friction coefficient=0"]),
    "sliding_blocks_3d": ("tests/data/sliding_blocks_3d.prm", []),
    "cattaneo_mindlin": ("tests/data/cattaneo_mindlin.prm", []),
    # The 3D mortar sphere on a block, level 3 (mortar_3d_hertz's largest).
    "sphere_on_block_mortar": ("parameters/hertz_3d.prm",
                               sphere_on_block(3, "mortar")),
}


def last_row(folder):
    with open(folder + "/history.csv") as f:
        rows = list(csv.DictReader(f))
    return rows


def one_run(tribos, prm, sets, mode, folder):
    command = [tribos, os.path.join(ROOT, prm),
               "--set", "Output/Directory=" + folder,
               "--set", "Output/Write VTU=false",
               "--set", "Time stepping/Extrapolation=" + mode]
    for s in sets:
        command += ["--set", s]
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    retries = result.stdout.count("the extrapolated start did not converge")
    return result.returncode, wall, retries


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(
        ROOT, "doc", "data", "extrapolation.csv"))
    parser.add_argument("--only", nargs="*")
    args = parser.parse_args()
    rows = []
    work = tempfile.mkdtemp(prefix="tribos_extrapolation_")
    for name, (prm, sets) in CASES.items():
        if args.only and name not in args.only:
            continue
        walls = {"none": [], "linear": []}
        info = {}
        for _ in range(args.runs):
            for mode in ("none", "linear"):
                folder = os.path.join(work, name + "_" + mode)
                status, wall, retries = one_run(args.tribos, prm, sets, mode,
                                                folder)
                walls[mode].append(wall)
                info[mode] = (status, retries, last_row(folder))
        forces = {}
        for mode in ("none", "linear"):
            status, retries, history = info[mode]
            forces[mode] = {k: float(v) for k, v in history[-1].items()
                            if re.search(r"(RF\d+_|_Fx|_Fy|_Fz|normal_force"
                                         r"|tangential_force)", k)}
        difference = 0.0
        if info["none"][0] == 0 and info["linear"][0] == 0:
            scale = max([abs(v) for v in forces["none"].values()] + [1e-300])
            difference = max([abs(forces["linear"][k] - v) / scale
                              for k, v in forces["none"].items()] + [0.0])
        for mode in ("none", "linear"):
            status, retries, history = info[mode]
            row = {
                "case": name, "extrapolation": mode, "exit": status,
                "newton": sum(int(h["newton_iterations"]) for h in history),
                "newton_all": sum(int(h["newton_iterations_all"])
                                  for h in history),
                "cutbacks": sum(int(h["cutbacks"]) for h in history),
                "retries": retries,
                "wall_median": "%.3f" % statistics.median(walls[mode]),
                "walls": " ".join("%.3f" % w for w in walls[mode]),
                "force_difference": "%.2e" % difference,
            }
            rows.append(row)
            print(",".join(str(v) for v in row.values()), flush=True)
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
