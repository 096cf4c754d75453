"""The assembled tangent against central finite differences of the
assembled residual (Nonlinear solver/Check tangent) in every Newton
iteration of two sliding runs where slave nodes cross master faces: the
2D ironing scene (deformable curved slave on a deformable master, also
with the smoothed master, node to segment and mortar) and 3D frictional block-on-block sliding
(bilinear master faces), each also with the defaults untouched (the
penalty in mixed form, the smoothed master). Asserts a
relative error below 1e-6 everywhere (columns of all contact dofs and
every 7th dof; with Lagrange multipliers also every multiplier column and
row). One state is excluded: the first check of a Lagrange run, at first
touch, has Lambda = 0 and dg_T = 0 at the node that just closed, which is
the kink |T_trial| = mu t_N = 0 of the semismooth stick/slip switch, where
central differences straddle two branches (its error is printed)."""

import re
import sys

from tribos_testing import setup, run, check, finish

tribos, tests, out = setup(sys.argv)
# The ironing pressed in 2 steps (t = 0.25, 0.5) and slid in 2 (0.0625
# each, as in the file's step): the checks of the press (stick) and of the
# slide (slip) are counted together.
ironing = ["Time stepping/End time=1", "Time stepping/Number of steps=4",
           "Boundary conditions/Dirichlet=11 : xy : if(t < 0.5, 0, "
           "0.25*(t - 0.5)), -0.05*min(2*t, 1) ; 2 : xy : 0, 0"]
lagrange = ["Contact/Method=lagrange multiplier"]
# The faceted master and the penalty's primal form, which the defaults
# (automatic: the smoothed master and the mixed form with a deformable
# master) no longer choose here; the defaults are the last case.
faceted = ["Contact/Master smoothing=none"]
primal = ["Contact/Penalty formulation=primal"]
# Smoothed master: the neighbour nodes' columns too. 31 block cells, so
# that no slave node sits exactly over a master vertex: there the
# projection changes segment within +-h and central differences average
# the two one-sided derivatives.
smoothed = ["Contact/Master smoothing=averaged normals",
            "Scene/Cylinder over block/Block subdivisions=31, 4"]
# Mortar with the smoothed master's normals: the element's nodal normal
# reads the master nodes beyond its segments.
mortar = ["Contact/Discretization=mortar"]
for name, prm, sets in (
        ("ironing_2d", "ironing_2d", ironing + faceted + primal),
        ("sliding_blocks_3d", "sliding_blocks_3d", faceted + primal),
        ("ironing_2d lagrange", "ironing_2d", ironing + faceted + lagrange),
        ("sliding_blocks_3d lagrange", "sliding_blocks_3d",
         faceted + lagrange),
        ("ironing_2d smoothed", "ironing_2d", ironing + smoothed + primal),
        ("ironing_2d smoothed lagrange", "ironing_2d",
         ironing + smoothed + lagrange),
        ("ironing_2d mortar smoothed", "ironing_2d",
         ironing + smoothed + mortar + primal),
        ("ironing_2d mortar smoothed lagrange", "ironing_2d",
         ironing + smoothed + mortar + lagrange),
        # The defaults: the smoothed master, the penalty in mixed form.
        ("ironing_2d defaults", "ironing_2d",
         ironing + ["Scene/Cylinder over block/Block subdivisions=31, 4"]),
        ("sliding_blocks_3d defaults", "sliding_blocks_3d", [])):
    result = run(tribos, "%s/%s.prm" % (tests, prm),
                 out + "/" + name.replace(" ", "_"),
                 sets + ["Nonlinear solver/Check tangent=true"])
    errors = [float(e) for e in
              re.findall(r"tangent check, iteration \d+: relative error (\S+)",
                         result.stdout)]
    if "lagrange" in name:
        print("%s: first check, at the kink, %.2e" % (name, errors[0]))
        errors = errors[1:]
    check(len(errors) > 10 and max(errors) < 1e-6,
          "%s: %d checks, max relative tangent error %.2e < 1e-6"
          % (name, len(errors), max(errors)))
finish()
