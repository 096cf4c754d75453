#!/usr/bin/env python3
"""Cost of the self-contact search (doc/self_contact.md): the U-shaped
body of tests/data/self_contact_u.prm with its contact given three ways,

  slot      Pairs = 1 : 1, the slot's faces as one self-contact surface;
  whole     the whole boundary (1, 2, 3, 5, 6, 7, 8) as one surface, as a
            user who does not know where the body folds would give it;
  two_pass  the slot's faces as two boundaries (u_shape_split.msh,
            9 : 10) with Passes = two-pass: the two-body search,

run alternately by one or more tribos builds (A B A B ...), --runs times.
Writes one CSV row per run: build, case, run, wall time, the 'contact
search' seconds of summary.txt, Newton iterations (all attempts).

    python3 benchmarks/self_contact_search.py build/tribos [OTHER/tribos]
        [--runs 3] [--out doc/data/self_contact_search.csv]"""

import argparse
import os
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "tests", "data", "self_contact_u.prm")
CASES = {
    "slot": ["Contact/Pairs=1 : 1"],
    "whole": ["Contact/Pairs=1, 2, 3, 5, 6, 7, 8 : 1, 2, 3, 5, 6, 7, 8"],
    "two_pass": ["Scene/Mesh file=u_shape_split.msh", "Contact/Pairs=9 : 10",
                 "Contact/Passes=two-pass"],
}


def run(tribos, sets, folder):
    command = [tribos, PRM, "--set", "Output/Directory=" + folder]
    for s in sets:
        command += ["--set", s]
    start = time.time()
    subprocess.run(command, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    wall = time.time() - start
    search, iterations = 0., 0
    for line in open(os.path.join(folder, "summary.txt")):
        if line.startswith("contact search"):
            search = float(line.split()[3])
        if line.startswith("newton iterations (all attempts)"):
            iterations = int(line.split()[-1])
    return wall, search, iterations


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("builds", nargs="+")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    rows = ["build,case,run,wall_s,search_s,newton_iterations_all"]
    with tempfile.TemporaryDirectory() as work:
        for r in range(args.runs):
            for b, tribos in enumerate(args.builds):
                for case, sets in CASES.items():
                    wall, search, its = run(tribos, sets,
                                            os.path.join(work, case))
                    rows.append("%s,%s,%d,%.3f,%.4f,%d" % (
                        "ABCD"[b], case, r + 1, wall, search, its))
                    print(rows[-1], flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
