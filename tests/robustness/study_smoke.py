"""Smoke test of the speed-against-error study (benchmarks/study.py
--smoke): it runs, and its CSV has the documented columns, one row per run,
every run completed, numbers where numbers belong and a finite, small
Hertz error."""

import csv
import math
import os
import subprocess
import sys

from tribos_testing import REPOSITORY, setup, check, finish

tribos, tests, out = setup(sys.argv)
study = os.path.join(REPOSITORY, "benchmarks", "study.py")
result = subprocess.run([sys.executable, study, "--smoke", "--tribos", tribos,
                         "--out", out], capture_output=True, text=True)
print(result.stdout[-2000:], result.stderr[-2000:])
check(result.returncode == 0, "study.py --smoke exits with 0")
path = os.path.join(out, "study.csv")
check(os.path.exists(path), "study.csv written")
with open(path) as f:
    reader = csv.DictReader(f)
    header = reader.fieldnames
    rows = list(reader)
expected = ["scene", "variant", "method", "penalty_factor", "tangent",
            "level", "dofs", "contact_dofs", "multipliers", "load_steps",
            "increments", "newton_iterations", "iterations_per_step",
            "cutbacks", "wall_time", "t_compute", "t_assembly", "t_search",
            "t_contact_assembly", "t_linear_solve", "peak_memory_mb",
            "error", "error_a", "error_p0", "error_profile", "error_force",
            "error_reference", "max_penetration", "status"]
check(header == expected, "columns as documented")
check(len(rows) == 2, "one row per run (%d)" % len(rows))
numeric = ["dofs", "contact_dofs", "load_steps", "newton_iterations",
           "wall_time", "t_assembly", "t_linear_solve", "peak_memory_mb",
           "error", "error_a", "error_p0"]
for r in rows:
    check(r["status"] == "completed", "%s completed" % r["variant"])
    values = [float(r[c]) for c in numeric]
    check(all(math.isfinite(v) and v >= 0 for v in values),
          "%s: numeric columns finite and >= 0" % r["variant"])
    check(float(r["t_assembly"]) > 0 and float(r["t_linear_solve"]) > 0,
          "%s: summary.txt times assembly and linear solves" % r["variant"])
    check(float(r["error"]) < 0.1, "%s: Hertz error %.3f < 0.1 on the "
          "coarse smoke mesh" % (r["variant"], float(r["error"])))
    check(int(r["multipliers"]) > 0 if "lagrange" in r["method"]
          else int(r["multipliers"]) == 0, "%s: multiplier count"
          % r["variant"])
finish()
