"""Verification of Contact/Method = lagrange multiplier.

* Hertz 2D (cylinder on a rigid plane and on an elastic block) and 3D
  (quarter sphere on a rigid plane): a and p0 within 3 % (2D) / 5 % (3D) of
  Hertz, as for the penalty; every closed slave node has |g_N| < 1e-10 of
  the element size (the constraint is exact).
* Patch test (two blocks, non-matching meshes, uniform pressure):
  equilibrium to 1e-8 and |g_N| < 1e-10 h at every slave node.
* Penalty -> Lagrange: on the rigid Hertz scene the penalty solutions
  with eps_N = 10E, 100E, 1000E, 1e4 E approach the Lagrange solution
  (contact force and peak pressure), each decade of eps_N reducing the
  difference at least 5-fold (the expected O(1/eps_N)).
* The augmented Lagrangian (tolerance 1e-4 of the element size) reaches
  the Lagrange solution closer than the plain 1000E penalty.
The differences and ratios are printed (they are quoted in doc/contact.md).
"""

import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish, hertz_compare

tribos, tests, out = setup(sys.argv)
E, nu, R = 1.0, 0.3, 1.0
LM = "Contact/Method=lagrange multiplier"


def max_gap(folder, step, size):
    """Largest |g_N| of a closed slave node over the element size."""
    nodes = read_csv(folder + "/contact-%05d.csv" % step)
    closed = [n for n in nodes if n["CSTATUS"] > 0]
    return max(abs(n["COPEN"]) for n in closed) / size, len(closed)


def spacing(folder, step):
    """Smallest distance between two closed slave nodes (2D)."""
    xs = sorted(n["x"] for n in read_csv(folder + "/contact-%05d.csv" % step)
                if n["CSTATUS"] > 0)
    return min(b - a for a, b in zip(xs, xs[1:]))


# Hertz, rigid plane and elastic block.
hertz = PARAMETERS + "/hertz_2d.prm"
block = ["Scene/Cylinder over block/With block=true", "Contact/Pairs=10 : 3",
         "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; 2 : xy : 0, 0"]
for name, sets, e_star in (("rigid", [], E / (1 - nu * nu)),
                           ("block", block, E / (2 * (1 - nu * nu)))):
    folder = out + "/hertz_" + name
    run(tribos, hertz, folder, [LM] + sets)
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(folder, 2, e_star, R, 1)
    print("hertz %s: a error %.2f %%, p0 error %.2f %%, profile L2 error "
          "%.3f, %d nodes" % (name, 100 * abs(a_h - a) / a,
                              100 * abs(p0_h - p0) / p0, profile, n))
    check(abs(a_h - a) / a < 0.03 and abs(p0_h - p0) / p0 < 0.03,
          "hertz %s: a and p0 within 3 %%" % name)
    gap, n_closed = max_gap(folder, 2, spacing(folder, 2))
    check(gap < 1e-10, "hertz %s: max |g_N| / h = %.1e < 1e-10 over %d "
          "closed nodes" % (name, gap, n_closed))

# Hertz 3D (quarter sphere, one level coarser than parameters/hertz_3d.prm;
# the saddle point needs the direct solver).
folder = out + "/hertz_3d"
run(tribos, PARAMETERS + "/hertz_3d.prm", folder, [
    LM, "Linear solver/Type=direct",
    "Scene/Cylinder over block/Contact refinements=3"])
a, p0, a_h, p0_h, profile, n, P = hertz_compare(folder, 3, E / (1 - nu * nu),
                                                R, 4)
print("hertz 3d: a error %.2f %%, p0 error %.2f %%, %d nodes"
      % (100 * abs(a_h - a) / a, 100 * abs(p0_h - p0) / p0, n))
check(abs(a_h - a) / a < 0.05 and abs(p0_h - p0) / p0 < 0.05,
      "hertz 3d: a and p0 within 5 %")
nodes = [r for r in read_csv(folder + "/contact-00002.csv")
         if r["CSTATUS"] > 0]
size = min(((u["x"] - v["x"]) ** 2 + (u["y"] - v["y"]) ** 2) ** 0.5
           for u in nodes for v in nodes if u is not v)
gap = max(abs(r["COPEN"]) for r in nodes) / size
check(gap < 1e-10, "hertz 3d: max |g_N| / h = %.1e < 1e-10 over %d closed "
      "nodes" % (gap, len(nodes)))

# Patch test.
folder = out + "/patch"
run(tribos, tests + "/patch_test.prm", folder, [LM])
history = read_csv(folder + "/history.csv")[-1]
force_error = abs(abs(history["pair0_Fy"]) - 0.01) / 0.01
nodes = read_csv(folder + "/contact-00001.csv")
pressure_error = max(abs(n["CPRESS"] - 0.01) / 0.01 for n in nodes)
gap, n_closed = max_gap(folder, 1, 1.0 / 3)
print("patch test: nodal pressure error max %.4f" % pressure_error)
check(force_error < 1e-8, "patch test: equilibrium (%.1e)" % force_error)
check(gap < 1e-10 and n_closed == len(nodes),
      "patch test: all %d slave nodes closed, max |g_N| / h = %.1e"
      % (n_closed, gap))

# Penalty converging to the Lagrange solution.
reference = read_csv(out + "/hertz_rigid/history.csv")[-1]
reference_p = max(n["CPRESS"]
                  for n in read_csv(out + "/hertz_rigid/contact-00002.csv"))


def difference(folder):
    h = read_csv(folder + "/history.csv")[-1]
    p = max(n["CPRESS"] for n in read_csv(folder + "/contact-00002.csv"))
    return (abs(h["pair0_normal_force"] - reference["pair0_normal_force"]) /
            reference["pair0_normal_force"],
            abs(p - reference_p) / reference_p)


previous = None
for factor in ("10", "100", "1000", "10000"):
    folder = out + "/penalty_" + factor
    run(tribos, hertz, folder, ["Contact/Penalty factor=%s*E/h" % factor])
    force, peak = difference(folder)
    print("penalty %6sE/h: force differs from Lagrange by %.3e, peak "
          "pressure by %.3e" % (factor, force, peak))
    if previous:
        check(force * 5 < previous[0] and peak * 5 < previous[1],
              "penalty %sE/h: at least 5x closer than %sE/h (force %.1fx, peak "
              "%.1fx)" % (factor, previous[2], previous[0] / force,
                          previous[1] / peak))
    previous = (force, peak, factor)
penalty_1000 = difference(out + "/penalty_1000")

folder = out + "/augmented"
run(tribos, hertz, folder, ["Contact/Method=augmented lagrangian"])
force, peak = difference(folder)
print("augmented lagrangian: force differs by %.3e, peak pressure by %.3e"
      % (force, peak))
check(force < penalty_1000[0] and force < 1e-4,
      "augmented lagrangian reaches the Lagrange force (%.1e < 1e-4)" % force)
finish()
