"""Load stepping: (1) an increment too large for the allowed Newton
iterations is cut back, converges in pieces, grows again, and ends on the
analytic state; the Newton iterations of the failed attempts are reported
beside the accepted ones; (2) a run that cannot converge (the block is compressed to
zero volume) stops with exit status 2 and a clear message, keeping the
converged steps' history, VTU files and a FAILED summary."""
# ctest: labels quick

import os
import re
import sys

from tribos_testing.analytic import neo_hookean_stress
from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = tests + "/neo_hookean_stretch.prm"
E, nu = 1.0, 0.3


def analytic_force(stretch):
    """Plane strain uniaxial stress of the unit block."""
    return neo_hookean_stress(stretch, E, nu, 1)


# (1) one nominal step to stretch 0.4 with at most 3 Newton iterations
# (it needs 6; the third leaves a relative residual of 1.7e-5; with 5 the
# increment converges, as the fifth meets the residual tolerance and
# gets its confirming solve)
recover = out + "/recover"
run(tribos, prm, recover, ["Boundary conditions/Dirichlet=1 : x : -0.6*t",
                           "Time stepping/Number of steps=1",
                           "Nonlinear solver/Maximum iterations=3"])
rows = read_csv(recover + "/history.csv")
exact = analytic_force(0.4)
check(rows[-1]["cutbacks"] >= 1 and len(rows) >= 2,
      "cut back %d times, converged in %d increments"
      % (rows[-1]["cutbacks"], len(rows)))
check(abs(rows[-1]["RF1_x"] - exact) < 1e-8 * abs(exact),
      "after cutbacks the reaction %.10g equals the analytic %.10g"
      % (rows[-1]["RF1_x"], exact))
# The Newton iterations of the failed attempts are counted too: each cut
# attempt spent Maximum iterations (3) solves before it was abandoned.
accepted = sum(r["newton_iterations"] for r in rows)
attempts = sum(r["newton_iterations_all"] for r in rows)
summary = open(recover + "/summary.txt").read()
reported = {key: int(value) for key, value in re.findall(
    r"^(newton iterations(?: \(all attempts\))?)\s+(\d+)$", summary, re.M)}
check(attempts == accepted + 3 * rows[-1]["cutbacks"] and
      reported == {"newton iterations": accepted,
                   "newton iterations (all attempts)": attempts},
      "iterations: %d accepted, %d with the %d failed attempts, in "
      "history.csv and summary.txt" % (accepted, attempts,
                                       rows[-1]["cutbacks"]))

# (2) compression to zero volume at t = 1/1.2: cannot converge
fail = out + "/fail"
result = run(tribos, prm, fail, [
    "Boundary conditions/Dirichlet=1 : x : -1.2*t",
    "Time stepping/Number of steps=6", "Time stepping/Maximum cutbacks=2",
    "Output/Write VTU=true"], expect_success=False)
check(result.returncode == 2, "exit status %d == 2" % result.returncode)
check("NO CONVERGENCE" in result.stderr and "Maximum cutbacks" in
      result.stderr, "message: " + result.stderr.strip().splitlines()[-1])
check("TimerOutput" not in result.stderr + result.stdout,
      "no TimerOutput warning during the failure")
rows = read_csv(fail + "/history.csv")
check(len(rows) >= 4 and rows[3]["time"] > 0.66,
      "history keeps the %d converged increments" % len(rows))
files = os.listdir(fail)
check(all("solution-%05d.vtu" % k in files for k in range(5)) and
      not any(f.endswith(".part") for f in files),
      "VTU of steps 0..4 kept, no partial files")
with open(fail + "/summary.txt") as f:
    check(f.readline().split()[1] == "FAILED:", "summary says FAILED")
finish()
