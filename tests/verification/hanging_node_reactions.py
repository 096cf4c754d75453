"""Reactions next to hanging nodes: the RF<id> columns of history.csv are
the supports' share of the condensed residual, so that they balance the
contact force wherever the mesh has hanging nodes.

A hanging node moves with its parents, so the force that the
unconstrained assembly puts on it acts on them, in the weights of its
constraint. Where the edge of a refined region meets a support, a parent
of a hanging node off the support is a dof of the support and carries a
share of that node's force. Summed from the raw residual at the support's
dofs alone, the reaction missed that share: 0.06 % to 4 % off in every
adaptive run checked and on fixed meshes with a Refinement box.

Two blocks (tests/data/pass_through.prm, node to segment, penalty), the
lower one's bottom (2) fixed, the upper one's top (13) pushed down by
0.02 in two steps; nothing else loads them. In every step the vertical
reactions must balance each other and the contact force: -RF13_y = RF2_y
= pair0_Fy, and the horizontal reactions too (RF13_x = -RF2_x), to
1e-8 of the normal force (Newton's residual tolerance), for

(1) the upper block's cells next to its top on the left refined once by
    Scene/Two blocks/Refinement box, the box ending in the middle of the
    top: a hanging node on the border of the box, one of whose parents is
    on the support (before: RF13_x + RF2_x 2.1 % of the normal force,
    RF13_y + RF2_y 3.7e-4 of it);
(2) the same without the box: the check itself (balanced before too,
    to 1e-16);
(3) adaptive refinement (Adaptivity, Maximum level 3, three initial
    cycles, Refine fraction 0.5) on the p4est mesh: the refined cells
    reach the supports in the first step (before: RF2_y 4.2 % above the
    contact force and -RF13_y);
(4) case mpi: (1) and (3) with -np 2 on a distributed mesh (a parent's
    owner adds the shares of its hanging nodes from their ghost values,
    whoever owns them): balanced to 1e-8 and equal to the serial runs to
    1e-8."""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi
# ctest: quick-cases serial

import sys

from tribos_testing import (setup, run, read_csv, check, finish, parts,
                            mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
prm = tests + "/pass_through.prm"
pressed = ["Boundary conditions/Dirichlet=2 : xy : 0, 0 ; "
           "13 : xy : 0, -0.02*t",
           "Contact/Discretization=node to segment",
           "Scene/Two blocks/Gap=0", "Time stepping/Number of steps=2"]
variants = {
    "box": ["Scene/Two blocks/Refinement box=0.2, 0.7 : 0.5, 0.91"],
    "uniform": [],
    "adaptive": ["Adaptivity/Enable=true", "Adaptivity/Maximum level=3",
                 "Adaptivity/Initial cycles=3",
                 "Adaptivity/Refine fraction=0.5"],
}


def balance(folder):
    """The largest of |RF13_y + RF2_y|, |RF2_y - pair0_Fy| and
    |RF13_x + RF2_x| over the steps, relative to the normal force; the
    rows."""
    rows = read_csv(folder + "/history.csv")
    worst = 0.0
    for r in rows:
        scale = max(abs(r["pair0_normal_force"]), 1e-300)
        errors = (r["RF13_y"] + r["RF2_y"], r["RF2_y"] - r["pair0_Fy"],
                  r["RF13_x"] + r["RF2_x"])
        worst = max(worst, max(abs(e) for e in errors) / scale)
    return worst, rows


if "serial" in selected:
    for name, sets in variants.items():
        folder = out + "/" + name
        run(tribos, prm, folder, pressed + sets)
        worst, rows = balance(folder)
        last = rows[-1]
        check(len(rows) == 2 and last["pair0_normal_force"] > 0 and
              worst < 1e-8,
              "%s: RF13_y = %.10g, RF2_y = %.10g, contact Fy = %.10g: the "
              "reactions balance each other and the contact force to %.1e "
              "(bound 1e-8)" % (name, last["RF13_y"], last["RF2_y"],
                                last["pair0_Fy"], worst))

if "mpi" in selected and mpi_part(selected):
    for name in ("box", "adaptive"):
        serial = out + "/" + name + "_np1"
        run(tribos, prm, serial, pressed + variants[name] +
            ["Parallel/Mesh=distributed"])
        folder = out + "/" + name + "_np2"
        run(tribos, prm, folder, pressed + variants[name] +
            ["Parallel/Mesh=distributed"], mpi_ranks=2)
        worst, rows = balance(folder)
        reference = read_csv(serial + "/history.csv")
        scale = max(abs(r["pair0_normal_force"]) for r in reference)
        difference = max(abs(x[k] - y[k]) / scale
                         for x, y in zip(rows, reference)
                         for k in ("RF13_x", "RF13_y", "RF2_x", "RF2_y"))
        check(len(rows) == len(reference) and worst < 1e-8 and
              difference < 1e-8,
              "%s, -np 2: the reactions balance to %.1e and equal the "
              "serial run's to %.1e (bounds 1e-8)"
              % (name, worst, difference))
finish()
