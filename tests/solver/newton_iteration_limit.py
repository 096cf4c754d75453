"""Nonlinear solver/Maximum iterations must not cut back an increment whose
residual has already met its tolerance and which only needs the one more
solve that confirms the update: Newton's last iteration of a converging
increment typically brings the residual to round-off while the update that
got it there is still above the increment tolerance. (3D Hertz, 226k dofs,
penalty: the 20th iteration had |R| = 2e-15 relative and the increment was
cut back.) The scene runs once with the defaults; then with Maximum
iterations one less than the largest count of any increment, where that
increment's second-last iteration met the residual tolerance: the run must
take no cutback and give the same history."""
# ctest: labels quick

import sys

from tribos_testing import (PARAMETERS, setup, run, read_csv, strip_columns, numdiff,
                         check, finish)

tribos, tests, out = setup(sys.argv)
prm = PARAMETERS + "/hertz_2d.prm"
sets = ["Scene/Cylinder over block/Contact refinements=3",
        "Output/Write VTU=false"]
run(tribos, prm, out + "/default", sets)
history = read_csv(out + "/default/history.csv")
convergence = read_csv(out + "/default/convergence.csv")
largest = max(int(r["newton_iterations"]) for r in history)
worst = [r for r in history if int(r["newton_iterations"]) == largest][0]
rows = [r for r in convergence if r["step"] == worst["step"] and
        r["increment"] == worst["increment"]]
second_last = [r for r in rows if int(r["iteration"]) == largest - 1][0]
check(second_last["relative_residual"] <= 1e-8,
      "step %d: iteration %d of %d already meets the residual tolerance "
      "(relative residual %.1e)" % (worst["step"], largest - 1, largest,
                                    second_last["relative_residual"]))

limited = out + "/limited"
run(tribos, prm, limited,
    sets + ["Nonlinear solver/Maximum iterations=%d" % (largest - 1)])
cutbacks = sum(int(r["cutbacks"]) for r in read_csv(limited + "/history.csv"))
check(cutbacks == 0, "Maximum iterations = %d: %d cutbacks (expected 0: "
      "the confirming solve is not cut)" % (largest - 1, cutbacks))
noisy = ("wall_time", "residual")
strip_columns(out + "/default/history.csv", out + "/a.csv", drop=noisy)
strip_columns(limited + "/history.csv", out + "/b.csv", drop=noisy)
numdiff(out + "/b.csv", out + "/a.csv", relative=1e-10, absolute=1e-14)
print("ok      the same history")
finish()
