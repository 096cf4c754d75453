"""Verification: manufactured solution u = a t (phi, phi(, phi)),
phi = prod sin(pi x_i), for small-strain linear elasticity on a shifted
box (non-zero Dirichlet data on every face). Asserts the optimal rates
p + 1 in L2 and p in the H1 seminorm for Q1 and Q2 in 2D and 3D, and for
P1 and P2 on the same boxes split into triangles and tetrahedra. A rate
is taken from the two finest levels of a case, which are the levels run
(and printed)."""

import math
import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
E, nu, a = 1.0, 0.3, 0.01
lam = E * nu / ((1 + nu) * (1 - 2 * nu))
mu = E / (2 * (1 + nu))
X = "xyz"


def expressions(dim):
    s = ["sin(pi*%s)" % X[i] for i in range(dim)]
    c = ["cos(pi*%s)" % X[i] for i in range(dim)]
    phi = "*".join(s)
    u = ["%g*t*%s" % (a, phi)] * dim
    force = []
    for j in range(dim):
        # sum over i != j of d_i d_j phi / pi^2
        mixed = []
        for i in range(dim):
            if i != j:
                factors = [c[k] if k in (i, j) else s[k] for k in range(dim)]
                mixed.append("*".join(factors))
        force.append("%.17g*t*pi^2*(%.17g*%s + %.17g*(%s - (%s)))" % (
            a, dim * mu, phi, lam + mu, phi, " + ".join(mixed)))
    return u, force


# (dimension, degree, cells): levels of Scene/Refinement. "simplices":
# every cell split into 8 triangles or 24 tetrahedra (P1, P2).
cases = {(2, 1, "as meshed"): range(2, 4), (2, 2, "as meshed"): range(1, 3),
         (3, 1, "as meshed"): range(1, 3), (3, 2, "as meshed"): range(1, 3),
         (2, 1, "simplices"): range(1, 3), (2, 2, "simplices"): range(1, 3),
         (3, 1, "simplices"): range(0, 2), (3, 2, "simplices"): range(0, 2)}
for (dim, degree, cells), levels in cases.items():
    name = ("Q%d" if cells == "as meshed" else "P%d") % degree
    u, force = expressions(dim)
    ids = range(2 * dim)
    dirichlet = " ; ".join("%d : %s : %s" % (b, X[:dim], ", ".join(u))
                           for b in ids)
    errors = []
    for level in levels:
        folder = "%s/%dd_%s_%d" % (out, dim, name, level)
        run(tribos, tests + "/mms_elasticity.prm", folder, [
            "Dimension=%d" % dim,
            "Finite element/Polynomial degree=%d" % degree,
            "Finite element/Cells=" + cells,
            "Scene/Refinement=%d" % level,
            "Boundary conditions/Dirichlet=" + dirichlet,
            "Boundary conditions/Body force=" + ", ".join(force),
            "Verification/Exact displacement=" + ", ".join(u)])
        row = read_csv(folder + "/history.csv")[-1]
        errors.append((row["error_L2"], row["error_H1"]))
    print("%dD %s errors (L2, H1) by level: %s" % (
        dim, name, "; ".join("%.3e, %.3e" % e for e in errors)))
    rate_l2 = math.log2(errors[-2][0] / errors[-1][0])
    rate_h1 = math.log2(errors[-2][1] / errors[-1][1])
    check(rate_l2 > degree + 1 - 0.15,
          "%dD %s L2 rate %.3f, expected %d" % (dim, name, rate_l2,
                                                degree + 1))
    check(rate_h1 > degree - 0.15,
          "%dD %s H1 rate %.3f, expected %d" % (dim, name, rate_h1,
                                                degree))
finish()
