"""Regression: run tests/<name>.prm and compare its history.csv with
tests/<name>.reference.csv: every number through numdiff except the
columns that depend on round-off or the clock (final residual, wall
time); Newton iteration counts as a range (+-1 per step).
Set TRIBOS_UPDATE_REFERENCES=1 to rewrite the reference after a change
that is understood and intended."""
# ctest: labels quick

import os
import shutil
import sys

from tribos_testing import updating_references, reference_updated, setup, run, strip_columns, numdiff, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
name = sys.argv[4]
run(tribos, "%s/%s.prm" % (tests, name), out)
reference = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                         name + ".reference.csv")
if updating_references():
    strip_columns(out + "/history.csv", reference, drop=("wall_time",))
    reference_updated(reference)
    finish()

noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all")
strip_columns(out + "/history.csv", out + "/result.csv", drop=noisy)
strip_columns(reference, out + "/reference.csv", drop=noisy)
numdiff(out + "/result.csv", out + "/reference.csv", relative=1e-6,
        absolute=1e-9)
print("ok      history matches %s within 1e-6 relative" % reference)

result_rows, reference_rows = read_csv(out + "/history.csv"), read_csv(reference)
check(len(result_rows) == len(reference_rows),
      "%d converged increments, reference %d"
      % (len(result_rows), len(reference_rows)))
for a, b in zip(result_rows, reference_rows):
    check(abs(a["newton_iterations"] - b["newton_iterations"]) <= 1,
          "increment %d: %d Newton iterations, reference %d (+-1)"
          % (a["increment"], a["newton_iterations"], b["newton_iterations"]))
finish()
