"""Adaptive refinement (Adaptivity, issue 58): the mesh refined and
coarsened during the run by Kelly's indicator and the contact's, on a p4est
mesh, with the state carried over.

1. Hertz 2D (parameters/hertz_2d.prm, penalty 100 E/h) from the scene's
   coarse uniform mesh (Contact refinements = 0: 256 cells, about 5 across
   the final contact width), Maximum level 7, Refine fraction 0.15, the
   default Contact zone depth (0.25: the cells within a quarter of the
   contact width of the zone as fine as the zone): a and p0 within 3 % of
   Hertz, and the pressure profile's L2 error against the converged one
   (tests/data/hertz_2d_reference_pressure.csv: x and CPRESS of the slave
   nodes, |x| < 0.12, of the hand-graded scene refined to Contact
   refinements = 8, 743 934 dofs, 0.35 % from its Contact refinements =
   7) below half the hand-graded scene's (Contact refinements = 5,
   13 482 dofs) with fewer dofs; the mesh must have changed. The
   indicator alone (Contact zone depth = 0, Refine fraction 0.3) within
   1.1 times the hand-graded scene's error with less than 0.6 times its
   dofs (it stops there: slave segments of several sizes inside the
   zone, on coarser cells beneath, make the nodal pressures oscillate).
   (Against Hertz's half-space profile the error of this scene does not
   converge: 3.7 % on a uniform mesh of 132k dofs; the finite block and
   cylinder differ from half-spaces.)
   The same with Maximum dofs = 2000: never more dofs than that.
1b. Hertz 3D (parameters/hertz_3d.prm, the quarter sphere on a rigid
   plane) from the coarse scene, Maximum level 4, 5 initial cycles: a and
   p0 within 5 % of Hertz, the profile error against Hertz below 4.8 %
   (the issue's target) with fewer dofs than the hand-graded scene
   (hanging slave nodes are carried by their parents: without, 36 %).
   The error against Hertz has a floor here: the hand-graded scene gives
   4.20 % at 21k dofs and 4.67 % refined once more (121k dofs).
2. Homogeneous J2 compression, loading, unloading and reverse yielding
   (tests/data/j2_uniaxial.prm on 2 x 2 x 2 cells), adapted after every
   step (the indicator is round-off: cells are refined and coarsened
   anyway): the force equals the run without adaptivity to 1e-8 (the
   plastic history is carried by copies, so a homogeneous state stays
   homogeneous).
3. The mortar patch test (tests/data/patch_test.prm, Lagrange
   multipliers) on a mesh refined by the initial cycles (slave and master
   segments of several sizes): the contact pressure uniform to 1e-10.
4. MPI: run 1 at -np 2 equal to the serial run to 1e-8 (forces and
   nodal pressures).
5. Friction (case ironing): the 2D ironing (parameters/ironing.prm, 150
   steps) from a mesh one level coarser (30 x 10 and 6 x 6 cells) refined
   up to the scene's mesh after every step, the stick points and slip
   carried over: the punch's forces V and H at t = 1.52, 3.52, 5 and 6
   (sliding) within 1 % of the run on the scene's mesh, at t = 0.52 and 1
   (sinking in) within 3 % (measured 2.3 %: H is then the difference of
   the friction forces on the two sides of the punch and feels the coarse
   cells away from it), with fewer dofs on average; and the sliding block (tests/data/sliding_block.prm,
   mu = 0.3) adapted after every step: tangential force = mu times the
   normal force to 1e-8 while it slides.
6. Restart after adaptations (case serial): the sliding block (friction:
   stick points, slip) and the homogeneous J2 compression (plastic
   history) adapted after every step with checkpoints, restarted from
   one: the mesh is refined to the checkpoint's cells, the step's
   adaptation made again, and history.csv and the last contact CSV equal
   the uninterrupted run's to 1e-10 with the same Newton iterations
   (measured: every digit written equal but the residual norms', which
   differ at round-off: deal.II stores the cells of a mesh made by
   refinement and coarsening in another order than the same mesh made by
   refinement alone, so assembly sums in another order). The
   sliding block's serial checkpoint restarted with -np 2 (case mpi): to
   1e-8.
8. Patch tests across hanging nodes in 3D (case serial;
   tests/data/patch_test_3d.prm, uniform pressure on the top, symmetry
   planes): hanging nodes made by the scene's Refinement box. Mortar
   (Lagrange multipliers and penalty) with the master's faces refined
   under the middle of a non-matching slave (3 x 3 on 5 x 5 cells): the
   nodal pressure uniform to 1e-10 (multipliers) and 1e-8 (penalty).
   Node to segment on matching meshes (5 x 5 on 5 x 5) refined alike on
   both sides: multipliers uniform to 1e-10, a uniform penalty (5000)
   to 1e-6 (measured 3.5e-8). (One-pass node to segment does not pass
   the patch test on non-matching meshes, with or without hanging nodes:
   tests/verification/patch_test.py. With the size-dependent penalty
   1000 E/h the pressure spreads by 41 %: outside Adaptivity the hanging
   slave nodes keep penalties of their own, of their finer faces' size,
   while their displacement follows their parents; carried by their
   parents, as Adaptivity does, 5.8e-4.)
9. A deformable master in 3D on an adapted mesh (case master3d): the Hertz
   sphere (parameters/hertz_3d.prm) on an elastic block of its material
   (With block = true, the pair 10 : 5) from the coarse scene, Maximum
   level 4: a and p0 within 5 % of Hertz for E* = E / (2 (1 - nu^2)), the
   mesh changed (hanging nodes on both surfaces: the master's faces join
   across them, ContactSurface::continues_across_refinement()).
7. Necking (case necking): Simo's necking bar (parameters/necking_bar.prm,
   axisymmetric Q2, finite-strain J2 with the hardening (36)) from its
   8 x 20 cells adapted after every step (Maximum level 1: the finest
   cells those of 16 x 40) against the uniform 16 x 40 run: the end
   force within 1 % of it along the whole force-elongation curve, the
   load maximum and the post-critical drop included (measured 0.57 %, at
   the end), with fewer dofs on average."""
# ctest: cases serial mpi ironing necking master3d
# ctest: mpirun-cases mpi
# ctest: quick-cases serial

import os
import shutil
import sys

from tribos_testing import (PARAMETERS, setup, run, read_csv, check, finish,
                            hertz_compare, parts, mpi_part, strip_columns,
                            numdiff, profile_difference, restart_identical,
                            restart_agrees, NEWTON_AGREEMENT)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi", "ironing", "necking",
                             "master3d"))


def summary(folder):
    values = {}
    for line in open(folder + "/summary.txt"):
        parts = line.split()
        if len(parts) >= 2 and parts[0] in ("cells", "dofs", "adaptations"):
            values[parts[0]] = int(parts[1])
    return values


def restart(prm, folder, sets, step, ranks=0):
    """Restart the run in folder (Output/Checkpoint every set) from its
    checkpoint after step in a copy of the folder; the copy's name."""
    copy = folder + "_restart_np%d" % ranks
    shutil.rmtree(copy, ignore_errors=True)
    shutil.copytree(folder, copy)
    run(tribos, prm, copy, sets, mpi_ranks=ranks,
        extra=["--restart", "%s/checkpoint-%05d" % (folder, step)])
    return copy


def last_contact(folder):
    files = sorted(f for f in os.listdir(folder) if f.startswith("contact-"))
    return files[-1:]


def restart_equal(prm, folder, sets, step):
    """6. The restarted run equal to the uninterrupted one in every digit
    of history.csv (but the wall times) and of the last contact CSV, and
    the same adaptations and final mesh."""
    copy = restart(prm, folder, sets, step)
    check(restart_identical(folder, copy) and
          summary(copy) == summary(folder) and
          summary(folder)["adaptations"] > step,
          "%s restarted after step %d (%d adaptations): history.csv "
          "%sequal in every digit, the same adaptations and final mesh"
          % (os.path.basename(folder), step, summary(folder)["adaptations"],
             "and %s " % last_contact(folder)[0]
             if last_contact(folder) else ""))


# 1. Hertz 2D from a coarse mesh against the hand-graded one.
E, nu, R = 1.0, 0.3, 1.0
hertz = PARAMETERS + "/hertz_2d.prm"
adaptive = ["Scene/Cylinder over block/Contact refinements=0",
            "Adaptivity/Enable=true", "Adaptivity/Maximum level=7",
            "Adaptivity/Initial cycles=8", "Adaptivity/Refine fraction=0.15",
            "Output/Write VTU=false"]
run(tribos, hertz, out + "/adaptive", adaptive)
# The indicator alone (no refinement around the contact zone).
indicator_only = adaptive + ["Adaptivity/Refine fraction=0.3",
                             "Adaptivity/Contact zone depth=0"]

# 4. -np 2 against serial.
if "mpi" in selected and mpi_part(selected):
    run(tribos, hertz, out + "/adaptive_np2", adaptive, mpi_ranks=2)
    serial = read_csv(out + "/adaptive/history.csv")
    parallel = read_csv(out + "/adaptive_np2/history.csv")
    force = max(abs(x["pair0_normal_force"] - y["pair0_normal_force"]) /
                abs(y["pair0_normal_force"]) for x, y in zip(parallel, serial))
    p_serial = sorted((r["X"], r["CPRESS"]) for r in
                      read_csv(out + "/adaptive/contact-00002.csv"))
    p_parallel = sorted((r["X"], r["CPRESS"]) for r in
                        read_csv(out + "/adaptive_np2/contact-00002.csv"))
    nodal = max(abs(p[1] - q[1]) for p, q in zip(p_parallel, p_serial)) / \
        max(q[1] for q in p_serial)
    check(len(p_serial) == len(p_parallel) and force < 1e-8 and nodal < 1e-8,
          "-np 2 equal to serial: force %.1e, nodal pressures %.1e "
          "(bound 1e-8)" % (force, nodal))

# 6. Restart after adaptations.
sliding_restart = ["Adaptivity/Enable=true", "Adaptivity/Maximum level=2",
                   "Output/Checkpoint every=5"]
if "serial" in selected:
    run(tribos, tests + "/sliding_block.prm", out + "/sliding_checkpoints",
        sliding_restart)
    restart_equal(tests + "/sliding_block.prm", out + "/sliding_checkpoints",
                  sliding_restart, 5)
    j2_restart = ["Scene/Block/Subdivisions=2, 2, 2", "Adaptivity/Enable=true",
                  "Adaptivity/Maximum level=2", "Output/Checkpoint every=3"]
    run(tribos, tests + "/j2_uniaxial.prm", out + "/j2_checkpoints",
        j2_restart)
    restart_equal(tests + "/j2_uniaxial.prm", out + "/j2_checkpoints",
                  j2_restart, 3)
if "mpi" in selected and mpi_part(selected, "the restart with -np 2"):
    folder = out + "/sliding_checkpoints_np"
    run(tribos, tests + "/sliding_block.prm", folder, sliding_restart)
    copy = restart(tests + "/sliding_block.prm", folder, sliding_restart, 5,
                   ranks=2)
    restart_agrees(folder, copy)
    print("ok      the serial checkpoint restarted with -np 2: history.csv "
          "and %s equal to %g (Newton's tolerance)"
          % (last_contact(folder)[0], NEWTON_AGREEMENT))

# 5. Friction: the sliding block and the ironing.
if "ironing" in selected:
    run(tribos, tests + "/sliding_block.prm", out + "/sliding",
        ["Adaptivity/Enable=true", "Adaptivity/Maximum level=2"])
    rows = read_csv(out + "/sliding/history.csv")
    sliding = [r for r in rows if r["n_slip"] > 0 and r["n_stick"] == 0]
    worst = max(abs(r["pair0_tangential_force"] -
                    0.3 * r["pair0_normal_force"]) / r["pair0_normal_force"]
                for r in sliding)
    check(len(sliding) >= 5 and summary(out + "/sliding")["adaptations"] >= 5
          and worst < 1e-8,
          "sliding block adapted %d times: T = mu N to %.1e in %d sliding "
          "steps" % (summary(out + "/sliding")["adaptations"], worst,
                     len(sliding)))
    ironing = PARAMETERS + "/ironing.prm"
    common = ["Time stepping/Number of steps=150", "Output/Write VTU=false"]
    run(tribos, ironing, out + "/ironing_fine", common)
    run(tribos, ironing, out + "/ironing_adaptive", common + [
        "Scene/Two blocks/Lower subdivisions=30, 10",
        "Scene/Two blocks/Upper subdivisions=6, 6",
        "Adaptivity/Enable=true", "Adaptivity/Maximum level=1"])
    fine = {round(r["time"], 6): r
            for r in read_csv(out + "/ironing_fine/history.csv")}
    adapted = read_csv(out + "/ironing_adaptive/history.csv")
    by_time = {round(r["time"], 6): r for r in adapted}
    worst = {"sinking in": 0, "sliding": 0}
    for t in (0.52, 1.0, 1.52, 3.52, 5.0, 6.0):
        for force in ("RF13_x", "RF13_y"):
            error = abs(by_time[t][force] / fine[t][force] - 1)
            phase = "sinking in" if t <= 1 else "sliding"
            worst[phase] = max(worst[phase], error)
            print("t = %g %s: adaptive %.5f, fine %.5f (%.2f %%)"
                  % (t, force, by_time[t][force], fine[t][force],
                     100 * error))
    mean_dofs = sum(r["dofs"] for r in adapted) / len(adapted)
    fine_dofs = summary(out + "/ironing_fine")["dofs"]
    check(len(adapted) == 150 and worst["sliding"] < 0.01 and
          worst["sinking in"] < 0.03 and mean_dofs < fine_dofs,
          "ironing adapted: V and H within %.2f %% (bound 1 %%) of the fine "
          "mesh's while the punch slides, within %.2f %% (bound 3 %%) while "
          "it sinks in, %.0f dofs on average against %d"
          % (100 * worst["sliding"], 100 * worst["sinking in"], mean_dofs,
             fine_dofs))
# 8. Patch tests across hanging nodes in 3D.
if "serial" in selected:
    patch3 = tests + "/patch_test_3d.prm"
    variants = [
        ("mortar, multipliers, master refined",
         ["Contact/Discretization=mortar",
          "Contact/Method=lagrange multiplier",
          "Scene/Two blocks/Refinement box=0.3, 0.3, 0.25 : 0.7, 0.7, 0.5"],
         1e-10),
        ("mortar, penalty, master refined",
         ["Contact/Discretization=mortar", "Contact/Method=penalty",
          "Scene/Two blocks/Refinement box=0.3, 0.3, 0.25 : 0.7, 0.7, 0.5"],
         1e-8),
        ("node to segment, penalty 5000, both sides refined alike",
         ["Contact/Discretization=node to segment", "Contact/Method=penalty",
          "Contact/Penalty factor=5000",
          "Scene/Two blocks/Upper subdivisions=5, 5, 2",
          "Scene/Two blocks/Refinement box=0.3, 0.3, 0.25 : 0.7, 0.7, 0.75"],
         1e-6),
        ("node to segment, multipliers, both sides refined alike",
         ["Contact/Discretization=node to segment",
          "Contact/Method=lagrange multiplier",
          "Scene/Two blocks/Upper subdivisions=5, 5, 2",
          "Scene/Two blocks/Refinement box=0.3, 0.3, 0.25 : 0.7, 0.7, 0.75"],
         1e-10)]
    for i, (name, sets, bound) in enumerate(variants):
        folder = out + "/patch_3d_%d" % i
        run(tribos, patch3, folder, sets)
        pressures = [r["CPRESS"] for r in
                     read_csv(folder + "/contact-00001.csv")]
        spread = (max(pressures) - min(pressures)) / max(pressures)
        check(spread < bound and min(pressures) > 0,
              "3D patch test across hanging nodes, %s: %d slave nodes, "
              "pressure spread %.1e (bound %.0e)"
              % (name, len(pressures), spread, bound))

# 9. A deformable master in 3D on an adapted mesh.
if "master3d" in selected:
    run(tribos, PARAMETERS + "/hertz_3d.prm", out + "/sphere_on_block", [
        "Scene/Cylinder over block/With block=true",
        "Scene/Cylinder over block/Contact refinements=0",
        "Contact/Pairs=10 : 5", "Contact/Rigid surfaces=",
        "Boundary conditions/Symmetry=12, 13, 0, 2",
        "Boundary conditions/Dirichlet=11 : z : -0.02*t ; 4 : xyz : 0, 0, 0",
        "Adaptivity/Enable=true", "Adaptivity/Maximum level=4",
        "Adaptivity/Initial cycles=5", "Output/Write VTU=false"])
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(
        out + "/sphere_on_block", 3, E / (2 * (1 - nu * nu)), R, 4)
    counts = summary(out + "/sphere_on_block")
    check(abs(a_h - a) / a < 0.05 and abs(p0_h - p0) / p0 < 0.05 and
          counts["adaptations"] >= 2,
          "sphere on a deformable block, adapted %d times (%d dofs): a %.4f "
          "(Hertz %.4f), p0 %.4f (Hertz %.4f), profile L2 error %.4f"
          % (counts["adaptations"], counts["dofs"], a_h, a, p0_h, p0,
             profile))

# 7. The necking bar.
if "necking" in selected:
    necking = PARAMETERS + "/necking_bar.prm"
    run(tribos, necking, out + "/necking_fine",
        ["Scene/Cylinder compression/Radial refinements=4",
         "Scene/Cylinder compression/Axial cells=40",
         "Output/Write VTU=false"])
    run(tribos, necking, out + "/necking_adaptive",
        ["Adaptivity/Enable=true", "Adaptivity/Maximum level=1",
         "Output/Write VTU=false"])
    fine = {round(r["time"], 6): r
            for r in read_csv(out + "/necking_fine/history.csv")}
    adapted = read_csv(out + "/necking_adaptive/history.csv")
    worst = max(abs(r["RF3_y"] / fine[round(r["time"], 6)]["RF3_y"] - 1)
                for r in adapted)
    peak = max(r["RF3_y"] for r in adapted), max(r["RF3_y"]
                                                   for r in fine.values())
    mean_dofs = sum(r["dofs"] for r in adapted) / len(adapted)
    fine_dofs = summary(out + "/necking_fine")["dofs"]
    check(len(adapted) == len(fine) and worst < 0.01 and
          adapted[-1]["RF3_y"] < 0.5 * peak[0] and mean_dofs < fine_dofs and
          summary(out + "/necking_adaptive")["adaptations"] >= 10,
          "necking bar adapted %d times: end force within %.2f %% (bound "
          "1 %%) of the uniform 16 x 40 run over %d increments (maximum "
          "%.3f against %.3f, dropping to %.3f), %.0f dofs on average "
          "against %d" % (summary(out + "/necking_adaptive")["adaptations"],
                          100 * worst, len(adapted), peak[0], peak[1],
                          adapted[-1]["RF3_y"], mean_dofs, fine_dofs))
if "serial" not in selected:
    finish()

run(tribos, hertz, out + "/graded", ["Output/Write VTU=false"])
run(tribos, hertz, out + "/indicator_only", indicator_only)
results = {}
reference = read_csv(tests + "/hertz_2d_reference_pressure.csv")
for name in ("graded", "adaptive", "indicator_only"):
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(
        out + "/" + name, 2, E / (1 - nu * nu), R, 1)
    error = profile_difference(read_csv(out + "/" + name +
                                        "/contact-00002.csv"), reference)
    results[name] = (error, summary(out + "/" + name))
    print("%s: %d dofs, a %.5f (Hertz %.5f), p0 %.5f (Hertz %.5f), "
          "profile L2 error against Hertz %.4f, against the converged "
          "profile %.4f, %d nodes in contact"
          % (name, results[name][1]["dofs"], a_h, a, p0_h, p0, profile,
             error, n))
    check(abs(a_h - a) / a < 0.03 and abs(p0_h - p0) / p0 < 0.03,
          "%s: a and p0 within 3 %% of Hertz" % name)
error, counts = results["adaptive"]
check(counts["adaptations"] >= 2, "the adaptive run changed its mesh (%d "
      "times)" % counts["adaptations"])
check(error <= 0.5 * results["graded"][0] and
      counts["dofs"] < results["graded"][1]["dofs"],
      "adaptive: pressure error %.4f against the converged profile, below "
      "half the hand-graded mesh's %.4f, with %d < %d dofs"
      % (error, results["graded"][0], counts["dofs"],
         results["graded"][1]["dofs"]))
error, counts = results["indicator_only"]
check(error <= 1.1 * results["graded"][0] and
      counts["dofs"] < 0.6 * results["graded"][1]["dofs"],
      "the indicator alone (Contact zone depth = 0): pressure error %.4f "
      "against the converged profile, within 1.1 times the hand-graded "
      "mesh's %.4f, with %d < 0.6 x %d dofs"
      % (error, results["graded"][0], counts["dofs"],
         results["graded"][1]["dofs"]))

# 1a. The dof budget: Maximum dofs = 2000 stops the same refinement there.
run(tribos, hertz, out + "/budget", adaptive + ["Adaptivity/Maximum dofs=2000"])
budget = [r["dofs"] for r in read_csv(out + "/budget/history.csv")]
check(max(budget) <= 2000 and summary(out + "/budget")["adaptations"] >= 2,
      "Maximum dofs = 2000: at most %d dofs after %d adaptations"
      % (max(budget), summary(out + "/budget")["adaptations"]))

# 1b. Hertz 3D.
hertz3 = PARAMETERS + "/hertz_3d.prm"
run(tribos, hertz3, out + "/graded_3d", ["Output/Write VTU=false"])
run(tribos, hertz3, out + "/adaptive_3d", [
    "Scene/Cylinder over block/Contact refinements=0",
    "Adaptivity/Enable=true", "Adaptivity/Maximum level=4",
    "Adaptivity/Initial cycles=5", "Adaptivity/Refine fraction=0.3",
    "Output/Write VTU=false"])
a, p0, a_h, p0_h, profile, n, P = hertz_compare(
    out + "/adaptive_3d", 3, E / (1 - nu * nu), R, 4)
dofs_3d = summary(out + "/adaptive_3d")["dofs"]
graded_3d = summary(out + "/graded_3d")["dofs"]
check(abs(a_h - a) / a < 0.05 and abs(p0_h - p0) / p0 < 0.05 and
      profile < 0.048 and dofs_3d < graded_3d,
      "Hertz 3D adaptive: a %.4f (Hertz %.4f), p0 %.4f (Hertz %.4f), "
      "profile L2 error %.4f < 0.048 with %d dofs < %d (hand-graded)"
      % (a_h, a, p0_h, p0, profile, dofs_3d, graded_3d))

# 2. Homogeneous J2 compression: the history carried exactly.
j2 = tests + "/j2_uniaxial.prm"
run(tribos, j2, out + "/j2_fixed")
run(tribos, j2, out + "/j2_adaptive",
    ["Scene/Block/Subdivisions=2, 2, 2", "Adaptivity/Enable=true",
     "Adaptivity/Maximum level=2"])
fixed = read_csv(out + "/j2_fixed/history.csv")
adapted = read_csv(out + "/j2_adaptive/history.csv")
worst = max(abs(x["RF5_z"] - y["RF5_z"]) / abs(y["RF5_z"])
            for x, y in zip(adapted, fixed))
check(len(adapted) == len(fixed) and worst < 1e-8 and
      summary(out + "/j2_adaptive")["adaptations"] >= 2,
      "J2 compression adapted %d times: force equal to the fixed mesh's to "
      "%.1e (bound 1e-8)" % (summary(out + "/j2_adaptive")["adaptations"],
                             worst))

# 3. The mortar patch test on an adapted mesh.
run(tribos, tests + "/patch_test.prm", out + "/patch",
    ["Contact/Discretization=mortar", "Contact/Method=lagrange multiplier",
     "Adaptivity/Enable=true", "Adaptivity/Maximum level=2"])
pressures = [r["CPRESS"] for r in read_csv(out + "/patch/contact-00001.csv")]
spread = (max(pressures) - min(pressures)) / max(pressures)
check(summary(out + "/patch")["adaptations"] >= 1 and len(pressures) > 4 and
      spread < 1e-10,
      "mortar patch test on an adapted mesh: %d slave nodes, pressure "
      "spread %.1e (bound 1e-10)" % (len(pressures), spread))

finish()
