"""Bodies that pass through each other within one increment (issue 56).

(1) Mortar, a punch pushed into a block by more than an element in one
    increment (tests/data/pass_through.prm): the search skipped master faces
    more than a segment behind an open slave node, and the run completed
    with normal force 0 and the penetrated nodes reported open (COPEN =
    +0.29 for nodes 0.29 inside). Now one increment gives the force of ten
    (to the Newton tolerance), penalty and multipliers, quadrilaterals and
    hexahedra, and no slave node reports an open gap.
(2) A rigid circle moved through a thin strip by four radii in one
    increment (tests/data/tunnelling.prm): every node is outside the circle at
    the increment's start and end, so the end gaps closed the increment
    with zero force. Now the swept path is checked: the increment is cut
    back until the circle cannot jump over a node, and the result equals
    a run of twenty increments.
(3) A rigid circle pushed through a block whose top is held, with a soft
    penalty: the contact force rose and then fell to 0 as the circle came
    out at the top, exit 0. A node in contact whose contact normal turns
    over went through the master: the increment is cut, and the run
    stops with exit 2 and a message naming the pair and the node."""

import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)


def last(folder):
    return read_csv(folder + "/history.csv")[-1]


def contact_rows(folder, step):
    return read_csv("%s/contact-%05d.csv" % (folder, step))


# (1) mortar, 2D
for method in ("penalty", "lagrange multiplier"):
    tag = method.split()[0]
    forces = {}
    for steps in (1, 10):
        folder = "%s/mortar_2d_%s_%d" % (out, tag, steps)
        run(tribos, tests + "/pass_through.prm", folder,
            ["Contact/Method=" + method,
             "Time stepping/Number of steps=%d" % steps])
        forces[steps] = last(folder)["pair0_normal_force"]
    one, ten = forces[1], forces[10]
    check(ten > 10 and abs(one - ten) < 1e-6 * ten,
          "mortar 2D, %s: one increment gives %.10g, ten %.10g" %
          (method, one, ten))
    rows = contact_rows("%s/mortar_2d_%s_1" % (out, tag), 1)
    check(all(r["COPEN"] < 1e-3 for r in rows) and
          all(r["CSTATUS"] > 0 for r in rows),
          "mortar 2D, %s, one increment: every slave node closed, largest "
          "COPEN %.2e" % (method, max(r["COPEN"] for r in rows)))

# (1) mortar, 3D hexahedra
blocks = ["Scene/Two blocks/Gap=0.01",
          "Scene/Two blocks/Upper block offset=0.2, 0.2",
          "Boundary conditions/Dirichlet=4 : xyz : 0, 0, 0 ; "
          "15 : xyz : 0, 0, -0.3*t",
          "Boundary conditions/Symmetry=", "Boundary conditions/Neumann=",
          "Materials/Young's modulus=100, 100",
          "Contact/Pairs=14 : 5", "Contact/Discretization=mortar"]
forces = {}
for steps in (1, 3):
    folder = "%s/mortar_3d_%d" % (out, steps)
    run(tribos, tests + "/two_blocks_3d.prm", folder,
        blocks + ["Time stepping/Number of steps=%d" % steps])
    forces[steps] = last(folder)["pair0_normal_force"]
check(forces[3] > 10 and abs(forces[1] - forces[3]) < 1e-6 * forces[3],
      "mortar 3D hexahedra: one increment gives %.10g, three %.10g"
      % (forces[1], forces[3]))

# (2) rigid tunnelling
one = out + "/tunnelling_1"
run(tribos, tests + "/tunnelling.prm", one)
twenty = out + "/tunnelling_20"
run(tribos, tests + "/tunnelling.prm", twenty,
    ["Time stepping/Number of steps=20"])
f1, f20 = last(one)["pair0_normal_force"], last(twenty)["pair0_normal_force"]
check(last(one)["cutbacks"] >= 1,
      "tunnelling: the one increment was cut back %d times"
      % last(one)["cutbacks"])
check(f20 > 1 and abs(f1 - f20) < 1e-6 * f20,
      "tunnelling: normal force %.10g after the cut increment, %.10g in "
      "twenty increments" % (f1, f20))

# (3) A block whose top is held, pushed through by a rigid circle with a
# soft penalty (0.1 E/h: within the range that draws no warning): the
# nodes sink into the circle, pass its centre and come out at its far
# side. The run completed with exit 0, the force rising to 0.064 and then
# falling to 0 at t = 0.6 as if the circle had let go. Now the increment
# in which a node in contact has its contact normal turned over is cut,
# and since smaller ones go through too the run stops (exit 2) naming
# the pair and the node, with the converged steps kept.
held = run(tribos, tests + "/pass_through.prm", out + "/held_top",
           ["Scene/Name=block", "Materials/Young's modulus=1",
            "Contact/Discretization=node to segment",
            "Scene/Block/Upper corner=1, 0.3",
            "Scene/Block/Subdivisions=8, 3",
            "Boundary conditions/Dirichlet=3 : xy : 0, 0",
            "Contact/Pairs=2 : ball",
            "Contact/Rigid surfaces=ball : cylinder : 0.5, -0.3, 0 : 0.3 : "
            "0, 1.0*t",
            "Contact/Penalty factor=0.1*E/h",
            "Time stepping/Number of steps=10"], expect_success=False)
rows = read_csv(out + "/held_top/history.csv")
check(held.returncode == 2 and "went through the master" in held.stderr and
      "<2 : ball>" in held.stderr and len(rows) >= 3 and
      min(r["pair0_normal_force"] for r in rows) > 0,
      "a circle pushed through a block whose top is held: exit %d, '%s', "
      "%d converged increments kept, every one with a contact force"
      % (held.returncode, "went through the master" if "went through"
         in held.stderr else held.stderr.strip()[-200:], len(rows)))
finish()
