#!/usr/bin/env python3
"""Implicit dynamics with contact: what each impact treatment, integrator
and enforcement does, and the error against the time step and the mesh.

    python3 benchmarks/dynamics_study.py             # ~6 min
    python3 benchmarks/dynamics_study.py --plots-only

Writes doc/data/dynamics_impact.csv (the Signorini bar, 80 x 2 cells, 800
steps, every mass treatment x integrator x enforcement),
doc/data/dynamics_steps.csv (bar and Hertzian sphere impact, error against
step size and mesh), the histories the plots need (doc/data/dynamics_*.dat)
and the plots doc/dynamics_*.png (gnuplot), which doc/dynamics.md shows.

Impact columns: mass, integrator, method, wall_time, newton_iterations,
status_changes (open/closed switches of the contact over the run),
energy_max and energy_end (kinetic + strain energy over the initial one:
the largest over the run and after the rebound), plateau_oscillation
(largest |F - mean| / mean over the middle of the contact), error_force
(mean plateau against rho c v A), error_duration (2 L / c), error_velocity
(rebound velocity, momentum / mass, against v0).
"""

import argparse
import csv
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from tribos_testing import analytic  # noqa: E402

TRIBOS = os.path.join(ROOT, "build", "tribos")
DATA = os.path.join(ROOT, "doc", "data")
WORK = "/tmp/tribos_dynamics_study"

MASSES = {"consistent": ["Time stepping/Mass matrix=consistent",
                         "Time stepping/Contact mass removal=false"],
          "lumped": ["Time stepping/Mass matrix=lumped",
                     "Time stepping/Contact mass removal=false"],
          "lumped without contact mass": [
              "Time stepping/Mass matrix=lumped",
              "Time stepping/Contact mass removal=true"]}
INTEGRATORS = {"newmark": ["Time stepping/Integrator=newmark"],
               "generalized alpha 0.8": [
                   "Time stepping/Integrator=generalized alpha",
                   "Time stepping/Spectral radius=0.8"],
               "generalized alpha 0.5": [
                   "Time stepping/Integrator=generalized alpha",
                   "Time stepping/Spectral radius=0.5"]}
METHODS = ["lagrange multiplier", "penalty", "augmented lagrangian"]


def run(prm, folder, sets):
    command = [TRIBOS, os.path.join(ROOT, "parameters", prm), "--set",
               "Output/Directory=" + folder, "--set", "Output/Write VTU=false"]
    for s in sets:
        command += ["--set", s]
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True)
    wall = time.time() - start
    if result.returncode != 0:
        raise SystemExit(result.stdout[-2000:] + result.stderr[-2000:])
    with open(folder + "/history.csv") as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return rows, wall


def bar_metrics(rows, length=1.0):
    duration, force = analytic.signorini_bar(length, 1, 0.01, 1, 0.05)
    initial = 2.5e-6
    active = [r["time"] for r in rows if r["n_active"] > 0]
    first, last = active[0], active[-1]
    plateau = [r["pair0_normal_force"] for r in rows
               if first + 0.25 <= r["time"] <= last - 0.25]
    mean = sum(plateau) / len(plateau)
    energy = [r["kinetic_energy"] + r["strain_energy"] for r in rows]
    changes = sum(1 for a, b in zip(rows, rows[1:])
                  if (a["n_active"] > 0) != (b["n_active"] > 0))
    return dict(status_changes=changes,
                energy_max=max(energy) / initial,
                energy_end=energy[-1] / initial,
                plateau_oscillation=max(abs(f - mean) for f in plateau) / mean,
                error_force=abs(mean / force - 1),
                error_duration=abs((last - first) / duration - 1),
                error_velocity=abs(rows[-1]["momentum_x"] / 0.05 / 0.01 - 1))


def sphere_metrics(rows, v=1e-4):
    mass = 2 * rows[0]["kinetic_energy"] / v ** 2
    _, force, duration = analytic.hertz_impact(mass, v, 1, 1 / (1 - 0.09))
    active = [r["time"] for r in rows if r["n_active"] > 0]
    dt = rows[1]["time"] - rows[0]["time"]
    peak = max(r["pair0_normal_force"] for r in rows)
    energy = [r["kinetic_energy"] + r["strain_energy"] for r in rows]
    return dict(error_force=abs(peak / force - 1),
                error_duration=abs((active[-1] - active[0] + dt) / duration
                                   - 1),
                energy_end=energy[-1] / energy[0])


def write_csv(path, rows):
    keys = list(rows[0].keys())
    with open(path, "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(str(r[k]) for k in keys) + "\n")


def impact_study():
    table = []
    for mass, mass_sets in MASSES.items():
        for integrator, integrator_sets in INTEGRATORS.items():
            for method in METHODS:
                folder = os.path.join(WORK, "impact")
                rows, wall = run("bar_impact.prm", folder,
                                 mass_sets + integrator_sets +
                                 ["Contact/Method=" + method])
                row = dict(mass=mass, integrator=integrator, method=method,
                           wall_time=round(wall, 3),
                           newton_iterations=int(sum(
                               r["newton_iterations"] for r in rows)))
                row.update({k: "%.4g" % v if isinstance(v, float) else v
                            for k, v in bar_metrics(rows).items()})
                print(row, flush=True)
                table.append(row)
                if integrator == "newmark" and method == "lagrange multiplier":
                    # Energy histories for the plot.
                    name = {"consistent": "consistent", "lumped": "lumped",
                            "lumped without contact mass":
                                "lumped_removed"}[mass]
                    with open(os.path.join(
                            DATA, "dynamics_bar_%s.dat" % name), "w") as f:
                        f.write("# time, (kinetic + strain) / E0, contact "
                                "force / (rho c v A)\n")
                        for r in rows:
                            f.write("%g,%g,%g\n" % (
                                r["time"],
                                (r["kinetic_energy"] + r["strain_energy"]) /
                                2.5e-6, r["pair0_normal_force"] / 5e-4))
    write_csv(os.path.join(DATA, "dynamics_impact.csv"), table)


def hertz_force_history(mass, v, e_star, radius=1.0, n=4000):
    """Hertz's force over time (m x'' = -4/3 E* R^1/2 x^3/2, RK4)."""
    k = 4.0 / 3.0 * e_star * math.sqrt(radius)
    _, _, duration = analytic.hertz_impact(mass, v, radius, e_star)
    dt = 1.05 * duration / n
    x, u, t, out = 0.0, v, 0.0, []

    def acc(x):
        return -k * max(x, 0) ** 1.5 / mass

    while x >= 0:
        out.append((t, k * max(x, 0) ** 1.5))
        k1x, k1u = u, acc(x)
        k2x, k2u = u + 0.5 * dt * k1u, acc(x + 0.5 * dt * k1x)
        k3x, k3u = u + 0.5 * dt * k2u, acc(x + 0.5 * dt * k2x)
        k4x, k4u = u + dt * k3u, acc(x + dt * k3x)
        x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        u += dt / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        t += dt
    return out


def step_study():
    table = []
    lagrange = ["Contact/Method=lagrange multiplier"]
    for cells, steps in [(40, 400), (80, 400), (80, 800), (80, 1600),
                         (160, 1600)]:
        folder = os.path.join(WORK, "bar_steps")
        rows, wall = run("bar_impact.prm", folder, lagrange + [
            "Scene/Block/Subdivisions=%d, 2" % cells,
            "Time stepping/Number of steps=%d" % steps])
        m = bar_metrics(rows)
        row = dict(scene="bar", level=cells, steps=steps, dt=4.0 / steps,
                   wall_time=round(wall, 3),
                   error_force=m["error_force"],
                   error_duration=m["error_duration"],
                   error_velocity=m["error_velocity"],
                   energy_end=m["energy_end"])
        print(row, flush=True)
        table.append(row)
    for refinements, steps in [(4, 340), (5, 170), (5, 340), (5, 680),
                               (6, 340)]:
        folder = os.path.join(WORK, "sphere_steps")
        rows, wall = run("sphere_impact.prm", folder, [
            "Scene/Cylinder over block/Contact refinements=%d" % refinements,
            "Time stepping/Number of steps=%d" % steps])
        m = sphere_metrics(rows)
        row = dict(scene="sphere", level=refinements, steps=steps,
                   dt=34.0 / steps, wall_time=round(wall, 3),
                   error_force=m["error_force"],
                   error_duration=m["error_duration"], error_velocity="",
                   energy_end=m["energy_end"])
        print(row, flush=True)
        table.append(row)
        if refinements == 5 and steps == 340:
            v = 1e-4
            mass = 2 * rows[0]["kinetic_energy"] / v ** 2
            with open(os.path.join(DATA, "dynamics_sphere.dat"), "w") as f:
                f.write("# time since first contact, force (tribos)\n")
                start = [r["time"] for r in rows if r["n_active"] > 0][0]
                for r in rows:
                    f.write("%g,%g\n" % (r["time"] - start,
                                         r["pair0_normal_force"]))
            with open(os.path.join(DATA, "dynamics_sphere_hertz.dat"),
                      "w") as f:
                f.write("# time, force (Hertz)\n")
                for t, force in hertz_force_history(mass, v, 1 / 0.91):
                    f.write("%g,%g\n" % (t, force))
    write_csv(os.path.join(DATA, "dynamics_steps.csv"), table)

    rows, _ = run("ring_drop.prm", os.path.join(WORK, "ring"),
                  ["Output/Frequency=0"])
    with open(os.path.join(DATA, "dynamics_ring.dat"), "w") as f:
        f.write("# time, kinetic, strain, contact work, total, "
                "contact force\n")
        for r in rows:
            f.write("%g,%g,%g,%g,%g,%g\n" % (
                r["time"], r["kinetic_energy"], r["strain_energy"],
                r["contact_work"], r["total_energy"],
                r["pair0_normal_force"]))


PLOTS = r"""
set datafile separator ","
set terminal pngcairo size 900,560 font ",11" noenhanced
set grid
set key top right
set output "doc/dynamics_bar_energy.png"
set title "Signorini bar, Newmark (1/4, 1/2), Lagrange multipliers: energy"
set xlabel "time (impact at t = 1, release at t = 3)"
set ylabel "(kinetic + strain energy) / initial"
set logscale y
plot "doc/data/dynamics_bar_consistent.dat" using 1:2 with lines lw 2 \
       title "consistent mass", \
     "doc/data/dynamics_bar_lumped.dat" using 1:2 with lines lw 2 \
       title "lumped mass", \
     "doc/data/dynamics_bar_lumped_removed.dat" using 1:2 with lines lw 2 \
       title "lumped, no mass on the contact nodes"
unset logscale y
set output "doc/dynamics_bar_force.png"
set title "Signorini bar: contact force / (rho c v A), exact: 1 in 1 < t < 3"
set ylabel "contact force / (rho c v A)"
set yrange [-0.5:8]
plot "doc/data/dynamics_bar_consistent.dat" using 1:3 with lines \
       title "consistent mass", \
     "doc/data/dynamics_bar_lumped_removed.dat" using 1:3 with lines lw 2 \
       title "lumped, no mass on the contact nodes"
set yrange [*:*]
set output "doc/dynamics_sphere_force.png"
set title "Hertzian impact (v = 1e-4, axisymmetric sphere): contact force"
set xlabel "time since the first contact"
set ylabel "contact force"
plot "doc/data/dynamics_sphere_hertz.dat" using 1:2 with lines lw 2 \
       title "Hertz's impact theory", \
     "doc/data/dynamics_sphere.dat" using 1:2 with points pt 7 ps 0.5 \
       title "tribos"
set output "doc/dynamics_ring_energy.png"
set title "Ring dropped on the foundation: energies"
set xlabel "time"
set ylabel "energy"
plot "doc/data/dynamics_ring.dat" using 1:2 with lines title "kinetic", \
     "doc/data/dynamics_ring.dat" using 1:3 with lines title "strain", \
     "doc/data/dynamics_ring.dat" using 1:4 with lines title "contact work", \
     "doc/data/dynamics_ring.dat" using 1:5 with lines lw 2 title "total"
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plots-only", action="store_true")
    args = parser.parse_args()
    os.makedirs(WORK, exist_ok=True)
    if not args.plots_only:
        impact_study()
        step_study()
    subprocess.run(["gnuplot"], input=PLOTS, text=True, cwd=ROOT, check=True)


if __name__ == "__main__":
    main()
