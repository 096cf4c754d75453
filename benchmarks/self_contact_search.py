#!/usr/bin/env python3
"""Cost of the self-contact search (doc/self_contact.md): the U-shaped
body of tests/data/self_contact_u.prm with its contact given three ways,

  slot      Pairs = 1 : 1, the slot's faces as one self-contact surface;
  whole     the whole boundary (1, 2, 3, 5, 6, 7, 8) as one surface, as a
            user who does not know where the body folds would give it;
  two_pass  the slot's faces as two boundaries (u_shape_split.msh,
            9 : 10) with Passes = two-pass: the two-body search,

and the C-clip of tests/data/self_contact_clip.prm with the penalty in
mixed form (a self pair refuses multipliers; measured with multipliers
before that), its inner boundary as one surface

  clip_nts     node to segment;
  clip_mortar  mortar;
  clip_pair    the tooth's end and the lower arm's top as two boundaries
               (c_clip_split.msh, 9 : 10), mortar: the two-body search,

run alternately by one or more tribos builds (A B A B ...), --runs times
(--cases: which). Writes one CSV row per run: build, case, run, wall time,
the 'contact search' seconds of summary.txt, Newton iterations (all
attempts), the slave nodes of the pairs.

    python3 benchmarks/self_contact_search.py build/tribos [OTHER/tribos]
        [--runs 3] [--cases slot whole ...]
        [--out doc/data/self_contact_search.csv]"""

import argparse
import os
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data")
U = os.path.join(DATA, "self_contact_u.prm")
CLIP = os.path.join(DATA, "self_contact_clip.prm")
MIXED = "Contact/Penalty formulation=mixed"
MORTAR = "Contact/Discretization=mortar"
CASES = {
    "slot": (U, ["Contact/Pairs=1 : 1"]),
    "whole": (U, ["Contact/Pairs=1, 2, 3, 5, 6, 7, 8 : 1, 2, 3, 5, 6, 7, 8"]),
    "two_pass": (U, ["Scene/Mesh file=u_shape_split.msh",
                     "Contact/Pairs=9 : 10", "Contact/Passes=two-pass"]),
    "clip_nts": (CLIP, [MIXED]),
    "clip_mortar": (CLIP, [MIXED, MORTAR]),
    "clip_pair": (CLIP, [MIXED, MORTAR,
                         "Scene/Mesh file=c_clip_split.msh",
                         "Contact/Pairs=9 : 10"]),
}


def run(tribos, prm, sets, folder):
    command = [tribos, prm, "--set", "Output/Directory=" + folder]
    for s in sets:
        command += ["--set", s]
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True,
                            check=True)
    wall = time.time() - start
    slaves = sum(int(line.split(" slave nodes")[0].split()[-1])
                 for line in result.stdout.splitlines()
                 if line.strip().startswith("contact pair <") and
                 " slave nodes" in line)
    search, iterations = 0., 0
    for line in open(os.path.join(folder, "summary.txt")):
        if line.startswith("contact search"):
            search = float(line.split()[3])
        if line.startswith("newton iterations (all attempts)"):
            iterations = int(line.split()[-1])
    return wall, search, iterations, slaves


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("builds", nargs="+")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--cases", nargs="+", default=list(CASES),
                        choices=list(CASES))
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    rows = ["build,case,run,wall_s,search_s,newton_iterations_all,"
            "slave_nodes"]
    with tempfile.TemporaryDirectory() as work:
        for r in range(args.runs):
            for b, tribos in enumerate(args.builds):
                for case in args.cases:
                    prm, sets = CASES[case]
                    wall, search, its, slaves = run(
                        tribos, prm, sets, os.path.join(work, case))
                    rows.append("%s,%s,%d,%.3f,%.4f,%d,%d" % (
                        "ABCD"[b], case, r + 1, wall, search, its, slaves))
                    print(rows[-1], flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
