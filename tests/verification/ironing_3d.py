"""3D large frictional sliding over a smoothed master (issue 55): the 2D
shallow ironing (parameters/ironing.prm) extruded to a slab of unit depth
between symmetry planes (parameters/ironing_3d.prm), node to segment against
the foundation's top with averaged nodal normals, the penalty in its mixed
form, pressed 1 and slid 0.6 (to t = 1.3) at the 3D file's step (300 steps
over t in [0, 6]).

Asserts:
* the 3D run completes without a cutback, in at most 6 Newton iterations
  per step on average (failed attempts included);
* its punch forces per unit depth equal the 2D run's (the slab is a
  plane-strain model): vertical and horizontal within 2 % at t = 1, 1.2
  and 1.3 (the 2D run at its own step, 0.01);
* with Lagrange multipliers the same, within 2 % of the penalty run's 3D
  forces;
* the 2D run (smoothed master, penalty) completes the full 1 mm press and
  the first 0.6 mm of sliding (past the 0.44 mm where the faceted master
  stops), with an apparent friction ratio Fx/Fy of the punch near mu
  (0.2 to 0.5; the check of tests/robustness/robustness.py's ironing, whose
  penalty run this is).
Before the smoothed 3D master (Master smoothing was 2D only) the faceted
run stopped at t = 1.22 after 6 cutbacks with the residual stalled at a
face edge.
"""

import sys

from tribos_testing import (PARAMETERS, setup, run, read_csv, check, finish,
                            iteration_budget)

tribos, tests, out = setup(sys.argv)
parameters = PARAMETERS + "/"
END = 1.3
TIMES = (1.0, 1.2, 1.3)


def forces(folder, vertical, horizontal):
    rows = read_csv(folder + "/history.csv")
    result = {}
    for t in TIMES:
        row = [r for r in rows if abs(r["time"] - t) < 1e-9][-1]
        result[t] = (abs(row[vertical]), abs(row[horizontal]))
    return rows, result


folder_2d = out + "/ironing_2d"
run(tribos, parameters + "ironing.prm", folder_2d,
    ["Time stepping/End time=%g" % END,
     "Time stepping/Number of steps=%d" % round(END / 0.01),
     "Output/Write VTU=false"])
rows_2d, reference = forces(folder_2d, "RF13_y", "RF13_x")
iteration_budget("ironing_t1.3_penalty", folder_2d)
ratio = abs(rows_2d[-1]["RF13_x"] / rows_2d[-1]["RF13_y"])
check(rows_2d[-1]["time"] > 1.299 and 0.2 < ratio < 0.5,
      "ironing, penalty: press and 0.6 mm sliding complete, apparent "
      "friction ratio Fx/Fy = %.3f (mu = 0.3)" % ratio)

n_steps = round(END / 0.02)
results = {}
for method, sets in (("penalty", []),
                     ("lagrange", ["Contact/Method=lagrange multiplier"])):
    folder = out + "/ironing_3d_" + method
    run(tribos, parameters + "ironing_3d.prm", folder,
        ["Time stepping/End time=%g" % END,
         "Time stepping/Number of steps=%d" % n_steps,
         "Output/Write VTU=false"] + sets)
    rows, results[method] = forces(folder, "RF15_z", "RF15_x")
    iteration_budget("ironing_3d_t1.3_" + method, folder)
    cutbacks = sum(max(r["cutbacks"] for r in rows if r["step"] == s)
                   for s in set(r["step"] for r in rows))
    newton = sum(r["newton_iterations_all"] for r in rows)
    check(cutbacks == 0, "3D %s: %d cutbacks (0 expected)"
          % (method, cutbacks))
    check(newton <= 6 * n_steps,
          "3D %s: %d Newton iterations in %d steps (at most 6 per step)"
          % (method, newton, n_steps))
    for t in TIMES:
        for i, name in ((0, "vertical"), (1, "horizontal")):
            expected = reference[t][i] if method == "penalty" else \
                results["penalty"][t][i]
            error = abs(results[method][t][i] - expected) / expected
            check(error < 0.02,
                  "3D %s, %s force at t = %g: %.4f against %.4f (%s), "
                  "relative %.2e (< 2e-2)"
                  % (method, name, t, results[method][t][i], expected,
                     "2D" if method == "penalty" else "3D penalty", error))

finish()
