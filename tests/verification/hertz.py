"""Verification: Hertz contact. 2D (plane strain cylinder, R = 1) on a
rigid plane and on an elastic block; 3D (sphere, quarter model) on a rigid
plane. The contact half-width a and the peak pressure p0 come from a
least-squares fit of p^2 = p0^2 (1 - x^2/a^2) to the nodal CPRESS of the
slave nodes in contact, the load P from the contact normal force; asserts
a and p0 within 3 % (2D, also with Master smoothing on the elastic
block) and 5 % (3D) of Hertz and reports the relative L2
error of the pressure profile."""

import math
import sys

from tribos_testing import PARAMETERS, setup, run, check, finish, hertz_compare

tribos, tests, out = setup(sys.argv)
E, nu, R = 1.0, 0.3, 1.0


def verify(name, dim, folder, e_star, bound, force_scale):
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(folder, dim, e_star, R,
                                                    force_scale)
    print("%s: P = %.6g, Hertz a = %.5g, p0 = %.5g; fitted a = %.5g, "
          "p0 = %.5g; %d nodes in contact; profile L2 error %.3f"
          % (name, P, a, p0, a_h, p0_h, n, profile))
    check(abs(a_h - a) / a < bound, "%s: a within %g %% (%.2f %%)"
          % (name, 100 * bound, 100 * abs(a_h - a) / a))
    check(abs(p0_h - p0) / p0 < bound, "%s: p0 within %g %% (%.2f %%)"
          % (name, 100 * bound, 100 * abs(p0_h - p0) / p0))
    check(n >= 10, "%s: at least 10 nodes in contact" % name)


prm = PARAMETERS + "/hertz_2d.prm"
run(tribos, prm, out + "/rigid")
verify("2D on rigid plane", 2, out + "/rigid", E / (1 - nu * nu), 0.03, 1)

# The faceted master and the primal penalty (the defaults choose the
# smoothed master and the mixed form between two bodies: the next case).
run(tribos, prm, out + "/block", [
    "Scene/Cylinder over block/With block=true", "Contact/Pairs=10 : 3",
    "Contact/Master smoothing=none", "Contact/Penalty formulation=primal",
    "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; 2 : xy : 0, 0"])
verify("2D on elastic block", 2, out + "/block", E / (2 * (1 - nu * nu)),
       0.03, 1)
# The same with the defaults (the smoothed master, averaged nodal
# normals, and the mixed penalty): on the nearly flat block the smoothing
# must not cost accuracy.
run(tribos, prm, out + "/block_smoothed", [
    "Scene/Cylinder over block/With block=true", "Contact/Pairs=10 : 3",
    "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; 2 : xy : 0, 0"])
verify("2D on elastic block, the defaults (smoothed master)", 2, out + "/block_smoothed",
       E / (2 * (1 - nu * nu)), 0.03, 1)

prm3 = PARAMETERS + "/hertz_3d.prm"
run(tribos, prm3, out + "/sphere")
# quarter model: the full load is four times the modelled one
verify("3D sphere on rigid plane", 3, out + "/sphere", E / (1 - nu * nu),
       0.05, 4)
finish()
