"""Adaptivity against hand-graded and uniform meshes (issue 58); writes
doc/data/adaptivity_hertz.csv, doc/data/adaptivity_ironing.csv and (with
gnuplot) doc/adaptivity_error_vs_dofs.png, doc/adaptivity_error_vs_time.png.

    python3 benchmarks/adaptivity.py build/tribos /tmp/adaptivity   # ~10 min

Hertz 2D (parameters/hertz_2d.prm, penalty 100 E/h, displacement
control): the pressure profile's relative L2 error against the converged
profile (reference_error: tests/data/hertz_2d_reference_pressure.csv, the
graded scene at Contact refinements 8, 743 934 dofs) and against Hertz
(profile_error, the fit of tests/tribos_testing: P from the contact force;
it does not converge on this finite scene), and the wall time of the
whole run (all adaptation cycles included; the process's, median of
three) for
  uniform  - Contact refinements 0, Scene/Refinement 1..4;
  graded   - the scene's hand grading, Contact refinements 1..7;
  adaptive - from the coarse scene (Contact refinements 0), Refine
             fraction 0.15, the default Contact zone depth (0.25),
             Initial cycles = Maximum level + 1, Maximum level 4..9;
  indicator_only - the same with Contact zone depth 0 (the indicator
             alone decides), Refine fraction 0.3, Maximum level 4..10.
Ironing 2D (parameters/ironing.prm at 150 steps): the run on the scene's
mesh refined once everywhere (Scene/Refinement = 1, 120 x 40 and 24 x 24
cells) against adaptive runs from the mesh two levels coarser (15 x 5 and
3 x 3, Maximum level 3, finest cells those of the fine run), adapted after
every step or every 5: the largest relative difference of V and H at
t = 0.52, 1, 1.52, 2.52, 3.52, 5, 6 and of those from t = 1.52 on (the
punch sliding), mean dofs, wall time (median of three), Newton iterations, adaptations and
redone increments."""

import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests"))
from tribos_testing import (read_csv, hertz_compare,  # noqa: E402
                            profile_difference)

tribos, work = sys.argv[1], sys.argv[2]
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
os.makedirs(work, exist_ok=True)


def run(prm, folder, sets, repeats=1):
    seconds = []
    for _ in range(repeats):
        command = [tribos, prm, "--set", "Output/Directory=" + folder,
                   "--set", "Output/Write VTU=false"]
        for s in sets:
            command += ["--set", s]
        start = time.perf_counter()
        subprocess.run(command, check=True, capture_output=True)
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds)


def summary(folder, key):
    for line in open(folder + "/summary.txt"):
        if line.startswith(key + " "):
            return int(line[len(key):].split()[0])
    return 0


hertz = os.path.join(root, "parameters/hertz_2d.prm")
E, nu, R = 1.0, 0.3, 1.0
reference = read_csv(os.path.join(
    root, "tests/data/hertz_2d_reference_pressure.csv"))
rows = ["kind,level,dofs,cells,adaptations,wall_s,profile_error,p0_error,"
        "a_error,reference_error"]
cases = [("uniform", n, ["Scene/Cylinder over block/Contact refinements=0",
                         "Scene/Refinement=%d" % n]) for n in range(1, 5)]
cases += [("graded", n, ["Scene/Cylinder over block/Contact refinements=%d"
                         % n]) for n in range(1, 8)]
adaptive = ["Scene/Cylinder over block/Contact refinements=0",
            "Adaptivity/Enable=true"]
cases += [("adaptive", n, adaptive + ["Adaptivity/Maximum level=%d" % n,
                                      "Adaptivity/Initial cycles=%d" % (n + 1),
                                      "Adaptivity/Refine fraction=0.15"])
          for n in range(4, 10)]
cases += [("indicator_only", n, adaptive + [
    "Adaptivity/Maximum level=%d" % n,
    "Adaptivity/Initial cycles=%d" % (n + 1),
    "Adaptivity/Refine fraction=0.3", "Adaptivity/Contact zone depth=0"])
    for n in range(4, 11)]
for kind, level, sets in cases:
    folder = "%s/hertz_%s_%d" % (work, kind, level)
    wall = run(hertz, folder, sets, repeats=3)
    a, p0, a_h, p0_h, profile, n, P = hertz_compare(
        folder, 2, E / (1 - nu * nu), R, 1)
    error = profile_difference(read_csv(folder + "/contact-00002.csv"),
                               reference)
    rows.append("%s,%d,%d,%d,%d,%.4f,%.5f,%.5f,%.5f,%.5f" % (
        kind, level, summary(folder, "dofs"), summary(folder, "cells"),
        summary(folder, "adaptations"), wall, profile, abs(p0_h / p0 - 1),
        abs(a_h / a - 1), error))
    print(rows[-1], flush=True)
with open(os.path.join(root, "doc/data/adaptivity_hertz.csv"), "w") as f:
    f.write("\n".join(rows) + "\n")

ironing = os.path.join(root, "parameters/ironing.prm")
common = ["Time stepping/Number of steps=150"]
coarse = ["Scene/Two blocks/Lower subdivisions=15, 5",
          "Scene/Two blocks/Upper subdivisions=3, 3",
          "Adaptivity/Enable=true", "Adaptivity/Maximum level=3"]
runs = [("fine", common + ["Scene/Refinement=1"]),
        ("adaptive_every_1", common + coarse),
        ("adaptive_every_5", common + coarse + ["Adaptivity/Every=5"])]
results, folders = {}, {}
for name, sets in runs:
    folder = folders[name] = "%s/ironing_%s" % (work, name)
    wall = run(ironing, folder, sets, repeats=3)
    history = read_csv(folder + "/history.csv")
    dofs = [r["dofs"] for r in history] if "dofs" in history[0] else \
        [summary(folder, "dofs")] * len(history)
    results[name] = (wall, history, sum(dofs) / len(dofs))
fine = {round(r["time"], 6): r for r in results["fine"][1]}
rows = ["run,mean_dofs,wall_s,newton_iterations,max_V_error,max_H_error,"
        "dofs_ratio,time_ratio,sliding_V_error,sliding_H_error,adaptations,"
        "redone_increments"]
for name, (wall, history, mean_dofs) in results.items():
    by_time = {round(r["time"], 6): r for r in history}
    errors, sliding = {}, {}
    for force in ("RF13_y", "RF13_x"):
        errors[force] = max(abs(by_time[t][force] / fine[t][force] - 1)
                            for t in (0.52, 1.0, 1.52, 2.52, 3.52, 5.0, 6.0))
        sliding[force] = max(abs(by_time[t][force] / fine[t][force] - 1)
                             for t in (1.52, 2.52, 3.52, 5.0, 6.0))
    rows.append("%s,%.0f,%.2f,%d,%.5f,%.5f,%.3f,%.3f,%.5f,%.5f,%d,%d" % (
        name, mean_dofs, wall, sum(r["newton_iterations"] for r in history),
        errors["RF13_y"], errors["RF13_x"],
        mean_dofs / results["fine"][2], wall / results["fine"][0],
        sliding["RF13_y"], sliding["RF13_x"],
        summary(folders[name], "adaptations"),
        summary(folders[name], "redone increments")))
    print(rows[-1], flush=True)
with open(os.path.join(root, "doc/data/adaptivity_ironing.csv"), "w") as f:
    f.write("\n".join(rows) + "\n")
