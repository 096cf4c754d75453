#!/usr/bin/python3
"""GetFEM side of the paired Hertz benchmark (tribos issue 44): load-
controlled frictionless Hertz contact on a rigid plane, one load step.

    /usr/bin/python3 getfem_hertz.py --dim 2 --mesh hertz_2d_13k.msh \\
        [--order 1] [--method nodal] [--csv results.csv] [--samples s.csv]

2D (plane strain): the quarter x >= 0 of the lower half of a cylinder,
R = 1, centre (0, R), E = 1, nu = 0.3; u_x = 0 on x = 0 (region 12); a
uniform pressure q = 0.005 E on the flat top y = R (region 11), i.e. a
full (half-cylinder) load P = 2 R q = 0.01 E R per unit thickness, Hertz
a = 0.1076 R, p0 = 0.0591 E; contact of the curved surface (region 10)
with the plane y = 0. 3D: the quarter x, y >= 0 of the lower half sphere,
R = 10, centre (0, 0, R), E = 2e5, nu = 0.3; u_x = 0 on x = 0 (12),
u_y = 0 on y = 0 (13); full load P = 50e3 as the uniform pressure
P / (pi R^2) on the flat top z = R (11), a = 1.195, p0 = 16.7e3; contact
of the curved surface (10) with z = 0. The regions are gmsh's physical
groups (hertz_2d.geo, hertz_3d.geo).

Contact (--method):
  nodal     GetFEM's nodal contact with a rigid obstacle brick
            (add_nodal_contact_with_rigid_obstacle_brick): one multiplier
            (a nodal force) per contact node, Alart-Curnier augmented
            Lagrangian, symmetric variant (--option 2, the default; 1 is
            the non-symmetric one: the same in 2D, 23 instead of 11
            Newton iterations on a 3D P1 mesh), r = E (--r-factor; 0.01 E
            to 100 E changed nothing but +-1 iteration).
            Pressure = nodal force / the node's tributary area (the
            integral of its shape function over the contact surface; first
            order only, where that weight is positive).
  integral  GetFEM's integral contact with a rigid obstacle brick
            (add_integral_contact_with_rigid_obstacle_brick), the same
            Alart-Curnier variants: the multiplier is a Lagrange field on the
            contact surface (the contact stress, order --mult-order,
            default the displacement's). Pressure = the field's values at
            its nodes (they oscillate in sign beyond the contact edge;
            --threshold drops the small positive ones). Less robust here:
            no convergence in 50 iterations on hertz_2d_49k.msh, 16-30
            iterations and 7-9 % error with P2 tetrahedra in 3D.
Symmetry: u.n = 0 by multipliers (add_normal_Dirichlet_condition_with_
multipliers, of the displacement's order). Newton: Model.solve with the
default line search and MUMPS, from u = 0 and zero multipliers, the whole
load in one step, converged when GetFEM's residual (relative to its
estimate of the external load) is below --rtol.

Error: hertz_error.py, tribos's definition (tests/tribos_testing/__init__.py): Hertz
a and p0 from the contact force carried (sum of the multipliers, times
the symmetry factor), nodal relative L2 error over the contact nodes at
their current positions X + u. Also printed with the applied load.

Times: 'solve_s' is Model.solve alone; 'total_s' is the whole script
after 'import getfem' (mesh reading, setup, solve, post-processing), i.e.
the script's wall time minus the Python start-up and import time
('import_s', measured from the first line of the script).
"""

import time

T_START = time.perf_counter()

import argparse  # noqa: E402
import csv  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402

import numpy as np  # noqa: E402
import getfem as gf  # noqa: E402

T_IMPORTED = time.perf_counter()

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hertz_error  # noqa: E402

CASES = {
    # R, E, nu, full load P, symmetry factor
    2: dict(R=1.0, E=1.0, nu=0.3, P=0.01, sym=2.0),
    3: dict(R=10.0, E=2e5, nu=0.3, P=50e3, sym=4.0),
}
CONTACT, TOP, SYM_X, SYM_Y = 10, 11, 12, 13


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dim", type=int, choices=(2, 3), required=True)
    parser.add_argument("--mesh", required=True, help="gmsh .msh file")
    parser.add_argument("--order", type=int, choices=(1, 2), default=1)
    parser.add_argument("--method", choices=("nodal", "integral"),
                        default="nodal")
    parser.add_argument("--mult-order", type=int, choices=(1, 2),
                        help="integral: multiplier order (default --order)")
    parser.add_argument("--r-factor", type=float, default=1.0,
                        help="augmentation parameter r = factor * E")
    parser.add_argument("--option", type=int, default=2, choices=(1, 2),
                        help="1: non-symmetric, 2: symmetric Alart-Curnier")
    parser.add_argument("--im-order", type=int,
                        help="integration degree (default 2 * order)")
    parser.add_argument("--rtol", type=float, default=1e-8)
    parser.add_argument("--max-iter", type=int, default=50)
    parser.add_argument("--lsolver", default="mumps")
    parser.add_argument("--lsearch", default="default")
    parser.add_argument("--threshold", type=float, default=1e-3,
                        help="samples below threshold * max pressure count "
                        "as open in the error (multiplier round-off)")
    parser.add_argument("--noisy", action="store_true")
    parser.add_argument("--csv", help="append one row of results here")
    parser.add_argument("--samples", help="write the (x, y, z, r, pressure) "
                        "samples of the contact surface here")
    args = parser.parse_args()
    if args.method == "nodal" and args.order != 1:
        parser.error("--method nodal: first order only (the tributary "
                     "weight of a P2 vertex is not positive)")
    dim = args.dim
    case = CASES[dim]
    R, E, nu, P, sym = case["R"], case["E"], case["nu"], case["P"], case["sym"]
    e_star = E / (1.0 - nu * nu)
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    # the full top: 2R wide (2D, per unit thickness) or a disc of radius R
    q = P / (2 * R) if dim == 2 else P / (math.pi * R * R)

    if not args.noisy:
        gf.util_trace_level(0)  # GetFEM prints its assembly traces else
    mesh = gf.Mesh("import", "gmsh", args.mesh)
    if mesh.dim() != dim:
        sys.exit("the mesh is %dD, --dim is %d" % (mesh.dim(), dim))
    sym_regions = (SYM_X, SYM_Y)[:dim - 1]
    for region in (CONTACT, TOP) + sym_regions:
        if region not in mesh.regions():
            sys.exit("the mesh has no physical group %d" % region)

    mfu = gf.MeshFem(mesh, dim)
    mfu.set_classical_fem(args.order)
    mfs = gf.MeshFem(mesh, 1)  # scalar, same order: obstacle, weights
    mfs.set_classical_fem(args.order)
    mim = gf.MeshIm(mesh, args.im_order or 2 * args.order)

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda_", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda_", "mu")
    traction = [0.0] * dim
    traction[-1] = -q
    md.add_initialized_data("traction", traction)
    md.add_source_term_brick(mim, "u", "traction", TOP)
    for region in sym_regions:
        md.add_normal_Dirichlet_condition_with_multipliers(
            mim, "u", args.order, region)
    md.add_initialized_data("r", [args.r_factor * E])
    if args.method == "nodal":
        contact_dofs = mfu.basic_dof_on_region(CONTACT)
        contact_nodes = mfu.basic_dof_nodes(contact_dofs[::dim])
        md.add_variable("lambda_n", len(contact_dofs) // dim)
        md.add_nodal_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "r", CONTACT, "xyz"[dim - 1], args.option)
    else:
        mfl = gf.MeshFem(mesh, 1)
        mfl.set_classical_fem(args.mult_order or args.order)
        contact_nodes = mfl.basic_dof_nodes(mfl.basic_dof_on_region(CONTACT))
        md.add_filtered_fem_variable("lambda_n", mfl, CONTACT)
        # signed distance to the plane y = 0 (2D) / z = 0 (3D) on a fem
        md.add_initialized_fem_data("obstacle", mfs,
                                    mfs.basic_dof_nodes()[dim - 1])
        md.add_integral_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "obstacle", "r", CONTACT, args.option)
    dofs_u = mfu.nbdof()
    dofs_all = md.nbdof()

    t0 = time.perf_counter()
    opts = ["max_iter", args.max_iter, "max_res", args.rtol,
            "lsolver", args.lsolver, "lsearch", args.lsearch]
    if args.noisy:
        opts.append("noisy")
    iterations, converged = md.solve(*opts)
    solve_s = time.perf_counter() - t0

    # pressure samples (compression positive) and the force they carry
    multipliers = md.variable("lambda_n")
    if args.method == "nodal":
        force = -sym * multipliers.sum()
        weights = gf.asm_generic(mim, 1, "Test_s", CONTACT, gf_scalar_model(
            mfs))[mfs.basic_dof_on_region(CONTACT)]
        if not np.allclose(mfs.basic_dof_nodes(
                mfs.basic_dof_on_region(CONTACT)), contact_nodes):
            sys.exit("internal: contact node orders differ")
        pressure = -multipliers / weights + 0.0  # no -0
    else:
        force = -sym * gf.asm_generic(mim, 0, "lambda_n", CONTACT, md)
        pressure = -multipliers + 0.0
    disp = gf.compute_interpolate_on(mfu, md.variable("u"), contact_nodes)
    pos = contact_nodes + disp
    rr = np.abs(pos[0]) if dim == 2 else np.hypot(pos[0], pos[1])
    cut = args.threshold * pressure.max()
    points = [(r, p if p > cut else 0.0)
              for r, p in zip(rr.tolist(), pressure.tolist())]
    nan = float("nan")
    if converged and force > 0 and any(p > 0 for r, p in points):
        rep = hertz_error.report(points, force, R, e_star, dim)
        error_applied = hertz_error.profile_error(points, P, R, e_star, dim)
    else:  # no solution: report the run, no error
        rep = dict(P=force, a=nan, p0=nan, a_fit=nan, p0_fit=nan,
                   r_contact=nan, p_max=nan, n_contact=0,
                   profile_error=nan)
        error_applied = nan
    a_applied, p0_applied = hertz_error.hertz(P, R, e_star, dim)
    total_s = time.perf_counter() - T_IMPORTED
    import_s = T_IMPORTED - T_START

    if args.samples:
        with open(args.samples, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["x", "y", "z", "r", "pressure"])
            for i in range(len(rr)):
                xyz = list(pos[:, i]) + ([0.0] if dim == 2 else [])
                w.writerow(["%.10g" % v for v in xyz] +
                           ["%.10g" % rr[i], "%.10g" % pressure[i]])

    row = dict(
        code="getfem", dim=dim, mesh=os.path.basename(args.mesh),
        method=args.method, order=args.order,
        mult_order=(args.mult_order or args.order)
        if args.method == "integral" else "",
        cells=mesh.nbcvs(), dofs_u=dofs_u, dofs_all=dofs_all,
        newton_iterations=int(iterations), converged=bool(converged),
        solve_s="%.4f" % solve_s, total_s="%.4f" % total_s,
        import_s="%.4f" % import_s,
        load_applied="%.6g" % P, force_contact="%.6g" % rep["P"],
        a_hertz="%.6g" % rep["a"], a_fit="%.6g" % rep["a_fit"],
        r_contact="%.6g" % rep["r_contact"],
        p0_hertz="%.6g" % rep["p0"], p0_fit="%.6g" % rep["p0_fit"],
        p_max="%.6g" % rep["p_max"], n_contact=rep["n_contact"],
        profile_error="%.5f" % rep["profile_error"],
        integrated_error="%.5f" % rep.get("integrated_error", float("nan")),
        profile_error_applied_load="%.5f" % error_applied,
        a_applied="%.6g" % a_applied, p0_applied="%.6g" % p0_applied)
    for key, value in row.items():
        print("%-27s %s" % (key, value))
    if args.csv:
        new = not os.path.exists(args.csv)
        with open(args.csv, "a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(row))
            if new:
                w.writeheader()
            w.writerow(row)
    return 0 if converged else 1


def gf_scalar_model(mf):
    """A model with one scalar variable 's' on mf, for asm_generic."""
    model = gf.Model("real")
    model.add_fem_variable("s", mf)
    return model


if __name__ == "__main__":
    sys.exit(main())
