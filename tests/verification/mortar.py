"""Verification of the 2D mortar discretization (Contact/Discretization =
mortar).

1. Contact patch test (tests/data/patch_test.prm: two stacked blocks, uniform
   pressure p = 0.01 E on the top, the lower one on rollers) with
   non-matching meshes at several size ratios, each side as slave, with
   penalty, Lagrange multipliers and augmented Lagrangian, dual and
   standard basis, plane strain and axisymmetric (the dual functions are
   biorthogonal in the measure 2 pi r dr there), Q1 and Q2 (quadratic
   segments and dual functions; Q2's vertex on the axis, whose tributary
   area int N 2 pi r vanishes, carries no contact and is left out): every
   slave node's pressure CPRESS equal to the others
   to 1e-10 relative with multipliers and 1e-9 with penalty (the
   penetration, 1e-6 of coordinates of order 1, carries 1e-10 of
   round-off), and the total contact force p
   times the width to 1e-8 (Newton's tolerance). Node-to-segment one-pass
   on the same meshes is run too and must fail it by more than 1 %. An
   upper block overhanging the lower one (a half-covered end segment) must
   converge in one increment, at most 12 Newton iterations, every method.
   Q2 refined (Refinement = 4, 97 slave nodes): one increment, at most 4
   Newton iterations, the pressure uniform (never converged before the
   round-off-aware projection onto the master curve).
2. Frictional sliding (tests/data/ironing_2d.prm: neo-Hookean half cylinder slid
   across a deformable block, mu = 0.3): penalty and multipliers converge,
   the observed Newton order near convergence is >= 1.8 in the median
   sliding increment (the consistent AD tangent through D, M and the
   normal), the tangential force is mu times the normal force in the
   steady slide to 1e-6, and mortar needs no more Newton iterations than
   node to segment.
3. Hertz 2D on an elastic block (parameters/hertz_2d.prm), mortar with
   penalty and multipliers: contact half-width and peak pressure within
   3 % of Hertz (the pressure profile's L2 error is printed). Node to
   segment on the same scene is tests/verification/hertz.py's "block"
   (penalty) and tests/verification/lagrange_multiplier.py's "hertz_block"
   (multipliers), with the same 3 % bounds. The penalty run takes 4 load
   steps instead of the file's 2 (in 2 steps the first cut back twice, in
   4 once: 68 Newton iterations in all instead of 83): the
   problem is small-strain, linear elastic and frictionless, so its state
   at t = 1 does not depend on the path.
"""
# ctest: labels slow

import math
import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish, hertz_compare

tribos, tests, out = setup(sys.argv)
p, width = 0.01, 1.0

# 1. Patch test.
ratios = [(5, 3), (7, 3), (9, 4), (4, 11)]
methods = ["penalty", "lagrange multiplier", "augmented lagrangian"]
worst_spread, worst_total, n_runs = 0.0, 0.0, 0
# Plane strain at every ratio; axisymmetric (the blocks are discs of radius
# 1 about x = 0, the load p pi R^2) at two.
geometries = [(r, False) for r in ratios] + [(r, True) for r in ratios[:2]]
for (lower, upper), axisymmetric, degree in [
        (ratio, axisymmetric, degree) for ratio, axisymmetric in geometries
        for degree in (1, 2)]:
    for pair in ("12 : 3", "3 : 12"):
        for method in methods:
            for basis in ("dual", "standard"):
                if basis == "standard" and (method != "lagrange multiplier"
                                            or (degree, axisymmetric) ==
                                            (2, True)):
                    continue
                name = "patch_%d_%d_%s_%s_%s%s%s" % (
                    lower, upper, "upper" if pair.startswith("12") else
                    "lower", method.replace(" ", "_"), basis,
                    "_axisymmetric" if axisymmetric else "",
                    "_q2" if degree == 2 else "")
                folder = out + "/" + name
                run(tribos, tests + "/patch_test.prm", folder, [
                    "Scene/Two blocks/Lower subdivisions=%d, 2" % lower,
                    "Scene/Two blocks/Upper subdivisions=%d, 2" % upper,
                    "Contact/Pairs=" + pair,
                    "Contact/Method=" + method,
                    "Contact/Discretization=mortar",
                    "Contact/Mortar basis=" + basis,
                    "Finite element/Polynomial degree=%d" % degree,
                    "Finite element/Axisymmetric=%s" % str(
                        axisymmetric).lower()])
                rows = read_csv(folder + "/contact-00001.csv")
                if degree == 2 and axisymmetric:
                    # Q2's vertex on the axis has int N 2 pi r = 0: it
                    # carries no contact (open, no pressure).
                    on_axis = [r for r in rows if r["X"] == 0]
                    check(len(on_axis) == 1 and on_axis[0]["CPRESS"] == 0,
                          "%s: the node on the axis carries nothing" % name)
                    rows = [r for r in rows if r["X"] != 0]
                pressures = [r["CPRESS"] for r in rows]
                mean = sum(pressures) / len(pressures)
                spread = (max(pressures) - min(pressures)) / mean
                history = read_csv(folder + "/history.csv")[-1]
                # The vertical resultant of the slave's contact forces.
                load = p * (math.pi * width ** 2 if axisymmetric else width)
                total = abs(abs(history["pair0_Fy"]) - load) / load
                worst_spread = max(worst_spread, spread)
                worst_total = max(worst_total, total)
                n_runs += 1
                # Penalty: t_N = eps_N (-g_N) with a penetration of 1e-6 of
                # coordinates of order 1, so round-off alone is 1e-10 of it.
                bound = 1e-10 if method == "lagrange multiplier" else 1e-9
                check(spread < bound and total < 1e-8,
                      "%s: pressure spread %.1e, total force error %.1e"
                      % (name, spread, total))
print("patch test, %d mortar runs: worst pressure spread %.2e, worst total "
      "force error %.2e" % (n_runs, worst_spread, worst_total))

# The upper block overhangs the lower one by 0.2: the slave's end segment
# is half covered (upper as slave), or the master's (lower as slave). The
# dual basis used to switch to the standard one at full coverage exactly,
# and the segment at the symmetry plane, tilting by round-off, flipped
# between the two: with multipliers Newton cycled and never converged.
for pair in ("12 : 3", "3 : 12"):
    for method in methods:
        folder = out + "/overhang_%s_%s" % (pair[0], method.replace(" ", "_"))
        run(tribos, tests + "/patch_test.prm", folder, [
            "Scene/Two blocks/Upper block size=1.2, 0.5",
            "Contact/Pairs=" + pair, "Contact/Method=" + method,
            "Contact/Discretization=mortar"])
        rows = read_csv(folder + "/history.csv")
        history = rows[-1]
        total = abs(abs(history["pair0_Fy"]) - p * 1.2) / (p * 1.2)
        check(len(rows) == 1 and history["cutbacks"] == 0 and
              history["newton_iterations"] <= 12 and total < 1e-8,
              "overhanging slave/master, pair %s, %s: one increment, %d "
              "Newton iterations (augmented: all Uzawa passes), resultant "
              "p x 1.2 to %.1e" % (pair, method,
                                   history["newton_iterations"], total))

# Refined Q2 (Scene/Refinement = 4: 97 slave nodes, h = 1/48): the Newton
# iteration that puts a master point on the slave normal at each Gauss
# point wanted a step below 1e-14 of the reference coordinate, which round-
# off of the coordinates does not reach on short segments; the Gauss point
# was dropped, the residual jumped, and Newton never converged (it took 20
# iterations at Refinement = 3).
for method in ("lagrange multiplier", "penalty"):
    folder = out + "/patch_q2_refined_" + method.split()[0]
    run(tribos, tests + "/patch_test.prm", folder, [
        "Scene/Refinement=4", "Contact/Method=" + method,
        "Contact/Discretization=mortar", "Finite element/Polynomial degree=2"])
    history = read_csv(folder + "/history.csv")
    pressures = [r["CPRESS"] for r in read_csv(folder + "/contact-00001.csv")]
    spread = (max(pressures) - min(pressures)) / (
        sum(pressures) / len(pressures))
    check(len(history) == 1 and history[0]["cutbacks"] == 0 and
          history[0]["newton_iterations"] <= 4 and
          # Penalty: the penetration's round-off grows as h shrinks.
          spread < (1e-10 if method == "lagrange multiplier" else 1e-8),
          "Q2 patch test at Refinement = 4, %s: %d Newton iterations "
          "(<= 4), %d slave nodes, pressure spread %.1e"
          % (method, history[0]["newton_iterations"], len(pressures),
             spread))

for lower, upper in ratios[:2]:
    for pair in ("12 : 3", "3 : 12"):
        folder = out + "/patch_nts_%d_%d_%s" % (lower, upper, pair[0])
        run(tribos, tests + "/patch_test.prm", folder, [
            "Scene/Two blocks/Lower subdivisions=%d, 2" % lower,
            "Scene/Two blocks/Upper subdivisions=%d, 2" % upper,
            "Contact/Pairs=" + pair,
            "Contact/Method=lagrange multiplier"])
        pressures = [r["CPRESS"] for r in
                     read_csv(folder + "/contact-00001.csv")]
        spread = (max(pressures) - min(pressures)) / (
            sum(pressures) / len(pressures))
        check(spread > 0.01, "node to segment %d/%d, pair %s fails the "
              "patch test: pressure spread %.3f" % (lower, upper, pair,
                                                    spread))


# 2. Frictional sliding: order, friction law, iterations.
def orders(folder):
    rows = read_csv(folder + "/convergence.csv")
    history = read_csv(folder + "/history.csv")
    best = []
    for h in history:
        if h["time"] <= 1 + 1e-12:
            continue
        r = [x["residual"] for x in rows if x["increment"] ==
             h["increment"] and x["iteration"] > 0 and
             x["relative_residual"] > 1e-12]
        o = [math.log(r[k] / r[k - 1]) / math.log(r[k - 1] / r[k - 2])
             for k in range(2, len(r))]
        best.append(max(o[-2:]) if o else 0.0)
    return best, sum(h["newton_iterations"] for h in history), history[-1]


_, nts_iterations, _ = (None, None, None)
folder = out + "/sliding_nts"
run(tribos, tests + "/ironing_2d.prm", folder)
_, nts_iterations, _ = orders(folder)
for method in ("penalty", "lagrange multiplier"):
    folder = out + "/sliding_" + method.replace(" ", "_")
    run(tribos, tests + "/ironing_2d.prm", folder,
        ["Contact/Discretization=mortar", "Contact/Method=" + method])
    best, iterations, last = orders(folder)
    median = sorted(best)[len(best) // 2]
    ratio = last["pair0_tangential_force"] / last["pair0_normal_force"]
    print("sliding, mortar %s: %d Newton iterations (node to segment %d); "
          "orders %s; F_T / F_N = %.8f" % (
              method, iterations, nts_iterations,
              " ".join("%.2f" % b for b in best), ratio))
    check(median >= 1.8, "sliding, mortar %s: median order %.2f >= 1.8"
          % (method, median))
    check(abs(ratio - 0.3) < 1e-6, "sliding, mortar %s: F_T / F_N = mu "
          "(%.8f)" % (method, ratio))
    check(iterations <= nts_iterations, "sliding, mortar %s: %d Newton "
          "iterations, node to segment %d" % (method, iterations,
                                              nts_iterations))

# 3. Hertz 2D on an elastic block.
E, nu, R = 1.0, 0.3, 1.0
prm = PARAMETERS + "/hertz_2d.prm"
block = ["Scene/Cylinder over block/With block=true", "Contact/Pairs=10 : 3",
         "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; 2 : xy : 0, 0",
         "Output/Write VTU=false"]
for method, steps in (("penalty", 4), ("lagrange multiplier", 2)):
    name = "hertz_mortar_" + method.replace(" ", "_")
    run(tribos, prm, out + "/" + name, block + [
        "Contact/Discretization=mortar", "Contact/Method=" + method,
        "Time stepping/Number of steps=%d" % steps])
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(
        out + "/" + name, 2, E / (2 * (1 - nu * nu)), R, 1, step=steps)
    print("%s: a error %.2f %%, p0 error %.2f %%, profile L2 error "
          "%.4f, %d nodes in contact" % (
              name, 100 * abs(a_h - a) / a, 100 * abs(p0_h - p0) / p0,
              profile, n))
    check(abs(a_h - a) / a < 0.03 and abs(p0_h - p0) / p0 < 0.03,
          "%s: a and p0 within 3 %% of Hertz" % name)
finish()
