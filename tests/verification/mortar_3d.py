"""Verification of the 3D mortar discretization (Contact/Discretization =
mortar, Mortar3D: auxiliary planes, polygon clipping, dual basis).

1. Contact patch test (tests/data/patch_test_3d.prm: two stacked blocks,
   uniform pressure p = 0.01 E on the top, symmetry planes x = 0 and
   y = 0) with non-matching meshes at several size ratios (5x5 / 3x3,
   7x7 / 3x3, 4x4 / 7x7 and the anisotropic 5x4 / 3x2), each side as
   slave, with Lagrange multipliers (dual and standard basis), penalty and
   augmented Lagrangian: every slave node's pressure CPRESS equal to the
   others to 1e-10 relative with multipliers and 1e-9 with penalty (the
   penetration carries the round-off), the vertical resultant p A to 1e-8,
   and at most 4 Newton iterations (the outer edges of both blocks
   coincide: the clipping must not turn that into a kink of the
   residual). Node to segment on the same meshes must fail it by more
   than 1 %.
2. An upper block overhanging the lower one in x and y (partly covered
   slave or master faces at two edges and a corner): one increment, at
   most 12 Newton iterations, resultant p A to 1e-8, every method, each
   side as slave.
3. Frictional sliding (tests/data/sliding_blocks_3d.prm, mu = 0.3): penalty
   and multipliers converge without cutbacks, F_T / F_N = mu to 1e-6 in the
   slide, within 20 % of node to segment's Newton iterations.
4. Hanging slave nodes (Scene/Two blocks/Refinement box: the slave
   block's cells with centres at x < 0.45 refined once, so the slave
   surface has hanging nodes where the refinement ends), each side as
   slave: the hanging nodes carry no multiplier,
   their functions go to their parents (ContactPair::carried), and the
   output reports at them their parents' values interpolated with the
   constraint's weights (the coefficient of their functions in the
   multiplier field). Every node closed; multipliers
   (dual and standard basis): every node's pressure equal to 1e-10,
   resultant p A to 1e-8, at most 4 Newton iterations, and the same with
   `mpirun -np 2` and 3 on the distributed mesh (and -np 2 on the shared
   one). Penalty: the resultant to 1e-8 and the pressure
   within 1e-3 (the penalty E/h doubles on the refined side, so the
   penetration, not the pressure, jumps there). The frictional sliding of
   3. with its slave's first column of cells refined, multipliers: no
   cutbacks, F_T / F_N = mu to 1e-6, and `-np 2` (distributed mesh) gives
   the serial history to 1e-8.
5. Q2 hexahedra (Finite element/Polynomial degree = 2: nine-node faces,
   the dual basis of their biquadratic functions, integrated on their
   four bilinear pieces): the patch test of 1. on 5x5 / 3x3 with either
   side the slave and on 4x4 / 7x7 with the finer side the slave, every
   method and basis, to the same bounds (penalty: 1e-8, the penetration's
   round-off summed over a modified basis of 25 nodes); the frictional sliding of 3.
   with multipliers and penalty: no cutbacks, F_T / F_N = mu to 1e-6 in
   the slide, `-np 2` gives the serial history to 1e-8 (multipliers, on
   smaller blocks: see the cases), and a restart
   from step 3 (in the slide) the uninterrupted one bit for bit.

Cases (argv[4]; without one, both run):
  serial  every run without mpirun: 1.-5. but the MPI runs.
  mpi     the MPI runs of 4. and 5. (two cores, one MPI test at a time):
          the hanging-node patch test at -np 2 and 3 on the distributed
          mesh and -np 2 on the shared one, each with the bounds of the
          serial runs; the hanging-node sliding at -np 2 against its serial
          run to 1e-8; the Q2 sliding with multipliers at -np 2 against its
          serial run to 1e-8, on smaller blocks (3 x 3 x 1 under 2 x 2 x 1,
          the steps unchanged: a comparison of np 2 with the serial run
          needs no fine mesh) whose slave nodes meet master faces of the
          other process (summary.txt: contact across processes > 0).
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi
# ctest: slow-cases serial

import re
import shutil
import sys

from tribos_testing import (setup, run, read_csv, check, finish, parts,
                            mpi_part, strip_columns, numdiff)

from vtu import nodal_values  # noqa: E402

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
p = 0.01
prm = tests + "/patch_test_3d.prm"
sliding = tests + "/sliding_blocks_3d.prm"
q2 = "Finite element/Polynomial degree=2"
q2_sets = [q2, "Contact/Discretization=mortar", "Output/Checkpoint every=1"]
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all", "chattering_nodes")
# The refinement boxes of 4.: the slave block's cells at x < 0.45.
boxes = (("14 : 5", "0, 0, 0.5 : 0.45, 1, 1"),
         ("5 : 14", "0, 0, 0 : 0.45, 1, 0.5"))
hanging_sliding = ["Scene/Two blocks/Refinement box=0, 0, 0.3 : 0.45, 1.2, 1",
                   "Contact/Method=lagrange multiplier",
                   "Contact/Discretization=mortar",
                   "Time stepping/Number of steps=8"]


def same_history(parallel, serial, what):
    """numdiff: the np history equals the serial one to 1e-8."""
    strip_columns(serial + "/history.csv", serial + "/h.csv", drop=noisy)
    strip_columns(parallel + "/history.csv", parallel + "/h.csv", drop=noisy)
    numdiff(parallel + "/h.csv", serial + "/h.csv", relative=1e-8,
            absolute=1e-8)
    print("ok      %s: np 2 history equals the serial one" % what)


def hanging(pair, box, method, basis, ranks, mesh):
    """A patch test run of 4. (hanging slave nodes) and its checks."""
    name = "hanging3d_%s_%s_%s_np%d_%s" % (
        "upper" if pair.startswith("14") else "lower",
        method.replace(" ", "_"), basis, max(ranks, 1), mesh)
    folder = out + "/" + name
    log = run(tribos, prm, folder, [
        "Scene/Two blocks/Refinement box=" + box,
        "Scene/Two blocks/Lower subdivisions=5, 5, 2",
        "Scene/Two blocks/Upper subdivisions=3, 3, 2",
        "Contact/Pairs=" + pair, "Contact/Method=" + method,
        "Contact/Mortar basis=" + basis, "Parallel/Mesh=" + mesh,
        "Output/Write VTU=" + str(ranks == 0).lower()],
        mpi_ranks=ranks).stdout
    rows = read_csv(folder + "/contact-00001.csv")
    # The hanging nodes carry no multiplier of their own and report
    # their parents' (the coefficient of their basis functions in the
    # multiplier field): the uniform pressure too, and closed.
    n_hanging = int(re.search(r"\((\d+) hanging on others\)",
                              log).group(1))
    closed = [r["CPRESS"] for r in rows if r["CSTATUS"] != 0]
    pressures = [r["CPRESS"] for r in rows]
    spread = ((max(pressures) - min(pressures)) /
              (sum(pressures) / len(pressures)))
    history = read_csv(folder + "/history.csv")[-1]
    total = abs(abs(history["pair0_Fz"]) - p) / p
    its = history["newton_iterations"]
    bound = 1e-10 if method == "lagrange multiplier" else 1e-3
    if ranks == 0:
        # The VTU's nodal CPRESS on the slave body's contact face (the
        # slave is the upper block with pair 14 : 5).
        upper = pair.startswith("14")
        on_face = [v[0] for x, v, tag in nodal_values(
            folder + "/solution-00001.vtu", "CPRESS",
            lambda arrays, cell, corners:
                max(c[2] for c in corners) > 0.5 + 1e-9)
            if abs(x[2] - 0.5) < 1e-6 and tag == upper]
        vtu_spread = ((max(on_face) - min(on_face)) /
                      (sum(on_face) / len(on_face)))
        check(len(on_face) == len(rows) and vtu_spread < max(bound, 1e-6),
              "%s: VTU CPRESS at the %d slave nodes spread %.1e"
              % (name, len(on_face), vtu_spread))
    check(n_hanging >= 2 and len(closed) == len(rows) and
          spread < bound and total < 1e-8 and its <= 4,
          "%s: %d hanging slave nodes, %d of %d nodes closed, pressure "
          "spread %.1e, resultant error %.1e, %d Newton iterations"
          % (name, n_hanging, len(closed), len(rows), spread, total,
             its))


# The MPI part: case mpi.
if "mpi" in selected and mpi_part(selected):
    # 4. at -np 2 and 3.
    for pair, box in boxes:
        for basis, ranks, mesh in (("dual", 2, "distributed"),
                                   ("dual", 3, "distributed"),
                                   ("dual", 2, "shared")):
            hanging(pair, box, "lagrange multiplier", basis, ranks, mesh)
    # The sliding with hanging slave nodes at -np 2 against its serial run
    # (whose checks are the serial part's).
    serial = out + "/hanging_sliding3d_np1_reference"
    parallel = out + "/hanging_sliding3d_np2"
    run(tribos, sliding, serial, hanging_sliding)
    run(tribos, sliding, parallel, hanging_sliding, mpi_ranks=2)
    same_history(parallel, serial, "sliding 3D with hanging slave nodes")
    # The Q2 sliding with multipliers at -np 2 on smaller blocks.
    small = q2_sets + ["Contact/Method=lagrange multiplier",
                       "Scene/Two blocks/Upper subdivisions=2, 2, 1",
                       "Scene/Two blocks/Lower subdivisions=3, 3, 1"]
    serial = out + "/q2_sliding3d_small_np1"
    parallel = out + "/q2_sliding3d_small_np2"
    run(tribos, sliding, serial, small)
    run(tribos, sliding, parallel, small, mpi_ranks=2)
    found = re.search(r"contact across processes (\d+) slave nodes",
                      open(parallel + "/summary.txt").read())
    across = int(found.group(1)) if found else 0
    check(across > 0, "sliding 3D on Q2 hexahedra (3 x 3 x 1 under 2 x 2 x "
          "1), np 2: %d slave nodes paired with another process's master "
          "face" % across)
    same_history(parallel, serial, "sliding 3D on Q2 hexahedra")
if "serial" not in selected:
    finish()


# 1. Patch test.
meshes = [("5, 5, 2", "3, 3, 2"), ("7, 7, 2", "3, 3, 2"),
          ("4, 4, 2", "7, 7, 2"), ("5, 4, 2", "3, 2, 2")]
variants = [("lagrange multiplier", "dual"),
            ("lagrange multiplier", "standard"),
            ("penalty", "dual"), ("augmented lagrangian", "dual")]
worst = {}
n_runs = 0


def spread_of(folder):
    pressures = [r["CPRESS"] for r in read_csv(folder + "/contact-00001.csv")]
    return (max(pressures) - min(pressures)) / (
        sum(pressures) / len(pressures))


for lower, upper in meshes:
    for pair in ("14 : 5", "5 : 14"):
        for method, basis in variants:
            name = "patch3d_%s_%s_%s_%s_%s" % (
                lower.replace(", ", "x"), upper.replace(", ", "x"),
                "upper" if pair.startswith("14") else "lower",
                method.replace(" ", "_"), basis)
            folder = out + "/" + name
            run(tribos, prm, folder, [
                "Scene/Two blocks/Lower subdivisions=" + lower,
                "Scene/Two blocks/Upper subdivisions=" + upper,
                "Contact/Pairs=" + pair, "Contact/Method=" + method,
                "Contact/Mortar basis=" + basis])
            spread = spread_of(folder)
            history = read_csv(folder + "/history.csv")[-1]
            total = abs(abs(history["pair0_Fz"]) - p) / p
            its = history["newton_iterations"]
            key = method if method != "lagrange multiplier" else basis
            s, t, n = worst.get(key, (0.0, 0.0, 0))
            worst[key] = (max(s, spread), max(t, total), max(n, its))
            n_runs += 1
            bound = 1e-10 if method == "lagrange multiplier" else 1e-9
            check(spread < bound and total < 1e-8 and its <= 4,
                  "%s: pressure spread %.1e, resultant error %.1e, %d "
                  "Newton iterations" % (name, spread, total, its))
for key, (s, t, n) in worst.items():
    print("patch test 3D, %s: worst pressure spread %.2e, resultant error "
          "%.2e, at most %d Newton iterations" % (key, s, t, n))
print("patch test 3D: %d mortar runs" % n_runs)

for lower, upper in meshes[:2]:
    for pair in ("14 : 5", "5 : 14"):
        folder = out + "/patch3d_nts_%s_%s_%s" % (
            lower.replace(", ", "x"), upper.replace(", ", "x"), pair[0])
        run(tribos, prm, folder, [
            "Scene/Two blocks/Lower subdivisions=" + lower,
            "Scene/Two blocks/Upper subdivisions=" + upper,
            "Contact/Pairs=" + pair, "Contact/Discretization=node to segment",
            "Contact/Method=lagrange multiplier"])
        spread = spread_of(folder)
        check(spread > 0.01, "node to segment %s / %s, pair %s fails the "
              "patch test: pressure spread %.3f" % (lower, upper, pair,
                                                    spread))

# 2. Overhanging upper block (1.2 x 1.2 on 1 x 1).
for pair in ("14 : 5", "5 : 14"):
    for method in ("lagrange multiplier", "penalty", "augmented lagrangian"):
        folder = out + "/overhang3d_%s_%s" % (pair[0],
                                              method.replace(" ", "_"))
        run(tribos, prm, folder, [
            "Scene/Two blocks/Upper block size=1.2, 1.2, 0.5",
            "Scene/Two blocks/Upper subdivisions=4, 4, 2",
            "Contact/Pairs=" + pair, "Contact/Method=" + method])
        rows = read_csv(folder + "/history.csv")
        history = rows[-1]
        load = p * 1.2 * 1.2
        total = abs(abs(history["pair0_Fz"]) - load) / load
        check(len(rows) == 1 and history["cutbacks"] == 0 and
              history["newton_iterations"] <= 12 and total < 1e-8,
              "overhanging block, pair %s, %s: one increment, %d Newton "
              "iterations, resultant p A to %.1e" % (
                  pair, method, history["newton_iterations"], total))

# 3. Frictional sliding.
for method in ("penalty", "lagrange multiplier"):
    iterations = {}
    for discretization in ("node to segment", "mortar"):
        folder = out + "/sliding3d_%s_%s" % (
            method.replace(" ", "_"), discretization.replace(" ", "_"))
        run(tribos, tests + "/sliding_blocks_3d.prm", folder, [
            "Contact/Method=" + method,
            "Contact/Discretization=" + discretization,
            "Time stepping/Number of steps=8"])
        history = read_csv(folder + "/history.csv")
        iterations[discretization] = sum(h["newton_iterations"]
                                         for h in history)
        if discretization == "mortar":
            ratios = [h["pair0_tangential_force"] / h["pair0_normal_force"]
                      for h in history if h["time"] > 1.2]
            worst_ratio = max(abs(r - 0.3) for r in ratios)
            check(all(h["cutbacks"] == 0 for h in history) and
                  worst_ratio < 1e-6,
                  "sliding 3D, mortar %s: no cutbacks, |F_T / F_N - mu| "
                  "<= %.1e in the slide" % (method, worst_ratio))
    check(iterations["mortar"] <= 1.2 * iterations["node to segment"],
          "sliding 3D, %s: mortar %d Newton iterations, node to segment %d"
          % (method, iterations["mortar"], iterations["node to segment"]))

# 4. Hanging slave nodes (the MPI runs: case mpi).
for pair, box in boxes:
    for method, basis in variants:
        hanging(pair, box, method, basis, 0, "distributed")

serial = out + "/hanging_sliding3d_np1"
run(tribos, sliding, serial, hanging_sliding)
history = read_csv(serial + "/history.csv")
ratios = [h["pair0_tangential_force"] / h["pair0_normal_force"]
          for h in history if h["time"] > 1.2]
worst_ratio = max(abs(r - 0.3) for r in ratios)
check(all(h["cutbacks"] == 0 for h in history) and worst_ratio < 1e-6,
      "sliding 3D with hanging slave nodes, mortar multipliers: no cutbacks, "
      "|F_T / F_N - mu| <= %.1e in the slide" % worst_ratio)

# 5. Q2 hexahedra: nine-node faces.
for lower, upper, pairs in (("5, 5, 2", "3, 3, 2", ("14 : 5", "5 : 14")),
                            ("4, 4, 2", "7, 7, 2", ("14 : 5",))):
    for pair in pairs:
        for method, basis in variants:
            name = "q2_patch3d_%s_%s_%s_%s_%s" % (
                lower.replace(", ", "x"), upper.replace(", ", "x"),
                "upper" if pair.startswith("14") else "lower",
                method.replace(" ", "_"), basis)
            folder = out + "/" + name
            run(tribos, prm, folder, [
                q2, "Scene/Two blocks/Lower subdivisions=" + lower,
                "Scene/Two blocks/Upper subdivisions=" + upper,
                "Contact/Pairs=" + pair, "Contact/Method=" + method,
                "Contact/Mortar basis=" + basis])
            spread = spread_of(folder)
            n_nodes = len(read_csv(folder + "/contact-00001.csv"))
            history = read_csv(folder + "/history.csv")[-1]
            total = abs(abs(history["pair0_Fz"]) - p) / p
            its = history["newton_iterations"]
            # Penalty: the pressure is eps_N times penetrations of 1e-6 of
            # the coordinates, whose round-off the weighted gap of the
            # modified basis sums over 25 nodes (measured 1.7e-9).
            bound = 1e-10 if method == "lagrange multiplier" else 1e-8
            check(spread < bound and total < 1e-8 and its <= 4,
                  "%s: %d slave nodes (vertices, edge middles, face "
                  "centres), pressure spread %.1e, resultant error %.1e, %d "
                  "Newton iterations" % (name, n_nodes, spread, total, its))

for method in ("penalty", "lagrange multiplier"):
    folder = out + "/q2_sliding3d_" + method.replace(" ", "_")
    run(tribos, sliding, folder, q2_sets + ["Contact/Method=" + method])
    history = read_csv(folder + "/history.csv")
    ratios = [h["pair0_tangential_force"] / h["pair0_normal_force"]
              for h in history if h["time"] > 1.2]
    worst_ratio = max(abs(r - 0.3) for r in ratios)
    check(all(h["cutbacks"] == 0 for h in history) and worst_ratio < 1e-6,
          "sliding 3D on Q2 hexahedra, mortar %s: no cutbacks, |F_T / F_N - "
          "mu| <= %.1e in the slide, %d Newton iterations"
          % (method, worst_ratio, sum(h["newton_iterations"]
                                      for h in history)))
# Restarted in the slide (from step 3, its frictional history included):
# the uninterrupted history bit for bit.
serial = out + "/q2_sliding3d_lagrange_multiplier"
restarted = out + "/q2_sliding3d_restart"
shutil.copytree(serial, restarted)
log = run(tribos, sliding, restarted,
          q2_sets + ["Contact/Method=lagrange multiplier"],
          extra=["--restart", serial + "/checkpoint-00003"]).stdout
history = read_csv(serial + "/history.csv")
again = read_csv(restarted + "/history.csv")
forces = [k for k in history[0] if k.startswith(("RF", "pair0"))]
# It resumed: the run computed step 4 only.
check(re.findall(r"^step +(\d+)/", log, re.M) == ["4"] and
      len(again) == len(history) and all(
          a[k] == b[k] for a, b in zip(history, again) for k in forces),
      "sliding 3D on Q2 hexahedra: restarted from step 3, step 4 computed, "
      "every force of history.csv bit for bit")
finish()
