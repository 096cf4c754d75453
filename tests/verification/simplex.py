"""Triangles and tetrahedra (P1 and P2, FE_SimplexP), issue 45.

- Homogeneous deformations are exact on simplices as on hexahedra: the
  neo-Hookean uniaxial stretch (2D plane strain and 3D, P1 and P2, the
  scene's cells split by Finite element/Cells = simplices) against the
  analytic stress to 1e-8; J2 plasticity in uniaxial compression and
  unloading (3D, P1 and P2 tetrahedra) against the 1D integration of the
  law to 1e-3; the axisymmetric paper's cylinder between frictionless
  rigid plates on P1 triangles with the force of the Q1 run to 1e-9.
- A gmsh triangle mesh (tests/data/triangles.msh) runs: the uniaxial force
  E u / L exactly.
- Contact on triangle faces (2D): the mortar patch test with Lagrange
  multipliers on split non-matching blocks, P1 and P2, gives the uniform
  pressure of the quadrilateral run at every active node (to 1e-9), and
  `mpirun -np 2` gives the serial history; the load-controlled Hertz 2D on
  a gmsh triangle mesh (tests/data/hertz_2d_tri.msh, 3578 dofs, from
  benchmarks/peers/hertz_2d.geo) with penalty and with multipliers: the
  pressure profile's L2 error against Hertz below 5 % (measured 4.5 %) in
  at most 8 Newton iterations, with the load carried; on P2 triangles
  (tri6 on the same mesh, the rigid plane against quadratic segments)
  below 6 % (measured 5.1 %, 5.2 %).
- Quadratic segments (P2 triangles and Q2 quadrilaterals) on a rigid
  plane: the applied pressure at every vertex and middle node to 1e-8.
- The paper's ring on a foundation on P2 triangles (its 64 x 2 mesh
  split by Cells = simplices: 21 764 dofs, the nodes of Q2 on the mesh
  refined once), mortar with multipliers: the foundation reaction within
  1 % of that Q2 run (tests/data/ring_refined.reference.csv) at the paper's
  steps (measured 0.25 %); P1 triangles lock in bending as Q1 does (more
  than 35 % above at the paper's step 10, our step 11: P1 runs through
  step 11 only, where it is 47 % above; the later steps are 46-49 %).
- A VTU file of quadratic triangles (VTK type 22) is written for a P2
  triangle run; J2 plasticity on P1 warns
  of locking.

Cases (argv[4]; without one, both run):
  serial  every run without mpirun.
  mpi     the mortar patch test on P1 and P2 triangles with -np 2 against
          the serial reactions to 1e-10, with the serial runs (two cores,
          one MPI test at a time).
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi
# ctest: slow-cases serial

import base64
import glob
import math
import os
import struct
import sys
import zlib


import hertz_error  # noqa: E402
from tribos_testing.analytic import J2Uniaxial, neo_hookean_stress  # noqa: E402
from tribos_testing import (PARAMETERS, REPOSITORY, setup, run, read_csv,  # noqa: E402
                            check, finish, parts, mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
split = "Finite element/Cells=simplices"
mortar = ["Contact/Discretization=mortar",
          "Contact/Method=lagrange multiplier"]


def patch_sets(degree):
    return mortar + [split, "Finite element/Polynomial degree=%d" % degree]


# The MPI part: case mpi.
if "mpi" in selected and mpi_part(selected):
    for degree in (1, 2):
        folder = "%s/patch_p%d_np1" % (out, degree)
        parallel = "%s/patch_p%d_np2" % (out, degree)
        run(tribos, tests + "/patch_test.prm", folder, patch_sets(degree))
        run(tribos, tests + "/patch_test.prm", parallel, patch_sets(degree),
            mpi_ranks=2)
        serial_row = read_csv(folder + "/history.csv")[-1]
        parallel_row = read_csv(parallel + "/history.csv")[-1]
        worst = max(abs(parallel_row[k] - serial_row[k])
                    for k in serial_row if k.startswith(("RF", "pair0")))
        check(worst < 1e-10, "mortar patch test, P%d triangles: -np 2 "
              "reactions equal the serial ones (worst difference %.1e)"
              % (degree, worst))
if "serial" not in selected:
    finish()

# Homogeneous: neo-Hookean stretch.
for dim in (2, 3):
    for degree in (1, 2):
        folder = "%s/stretch_%dd_p%d" % (out, dim, degree)
        sets = [split, "Finite element/Polynomial degree=%d" % degree]
        if dim == 3:
            # Three symmetry planes meet at the origin: deal.II 9.4 left
            # a direction free there on P1 tetrahedra (0.5 % off).
            sets += ["Dimension=3", "Boundary conditions/Symmetry=0, 2, 4"]
        run(tribos, tests + "/neo_hookean_stretch.prm", folder, sets)
        worst = 0
        for row in read_csv(folder + "/history.csv"):
            exact = neo_hookean_stress(1 + 0.6 * row["time"], 1.0, 0.3,
                                       dim - 1)
            worst = max(worst, abs(row["RF1_x"] - exact) / abs(exact))
        check(worst < 1e-8, "neo-Hookean stretch, %dD P%d: reaction vs "
              "analytic, worst relative error %.2e < 1e-8"
              % (dim, degree, worst))

# Homogeneous: J2 uniaxial compression and unloading on tetrahedra.
for degree in (1, 2):
    folder = "%s/j2_p%d" % (out, degree)
    result = run(tribos, tests + "/j2_uniaxial.prm", folder,
                 [split, "Finite element/Polynomial degree=%d" % degree])
    material, worst = J2Uniaxial(), 0.0
    for row in read_csv(folder + "/history.csv"):
        u = -0.2 * min(row["time"], 1) + 0.02 * max(row["time"] - 1, 0)
        force = material.update(1 + u) / (1 + u)
        worst = max(worst, abs(row["RF5_z"] - force) / abs(force))
    check(worst < 1e-3, "J2 uniaxial, P%d tetrahedra: force vs 1D "
          "integration, worst relative error %.2e < 1e-3" % (degree, worst))
    warned = "P1 locks" in result.stderr
    check(warned == (degree == 1), "J2 on P%d %s of locking"
          % (degree, "warns" if degree == 1 else "does not warn"))

# A traction on tetrahedron faces: the fixed face carries it.
folder = out + "/traction_3d"
run(tribos, tests + "/neo_hookean_stretch.prm", folder,
    [split, "Dimension=3", "Boundary conditions/Symmetry=",
     "Boundary conditions/Dirichlet=0 : xyz : 0, 0, 0",
     "Boundary conditions/Neumann=1 : 0.01*t, 0.002*t, 0"])
row = read_csv(folder + "/history.csv")[-1]
check(abs(row["RF0_x"] + 0.01) < 1e-10 and abs(row["RF0_y"] + 0.002) < 1e-10,
      "traction on tetrahedron faces: reaction (%.12g, %.12g), load "
      "(0.01, 0.002) on the unit face" % (row["RF0_x"], row["RF0_y"]))

# The paper's cylinder (axisymmetric, frictionless plates): P1 triangles
# and Q1 carry the same force in this homogeneous compression.
forces = {}
for cells in ("as meshed", "simplices"):
    folder = "%s/cylinder_%s" % (out, cells.replace(" ", "_"))
    run(tribos, PARAMETERS + "/cylinder_compression_axisymmetric.prm",
        folder, ["Finite element/Cells=" + cells, "Output/Write VTU=false"])
    forces[cells] = read_csv(folder + "/history.csv")[-1]["pair0_normal_force"]
check(abs(forces["simplices"] - forces["as meshed"])
      <= 1e-9 * abs(forces["as meshed"]),
      "axisymmetric cylinder: P1 triangles %.10g, Q1 %.10g"
      % (forces["simplices"], forces["as meshed"]))

# A gmsh triangle mesh: the unit square pulled along x (nu = 0).
folder = out + "/gmsh_triangles"
run(tribos, tests + "/gmsh_import.prm", folder,
    ["Scene/Mesh file=%s/triangles.msh" % tests,
     "Materials/Young's modulus=3", "Materials/Poisson's ratio=0",
     "Boundary conditions/Symmetry=4",
     "Boundary conditions/Dirichlet=1 : y : 0 ; 2 : x : 0.01*t"])
row = read_csv(folder + "/history.csv")[-1]
check(abs(row["RF2_x"] - 0.03) < 1e-10 * 0.03,
      "gmsh triangles: uniaxial force %.12g, exact 0.03" % row["RF2_x"])


def pressures(folder):
    rows = read_csv(sorted(glob.glob(folder + "/contact-*.csv"))[-1])
    return [r["CPRESS"] for r in rows if r["CSTATUS"] != 0]


# Mortar patch test on triangles (-np 2: case mpi).
run(tribos, tests + "/patch_test.prm", out + "/patch_quads", mortar)
reference = pressures(out + "/patch_quads")[0]
for degree in (1, 2):
    folder = "%s/patch_p%d" % (out, degree)
    run(tribos, tests + "/patch_test.prm", folder, patch_sets(degree))
    p = pressures(folder)
    spread = max(abs(x - reference) for x in p) / reference
    check(len(p) > 4 and spread < 1e-9,
          "mortar patch test, P%d triangles: %d active nodes, pressure of "
          "the quadrilateral run %.10g to %.1e" % (degree, len(p), reference,
                                                   spread))

# Hertz 2D on a gmsh triangle mesh, load control.
peers = os.path.join(REPOSITORY, "benchmarks", "peers")
# P2 on the same mesh: 5.1 % and 5.2 % (the nodal error is the sampling
# of the profile's square-root edge, which the middle nodes do not help).
bound = {1: 0.05, 2: 0.06}
for degree, method in ((1, "penalty"), (1, "lagrange multiplier"),
                       (2, "penalty"), (2, "lagrange multiplier")):
    folder = "%s/hertz_p%d_%s" % (out, degree, method.split()[0])
    run(tribos, peers + "/hertz_2d_load.prm", folder,
        ["Scene/Mesh file=%s/hertz_2d_tri.msh" % tests,
         "Finite element/Polynomial degree=%d" % degree,
         "Contact/Method=" + method])
    points = hertz_error.read_tribos_contact(
        sorted(glob.glob(folder + "/contact-*.csv"))[-1], 2)
    force = hertz_error.read_tribos_force(folder + "/history.csv")
    error = hertz_error.profile_error(points, 2 * force, 1.0,
                                      1.0 / (1 - 0.3 ** 2), 2)
    row = read_csv(folder + "/history.csv")[-1]
    check(error < bound[degree] and abs(force - 0.005) < 1e-8
          and row["newton_iterations_all"] <= 8,
          "Hertz 2D on P%d triangles, %s: pressure L2 error %.4f < %.2f, "
          "contact force %.8f (load 0.005), %d Newton iterations (<= 8)"
          % (degree, method, error, bound[degree], force,
             row["newton_iterations_all"]))

# Quadratic segments on a rigid plane (2D P2 and Q2): the block of
# tests/data/patch_test.prm on the plane y = 0.5 under its uniform load, with
# the nodes' areas h/6, 2h/3, h/6: the applied pressure at every vertex
# and middle node.
for cells in ("simplices", "as meshed"):
    for method in ("penalty", "lagrange multiplier"):
        folder = "%s/rigid_q2_%s_%s" % (out, cells.split()[0],
                                        method.split()[0])
        run(tribos, tests + "/patch_test.prm", folder,
            ["Finite element/Cells=" + cells,
             "Finite element/Polynomial degree=2", "Contact/Method=" + method,
             "Contact/Pairs=12 : floor", "Contact/Rigid surfaces=floor : plane : "
             "0, 0.5, 0 : 0, 1, 0 : 0, 0"])
        p = pressures(folder)
        spread = max(abs(x - 0.01) for x in p) / 0.01
        check(len(p) > 4 and spread < 1e-8,
              "quadratic %s on a rigid plane, %s: the applied pressure at "
              "all %d nodes to %.1e" % (cells, method, len(p), spread))

# VTU on P2 triangles.
folder = out + "/vtu_p2"
run(tribos, tests + "/patch_test.prm", folder,
    mortar + [split, "Finite element/Polynomial degree=2",
              "Output/Write VTU=true"])
vtu = open(folder + "/solution-00001.vtu").read()


def vtk_cell_types(text):
    """The set of VTK cell types of a deal.II VTU file (zlib-compressed
    binary, one block: a header of 4 uint32, then the data)."""
    start = text.find('Name="types"')
    data = text[text.find(">", start) + 1:text.find("</DataArray>", start)]
    data = data.strip()
    header = struct.unpack("<4I", base64.b64decode(data[:24]))
    return set(zlib.decompress(base64.b64decode(data[24:])[:header[3]]))


types = vtk_cell_types(vtu)
check("<VTKFile" in vtu and types == {22},
      "P2 triangles: solution-00001.vtu written with quadratic triangles "
      "(VTK cell types %s, 22 expected)" % sorted(types))
# The ring on a foundation on triangles, against Q2 mortar on the mesh
# refined once, the same nodes (benchmarks/ring_study.sh wrote it).
reference = {int(r["step"]): float(r["RF12_y"])
             for r in read_csv(tests + "/ring_refined.reference.csv")}
ring = PARAMETERS + "/ring_on_foundation.prm"
worst = {}
# P1 through step 11 only (the paper's step 10, the first reference
# step, at the same step size): its locking shows there as at every later
# reference step. It is checked at step 11 alone, which the run must reach.
first = min(reference)
for degree, steps in ((1, ["Time stepping/End time=%d" % first,
                           "Time stepping/Number of steps=%d" % first]),
                      (2, [])):
    folder = "%s/ring_p%d" % (out, degree)
    run(tribos, ring, folder,
        [split, "Finite element/Polynomial degree=%d" % degree,
         "Contact/Method=lagrange multiplier", "Contact/Discretization=mortar",
         "Output/Write VTU=false"] + steps)
    reaction = {int(r["step"]): r["RF12_y"]
                for r in read_csv(folder + "/history.csv")}
    checked = reference if degree == 2 else {first: reference[first]}
    worst[degree] = max(abs(reaction.get(step, math.inf) / f - 1)
                        for step, f in checked.items())
    if degree == 1:
        # A run that missed step 11 would give inf and pass "above".
        check(first in reaction, "ring on P1 triangles: step %d reached"
              % first)
check(worst[2] < 0.01 and worst[1] > 0.35,
      "ring on a foundation, mortar, multipliers: P2 triangles within %.2f "
      "%% of Q2 on the same nodes at the paper's steps (< 1 %%); P1 "
      "triangles %.0f %% above at step %d (locking, as Q1)"
      % (100 * worst[2], 100 * worst[1], first))

finish()
