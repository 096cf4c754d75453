"""Verification: manufactured solution u = a t (phi, phi(, phi)),
phi = prod sin(pi x_i), for small-strain linear elasticity on a shifted
box (non-zero Dirichlet data on every face). Asserts the optimal rates
p + 1 in L2 and p in the H1 seminorm for Q1 and Q2 in 2D and 3D."""

import math
import sys

from tribos_test import setup, run, read_csv, check, finish

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


cases = {(2, 1): range(0, 4), (2, 2): range(0, 3),
         (3, 1): range(0, 3), (3, 2): range(0, 3)}
for (dim, degree), levels in cases.items():
    u, force = expressions(dim)
    ids = range(2 * dim)
    dirichlet = " ; ".join("%d : %s : %s" % (b, X[:dim], ", ".join(u))
                           for b in ids)
    errors = []
    for level in levels:
        folder = "%s/%dd_q%d_%d" % (out, dim, degree, level)
        run(tribos, tests + "/mms_elasticity.prm", folder, [
            "Dimension=%d" % dim,
            "Finite element/Polynomial degree=%d" % degree,
            "Scene/Refinement=%d" % level,
            "Boundary conditions/Dirichlet=" + dirichlet,
            "Boundary conditions/Body force=" + ", ".join(force),
            "Verification/Exact displacement=" + ", ".join(u)])
        row = read_csv(folder + "/history.csv")[-1]
        errors.append((row["error_L2"], row["error_H1"]))
    print("%dD Q%d errors (L2, H1) by level: %s" % (
        dim, degree, "; ".join("%.3e, %.3e" % e for e in errors)))
    rate_l2 = math.log2(errors[-2][0] / errors[-1][0])
    rate_h1 = math.log2(errors[-2][1] / errors[-1][1])
    check(rate_l2 > degree + 1 - 0.15,
          "%dD Q%d L2 rate %.3f, expected %d" % (dim, degree, rate_l2,
                                                 degree + 1))
    check(rate_h1 > degree - 0.15,
          "%dD Q%d H1 rate %.3f, expected %d" % (dim, degree, rate_h1,
                                                 degree))
finish()
