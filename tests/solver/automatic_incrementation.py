"""Automatic incrementation (issue 74, Time stepping's Initial, Minimum and
Maximum increment, Output times, Maximum contact changes; doc/robustness.md
"Automatic incrementation"):

(1) the 2D ironing (parameters/ironing.prm) on 10 nominal steps instead of
    600, with Maximum contact changes = 0.25: it completes, lands on the
    output times 1, 1.5
    and 3.5, and its punch forces there are within 0.5 % of the 600-step
    run's (doc/data/hard_cases.csv, row ironing_600_penalty), in at most
    the 688 Newton iterations (failed attempts included) of the 150-step
    run; without the accuracy control (Maximum contact changes = 0, the
    default, as Abaqus: convergence alone sizes the increments) they are
    off by more than 0.5 % (1.2 % at t = 1): the press is a
    frictional path, and its nodes close in slip where they should stick;
(2) Initial and Maximum increment bound the increments (a sliding block on
    one nominal step): the first is the initial one, none larger than the
    maximum, and the end is reached;
(3) Minimum increment: a run that cannot converge stops once an increment
    would be cut below it, naming the entry, with exit status 2.
"""
# ctest: labels quick

import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)

# The 600-step run (benchmarks/hard_cases.py --cases ironing_600_penalty):
# the punch's vertical and horizontal reactions.
REFERENCE = {1: (-315.8708, 66.7275), 1.5: (-389.7488, 127.8409),
             3.5: (-407.8292, 133.6812)}


def at(rows, t):
    found = [r for r in rows if abs(r["time"] - t) < 1e-12]
    return found[0] if found else None


def worst_error(rows):
    worst = 0
    for t, (v, h) in REFERENCE.items():
        r = at(rows, t)
        if r is None:
            return float("inf")
        worst = max(worst, abs(r["RF13_y"] / v - 1), abs(r["RF13_x"] / h - 1))
    return worst


ironing = PARAMETERS + "/ironing.prm"
coarse = ["Time stepping/Number of steps=10",
          "Time stepping/Output times=1, 1.5, 3.5",
          "Output/Write VTU=false"]
folder = out + "/ironing_10"
run(tribos, ironing, folder,
    coarse + ["Time stepping/Maximum contact changes=0.25"])
rows = read_csv(folder + "/history.csv")
newton = sum(r["newton_iterations_all"] for r in rows)
error = worst_error(rows)
steps = sorted(set(int(r["step"]) for r in rows))
check(rows[-1]["time"] == 6 and steps == list(range(1, 14)),
      "ironing on 10 nominal steps: completed, 13 steps (10 nominal and "
      "the 3 output times), %d increments" % len(rows))
check(error < 0.005 and newton <= 688,
      "forces at t = 1, 1.5, 3.5 within %.3f %% of the 600-step run "
      "(bound 0.5 %%), %d Newton iterations (bound 688)"
      % (100 * error, newton))

folder = out + "/ironing_10_uncontrolled"
run(tribos, ironing, folder, coarse)
rows = read_csv(folder + "/history.csv")
uncontrolled = worst_error(rows)
check(uncontrolled > 0.005,
      "without the control: %.2f %% off at worst (outside the 0.5 %% the "
      "control meets)" % (100 * uncontrolled))

# (2) the bounds
folder = out + "/bounds"
run(tribos, tests + "/sliding_block.prm", folder,
    ["Time stepping/Number of steps=1",
     "Time stepping/Initial increment=0.05",
     "Time stepping/Maximum increment=0.2"])
rows = read_csv(folder + "/history.csv")
end = rows[-1]["time"]
sizes = [b["time"] - a["time"] for a, b in zip(rows, rows[1:])]
check(abs(rows[0]["time"] - 0.05 * 1) < 1e-12 and
      max(sizes) <= 0.2 + 1e-12 and max(sizes) > 0.05 + 1e-12,
      "one nominal step to t = %g: first increment %g, the largest %g "
      "(Maximum increment 0.2), %d increments"
      % (end, rows[0]["time"], max(sizes), len(rows)))

# (3) the minimum: the block compressed to zero volume at t = 1/1.2
folder = out + "/minimum"
result = run(tribos, tests + "/neo_hookean_stretch.prm", folder,
             ["Boundary conditions/Dirichlet=1 : x : -1.2*t",
              "Time stepping/Minimum increment=0.05",
              "Time stepping/Maximum cutbacks=30"], expect_success=False)
check(result.returncode == 2 and
      "(Time stepping/Minimum increment)" in result.stderr,
      "cannot converge: exit %d, %s" % (
          result.returncode, result.stderr.strip().splitlines()[-1][:160]))
finish()
