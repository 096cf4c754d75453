"""Load control on first touch (issue 44): parameters/hertz_3d_load.prm,
the quarter sphere R = 10 held by contact alone and pressed by its whole
load P = 50 000 in one step, default settings. Asserts, per run:

* the run completes without a cutback in at most 8 Newton iterations
  (every attempt counted) from the touching start, 10 from a gap of
  1e-3 R (the body floats under its load until contact closes);
* the contact carries the applied load: the same force in every run to
  1e-8 (the load is the same), within 1 % of P (quarter model: times 4;
  the faceted flat top's area is 0.64 % below pi R^2 / 4, and so is the
  load the pressure makes);
* the fitted a and p0 within 5 % of Hertz and the pressure profile's
  relative L2 error below 5 % (4.0 % measured on this mesh).

Penalty (the default) and Lagrange multipliers, both starts."""

import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish, hertz_compare

tribos, tests, out = setup(sys.argv)
prm = PARAMETERS + "/hertz_3d_load.prm"
E, nu, R, P = 2e5, 0.3, 10.0, 50e3
forces = []

for method in ("penalty", "lagrange multiplier"):
    for start, gap, limit in (("touching", 0, 8), ("gap", 1e-3 * R, 10)):
        name = "%s, %s start" % (method, start)
        folder = "%s/%s_%s" % (out, method.split()[0], start)
        run(tribos, prm, folder, [
            "Contact/Method=" + method, "Output/Write VTU=false",
            "Scene/Cylinder over block/Gap=%g" % gap])
        history = read_csv(folder + "/history.csv")
        iterations = sum(r["newton_iterations_all"] for r in history)
        cutbacks = sum(r["cutbacks"] for r in history)
        check(len(history) == 1 and cutbacks == 0 and iterations <= limit,
              "%s: one increment, %d cutbacks, %d Newton iterations "
              "(at most %d)" % (name, cutbacks, iterations, limit))
        force = 4 * history[-1]["pair0_normal_force"]
        forces.append(force)
        check(abs(force - P) <= 1e-2 * P and
              abs(force - forces[0]) <= 1e-8 * P,
              "%s: contact force %.6f (first run %.6f), load %g"
              % (name, force, forces[0], P))
        a, p0, a_h, p0_h, profile, n, _ = hertz_compare(
            folder, 3, E / (1 - nu * nu), R, 4, step=1)
        check(abs(a_h - a) / a < 0.05 and abs(p0_h - p0) / p0 < 0.05 and
              profile < 0.05 and n >= 10,
              "%s: a %.4f (Hertz %.4f), p0 %.0f (Hertz %.0f) within 5 %%, "
              "profile L2 error %.4f < 0.05, %d nodes in contact"
              % (name, a_h, a, p0_h, p0, profile, n))
finish()
