#!/usr/bin/python3
"""GetFEM side of the paired shallow-ironing benchmark (parameters/
ironing.prm): the same plane-strain problem, mesh, material, friction and
loading, solved with GetFEM 5.4's large-sliding contact brick.

    /usr/bin/python3 getfem_ironing.py --steps 150 [--csv results.csv]
        [--history h.csv] [--r 3448] [--release 0.5] [--rtol 1e-8]
        [--max-iter 20] [--lsearch plain] [--slave-points nodes]
        [--friction 0.3] [--until 6] [--noisy]

Mesh (node for node tribos's scene "two blocks", source/scene/blocks.cc):
foundation [0, 12] x [0, 4], 60 x 20 Q1 cells; punch [0.2, 1.4] x
[4.2, 5.4], 12 x 12 Q1 cells, each node moved vertically so that the bottom
is the arc of radius 0.75 through the bottom corners (lowest point at
y = 4.2, sagitta 0.3) and the top stays flat: y = y0 + b + eta (H - b),
b = R - sqrt(R^2 - (x - 0.8)^2), eta = (y - y0) / H. Two meshes, two
displacement fields, 2 x 2 Gauss points. Both are built as "cartesian Q1"
(bilinear geometric transformation GT_QK(2,1), as deal.II's Q1 mapping):
GetFEM's plain "cartesian" uses GT_LINEAR_PRODUCT, an affine map that is
exact only for parallelograms, and the punch's cells are trapezoids after
the arc mapping. With it the punch's strains were wrong and its bulk about
2.4 times too soft (bottom glued, top pushed 0.1 down: 440 instead of
tribos's 1077), and the ironing forces 6 % low in V (296.9 against 316.1
at t = 1).

Material: tribos's compressible neo-Hookean (source/material/
neo_hookean.cc), psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2 in plane
strain (I1 = F:F + 1): GetFEM's 'Compressible Neo Hookean Bonet' law with
params [lambda, mu] (its potential equals this formula to round-off, and a
GWFL weak form of tribos's P = mu (F - F^-T) + lambda ln J F^-T gives the
same forces); E = 689.6 (foundation), 6896 (punch), nu = 0.32.

Loading: foundation bottom fixed; punch top u = (0, -t) for t in [0, 1],
then (2 (t - 1), -1) for t in [1, 6] (Dirichlet by simplification, its
data set per increment); --steps equal increments of the time 6.

Contact: add_integral_large_sliding_contact_brick_raytracing (Alart-
Curnier augmented Lagrangian, non-symmetric version 0), slave = the
punch's left side, right side and arc (P1 vector multiplier, the contact
stress), master = the foundation's top (faceted: GetFEM has no smoothing),
Coulomb mu = 0.3 on the slip increment (alpha = 1, w = each body's last
converged displacement). --slave-points nodes (default) integrates the
slave faces at their nodes (Gauss-Lobatto), GetFEM's nodal counterpart of
tribos's node to segment; gauss: 2 Gauss points per face. r (--r) is in
stress per length: the default 3448 = E/h of the foundation (tribos's
scale for its friction parameter); 1724 behaves alike (150 steps: 8
cutbacks against 10), 6896 cuts back 74 times, 689.6 3 times by t = 1.6
(these counts predate the Q1 mesh fix; with it, r = 3448 and 150 steps
cut back once).
--release 0.5 = 2.5 foundation cells, below both bodies' thickness (0.25
and 1.0 gave the same forces).

Newton: Model.solve, MUMPS, at most --max-iter iterations; --lsearch plain
= full Newton steps (GetFEM's 'simplest' line search with alpha min = 1,
i.e. classical Newton; its default step control spends ~5 damped
iterations in every sliding increment). Converged when GetFEM's min(|R|_1
/ |external load|, |du|_1 / |U|_1) < --rtol. A failed increment (no
convergence, or an exception, e.g. an inverted element) is restored and
halved, at most --max-cutbacks times in a row ("cutbacks"); the rest of
the nominal step goes on in increments of the halved size. newton_total
counts every attempt's iterations (an exception counts --max-iter).

Reaction at the punch top (tribos's RF13_x, RF13_y: the force exerted by
the support on the punch): the sum of the punch's internal force over the
top dofs. V = -RF_y, H = RF_x, at t = 0.5, 1, 1.5, 3.5 and the end, linear
between increments (150 steps do not hit 0.5, 1.5 or 3.5).

Columns (printed, and appended to --csv): code, steps, increments,
cutbacks, newton_total, converged, wall_s (the script after 'import
getfem'), import_s, V_0.5, H_0.5, V_1, H_1, V_1.5, H_1.5, V_3.5, H_3.5,
V_end, H_end, t_end, r, release, rtol. --history: one row per increment
(time, newton_iterations of the accepted attempt, RF_x, RF_y).
Exit status 1 if the run stopped after its cutbacks (the row is written).
"""

import time

T_START = time.perf_counter()

import argparse  # noqa: E402
import csv  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402

# The times where the forces are compared (and the end).
REPORT_TIMES = (0.5, 1.0, 1.5, 3.5)
END_TIME = 6.0
E_FOUNDATION, E_PUNCH, NU, FRICTION = 689.6, 6896.0, 0.32, 0.3
BOTTOM, TOP, LEFT, RIGHT, ARC, TOP_PUNCH, SLAVE = 2, 3, 10, 11, 12, 13, 20


def interpolate(times, values, t):
    """values at time t, linear between the neighbouring entries of the
    increasing times (nan outside)."""
    for k in range(1, len(times)):
        if times[k - 1] - 1e-12 <= t <= times[k] + 1e-12:
            if times[k] == times[k - 1]:
                return values[k]
            s = (t - times[k - 1]) / (times[k] - times[k - 1])
            return (1 - s) * values[k - 1] + s * values[k]
    return float("nan")


def punch_top(t):
    """The punch top's displacement at time t (ironing.prm)."""
    return [0.0 if t <= 1 else 2 * (t - 1), -min(t, 1.0)]


def build_meshes(gf, np):
    """The foundation and the punch of blocks.cc with their regions."""
    # "cartesian Q1": bilinear cells (GT_QK(2,1)). Plain "cartesian" gives
    # GT_LINEAR_PRODUCT, an affine map meant for parallelograms: after the
    # arc mapping below the punch's cells are trapezoids, and with it their
    # strains are wrong (the punch's bulk is much too soft: glued bottom,
    # top pushed 0.1 down, RF 440 instead of tribos's 1077).
    foundation = gf.Mesh("cartesian Q1", np.linspace(0, 12, 61),
                         np.linspace(0, 4, 21))
    x0, y0, width, height, radius = 0.2, 4.2, 1.2, 1.2, 0.75
    punch = gf.Mesh("cartesian Q1", np.linspace(x0, x0 + width, 13),
                    np.linspace(y0, y0 + height, 13))
    pts = punch.pts()
    dx = pts[0] - (x0 + 0.5 * width)
    bottom = radius - np.sqrt(radius * radius - dx * dx)
    eta = (pts[1] - y0) / height
    pts[1] = y0 + bottom + eta * (height - bottom)
    punch.set_pts(pts)

    def mark(mesh, regions):
        faces = mesh.outer_faces()
        normals = mesh.normal_of_faces(faces)
        for region, test in regions:
            mesh.set_region(region, faces[:, np.nonzero(test(normals))[0]])

    mark(foundation, [(BOTTOM, lambda n: n[1] < -0.5),
                      (TOP, lambda n: n[1] > 0.5)])
    mark(punch, [(LEFT, lambda n: n[0] < -0.99),
                 (RIGHT, lambda n: n[0] > 0.99),
                 (ARC, lambda n: (n[1] < -0.01) & (abs(n[0]) < 0.99)),
                 (TOP_PUNCH, lambda n: n[1] > 0.99),
                 (SLAVE, lambda n: n[1] < 0.99)])
    return foundation, punch


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=150)
    parser.add_argument("--r", type=float, default=E_FOUNDATION / 0.2,
                        help="augmentation parameter (stress / length)")
    parser.add_argument("--release", type=float, default=0.5,
                        help="release distance of the ray tracing")
    parser.add_argument("--rtol", type=float, default=1e-8)
    parser.add_argument("--max-iter", type=int, default=20)
    parser.add_argument("--friction", type=float, default=FRICTION,
                        help="Coulomb coefficient (0: frictionless check)")
    parser.add_argument("--max-cutbacks", type=int, default=6)
    parser.add_argument("--lsearch", default="plain",
                        help="plain (full Newton steps: GetFEM's 'simplest' "
                        "line search with alpha min = 1) or a GetFEM line "
                        "search: default, simplest, basic, systematic")
    parser.add_argument("--slave-points", choices=("nodes", "gauss"),
                        default="nodes", help="integration points of the "
                        "slave faces: its nodes (Gauss-Lobatto) or 2 Gauss")
    parser.add_argument("--until", type=float, default=END_TIME,
                        help="stop after this time (a shorter check)")
    parser.add_argument("--noisy", action="store_true")
    parser.add_argument("--csv", help="append one row of results here")
    parser.add_argument("--history", help="write one row per increment")
    args = parser.parse_args()

    os.environ.setdefault("OMP_NUM_THREADS", "1")
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    import numpy as np
    import getfem as gf
    t_imported = time.perf_counter()
    if not args.noisy:
        gf.util_trace_level(0)

    foundation, punch = build_meshes(gf, np)
    md = gf.Model("real")
    mims, mfus = {}, {}
    for name, mesh, young in (("u1", punch, E_PUNCH),
                              ("u2", foundation, E_FOUNDATION)):
        mfus[name] = gf.MeshFem(mesh, 2)
        mfus[name].set_classical_fem(1)
        mims[name] = gf.MeshIm(mesh, 2)
        md.add_fem_variable(name, mfus[name])
        md.add_fem_data("w" + name[1], mfus[name])  # last converged u
        lam = young * NU / ((1 + NU) * (1 - 2 * NU))
        mu = young / (2 * (1 + NU))
        md.add_initialized_data("params" + name[1], [lam, mu])
        md.add_finite_strain_elasticity_brick(
            mims[name], "Compressible Neo Hookean Bonet", name,
            "params" + name[1])
    md.add_initialized_data("zero", [0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("u2", BOTTOM, "zero")
    md.add_initialized_data("top", punch_top(0.0))
    md.add_Dirichlet_condition_with_simplification("u1", TOP_PUNCH, "top")

    mflambda = gf.MeshFem(punch, 2)
    mflambda.set_classical_fem(1)
    md.add_filtered_fem_variable("lambda1", mflambda, SLAVE)
    md.add_initialized_data("r", [args.r])
    md.add_initialized_data("f", [args.friction])
    md.add_initialized_data("alpha", [1.0])
    brick = md.add_integral_large_sliding_contact_brick_raytracing(
        "r", args.release, "f", "alpha", 0)
    # (keep the Python objects alive: GetFEM drops what they own)
    rule = "IM_GAUSSLOBATTO1D(1)" if args.slave_points == "nodes" \
        else "IM_GAUSS1D(2)"
    mims["c1"] = gf.MeshIm(punch, gf.Integ("IM_PRODUCT(%s,%s)" % (rule,
                                                                  rule)))
    mims["c2"] = gf.MeshIm(foundation, 2)
    md.add_slave_contact_boundary_to_large_sliding_contact_brick(
        brick, mims["c1"], SLAVE, "u1", "lambda1", "w1")
    md.add_master_contact_boundary_to_large_sliding_contact_brick(
        brick, mims["c2"], TOP, "u2", "w2")

    # The reaction at the punch top: the punch's internal force (first
    # Piola-Kirchhoff stress of the law above) summed over the top dofs.
    top = mfus["u1"].basic_dof_on_region(TOP_PUNCH)
    lam, mu = md.variable("params1")
    stress = "{mu}*({F} - Inv({F})') + {lam}*log(Det({F}))*Inv({F})'".format(
        mu=repr(mu), lam=repr(lam), F="(Id(2)+Grad_u)")

    def reaction():
        f = gf.asm_generic(mims["u1"], 1, "(%s):Grad_Test_u" % stress, -1,
                           "u", 1, mfus["u1"], md.variable("u1"))
        return f[top[top % 2 == 0]].sum(), f[top[top % 2 == 1]].sum()

    opts = ["max_iter", args.max_iter, "max_res", args.rtol,
            "lsolver", "mumps"]
    if args.lsearch == "plain":
        opts += ["lsearch", "simplest", "alpha min", 1.0]
    else:
        opts += ["lsearch", args.lsearch]
    if args.noisy:
        opts.append("noisy")
    step = END_TIME / args.steps
    t, increments, cutbacks, newton_total = 0.0, 0, 0, 0
    history = [(0.0, 0, 0.0, 0.0)]
    converged_all = True
    for k in range(1, args.steps + 1):
        target = k * step
        dt, halvings = step, 0
        while target - t > 1e-9 * step:
            dt_try = min(dt, target - t)
            saved = {v: md.variable(v).copy()
                     for v in ("u1", "u2", "lambda1")}
            md.set_variable("w1", saved["u1"])
            md.set_variable("w2", saved["u2"])
            md.set_variable("top", punch_top(t + dt_try))
            try:
                iterations, converged = md.solve(*opts)
            except (RuntimeError, ValueError) as error:
                iterations, converged = args.max_iter, False
                if args.noisy:
                    print("exception:", error)
            converged = bool(converged) and all(
                np.isfinite(md.variable(v)).all() for v in saved)
            newton_total += int(iterations)
            if not converged:
                for v, value in saved.items():
                    md.set_variable(v, value)
                halvings += 1
                cutbacks += 1
                if halvings > args.max_cutbacks:
                    converged_all = False
                    break
                dt = dt_try / 2
                continue
            t = target if target - t - dt_try < 1e-9 * step else t + dt_try
            increments += 1
            rx, ry = reaction()
            history.append((t, int(iterations), rx, ry))
            print("step %d t %.4f newton %d RF %.4f %.4f" %
                  (k, t, iterations, rx, ry), flush=True)
        if not converged_all or t >= args.until - 1e-12:
            break
    wall = time.perf_counter() - t_imported

    times = [h[0] for h in history]
    row = dict(code="getfem", steps=args.steps, increments=increments,
               cutbacks=cutbacks, newton_total=newton_total,
               converged=converged_all, wall_s="%.3f" % wall,
               import_s="%.3f" % (t_imported - T_START))
    for tr in REPORT_TIMES + ("end",):
        tt = times[-1] if tr == "end" else tr
        label = "end" if tr == "end" else "%g" % tr
        row["V_" + label] = "%.4f" % -interpolate(
            times, [h[3] for h in history], tt)
        row["H_" + label] = "%.4f" % interpolate(
            times, [h[2] for h in history], tt)
    row.update(t_end="%.4f" % times[-1], r=args.r, release=args.release,
               rtol=args.rtol)
    for key, value in row.items():
        print("%-14s %s" % (key, value))
    if args.csv:
        new = not os.path.exists(args.csv)
        with open(args.csv, "a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(row))
            if new:
                w.writeheader()
            w.writerow(row)
    if args.history:
        with open(args.history, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["time", "newton_iterations", "RF_x", "RF_y"])
            w.writerows(history)
    return 0 if converged_all else 1


if __name__ == "__main__":
    sys.exit(main())
