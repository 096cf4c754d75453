#!/usr/bin/env python3
"""What the curved geometry of a second-order mesh costs: the same run on
the same nodes with straight cells (a first-order mesh, P2 on its chords)
and with curved ones (the mesh of second order: MappingFEField on the
dofs' reference positions), alternately (straight, curved, straight, ...),
medians of the wall time and of summary.txt's sections.

    python3 benchmarks/curved_cost.py build/tribos [--runs 5] \\
        [--out doc/data/curved_cost.csv]

Cases: the load-controlled Hertz 3D of parameters/hertz_3d_load.prm on
tests/data/hertz_3d_tet.msh and tests/data/hertz_3d_tet10.msh (P2, Lagrange
multipliers, VTU written), and the Hertz 2D of
benchmarks/peers/hertz_2d_load.prm on tests/data/hertz_2d_tri.msh and
tests/data/hertz_2d_tri6.msh. Columns: case, geometry, runs, wall, assembly,
setup, output, linear_solve (medians, s)."""

import argparse
import os
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TESTS = os.path.join(ROOT, "tests", "data")
SETS = ["Finite element/Polynomial degree=2",
        "Contact/Method=lagrange multiplier", "Output/Write VTU=true"]
CASES = {
    "hertz_3d": (os.path.join(ROOT, "parameters", "hertz_3d_load.prm"),
                 {"straight": "hertz_3d_tet.msh",
                  "curved": "hertz_3d_tet10.msh"},
                 ["Scene/Name=gmsh"]),
    "hertz_2d": (os.path.join(ROOT, "benchmarks", "peers",
                              "hertz_2d_load.prm"),
                 {"straight": "hertz_2d_tri.msh",
                  "curved": "hertz_2d_tri6.msh"}, []),
}
SECTIONS = {"assembly": "assembly", "setup": "setup", "output": "output",
            "linear_solve": "linear solve"}


def run(tribos, prm, mesh, sets, folder):
    command = [tribos, prm, "--set", "Output/Directory=" + folder,
               "--set", "Scene/Mesh file=" + os.path.join(TESTS, mesh)]
    for s in sets + SETS:
        command += ["--set", s]
    start = time.time()
    subprocess.run(command, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    values = {"wall": time.time() - start}
    with open(os.path.join(folder, "summary.txt")) as f:
        for line in f:
            for key, name in SECTIONS.items():
                if line.startswith(name + " "):
                    values[key] = float(line[len(name):].split()[1])
    return values


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    columns = ["wall"] + list(SECTIONS)
    rows = ["case,geometry,runs," + ",".join(columns)]
    with tempfile.TemporaryDirectory() as work:
        for case, (prm, meshes, sets) in CASES.items():
            samples = {g: [] for g in meshes}
            for k in range(args.runs):
                for geometry, mesh in meshes.items():
                    samples[geometry].append(
                        run(os.path.abspath(args.tribos), prm, mesh, sets,
                            os.path.join(work, "%s_%s_%d"
                                         % (case, geometry, k))))
            for geometry in meshes:
                medians = [statistics.median(s[c] for s in samples[geometry])
                           for c in columns]
                rows.append("%s,%s,%d," % (case, geometry, args.runs) +
                            ",".join("%.4f" % m for m in medians))
                print(rows[-1], flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
