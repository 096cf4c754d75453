"""Contact on the triangle faces of linear tetrahedra (issue 45).

- Mortar patch test on non-matching tetrahedral meshes (the two blocks of
  tests/data/patch_test_3d.prm split by Finite element/Cells = simplices, 5 x 5
  and 3 x 3 hexahedra per layer before the split), either block the
  slave, penalty and Lagrange multipliers: every active node carries the
  pressure of the hexahedral run to 1e-9. Node-to-segment on matching
  split meshes: the same.
- The punch on a block (parameters/punch_on_block_tet.prm: two gmsh
  tetrahedral meshes, non-matching, pressed and then slid with Coulomb
  friction mu = 0.3, mortar with multipliers; up to t = 1.5): at full
  slip the
  tangential contact force is mu times the normal one to 1e-6;
  `mpirun -np 2` gives the serial history (1e-9; through t = 1.25, at the
  same step size: the press and the first slide step); restarted from its
  step-5 checkpoint it gives the uninterrupted history, every force bit
  for bit.
- The same scene with node-to-segment contact and penalty: mu at full
  slip too; and the 3D sliding blocks split into P1 tetrahedra with
  penalty (one and two passes), augmented Lagrangian (node-to-segment and
  mortar) and multipliers.
- P2 tetrahedra (six-node triangle faces): the mortar patch test with
  either side the slave (modified dual basis), penalty and multipliers,
  to 1e-8; against a rigid plane (the edge middles' virtual points) the
  applied pressure at every vertex and edge middle to 1e-8; the sliding
  blocks with mortar: mu at full slip; the cylinder between frictionless
  rigid plates (multipliers, 5 % in one step) gives the force of the
  prescribed homogeneous compression to 1e-10.
- Hertz 3D under load control on a gmsh tetrahedral mesh
  (tests/data/hertz_3d_tet.msh: benchmarks/peers/hertz_3d.geo with
  -setnumber hex 0 -setnumber hf 0.15, 2433 dofs), rigid plane, penalty
  and multipliers: pressure L2 error against Hertz below 10 % (measured
  8.9 % and 9.1 %), at most 8 Newton iterations (5 and 6); with P2
  (16236 dofs) and multipliers below 7 % (measured 5.7 %, 7
  iterations).

Cases (argv[4]; without one, both run):
  serial  every run without mpirun.
  mpi     the punch to t = 1.25 serially and with -np 2 (two cores, one MPI
          test at a time): an MPI = serial comparison, which needs neither
          the second slide step nor the checkpoints.
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi
# ctest: slow-cases serial

import glob
import os
import shutil
import sys


import hertz_error  # noqa: E402
from tribos_testing import (PARAMETERS, REPOSITORY, setup, run, read_csv,  # noqa: E402
                            check, finish, parts, mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
parameters = PARAMETERS
split = "Finite element/Cells=simplices"
punch = parameters + "/punch_on_block_tet.prm"

# The MPI part (case mpi): the punch pressed in 4 steps and slid in one.
if "mpi" in selected and mpi_part(selected):
    to_125 = ["Time stepping/End time=1.25", "Time stepping/Number of steps=5",
              "Output/Write VTU=false"]
    serial, parallel = out + "/punch_125", out + "/punch_125_np2"
    run(tribos, punch, serial, to_125)
    run(tribos, punch, parallel, to_125, mpi_ranks=2)
    history = read_csv(serial + "/history.csv")
    forces = [k for k in history[0] if k.startswith(("RF", "pair0"))]
    worst = 0
    for a, b in zip(history, read_csv(parallel + "/history.csv")):
        for k in forces:
            worst = max(worst, abs(a[k] - b[k]) / max(abs(a[k]), 1e-3))
    check(worst < 1e-9, "punch on a block to t = 1.25: -np 2 forces equal "
          "the serial ones (worst relative difference %.1e)" % worst)
if "serial" not in selected:
    finish()


def pressures(folder):
    rows = read_csv(sorted(glob.glob(folder + "/contact-*.csv"))[-1])
    return [r["CPRESS"] for r in rows if r["CSTATUS"] != 0]


# Patch tests.
for method in ("penalty", "lagrange multiplier"):
    sets = ["Contact/Method=" + method]
    run(tribos, tests + "/patch_test_3d.prm", out + "/patch_hex", sets)
    reference = pressures(out + "/patch_hex")[0]
    for pairs in ("14 : 5", "5 : 14"):
        folder = "%s/patch_%s_%s" % (out, method.split()[0], pairs[0])
        run(tribos, tests + "/patch_test_3d.prm", folder,
            sets + [split, "Contact/Pairs=" + pairs])
        p = pressures(folder)
        spread = max(abs(x - reference) for x in p) / reference
        check(len(p) > 20 and spread < 1e-9,
              "mortar patch test on non-matching tetrahedra, %s, pair %s: "
              "%d active nodes, the hexahedral pressure %.10g to %.1e"
              % (method, pairs, len(p), reference, spread))
    folder = "%s/patch_nts_%s" % (out, method.split()[0])
    matching = sets + [split, "Contact/Discretization=node to segment",
                       "Scene/Two blocks/Lower subdivisions=3, 3, 2"]
    run(tribos, tests + "/patch_test_3d.prm", folder, matching)
    p = pressures(folder)
    spread = max(abs(x - 0.01) for x in p) / 0.01
    check(len(p) == 25 and spread < 1e-9,
          "node-to-segment patch test on matching tetrahedra, %s: the "
          "applied pressure 0.01 at all 25 nodes to %.1e" % (method, spread))


# Every enforcement and both passes on P1 tetrahedra: the 3D sliding
# blocks split (tests/data/sliding_blocks_3d.prm), mu at full slip.
for name, sets in (("penalty", []),
                   ("two-pass", ["Contact/Passes=two-pass"]),
                   ("augmented", ["Contact/Method=augmented lagrangian"]),
                   ("multipliers", ["Contact/Method=lagrange multiplier"]),
                   ("augmented, mortar",
                    ["Contact/Method=augmented lagrangian",
                     "Contact/Discretization=mortar"])):
    folder = "%s/sliding_%s" % (out, name.replace(", ", "_"))
    run(tribos, tests + "/sliding_blocks_3d.prm", folder, [split] + sets)
    row = read_csv(folder + "/history.csv")[-1]
    ratio = row["pair0_tangential_force"] / row["pair0_normal_force"]
    check(row["n_slip"] == row["n_active"] > 20 and abs(ratio - 0.3) < 1e-6,
          "sliding blocks on P1 tetrahedra, %s: %d nodes slip, tangential "
          "/ normal force %.9f (mu = 0.3)" % (name, row["n_slip"], ratio))

# P2 tetrahedra: mortar on six-node triangles (modified dual basis), both
# sides slave (the blocks 4 x 4 and 3 x 3 per layer: a six-node triangle
# has four times the nodes of a bilinear face per area, and a mortar
# element couples at most 96 master nodes); against a rigid plane (the
# edge middles' virtual points).
quadratic = [split, "Finite element/Polynomial degree=2"]
for method in ("penalty", "lagrange multiplier"):
    sets = ["Contact/Method=" + method]
    reference = pressures(out + "/patch_hex")[0]
    for pairs in ("14 : 5", "5 : 14"):
        folder = "%s/patch_p2_%s_%s" % (out, method.split()[0], pairs[0])
        run(tribos, tests + "/patch_test_3d.prm", folder,
            sets + quadratic + ["Contact/Pairs=" + pairs,
                                "Scene/Two blocks/Lower subdivisions=4, 4, 2"])
        p = pressures(folder)
        spread = max(abs(x - reference) for x in p) / reference
        check(len(p) > 80 and spread < 1e-8,
              "mortar patch test on non-matching P2 tetrahedra, %s, pair "
              "%s: %d active nodes, the hexahedral pressure to %.1e"
              % (method, pairs, len(p), spread))
    folder = "%s/patch_p2_rigid_%s" % (out, method.split()[0])
    run(tribos, tests + "/patch_test_3d.prm", folder,
        sets + quadratic + ["Contact/Pairs=14 : floor",
                            "Contact/Rigid surfaces=floor : plane : "
                            "0, 0, 0.5 : 0, 0, 1 : 0, 0, 0"])
    p = pressures(folder)
    spread = max(abs(x - 0.01) for x in p) / 0.01
    check(len(p) == 85 and spread < 1e-8,
          "P2 tetrahedra on a rigid plane, %s: the applied pressure 0.01 "
          "at all 85 vertices and edge middles to %.1e" % (method, spread))
folder = out + "/sliding_p2"
run(tribos, tests + "/sliding_blocks_3d.prm", folder,
    quadratic + ["Contact/Discretization=mortar",
                 "Time stepping/Number of steps=2"])
row = read_csv(folder + "/history.csv")[-1]
ratio = row["pair0_tangential_force"] / row["pair0_normal_force"]
check(row["n_slip"] == row["n_active"] > 20 and abs(ratio - 0.3) < 1e-6,
      "sliding blocks on P2 tetrahedra, mortar: %d nodes slip, tangential "
      "/ normal force %.9f (mu = 0.3)" % (row["n_slip"], ratio))

# The cylinder compressed between frictionless rigid plates on P2
# tetrahedra (tests/data/cylinder_3d.prm split): with multipliers the plate
# gives the homogeneous compression of the prescribed top displacement,
# the same force at every step to round-off.
one_step = [split, "Time stepping/Number of steps=1"]
folder = out + "/cylinder_dirichlet"
run(tribos, tests + "/cylinder_3d.prm", folder, one_step)
plate = out + "/cylinder_plate"
run(tribos, tests + "/cylinder_3d.prm", plate,
    one_step + ["Boundary conditions/Dirichlet=", "Contact/Pairs=3 : plate",
                "Contact/Rigid surfaces=plate : plane : 0, 0, 6.35 : "
                "0, 0, -1 : 0, 0, -0.635*t",
                "Contact/Method=lagrange multiplier"])
worst = max(abs(b["pair0_normal_force"] + a["RF3_z"]) / abs(a["RF3_z"])
            for a, b in zip(read_csv(folder + "/history.csv"),
                            read_csv(plate + "/history.csv")))
check(worst < 1e-10, "cylinder on P2 tetrahedra between rigid plates, "
      "multipliers, 5 %% in one step: the force of the prescribed "
      "compression to %.1e" % worst)

# The punch on a block.
def slip_ratio(folder):
    row = read_csv(folder + "/history.csv")[-1]
    check(row["n_slip"] == row["n_active"] and row["n_active"] > 20,
          "%s: all %d active nodes slip at the end"
          % (os.path.basename(folder), row["n_active"]))
    return row["pair0_tangential_force"] / row["pair0_normal_force"]


# Up to t = 1.5: pressed in 4 steps, slid in 2 (every node slips from the
# first slide step on).
short = ["Time stepping/End time=1.5", "Time stepping/Number of steps=6",
         "Output/Write VTU=false"]
serial = out + "/punch"
run(tribos, punch, serial, short + ["Output/Checkpoint every=5"])
ratio = slip_ratio(serial)
check(abs(ratio - 0.3) < 1e-6, "punch on a block, mortar, multipliers: "
      "tangential / normal force %.9f at full slip (mu = 0.3)" % ratio)
folder = out + "/punch_nts"
run(tribos, punch, folder, short + ["Contact/Discretization=node to segment",
                                    "Contact/Method=penalty"])
ratio = slip_ratio(folder)
check(abs(ratio - 0.3) < 1e-6, "punch on a block, node-to-segment, "
      "penalty: tangential / normal force %.9f at full slip" % ratio)

history = read_csv(serial + "/history.csv")
forces = [k for k in history[0] if k.startswith(("RF", "pair0"))]
restarted = out + "/punch_restart"
shutil.rmtree(restarted, ignore_errors=True)
shutil.copytree(serial, restarted)
run(tribos, punch, restarted, short,
    extra=["--restart", serial + "/checkpoint-00005"])
again = read_csv(restarted + "/history.csv")
same = len(again) == len(history) and all(
    a[k] == b[k] for a, b in zip(history, again) for k in forces)
check(same, "punch on a block: restarted from step 5, every force of "
      "history.csv equals the uninterrupted run's bit for bit")

# Hertz 3D on tetrahedra, load control.
peers = os.path.join(REPOSITORY, "benchmarks", "peers")
bounds = {1: 0.10, 2: 0.07}
for degree, method in ((1, "penalty"), (1, "lagrange multiplier"),
                       (2, "lagrange multiplier")):
    folder = "%s/hertz_p%d_%s" % (out, degree, method.split()[0])
    run(tribos, parameters + "/hertz_3d_load.prm", folder,
        ["Scene/Name=gmsh", "Scene/Mesh file=%s/hertz_3d_tet.msh" % tests,
         "Finite element/Polynomial degree=%d" % degree,
         "Contact/Method=" + method, "Output/Write VTU=false"])
    points = hertz_error.read_tribos_contact(
        sorted(glob.glob(folder + "/contact-*.csv"))[-1], 3)
    force = hertz_error.read_tribos_force(folder + "/history.csv")
    error = hertz_error.profile_error(points, 4 * force, 10.0,
                                      2e5 / (1 - 0.3 ** 2), 3)
    row = read_csv(folder + "/history.csv")[-1]
    # The load is the top pressure times the area of the top's facets,
    # 0.64 % below pi R^2 / 4 on this mesh; Hertz's a and p0 are taken
    # for the force the contact carries.
    check(error < bounds[degree] and abs(4 * force - 50e3) < 0.01 * 50e3
          and row["newton_iterations_all"] <= 8,
          "Hertz 3D on P%d tetrahedra, %s: pressure L2 error %.4f < %.2f, "
          "contact force %.2f (load 50000 on a round top), %d Newton "
          "iterations (<= 8)"
          % (degree, method, error, bounds[degree], 4 * force,
             row["newton_iterations_all"]))
finish()
