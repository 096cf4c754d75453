#!/usr/bin/env python3
"""The force curves of the self-contact scenes against their half (or
quarter) models with a rigid wall at the plane of symmetry
(doc/self_contact.md): one CSV row per scene, method and time with the
self-contact force of the full model, the wall force of the half model
and their difference over the half model's force at t = 1.

    python3 benchmarks/self_contact_curves.py build/tribos \\
        [--out doc/data/self_contact_curves.csv]

Scenes: the U-shaped body (tests/data/self_contact_u.prm, node to segment,
penalty; the half model the right half), the ring (the tube's
cross-section, plane strain, mortar: penalty, mixed penalty, Q2 penalty)
and the tube (3D, mortar with penalty, Q1 and Q2) against their
quarters."""

import argparse
import csv
import os
import tempfile

import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data")
U = os.path.join(DATA, "self_contact_u.prm")
TUBE = os.path.join(DATA, "self_contact_tube.prm")
U_HALF = ["Scene/Mesh file=u_shape_half.msh",
          "Boundary conditions/Neumann=7 : -0.15*t, 0",
          "Boundary conditions/Symmetry=4", "Contact/Pairs=1 : wall",
          "Contact/Rigid surfaces=wall : plane : 0, 0, 0 : 1, 0, 0 : 0, 0"]
RING = ["Dimension=2", "Scene/Mesh file=ring_half.msh",
        "Boundary conditions/Symmetry=5",
        "Contact/Rigid surfaces=top : plane : 0, 1, 0 : 0, -1, 0 : 0, -0.7*t ;"
        " bottom : plane : 0, -1, 0 : 0, 1, 0 : 0, 0.7*t"]
RING_QUARTER = ["Dimension=2", "Scene/Mesh file=ring_quarter.msh",
                "Boundary conditions/Symmetry=5, 6",
                "Contact/Rigid surfaces=top : plane : 0, 1, 0 : 0, -1, 0 :"
                " 0, -0.7*t ; wall : plane : 0, 0, 0 : 0, 1, 0 : 0, 0",
                "Contact/Pairs=2 : top ; 1 : wall"]
TUBE_QUARTER = ["Scene/Mesh file=tube_quarter.msh",
                "Boundary conditions/Symmetry=3, 4, 5, 6",
                "Contact/Rigid surfaces=top : plane : 0, 1, 0 : 0, -1, 0 :"
                " 0, -0.7*t, 0 ; wall : plane : 0, 0, 0 : 0, 1, 0 : 0, 0, 0",
                "Contact/Pairs=2 : top ; 1 : wall"]
MORTAR = ["Contact/Discretization=mortar"]
MIXED = ["Contact/Penalty formulation=mixed"]
Q2 = ["Finite element/Polynomial degree=2"]
# scene, method, prm, full model's sets and force column, half model's.
SCENES = [
    ("U", "node to segment, penalty", U, [], "pair0", U_HALF, "pair0"),
    ("ring", "mortar, penalty", TUBE, RING + MORTAR, "pair2", RING_QUARTER,
     "pair1"),
    ("ring", "mortar, mixed penalty", TUBE, RING + MORTAR + MIXED,
     "pair2", RING_QUARTER + MIXED, "pair1"),
    ("ring", "mortar, penalty, Q2", TUBE, RING + MORTAR + Q2, "pair2",
     RING_QUARTER + Q2, "pair1"),
    ("tube", "mortar, penalty", TUBE, MORTAR, "pair2", TUBE_QUARTER,
     "pair1"),
    ("tube", "mortar, penalty, Q2", TUBE, MORTAR + Q2, "pair2",
     TUBE_QUARTER + Q2, "pair1"),
]


def forces(tribos, prm, sets, column, folder):
    command = [tribos, prm, "--set", "Output/Directory=" + folder]
    for s in sets:
        command += ["--set", s]
    subprocess.run(command, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    with open(os.path.join(folder, "history.csv")) as f:
        return {round(float(r["time"]), 9): float(r[column + "_normal_force"])
                for r in csv.DictReader(f)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    rows = ["scene,method,time,self_contact_force,half_model_force,"
            "difference_over_final"]
    with tempfile.TemporaryDirectory() as work:
        for i, (scene, method, prm, sets, column, half, half_column) in \
                enumerate(SCENES):
            full = forces(args.tribos, prm, sets, column,
                          os.path.join(work, "full%d" % i))
            reference = forces(args.tribos, prm, half, half_column,
                               os.path.join(work, "half%d" % i))
            final = reference[max(reference)]
            for t in sorted(reference):
                if t in full:
                    rows.append('%s,"%s",%g,%.10g,%.10g,%.3e' % (
                        scene, method, t, full[t], reference[t],
                        (full[t] - reference[t]) / final))
            print(rows[-1], flush=True)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
