#!/usr/bin/env python3
"""Speed against error: runs families of variants of the verification
scenes through `tribos --set ...` and writes one CSV row per run.

    python3 benchmarks/study.py                 # default study (~12 min)
    python3 benchmarks/study.py --full          # adds finer meshes (~40 min)
    python3 benchmarks/study.py --smoke --out /tmp/smoke   # CI: seconds
    python3 benchmarks/study.py --plots-only    # redraw from doc/data/study.csv
    python3 benchmarks/study.py --mortar        # node to segment vs mortar
                                                # (~3 min) -> study_mortar.csv

Default output: doc/data/study.csv and the plots doc/study_*.png (gnuplot),
which doc/benchmarks.md shows. Every number in doc/benchmarks.md comes from
this command. Columns:

  scene, variant, method, penalty_factor, tangent, level, dofs,
  contact_dofs, multipliers, load_steps, increments, newton_iterations,
  iterations_per_step, cutbacks, wall_time, t_compute, t_assembly, t_search,
  t_contact_assembly, t_linear_solve, peak_memory_mb, error, error_a,
  error_p0, error_profile, error_force, error_reference, max_penetration,
  status

`error` is the scene's headline error: Hertz max(|a error|, |p0 error|)
against the analytic values for the run's load; cylinder |force error| at
the last step against the analytic homogeneous compression; ring |final
foundation reaction - reference| / reference with the finest Lagrange run
of the study as reference (error_reference, --mortar only: the Hertz
pressures against a run two levels finer); modelling choices: the quantity each pair
compares (see doc/benchmarks.md). Wall time is that of the process (start
to exit, ~0.7 s of it loading libraries and MPI), t_compute the sum of the
timer sections (setup, assembly, search, solve, output), peak memory the
process's maximum resident set size.
"""

import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from tribos_testing.analytic import cylinder_force, hertz, polygon_section  # noqa: E402
from tribos_testing import hertz_fit  # noqa: E402

COLUMNS = ["scene", "variant", "method", "penalty_factor", "tangent", "level",
           "dofs", "contact_dofs", "multipliers", "load_steps", "increments",
           "newton_iterations", "iterations_per_step", "cutbacks",
           "wall_time", "t_compute", "t_assembly", "t_search",
           "t_contact_assembly",
           "t_linear_solve", "peak_memory_mb", "error", "error_a",
           "error_p0", "error_profile", "error_force", "error_reference",
           "max_penetration", "status"]

METHODS = {"10E/h": ("penalty", "10"), "100E/h": ("penalty", "100"),
           "1000E/h": ("penalty", "1000"), "1e4E/h": ("penalty", "10000"),
           "lagrange": ("lagrange multiplier", ""),
           "augmented": ("augmented lagrangian", "")}


def method_sets(key):
    method, factor = METHODS[key]
    sets = ["Contact/Method=" + method]
    if factor:
        sets.append("Contact/Penalty factor=%s*E/h" % factor)
    return sets


def run(tribos, prm, folder, sets):
    """Run tribos; return (wall time, peak RSS in MB, exit status)."""
    shutil.rmtree(folder, ignore_errors=True)
    command = [tribos, os.path.join(ROOT, prm), "--set",
               "Output/Directory=" + folder, "--set", "Output/Write VTU=false"]
    for s in sets:
        command += ["--set", s]
    start = time.time()
    with open(os.devnull, "w") as null:
        process = subprocess.Popen(command, stdout=null, stderr=null)
        _, status, usage = os.wait4(process.pid, 0)
    wall = time.time() - start
    return wall, usage.ru_maxrss / 1024.0, os.waitstatus_to_exitcode(status)


def summary(folder):
    """Sizes and timer sections from summary.txt."""
    text = open(os.path.join(folder, "summary.txt")).read()
    value = lambda key: int(re.search(r"^%s\s+(\d+)" % key, text, re.M)
                            .group(1))
    section = lambda name: float(m.group(1)) if (m := re.search(
        r"^%s\s+\d+\s+([\d.]+)" % name, text, re.M)) else 0.0
    total = sum(float(x) for x in re.findall(
        r"^\S[\w ]*?\s+\d+\s+([\d.]+)\s+[\d.]+%", text, re.M))
    return {"dofs": value("dofs"), "contact_dofs": value("contact dofs"),
            "t_compute": "%.4f" % total,
            "multipliers": value("multipliers"),
            "t_assembly": section("assembly"),
            "t_search": section("contact search"),
            "t_contact_assembly": section("contact assembly"),
            "t_linear_solve": section("linear solve")}


def history(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def record(rows, scene, variant, prm, folder, sets, error_of, level="",
           method="", factor="", tangent="consistent", tribos=None):
    """Run one variant and append its row (error_of(folder) -> dict)."""
    wall, memory, status = run(tribos, prm, folder, sets)
    row = {c: "" for c in COLUMNS}
    row.update(scene=scene, variant=variant, method=method,
               penalty_factor=factor, tangent=tangent, level=level,
               wall_time="%.3f" % wall, peak_memory_mb="%.1f" % memory,
               status="completed" if status == 0 else "failed(%d)" % status)
    if os.path.exists(os.path.join(folder, "summary.txt")):
        row.update(summary(folder))
    if status == 0:
        h = history(folder)
        steps = int(h[-1]["step"])
        iterations = sum(r["newton_iterations"] for r in h)
        row.update(load_steps=steps, increments=len(h),
                   newton_iterations=int(iterations),
                   iterations_per_step="%.2f" % (iterations / steps),
                   cutbacks=sum(1 for r in h if r["cutbacks"] > 0),
                   max_penetration="%.3e" % max(
                       (r.get("max_penetration", 0.0) for r in h),
                       default=0.0))
        for key, value in error_of(folder, h).items():
            row[key] = "%.4e" % value
    rows.append(row)
    print("%-14s %-28s %8s dofs %7.2f s  error %s  %s"
          % (scene, variant, row["dofs"], wall, row["error"], row["status"]),
          flush=True)


def hertz_errors(dim, e_star, force_scale, radius=1.0):
    def errors(folder, h):
        P = h[-1]["pair0_normal_force"] * force_scale
        a, p0 = hertz(P, radius, e_star, dim)
        step = int(h[-1]["step"])
        with open(os.path.join(folder, "contact-%05d.csv" % step)) as f:
            nodes = [{k: float(v) if v not in ("", "nan") else math.nan
                      for k, v in r.items()} for r in csv.DictReader(f)]
        try:
            p0_h, a_h, points = hertz_fit(nodes, dim)
        except ValueError:
            # The pressures are not a Hertz ellipse at all (p^2 has no
            # positive intercept): no error to report.
            print("    (no Hertz fit of the pressures of %s)" % folder)
            return {}
        profile = math.sqrt(sum(
            (p - p0 * math.sqrt(max(0.0, 1 - x * x / (a * a)))) ** 2
            for x, p in points) / sum(p * p for x, p in points))
        ea, ep = abs(a_h - a) / a, abs(p0_h - p0) / p0
        return {"error": max(ea, ep), "error_a": ea, "error_p0": ep,
                "error_profile": profile}
    return errors


def cylinder_analytic(k):
    """Force on the 1/8 model (8-chord section) after k steps of 0.2 mm."""
    return cylinder_force(k, polygon_section(6.35, 8))


def cylinder_errors(axisymmetric=False):
    def errors(folder, h):
        k = int(h[-1]["step"])
        if axisymmetric:  # full section -> the 1/8 model's polygon
            F = abs(h[-1]["pair0_Fy"]) * 4 * math.sin(math.pi / 16) / math.pi
        else:
            F = abs(h[-1]["pair0_Fz"])
        e = abs(F / cylinder_analytic(k) - 1)
        return {"error": e, "error_force": e}
    return errors


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--out", default=None,
                        help="folder for study.csv and the runs (default: "
                        "doc/data, runs in /tmp)")
    level = parser.add_mutually_exclusive_group()
    level.add_argument("--full", action="store_true")
    level.add_argument("--smoke", action="store_true")
    level.add_argument("--plots-only", action="store_true",
                       help="redraw the plots from an existing study.csv")
    level.add_argument("--mortar", action="store_true",
                       help="node to segment against mortar only "
                       "(study_mortar.csv)")
    args = parser.parse_args()
    if args.plots_only:
        plots(args.out or os.path.join(ROOT, "doc", "data"))
        return
    work = os.path.join(args.out or "/tmp", "tribos_study_runs")
    data = args.out or os.path.join(ROOT, "doc", "data")
    os.makedirs(work, exist_ok=True)
    os.makedirs(data, exist_ok=True)
    rows = []
    go = lambda *a, **k: record(rows, *a, tribos=args.tribos, **k)
    if args.mortar:
        mortar_study(go, work)
        write(rows, data, "study_mortar.csv")
        return

    E, nu = 1.0, 0.3
    hertz2 = "parameters/hertz_2d.prm"
    rigid2 = hertz_errors(2, E / (1 - nu * nu), 1)
    levels = [2] if args.smoke else ([3, 4, 5, 6] if args.full else
                                     [3, 4, 5])
    methods = ["1000E/h", "lagrange"] if args.smoke else list(METHODS)
    # Hertz 2D: method x mesh level (Contact refinements).
    for lv in levels:
        for m in methods:
            go("hertz_2d", "%s L%d" % (m, lv), hertz2,
               os.path.join(work, "hertz2d_%s_%d" % (m, lv)),
               method_sets(m) + ["Scene/Cylinder over block/Contact "
                                 "refinements=%d" % lv], rigid2, level=lv,
               method=METHODS[m][0], factor=METHODS[m][1])
        if not args.smoke:
            go("hertz_2d", "1000E/h paper tangent L%d" % lv, hertz2,
               os.path.join(work, "hertz2d_paper_%d" % lv),
               method_sets("1000E/h") + [
                   "Contact/Tangent=paper",
                   "Scene/Cylinder over block/Contact refinements=%d" % lv],
               rigid2, level=lv, method="penalty", factor="1000",
               tangent="paper")
    if args.smoke:
        write(rows, data)
        return

    # Hertz 3D (quarter sphere): two mesh levels, penalty (AMG) and
    # Lagrange (direct).
    hertz3 = "parameters/hertz_3d.prm"
    rigid3 = hertz_errors(3, E / (1 - nu * nu), 4)
    for lv in ([2, 3, 4] if args.full else [2, 3]):
        for m in ("1000E/h", "lagrange"):
            extra = ["Linear solver/Type=direct"] if m == "lagrange" else []
            go("hertz_3d", "%s L%d" % (m, lv), hertz3,
               os.path.join(work, "hertz3d_%s_%d" % (m, lv)),
               method_sets(m) + extra + [
                   "Scene/Cylinder over block/Contact refinements=%d" % lv],
               rigid3, level=lv, method=METHODS[m][0], factor=METHODS[m][1])

    # Cylinder compression: every method on the paper's mesh.
    cylinder = "parameters/cylinder_compression.prm"
    for m in METHODS:
        go("cylinder", m, cylinder, os.path.join(work, "cylinder_" + m),
           method_sets(m), cylinder_errors(), method=METHODS[m][0],
           factor=METHODS[m][1])

    # Ring: penalty 1e5 (the paper's), Lagrange, augmented on two (full:
    # three) meshes; reference = the finest Lagrange run.
    ring = "parameters/ring_on_foundation.prm"
    ring_levels = [0, 1, 2] if args.full else [0, 1]
    ring_runs = []
    for lv in ring_levels:
        for m, sets in (("penalty 1e5", ["Contact/Method=penalty"]),
                        ("lagrange", method_sets("lagrange")),
                        ("augmented", method_sets("augmented"))):
            folder = os.path.join(work, "ring_%s_%d" % (m.split()[0], lv))
            ring_runs.append((len(rows), folder))
            go("ring", "%s L%d" % (m, lv), ring, folder,
               sets + ["Scene/Refinement=%d" % lv], lambda f, h: {},
               level=lv, method=sets[0].split("=")[1],
               factor="1e5" if m.startswith("penalty") else "")
    reference = history(os.path.join(
        work, "ring_lagrange_%d" % ring_levels[-1]))[-1]["RF12_y"]
    for index, folder in ring_runs:
        if rows[index]["status"] == "completed":
            e = abs(history(folder)[-1]["RF12_y"] / reference - 1)
            rows[index]["error"] = rows[index]["error_force"] = "%.4e" % e

    # Modelling choices: each pair is valid for its scene; the error
    # columns say what each buys.
    block2 = ["Scene/Cylinder over block/With block=true",
              "Contact/Pairs=10 : 3",
              "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; "
              "2 : xy : 0, 0"]
    stiff = E / (1 - nu * nu) / (1 + E / 1e4)  # E* with a 1e4 E block
    go("choice_plate", "rigid analytic plane", hertz2,
       os.path.join(work, "choice_rigid"), method_sets("1000E/h"), rigid2)
    go("choice_plate", "meshed plate E_plate = 1e4 E", hertz2,
       os.path.join(work, "choice_meshed"), method_sets("1000E/h") + block2 +
       ["Materials/Young's modulus=1, 1e4"],
       hertz_errors(2, 1 / ((1 - nu * nu) / E + (1 - nu * nu) / 1e4), 1))
    go("choice_axisymmetry", "3D 1/8 model", cylinder,
       os.path.join(work, "choice_3d"), method_sets("1000E/h"),
       cylinder_errors())
    go("choice_axisymmetry", "2D axisymmetric",
       "parameters/cylinder_compression_axisymmetric.prm",
       os.path.join(work, "choice_axisymmetric"), method_sets("1000E/h"),
       cylinder_errors(axisymmetric=True))
    for model in ("linear elastic", "neo-Hookean"):
        go("choice_strain", model, hertz2,
           os.path.join(work, "choice_" + model.split()[0]),
           method_sets("1000E/h") + ["Materials/Model=" + model], rigid2)
    go("choice_plasticity", "neo-Hookean (no history)", hertz2,
       os.path.join(work, "choice_elastic"),
       method_sets("1000E/h") + block2 + ["Materials/Model=neo-Hookean"],
       hertz_errors(2, E / (2 * (1 - nu * nu)), 1))
    go("choice_plasticity", "J2 plasticity yield never reached", hertz2,
       os.path.join(work, "choice_j2"),
       method_sets("1000E/h") + block2 + ["Materials/Model=J2 plasticity",
                                        "Materials/Yield stress=1e6",
                                        "Materials/Saturation yield "
                                        "stress=1e6"],
       hertz_errors(2, E / (2 * (1 - nu * nu)), 1))
    for mu in ("0", "0.3"):
        go("choice_friction", "mu = " + mu, hertz2,
           os.path.join(work, "choice_mu" + mu), method_sets("1000E/h") +
           block2 + ["Contact/Friction coefficient=" + mu],
           hertz_errors(2, E / (2 * (1 - nu * nu)), 1))
    write(rows, data)
    plots(data)


def mortar_study(go, work):
    """Node to segment against mortar (2D, deformable master): Hertz on an
    elastic block over three contact refinements (penalty 1000 E/h and
    multipliers; against Hertz and against a reference two levels finer), the frictional ironing of tests/data/ironing_2d.prm (Newton
    iterations) and the contact patch test (pressure spread in error)."""
    E, nu = 1.0, 0.3
    hertz2 = "parameters/hertz_2d.prm"
    block2 = ["Scene/Cylinder over block/With block=true",
              "Contact/Pairs=10 : 3",
              "Boundary conditions/Dirichlet=11 : xy : 0, -0.01*t ; "
              "2 : xy : 0, 0"]
    hertz_block = hertz_errors(2, E / (2 * (1 - nu * nu)), 1)
    # Reference: mortar with multipliers two levels finer than the finest
    # compared (182k dofs, about a minute); error_reference is the relative
    # L2 difference of the nodal pressures from it (linear interpolation of
    # the reference's nodal pressures along x), the discretization error
    # without Hertz's half-space idealization.
    reference = os.path.join(work, "mortar_hertz_reference_7")
    go("mortar_hertz_block", "reference mortar lagrange L7", hertz2,
       reference, method_sets("lagrange") + block2 + [
           "Contact/Discretization=mortar",
           "Scene/Cylinder over block/Contact refinements=7"], hertz_block,
       level=7, method="lagrange multiplier")
    with open(os.path.join(reference, "contact-00002.csv")) as f:
        ref = sorted((float(r["x"]), float(r["CPRESS"]))
                     for r in csv.DictReader(f))

    def p_ref(x):
        for (x0, p0), (x1, p1) in zip(ref, ref[1:]):
            if x0 <= x <= x1:
                return p0 + (p1 - p0) * (x - x0) / (x1 - x0)
        return 0.0

    def on_block(folder, h):
        errors = hertz_block(folder, h)
        with open(os.path.join(folder, "contact-00002.csv")) as f:
            nodes = [(float(r["x"]), float(r["CPRESS"]))
                     for r in csv.DictReader(f)]
        num = sum((p - p_ref(x)) ** 2 for x, p in nodes)
        den = sum(p_ref(x) ** 2 for x, p in nodes)
        errors["error_reference"] = math.sqrt(num / den)
        return errors

    discretizations = ("node to segment", "mortar")
    for lv in (3, 4, 5):
        for d in discretizations:
            for m in ("1000E/h", "lagrange"):
                go("mortar_hertz_block", "%s %s L%d" % (d, m, lv), hertz2,
                   os.path.join(work, "mortar_hertz_%s_%s_%d" % (
                       d.split()[0], m, lv)),
                   method_sets(m) + block2 + [
                       "Contact/Discretization=" + d,
                       "Scene/Cylinder over block/Contact refinements=%d"
                       % lv], on_block, level=lv, method=METHODS[m][0],
                   factor=METHODS[m][1])
    for d in discretizations:
        for m in ("10E/h", "lagrange"):
            go("mortar_ironing_2d", "%s %s" % (d, m), "tests/data/ironing_2d.prm",
               os.path.join(work, "mortar_ironing_%s_%s" % (d.split()[0], m)),
               method_sets(m) + ["Contact/Discretization=" + d],
               lambda f, h: {}, method=METHODS[m][0], factor=METHODS[m][1])

    def spread(folder, h):
        with open(os.path.join(folder, "contact-00001.csv")) as f:
            p = [float(r["CPRESS"]) for r in csv.DictReader(f)]
        return {"error": (max(p) - min(p)) / (sum(p) / len(p))}
    for d in discretizations:
        for pair in ("12 : 3", "3 : 12"):
            go("mortar_patch", "%s slave %s" % (d, pair.split()[0]),
               "tests/data/patch_test.prm",
               os.path.join(work, "mortar_patch_%s_%s" % (d.split()[0],
                                                          pair[0])),
               method_sets("lagrange") + ["Contact/Discretization=" + d,
                                          "Contact/Pairs=" + pair],
               spread, method="lagrange multiplier")


def write(rows, data, name="study.csv"):
    path = os.path.join(data, name)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    print("wrote " + path)


def plots(data):
    """Pareto (error vs wall time), penalty convergence and cost growth."""
    rows = list(csv.DictReader(open(os.path.join(data, "study.csv"))))
    ok = [r for r in rows if r["status"] == "completed" and r["error"]]
    by = lambda scene: [r for r in ok if r["scene"] == scene]
    tables = {}
    for scene in ("hertz_2d", "hertz_3d", "cylinder", "ring"):
        tables[scene] = os.path.join(data, "study_%s.dat" % scene)
        with open(tables[scene], "w") as f:
            for m in ("penalty", "lagrange multiplier",
                      "augmented lagrangian"):
                # (a NaN line keeps an empty block an index of its own)
                f.write("NaN NaN none\n")
                for r in by(scene):
                    if r["method"] == m and r["tangent"] == "consistent":
                        f.write("%s %s %s\n" % (r["wall_time"],
                                                max(float(r["error"]), 1e-16),
                                                r["variant"].replace(" ", "_")))
                f.write("\n\n")
            # The Pareto front: runs no other run beats in both time and
            # error.
            points = sorted((float(r["wall_time"]), max(float(r["error"]),
                                                        1e-16))
                            for r in by(scene))
            best = math.inf
            for t, e in points:
                if e < best:
                    f.write("%g %g front\n" % (t, e))
                    best = e
            f.write("\n\n")
    # Penalty error and iterations vs eps_N (finest default Hertz level,
    # cylinder).
    finest = max(int(r["level"]) for r in by("hertz_2d"))
    with open(os.path.join(data, "study_penalty.dat"), "w") as f:
        for scene, level in (("hertz_2d", str(finest)), ("cylinder", "")):
            for r in by(scene):
                if r["method"] == "penalty" and r["level"] == level and \
                        r["tangent"] == "consistent":
                    f.write("%s %s %s\n" % (r["penalty_factor"], r["error"],
                                            r["newton_iterations"]))
            f.write("\n\n")
    # Cost growth: fit t_compute ~ dofs^k over the Hertz 2D levels.
    fits = {}
    with open(os.path.join(data, "study_cost.dat"), "w") as f:
        for m in ("penalty", "lagrange multiplier"):
            points = [(float(r["dofs"]), float(r["t_compute"]))
                      for r in by("hertz_2d") if r["method"] == m and
                      r["penalty_factor"] in ("1000", "")
                      and r["tangent"] == "consistent"]
            for x, y in sorted(points):
                f.write("%g %g\n" % (x, y))
            f.write("\n\n")
            n = len(points)
            lx = [math.log(x) for x, _ in points]
            ly = [math.log(y) for _, y in points]
            mx, my = sum(lx) / n, sum(ly) / n
            fits[m] = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum(
                (a - mx) ** 2 for a in lx)
    with open(os.path.join(data, "study_fits.csv"), "w") as f:
        f.write("method,compute_time_exponent\n")
        for m, k in fits.items():
            f.write("%s,%.3f\n" % (m, k))
    print("cost exponents (t_compute ~ dofs^k, Hertz 2D):", fits)
    script = """
set terminal pngcairo size 1200,900 font ",10" noenhanced
set output "doc/study_pareto.png"
set multiplot layout 2,2 title "Error against wall time (one point per run; lower left is better)"
set logscale xy
set grid
set xlabel "wall time [s]"
set ylabel "error"
do for [s in "hertz_2d hertz_3d cylinder ring"] {
  set title s
  plot "DATA/study_".s.".dat" index 0 using 1:2 with points pt 7 title "penalty", \\
       "" index 1 using 1:2 with points pt 5 title "Lagrange", \\
       "" index 2 using 1:2 with points pt 9 title "augmented", \
       "" index 3 using 1:2 with steps lc rgb "gray" title "Pareto front"
}
unset multiplot
set output "doc/study_penalty.png"
set multiplot layout 1,2 title "Penalty: error and Newton iterations against k = eps_N h / E"
set xlabel "k = eps_N h / E"
set title "error"
plot "DATA/study_penalty.dat" index 0 using 1:2 with linespoints title "Hertz 2D (a, p0)", \\
     "" index 1 using 1:2 with linespoints title "cylinder (force)", \\
     x > 0 ? 20/x : 1/0 with lines dt 2 title "20 / eps_N"
unset logscale y
set title "Newton iterations"
set ylabel "iterations (all steps)"
plot "DATA/study_penalty.dat" index 0 using 1:3 with linespoints title "Hertz 2D", \\
     "" index 1 using 1:3 with linespoints title "cylinder"
unset multiplot
set output "doc/study_cost.png"
set size 1,1
set logscale xy
set title "Hertz 2D: compute time against dofs (KPEN, KLAG)"
set xlabel "dofs"
set ylabel "compute time (timer sections) [s]"
plot "DATA/study_cost.dat" index 0 using 1:2 with linespoints title "penalty 1000E/h", \\
     "" index 1 using 1:2 with linespoints title "Lagrange"
""".replace("DATA", os.path.relpath(data, ROOT)).replace(
        "KPEN", "penalty exponent %.2f" % fits["penalty"]).replace(
        "KLAG", "Lagrange exponent %.2f" % fits["lagrange multiplier"])
    subprocess.run(["gnuplot"], input=script, text=True, cwd=ROOT,
                   check=True)
    print("wrote doc/study_pareto.png, doc/study_penalty.png, "
          "doc/study_cost.png")


if __name__ == "__main__":
    main()
