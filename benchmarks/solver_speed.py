#!/usr/bin/env python3
"""Solver speed (issue 16): a fixed set of runs, each repeated, with the
median wall time, Newton iterations, timer sections, ms per linear solve,
peak resident memory and the Hertz pressure error; prints each target with
measured / target.

    python3 benchmarks/solver_speed.py [--tribos build/tribos] [--runs 3]
        [--out doc/data/solver_speed.csv] [--only NAME ...]

Cases (all Release, one process, VTU off):
  hertz2d_*   parameters/hertz_2d.prm under load control (a traction of
              0.005 E on the flat top, x held there, one increment:
              p0 = 0.059 E as in the issue's case), Contact refinements 5
              and 6 (13.5k and 49.4k unknowns); penalty (100 E/h) and
              Lagrange multipliers
  hertz3d_*   parameters/hertz_3d.prm under load control (0.005 E, the
              whole load in one increment), Contact refinements 4 in a
              radius of 0.25 and of 0.23 (the contact radius is 0.22),
              default solver settings; penalty and multipliers
  hertz3d_default_*  parameters/hertz_3d.prm unchanged with one thread,
              two threads and mpirun -np 2 (the speed-up target)
  hertz3d_L4_penalty_np2  hertz3d_L4_penalty with mpirun -np 2
  upsetting   parameters/upsetting.prm, the first 5 of 25 steps (the whole
              stroke takes minutes; the per-iteration cost is the target)
  start       tribos --help, and parameters/patch_test-like small 2D scene
              end to end (tests/data/sliding_block.prm); start_floor is
              benchmarks/startup_floor, a program linked as tribos is that
              returns at once (the loading of the shared libraries)
The pressure error e_L2 is the relative L2 distance of the nodal CPRESS to
Hertz's profile for the run's own contact force (tests/tribos_testing/__init__.py,
hertz_compare), with the nodes at their reference positions (Hertz's
theory is geometrically linear); e_L2_deformed measures them where they
are after the deformation."""

import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from tribos_testing import hertz_compare  # noqa: E402

E, NU, R = 1.0, 0.3, 1.0
LAGRANGE = "Contact/Method=lagrange multiplier"


def hertz2d(level, traction, extra=()):
    return ("parameters/hertz_2d.prm",
            ["Scene/Cylinder over block/Contact refinements=%d" % level,
             "Boundary conditions/Dirichlet=11 : x : 0",
             "Boundary conditions/Neumann=11 : 0, -%g*t" % traction,
             "Time stepping/Number of steps=1"] + list(extra))


def hertz3d(level, traction, extra=(), radius=0.25):
    return ("parameters/hertz_3d.prm",
            ["Scene/Cylinder over block/Contact refinements=%d" % level,
             "Scene/Cylinder over block/Refinement radius=%g" % radius,
             "Boundary conditions/Dirichlet=",
             "Boundary conditions/Neumann=11 : 0, 0, -%g*t" % traction,
             "Time stepping/Number of steps=1"] + list(extra))


# name, (prm, sets), Hertz (dim, force scale) or None
CASES = [
    ("hertz2d_L5_penalty", hertz2d(5, 0.005), (2, 1)),
    ("hertz2d_L5_lagrange", hertz2d(5, 0.005, [LAGRANGE]), (2, 1)),
    ("hertz2d_L6_penalty", hertz2d(6, 0.005), (2, 1)),
    ("hertz2d_L6_lagrange", hertz2d(6, 0.005, [LAGRANGE]), (2, 1)),
    ("hertz3d_L4_penalty", hertz3d(4, 0.005), (3, 4)),
    ("hertz3d_L4_lagrange", hertz3d(4, 0.005, [LAGRANGE]), (3, 4)),
    ("hertz3d_L4r23_penalty", hertz3d(4, 0.005, radius=0.23), (3, 4)),
    ("hertz3d_L4r23_lagrange", hertz3d(4, 0.005, [LAGRANGE], radius=0.23),
     (3, 4)),
    # parameters/hertz_3d.prm as it is (displacement control, 21k
    # unknowns): one thread, two threads, two MPI processes (MUMPS). One
    # thread means one for OpenBLAS too: with DEAL_II_NUM_THREADS alone
    # CHOLMOD's dense kernels still ran on both cores, and the speed-up
    # of two over one was understated (1.13 against 1.38 with one OpenBLAS thread).
    ("hertz3d_default_1thread", ("parameters/hertz_3d.prm", []), None,
     {"env": {"DEAL_II_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}}),
    ("hertz3d_default_2threads", ("parameters/hertz_3d.prm", []), None,
     {"env": {"DEAL_II_NUM_THREADS": "2", "OPENBLAS_NUM_THREADS": "2"}}),
    ("hertz3d_default_np2", ("parameters/hertz_3d.prm", []), None,
     {"ranks": 2}),
    # The load-controlled 36k case on two processes (GMRES + ML by Type =
    # auto under MPI) against hertz3d_L4_penalty on one.
    ("hertz3d_L4_penalty_np2", hertz3d(4, 0.005), (3, 4), {"ranks": 2}),
    ("upsetting_5_steps", ("parameters/upsetting.prm",
                           ["Time stepping/End time=5",
                            "Time stepping/Number of steps=5"]), None),
    ("small_2d_scene", ("tests/data/sliding_block.prm", []), None),
]

SECTIONS = ["assembly", "contact assembly", "contact search",
            "linear solve", "output", "setup"]


def with_earlier_rows(path, rows, cases):
    """rows after the rows of the CSV at path whose case is not in cases:
    a run of some cases keeps the others' measurements."""
    if not os.path.exists(path):
        return rows
    with open(path) as f:
        return [r for r in csv.DictReader(f) if r["case"] not in cases] + rows


def run_once(tribos, prm, sets, folder, launch=None):
    """Wall time and peak RSS (MB) of one run (os.wait4 gives the child's
    own rusage, under mpirun the largest of its processes'). launch:
    {"env": {...}, "ranks": n} for the thread and MPI cases."""
    launch = launch or {}
    command = [tribos, os.path.join(ROOT, prm), "--set",
               "Output/Directory=" + folder, "--set", "Output/Write VTU=false"]
    for s in sets:
        command += ["--set", s]
    if launch.get("ranks"):
        command = [os.environ.get("MPIEXEC", "mpirun"), "-np",
                   str(launch["ranks"])] + command
    env = dict(os.environ)
    env.update(launch.get("env", {}))
    if os.geteuid() == 0:
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    start = time.time()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, env=env)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.time() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    error = child.stderr.read().decode()
    if child.returncode != 0:
        raise SystemExit("failed (%d): %s\n%s" % (child.returncode,
                                                  " ".join(command), error))
    return wall, usage.ru_maxrss / 1024.0


def summary(folder):
    """Timer sections (calls, wall) and counters from summary.txt."""
    sections, values = {}, {}
    with open(folder + "/summary.txt") as f:
        for line in f:
            m = re.match(r"(\w[\w ]*?)\s{2,}(\d+)\s+([\d.e+-]+)\s+[\d.]+%",
                         line)
            if m:
                sections[m.group(1).strip()] = (int(m.group(2)),
                                                float(m.group(3)))
                continue
            m = re.match(r"(dofs|multipliers|newton iterations|"
                         r"newton iterations \(all attempts\)|cutbacks|"
                         r"increments)\s+(\d+)$", line.strip())
            if m:
                values[m.group(1)] = int(m.group(2))
            m = re.match(r"linear solver\s{2,}(.+)$", line.strip())
            if m:
                values["linear solver"] = m.group(1)
    return sections, values


def start_time(tribos, runs):
    """Medians of `tribos --help` and of benchmarks/startup_floor (linked as
    tribos is, returns at once: the libraries' loading alone), alternated
    so that both see the same machine."""
    floor = os.path.join(os.path.dirname(tribos), "benchmarks",
                         "startup_floor")
    walls = {"help": [], "floor": []}
    for _ in range(runs):
        for name, command in (("help", [tribos, "--help"]),
                              ("floor", [floor])):
            start = time.time()
            subprocess.run(command, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, check=True)
            walls[name].append(time.time() - start)
    return (statistics.median(walls["help"]),
            statistics.median(walls["floor"]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tribos", default=os.path.join(ROOT, "build",
                                                         "tribos"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "data",
                                                      "solver_speed.csv"))
    parser.add_argument("--only", nargs="*", default=[])
    args = parser.parse_args()

    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name, (prm, sets), hertz, *launch in CASES:
            if args.only and name not in args.only:
                continue
            folder = os.path.join(work, name)
            walls, rss = [], []
            for _ in range(args.runs):
                w, m = run_once(args.tribos, prm, sets, folder,
                                launch[0] if launch else None)
                walls.append(w)
                rss.append(m)
            sections, values = summary(folder)
            solve_calls, solve_wall = sections.get("linear solve", (0, 0.0))
            row = {
                "case": name,
                "runs": args.runs,
                "dofs": values.get("dofs", 0),
                "multipliers": values.get("multipliers", 0),
                "linear_solver": values.get("linear solver", ""),
                "increments": values.get("increments", 0),
                "cutbacks": values.get("cutbacks", 0),
                "newton_iterations": values.get(
                    "newton iterations (all attempts)", 0),
                "wall_median": statistics.median(walls),
                "wall_min": min(walls),
                "wall_max": max(walls),
                "ms_per_solve": 1e3 * solve_wall / max(solve_calls, 1),
                "ms_per_newton_iteration": 1e3 * statistics.median(walls) /
                max(values.get("newton iterations (all attempts)", 1), 1),
                "peak_rss_mb": max(rss),
                "e_L2": "",
                "e_L2_deformed": "",
            }
            for s in SECTIONS:
                row["t_" + s.replace(" ", "_")] = sections.get(s, (0, 0))[1]
            if hertz:
                for key, reference in (("e_L2", True),
                                       ("e_L2_deformed", False)):
                    try:
                        row[key] = hertz_compare(
                            folder, hertz[0], E / (1 - NU * NU), R,
                            hertz[1], step=1, reference=reference)[4]
                    except KeyError:
                        pass  # a build whose contact CSV has no X, Y, Z
            rows.append(row)
            print("%-22s %7d dofs %3d Newton  %7.2f s (%s)  %7.1f ms/solve  "
                  "%6.0f MB  e_L2 %s  [%s]" % (
                      name, row["dofs"] + row["multipliers"],
                      row["newton_iterations"], row["wall_median"],
                      " ".join("%.2f" % w for w in walls),
                      row["ms_per_solve"], row["peak_rss_mb"],
                      "%.2f %%" % (100 * row["e_L2"]) if row["e_L2"] != ""
                      else "-", row["linear_solver"]), flush=True)
        if not args.only or "start" in args.only:
            runs = max(args.runs, 15)
            help_wall, floor_wall = start_time(args.tribos, runs)
            rows.append({"case": "start_help", "runs": runs,
                         "wall_median": help_wall})
            rows.append({"case": "start_floor", "runs": runs,
                         "wall_median": floor_wall})
            print("%-22s %7.3f s" % ("tribos --help", help_wall))
            print("%-22s %7.3f s (libraries loaded, main returns at once)"
                  % ("startup_floor", floor_wall))

    # With --only, the rows of the cases not run stay as they were.
    if args.only and rows:
        rows = with_earlier_rows(args.out, rows, {r["case"] for r in rows})
    if rows:
        names = []
        for r in rows:
            names += [k for k in r if k not in names]
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=names)
            writer.writeheader()
            for r in rows:
                writer.writerow({k: ("%.4g" % v if isinstance(v, float)
                                     else v) for k, v in r.items()})

    # Targets of issue 16, measured / target (<= 1 meets it).
    by = {r["case"]: r for r in rows}

    def target(text, value, bound):
        if value is None:
            return
        print("target %-58s %8.3f / %-7g = %.2f %s" % (
            text, value, bound, value / bound,
            "met" if value <= bound else "NOT met"))

    def get(case, key):
        if case not in by or by[case].get(key) in (None, ""):
            return None
        return float(by[case][key])

    print()
    for m in ("penalty", "lagrange"):
        target("Hertz 2D 13.5k %s wall [s]" % m,
               get("hertz2d_L5_" + m, "wall_median"), 1.0)
        target("Hertz 2D 49.4k %s wall [s]" % m,
               get("hertz2d_L6_" + m, "wall_median"), 5.0)
        for mesh in ("L4", "L4r23"):
            target("Hertz 3D %s %s wall [s]" % (mesh, m),
                   get("hertz3d_%s_%s" % (mesh, m), "wall_median"), 20.0)
            e = get("hertz3d_%s_%s" % (mesh, m), "e_L2")
            target("Hertz 3D %s %s e_L2 [%%]" % (mesh, m),
                   None if e is None else 100 * e, 2.5)
    target("upsetting per Newton iteration [s]",
           None if "upsetting_5_steps" not in by else
           float(by["upsetting_5_steps"]["ms_per_newton_iteration"]) / 1e3, 0.3)
    help_wall = get("start_help", "wall_median")
    floor = get("start_floor", "wall_median")
    target("tribos --help [s]", help_wall, 0.2)
    if help_wall is not None and floor is not None:
        print("       of which loading the shared libraries %.3f s, tribos' "
              "own start %.3f s" % (floor, help_wall - floor))
    one = get("hertz3d_default_1thread", "wall_median")
    for case, what in (("hertz3d_default_2threads", "two threads"),
                       ("hertz3d_default_np2", "mpirun -np 2")):
        other = get(case, "wall_median")
        if one and other:
            # A speed-up: measured / target >= 1 meets it here.
            print("target %-58s %8.3f / %-7g = %.2f %s" % (
                "Hertz 3D speed-up, %s vs one thread" % what, one / other,
                1.7, one / other / 1.7,
                "met" if one / other >= 1.7 else "NOT met"))
    one, other = (get("hertz3d_L4_penalty", "wall_median"),
                  get("hertz3d_L4_penalty_np2", "wall_median"))
    if one and other:
        print("target %-58s %8.3f / %-7g = %.2f %s" % (
            "Hertz 3D 36k load control, mpirun -np 2 vs one process",
            one / other, 1.7, one / other / 1.7,
            "met" if one / other >= 1.7 else "NOT met"))
    for level in ("2d_L5", "2d_L6", "3d_L4", "3d_L4r23"):
        p, l = (get("hertz%s_penalty" % level, "wall_median"),
                get("hertz%s_lagrange" % level, "wall_median"))
        if p and l:
            target("Lagrange / penalty wall, Hertz %s" % level, l / p, 1.3)


if __name__ == "__main__":
    main()
