#!/usr/bin/env python3
"""Paired wall-time comparison of two tribos builds on the same scenes:
runs A and B alternately (A B A B ...) so that the machine's load drifts
hit both alike, and prints the median of each and their ratio.

    python3 benchmarks/paired_timing.py OLD/build/tribos NEW/build/tribos \\
        [--runs 5] [--vtu] [--out doc/data/paired_timing.csv] [scene.prm ...]

Default scenes: parameters/hertz_2d.prm and parameters/ring_on_foundation.prm
(VTU off unless --vtu). Writes one CSV row per scene: scene, runs,
median_a, median_b, ratio (b / a)."""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def wall(tribos, prm, folder, vtu):
    start = time.time()
    subprocess.run([tribos, prm, "--set", "Output/Directory=" + folder,
                    "--set", "Output/Write VTU=" + str(vtu).lower()],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True)
    return time.time() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--out", default="")
    parser.add_argument("--vtu", action="store_true",
                        help="write the VTU files (off by default)")
    args = parser.parse_args()
    scenes = args.scenes or [os.path.join(ROOT, "parameters", p) for p in
                             ("hertz_2d.prm", "ring_on_foundation.prm")]
    rows = ["scene,runs,median_a,median_b,ratio"]
    with tempfile.TemporaryDirectory() as work:
        for prm in scenes:
            times = {"a": [], "b": []}
            for _ in range(args.runs):
                for key in ("a", "b"):
                    times[key].append(wall(getattr(args, key), prm,
                                           os.path.join(work, key),
                                           args.vtu))
            a, b = statistics.median(times["a"]), statistics.median(times["b"])
            name = os.path.basename(prm)
            print("%-28s A %.3f s  B %.3f s  B/A %.3f   (A: %s; B: %s)" % (
                name, a, b, b / a, " ".join("%.2f" % t for t in times["a"]),
                " ".join("%.2f" % t for t in times["b"])))
            rows.append("%s,%d,%.4f,%.4f,%.4f" % (name, args.runs, a, b, b / a))
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    sys.exit(main())
