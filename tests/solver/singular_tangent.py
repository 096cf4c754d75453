"""Regression: a singular first tangent must not leave the first Newton
update to the linear solver's round-off (Nonlinear solver/Tangent shift).

The 2D Hertz half cylinder of parameters/hertz_2d.prm under load control
(a traction of 0.005 E on the flat top, the top held in x, the whole load
in one increment): the first iterate rests on the one frictionless node at
the bottom, and the cylinder can still turn about the centre of its top
(the top's nodes then move vertically, the bottom node horizontally).
The tangent is singular; without the shift the direct solver returned an
arbitrary amount of that turn, and which amount depended on the dof
numbering: Contact refinements = 3 took 121 Newton iterations on the
shared mesh and 13 on the distributed one (at 6, 10 and 44; 5.3 and 12.7
for the first update's norm). Asserts, on both meshes and at two
refinements: the first update the same to 1e-8, at most 8 Newton
iterations, no cutback, and the contact force equal to the load.
"""

import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = PARAMETERS + "/hertz_2d.prm"
traction, width = 0.005, 2.0
for level in (3, 4):
    first = {}
    for mesh in ("shared", "distributed"):
        folder = "%s/L%d_%s" % (out, level, mesh)
        run(tribos, prm, folder, [
            "Scene/Cylinder over block/Contact refinements=%d" % level,
            "Boundary conditions/Dirichlet=11 : x : 0",
            "Boundary conditions/Neumann=11 : 0, -%g*t" % traction,
            "Time stepping/Number of steps=1", "Output/Write VTU=false",
            "Parallel/Mesh=" + mesh])
        iterations = [r for r in read_csv(folder + "/convergence.csv")
                      if r["iteration"] > 0]
        # The linear solve's answer (the step taken is that times the
        # penetration limit's length, which interpolates gaps).
        first[mesh] = iterations[0]["correction_norm"]
        h = read_csv(folder + "/history.csv")[-1]
        force = abs(h["pair0_Fy"])
        check(h["cutbacks"] == 0 and len(iterations) <= 8 and
              abs(force - traction * width) < 1e-6 * traction * width,
              "level %d, %s mesh: %d Newton iterations, no cutback, contact "
              "force %.10f (load %.10f), first update %.9f"
              % (level, mesh, len(iterations), force, traction * width,
                 first[mesh]))
    spread = abs(first["shared"] - first["distributed"]) / first["shared"]
    check(spread < 1e-8,
          "level %d: the first update does not depend on the dof numbering "
          "(%.1e relative)" % (level, spread))
finish()
