#!/usr/bin/env python3
"""Newton on load-controlled contact: how many iterations the first touch
and the active-set changes take, per enforcement method, with and without
friction, from a touching start and from a small gap (a body floating
under its load), with the pressure error against Hertz. Writes one CSV row
per run:

    python3 benchmarks/newton_contact.py build/tribos \\
        [--out doc/data/newton_contact.csv] [--set "Section/Entry=value"]...
        [--only hertz_3d] [--scenes]

Cases (benchmarks/peers/README.md has the physics):
  hertz_2d_13k, hertz_2d_49k  the quarter cylinder R = 1 on gmsh's
      all-quad meshes of benchmarks/peers/hertz_2d.geo (13 790 and 49 242
      dofs, made with gmsh if missing), pressure 0.005 E on the flat top;
  hertz_3d  parameters/hertz_3d_load.prm (the quarter sphere R = 10, 21k
      dofs on tribos's own mesh).
Variants: penalty 100 and 1000 E/h, Lagrange multipliers, augmented
Lagrangian; mu = 0 and 0.3; touching start and a gap of 1e-3 R. Every
variant in one load step, the default Nonlinear solver settings but for
the --set overrides (e.g. --set "Nonlinear solver/Penetration limit=0"
for the Newton without the step limit).

Columns: case, dofs, method, mu, start, newton (accepted iterations),
newton_all (every linear solve, failed attempts included), cutbacks,
short_steps (Newton steps shorter than 1: limited or line search), order
(the observed order of convergence at the end, observed_order()), wall
(s, the process), error (the nodal pressure error against Hertz for the
carried load, hertz_error.py), status.

--scenes instead runs every parameters/*.prm at its own steps and writes
scene, increments, cutbacks, ratio, newton, newton_all, wall, status.
"""

import argparse
import csv
import glob
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PEERS = os.path.join(ROOT, "benchmarks", "peers")
sys.path.insert(0, PEERS)
import hertz_error  # noqa: E402
from peer_runs import mesh, summary_value  # noqa: E402

METHODS = [("penalty 100 E/h", ["Contact/Method=penalty",
                                "Contact/Penalty factor=100*E/h"]),
           ("penalty 1000 E/h", ["Contact/Method=penalty",
                                 "Contact/Penalty factor=1000*E/h"]),
           ("multipliers", ["Contact/Method=lagrange multiplier"]),
           ("augmented", ["Contact/Method=augmented lagrangian",
                          "Contact/Penalty factor=100*E/h"])]

# name: parameter file, settings, dim, R, E, nu, symmetry factor, gap
# entry for the floating start
CASES = {
    "hertz_2d_13k": (os.path.join(PEERS, "hertz_2d_load.prm"),
                     ["Scene/Mesh file=" +
                      os.path.join(PEERS, "hertz_2d_13k.msh")],
                     2, 1.0, 1.0, 0.3, 2.0, None),
    "hertz_2d_49k": (os.path.join(PEERS, "hertz_2d_load.prm"),
                     ["Scene/Mesh file=" +
                      os.path.join(PEERS, "hertz_2d_49k.msh")],
                     2, 1.0, 1.0, 0.3, 2.0, None),
    "hertz_3d": (os.path.join(ROOT, "parameters", "hertz_3d_load.prm"), [],
                 3, 10.0, 2e5, 0.3, 4.0,
                 "Scene/Cylinder over block/Gap"),
}

def shift_mesh(source, target, gap):
    """A copy of the gmsh mesh @p source lifted by @p gap in y (the 2D
    floating start)."""
    with open(source) as f, open(target, "w") as g:
        section = None
        for line in f:
            stripped = line.strip()
            if stripped.startswith("$"):
                section = stripped
                g.write(line)
                continue
            parts = stripped.split()
            if section == "$Nodes" and len(parts) == 4:
                parts[2] = repr(float(parts[2]) + gap)
                g.write(" ".join(parts) + "\n")
            else:
                g.write(line)


def count_short_steps(folder):
    rows = list(csv.DictReader(open(os.path.join(folder,
                                                 "convergence.csv"))))
    return sum(1 for r in rows if r["line_search_step"] not in ("nan", "")
               and float(r["line_search_step"]) < 1)


def observed_order(folder):
    """The observed order of the final increment's last iteration (of the
    one before if the last residual is at round-off: relative 1e-10, where
    the stiffest penalty's residual stops falling)."""
    rows = list(csv.DictReader(open(os.path.join(folder,
                                                 "convergence.csv"))))
    last = [r for r in rows if r["step"] == rows[-1]["step"] and
            r["increment"] == rows[-1]["increment"]]
    if len(last) >= 2 and float(last[-1]["relative_residual"]) < 1e-10:
        last = last[:-1]
    order = float(last[-1]["order"]) if last else float("nan")
    return "" if order != order else "%.2f" % order


def run(tribos, prm, folder, sets):
    command = [tribos, prm, "--set", "Output/Directory=" + folder,
               "--set", "Output/Write VTU=false"]
    for s in sets:
        command += ["--set", s]
    start = time.time()
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    return result.returncode, time.time() - start, result.stdout


def hertz_case(tribos, name, method, mu, start, extra, work):
    prm, sets, dim, radius, young, nu, factor, gap_entry = CASES[name]
    sets = list(sets) + list(METHODS[method][1]) + [
        "Contact/Friction coefficient=%g" % mu] + list(extra)
    if start == "gap":
        gap = 1e-3 * radius
        if gap_entry:
            sets.append("%s=%g" % (gap_entry, gap))
        else:
            source = sets[0].split("=", 1)[1]
            lifted = os.path.join(work, "lifted_" + os.path.basename(source))
            shift_mesh(source, lifted, gap)
            sets[0] = "Scene/Mesh file=" + lifted
    folder = os.path.join(work, "%s_%d_%g_%s" % (name, method, mu, start))
    code, wall, output = run(tribos, prm, folder, sets)
    row = {"case": name, "method": METHODS[method][0], "mu": mu,
           "start": start, "wall": "%.3f" % wall,
           "status": {0: "ok", 2: "no convergence"}.get(code, "error")}
    try:
        row["dofs"] = summary_value(folder, "dofs")
        row["newton"] = summary_value(folder, "newton iterations ")
        row["newton_all"] = summary_value(folder,
                                          "newton iterations (all attempts)")
        row["cutbacks"] = summary_value(folder, "cutbacks")
        row["short_steps"] = count_short_steps(folder)
        row["order"] = observed_order(folder)
    except OSError:
        pass
    if code == 0:
        contact = sorted(glob.glob(os.path.join(folder, "contact-*.csv")))[-1]
        points = hertz_error.read_tribos_contact(contact, dim)
        force = hertz_error.read_tribos_force(
            os.path.join(folder, "history.csv"))
        e_star = young / (1 - nu * nu)
        row["error"] = "%.4f" % hertz_error.profile_error(
            points, factor * force, radius, e_star, dim)
    else:
        print(output[-1500:])
    return row


def scenes(tribos, extra, work, out):
    fields = ["scene", "increments", "cutbacks", "ratio", "newton",
              "newton_all", "wall", "status"]
    rows = []
    for prm in sorted(glob.glob(os.path.join(ROOT, "parameters", "*.prm"))):
        name = os.path.basename(prm)
        folder = os.path.join(work, name)
        code, wall, _ = run(tribos, prm, folder, extra)
        row = {"scene": name, "wall": "%.2f" % wall,
               "status": {0: "ok", 2: "no convergence"}.get(code, "error")}
        try:
            row["increments"] = int(summary_value(folder, "increments"))
            row["cutbacks"] = int(summary_value(folder, "cutbacks"))
            row["ratio"] = "%.4f" % (row["cutbacks"] /
                                     max(row["increments"], 1))
            row["newton"] = summary_value(folder, "newton iterations ")
            row["newton_all"] = summary_value(
                folder, "newton iterations (all attempts)")
        except (OSError, ValueError):
            pass
        print(",".join(str(row.get(f, "")) for f in fields), flush=True)
        rows.append(row)
    write(out, fields, rows)


def write(out, fields, rows):
    if not out:
        return
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row.get(k, "") for k in fields})


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--out", default="")
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--only", default="")
    parser.add_argument("--scenes", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        if args.scenes:
            return scenes(os.path.abspath(args.tribos), args.set, work,
                          args.out)
        for name in ("hertz_2d_13k.msh", "hertz_2d_49k.msh"):
            mesh(name)
        fields = ["case", "dofs", "method", "mu", "start", "newton",
                  "newton_all", "cutbacks", "short_steps", "order", "wall",
                  "error", "status"]
        print(",".join(fields))
        rows = []
        for name in CASES:
            if args.only and args.only not in name:
                continue
            for start in ("touching", "gap"):
                for mu in (0.0, 0.3):
                    for method in range(len(METHODS)):
                        row = hertz_case(os.path.abspath(args.tribos), name,
                                         method, mu, start, args.set, work)
                        print(",".join(str(row.get(f, "")) for f in fields),
                              flush=True)
                        rows.append(row)
        write(args.out, fields, rows)


if __name__ == "__main__":
    sys.exit(main())
