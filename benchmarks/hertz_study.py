"""Speed against error on the Hertz scenes: mesh level x penalty factor.

    python3 benchmarks/hertz_study.py [build/tribos] [out-folder]

Runs parameters/hertz_2d.prm (rigid plane), its elastic-block variant and
parameters/hertz_3d.prm with Contact refinements and Penalty factor varied
through --set, and writes one CSV row per run to doc/data/hertz_study.csv:
scene, level, penalty factor, dofs, Newton iterations, wall time, time in
assembly / contact search / contact assembly / linear solve, errors of a
and p0 against Hertz (fit of the nodal pressures), profile L2 error and
max penetration relative to a."""

import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
from tribos_testing import run, read_csv, hertz_compare  # noqa: E402

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
tribos = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build",
                                                            "tribos")
out = sys.argv[2] if len(sys.argv) > 2 else "/tmp/tribos_hertz_study"
E, nu, R = 1.0, 0.3, 1.0

scenes = [
    ("2d_rigid", 2, "hertz_2d.prm", [], E / (1 - nu * nu), 1, [3, 4, 5, 6]),
    ("2d_block", 2, "hertz_2d.prm",
     ["Scene/Cylinder over block/With block=true", "Contact/Pairs=10 : 3",
      "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; 2 : xy : 0, 0"],
     E / (2 * (1 - nu * nu)), 1, [3, 4, 5]),
    ("3d_rigid", 3, "hertz_3d.prm", [], E / (1 - nu * nu), 4, [2, 3, 4]),
]
factors = ["10*E/h", "100*E/h", "1000*E/h", "1e4*E/h"]


def timings(folder):
    sections, values = {}, {}
    with open(folder + "/summary.txt") as f:
        for line in f:
            m = re.match(r"(\w[\w ]*?)\s{2,}(\d+)\s+([\d.e+-]+)\s+[\d.]+%", line)
            if m:
                sections[m.group(1).strip()] = float(m.group(3))
            m = re.match(r"(dofs|newton iterations)\s+(\d+)", line)
            if m:
                values[m.group(1)] = int(m.group(2))
    return sections, values


os.makedirs(os.path.join(root, "doc", "data"), exist_ok=True)
target = os.path.join(root, "doc", "data", "hertz_study.csv")
with open(target, "w", newline="") as f:
    writer = csv.writer(f)
    writer.writerow(["scene", "level", "penalty", "dofs", "newton_iterations",
                     "wall_time", "assembly", "contact_search",
                     "contact_assembly", "linear_solve", "error_a",
                     "error_p0", "profile_error", "penetration_over_a"])
    for name, dim, prm, sets, e_star, force_scale, levels in scenes:
        for level in levels:
            for factor in factors:
                folder = "%s/%s_%d_%s" % (out, name, level,
                                          factor.replace("*", "").replace("/", ""))
                result = run(tribos, os.path.join(root, "parameters", prm), folder,
                             sets + ["Scene/Cylinder over block/Contact refinements=%d" % level,
                                     "Contact/Penalty factor=" + factor,
                                     "Output/Write VTU=false"],
                             expect_success=False)
                if result.returncode != 0:
                    print("%s level %d %s: no convergence" % (name, level, factor))
                    continue
                history = read_csv(folder + "/history.csv")[-1]
                a, p0, a_h, p0_h, profile, n, P = hertz_compare(
                    folder, dim, e_star, R, force_scale)
                sections, values = timings(folder)
                wall = sum(sections.values())
                writer.writerow([name, level, factor, values["dofs"],
                                 values["newton iterations"], "%.4g" % wall,
                                 "%.4g" % sections.get("assembly", 0),
                                 "%.4g" % sections.get("contact search", 0),
                                 "%.4g" % sections.get("contact assembly", 0),
                                 "%.4g" % sections.get("linear solve", 0),
                                 "%.4g" % (abs(a_h - a) / a),
                                 "%.4g" % (abs(p0_h - p0) / p0),
                                 "%.4g" % profile,
                                 "%.4g" % (history["max_penetration"] / a)])
                f.flush()
                print(name, level, factor, values["dofs"], "%.2fs" % wall,
                      "a %.4f p0 %.4f" % (abs(a_h - a) / a, abs(p0_h - p0) / p0))
print("wrote " + target)
