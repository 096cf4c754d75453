#!/usr/bin/python3
"""Paired wall time of tribos against GetFEM on load-controlled Hertz (issue
44): the two programs run alternately (tribos, GetFEM, tribos, ...), each
as the process a user starts, and the median of each and their ratio are
written per case, with both codes' Newton iterations and pressure errors.

    /usr/bin/python3 benchmarks/peers/paired_getfem.py build/tribos \\
        [--runs 5] [--out doc/data/paired_getfem.csv] [--only 2d]
        [--set "Section/Entry=value"]...

Cases: hertz_2d_13k and hertz_2d_49k (the same gmsh mesh for both codes),
hertz_3d (tribos on parameters/hertz_3d_load.prm, its own hexahedral
mesh; GetFEM on hertz_3d_20k.msh, first-order hexahedra, whose pressure
error is the larger), hertz_3d_tet_p1 and hertz_3d_tet_p2 (issue 45:
tests/data/hertz_3d_tet.msh for both codes, P1 and P2 tetrahedra; tribos with
Lagrange multipliers), hertz_3d_tet10_p2 and hertz_2d_tri6_p2 (the same
meshes of second order, curved: tests/data/hertz_3d_tet10.msh and
tests/data/hertz_2d_tri6.msh; P2, tribos with multipliers, GetFEM's integral
contact). Both: small strain, frictionless rigid plane,
touching start, the whole load in one step, default Newton settings;
GetFEM's augmented Lagrangian (getfem_hertz.py), tribos's default method
(penalty 100 E/h) unless --set says otherwise. Needs `import getfem`
(README.md).

Columns: case, runs, tribos_dofs, getfem_dofs, tribos_newton,
getfem_newton, tribos_error, getfem_error, tribos_wall, getfem_wall
(medians, s), ratio (tribos / GetFEM), tribos_in_process (the median of
tribos's own wall_time of the last increment in history.csv: the run
without loading the libraries and without writing the output),
getfem_failures (GetFEM's runs whose Newton did not converge in its 50
iterations: their times count, their error is not shown unless no run
converged, "no convergence").
"""

import argparse
import csv
import glob
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import hertz_error  # noqa: E402
from peer_runs import mesh, summary_value  # noqa: E402

# The tetrahedral mesh of tests/verification/tet_contact.py (hertz_3d.geo with
# -setnumber hex 0 -setnumber hf 0.15: fine zone a / 8), for both codes.
TET_MESH = os.path.join(ROOT, "tests", "data", "hertz_3d_tet.msh")
TET_SETS = ["Scene/Name=gmsh", "Scene/Mesh file=" + TET_MESH,
            "Contact/Method=lagrange multiplier"]
# The same meshes of second order (-setnumber order 2): curved tet10 and
# tri6, both codes on their curved geometry.
TET10_MESH = os.path.join(ROOT, "tests", "data", "hertz_3d_tet10.msh")
TRI6_MESH = os.path.join(ROOT, "tests", "data", "hertz_2d_tri6.msh")
P2_SETS = ["Finite element/Polynomial degree=2",
           "Contact/Method=lagrange multiplier"]

# name: tribos parameter file, tribos mesh, GetFEM mesh, dim, R, E, nu,
# symmetry factor, tribos settings, getfem_hertz.py arguments
CASES = {
    "hertz_2d_13k": ("hertz_2d_load.prm", "hertz_2d_13k.msh",
                     "hertz_2d_13k.msh", 2, 1.0, 1.0, 0.3, 2.0, [], []),
    "hertz_2d_49k": ("hertz_2d_load.prm", "hertz_2d_49k.msh",
                     "hertz_2d_49k.msh", 2, 1.0, 1.0, 0.3, 2.0, [], []),
    "hertz_3d": (os.path.join(ROOT, "parameters", "hertz_3d_load.prm"), None,
                 "hertz_3d_20k.msh", 3, 10.0, 2e5, 0.3, 4.0, [], []),
    # Issue 45: the same tetrahedral mesh, P1 (both codes' nodal
    # multipliers) and P2 (tribos's multipliers at the vertices and the
    # edge middles' virtual points; GetFEM's integral contact, its only
    # contact for P2).
    "hertz_3d_tet_p1": (os.path.join(ROOT, "parameters", "hertz_3d_load.prm"),
                        None, TET_MESH, 3, 10.0, 2e5, 0.3, 4.0, TET_SETS,
                        ["--order", "1"]),
    "hertz_3d_tet_p2": (os.path.join(ROOT, "parameters", "hertz_3d_load.prm"),
                        None, TET_MESH, 3, 10.0, 2e5, 0.3, 4.0,
                        TET_SETS + ["Finite element/Polynomial degree=2"],
                        ["--order", "2", "--method", "integral"]),
    # The curved second-order meshes (the rest of issue 45).
    "hertz_3d_tet10_p2": (os.path.join(ROOT, "parameters",
                                       "hertz_3d_load.prm"),
                          None, TET10_MESH, 3, 10.0, 2e5, 0.3, 4.0,
                          ["Scene/Name=gmsh", "Scene/Mesh file=" + TET10_MESH]
                          + P2_SETS,
                          ["--order", "2", "--method", "integral"]),
    "hertz_2d_tri6_p2": ("hertz_2d_load.prm", None, TRI6_MESH, 2, 1.0, 1.0,
                         0.3, 2.0, ["Scene/Mesh file=" + TRI6_MESH] + P2_SETS,
                         ["--order", "2", "--method", "integral"]),
}

def run_tribos(tribos, case, folder, sets):
    prm, tribos_mesh, _, dim, radius, young, nu, factor = CASES[case][:8]
    command = [tribos, os.path.join(HERE, prm), "--set",
               "Output/Directory=" + folder, "--set", "Output/Write VTU=false"]
    if tribos_mesh:
        command += ["--set", "Scene/Mesh file=" + mesh(tribos_mesh)]
    for s in CASES[case][8] + list(sets):
        command += ["--set", s]
    start = time.time()
    subprocess.run(command, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True)
    wall = time.time() - start
    contact = sorted(glob.glob(os.path.join(folder, "contact-*.csv")))[-1]
    force = hertz_error.read_tribos_force(os.path.join(folder,
                                                       "history.csv"))
    error = hertz_error.profile_error(
        hertz_error.read_tribos_contact(contact, dim), factor * force,
        radius, young / (1 - nu * nu), dim)
    history = list(csv.DictReader(open(os.path.join(folder,
                                                    "history.csv"))))
    in_process = float(history[-1]["wall_time"])
    return wall, {"tribos_dofs": summary_value(folder, "dofs"),
                  "tribos_newton": summary_value(folder,
                                                 "newton iterations "),
                  "tribos_error": "%.4f" % error}, in_process


def run_getfem(case, results):
    _, _, getfem_mesh, dim = CASES[case][:4]
    path = getfem_mesh if os.path.isabs(getfem_mesh) else mesh(getfem_mesh)
    start = time.time()
    result = subprocess.run(["/usr/bin/python3",
                             os.path.join(HERE, "getfem_hertz.py"),
                             "--dim", str(dim), "--mesh", path,
                             "--csv", results] + CASES[case][9],
                            stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    rows = list(csv.DictReader(open(results))) if os.path.exists(results) \
        else []
    # getfem_hertz.py exits with 1 after writing its row if Newton did not
    # converge: that run counts, as "no convergence".
    if result.returncode != 0 and not (result.returncode == 1 and rows and
                                       rows[-1]["converged"] == "False"):
        sys.exit("GetFEM failed on %s (exit status %d):\n%s"
                 % (case, result.returncode, result.stderr[-2000:]))
    row = rows[-1]
    converged = row["converged"] == "True"
    return wall, {"getfem_dofs": row["dofs_u"],
                  "getfem_newton": row["newton_iterations"],
                  "getfem_error": ("%.4f" % float(row["profile_error"]))
                  if converged else "no convergence"}, converged


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--out", default="")
    parser.add_argument("--only", default="")
    parser.add_argument("--set", action="append", default=[])
    args = parser.parse_args()
    try:
        import getfem  # noqa: F401
    except ImportError:
        sys.exit("GetFEM is missing: apt-get install python3-getfem, and "
                 "run with /usr/bin/python3 (benchmarks/peers/README.md)")
    fields = ["case", "runs", "tribos_dofs", "getfem_dofs", "tribos_newton",
              "getfem_newton", "tribos_error", "getfem_error", "tribos_wall",
              "getfem_wall", "ratio", "tribos_in_process", "getfem_failures"]
    rows = []
    print(",".join(fields), flush=True)
    with tempfile.TemporaryDirectory() as work:
        for case in CASES:
            if args.only and args.only not in case:
                continue
            row = {"case": case, "runs": args.runs}
            walls = {"tribos": [], "getfem": []}
            failures = 0
            in_process = []
            for k in range(args.runs):
                wall, values, inside = run_tribos(
                    os.path.abspath(args.tribos), case,
                    os.path.join(work, "%s_%d" % (case, k)), args.set)
                walls["tribos"].append(wall)
                in_process.append(inside)
                row.update(values)
                wall, values, converged = run_getfem(
                    case, os.path.join(work, "getfem.csv"))
                walls["getfem"].append(wall)
                failures += 0 if converged else 1
                if converged or "getfem_error" not in row:
                    row.update(values)
            row["getfem_failures"] = failures
            for code in walls:
                row[code + "_wall"] = "%.3f" % statistics.median(walls[code])
            row["ratio"] = "%.3f" % (statistics.median(walls["tribos"]) /
                                     statistics.median(walls["getfem"]))
            row["tribos_in_process"] = "%.3f" % statistics.median(in_process)
            print(",".join(str(row.get(f, "")) for f in fields), flush=True)
            rows.append(row)
    if args.out:
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=fields)
            writer.writeheader()
            for row in rows:
                writer.writerow(row)


if __name__ == "__main__":
    sys.exit(main())
