"""Second-order (curved) gmsh meshes (issue 45): tri6, quad8, quad9,
tet10, hex20 and hex27 read with their mid-side, face and centre nodes
(libgmsh), the cells curved (MappingFEField on the dofs' reference
positions) with Polynomial degree = 2.

- The geometry: a body force's reaction is the volume. The quarter disc
  (tests/data/quarter_disc_*.msh) on curved P2/Q2 has the area pi / 4 within
  2e-5 (measured 9.8e-6 on tri6, 6.1e-7 on quad8 and quad9); with
  Polynomial degree = 1 the cells are straight (a warning says so) and
  the area is 2.9e-3 short. Scene/Refinement = 2 keeps the coarse cells'
  curved geometry (the same area to 1e-12), and so does `mpirun -np 2`
  on a distributed mesh. The ball octant (tests/data/ball_octant_*.msh):
  the volume of gmsh's own element maps to 1e-9 (gmsh 4.8.4's
  getJacobians integrated with its Gauss8 rule: tet10 0.523454964704,
  hex20 0.524305263735, hex27 0.523553253599; the hex20 serendipity map
  becomes a Q2 map exactly, its face and centre points the serendipity
  values), within 2e-3 of pi / 6.
- VTU of a curved mesh: the edge middles sit on the sphere (curved
  quadratic output), not on its chords.
- Symmetry planes on tetrahedra: the paper's cylinder as a gmsh 1/8
  model (tests/data/cylinder_octant_tet10.msh) compressed 1 % by a Dirichlet
  top: Symmetry = 1, 2, 3 gives the force of the same planes held by
  Dirichlet conditions to 1e-10 (deal.II 9.4's no-normal-flux constraints
  left the edges where two planes meet free to slide: 1 % off on P2, 2 %
  on P1). On curved P2 the force is E eps pi r^2 / 4 within 1e-4
  (measured 2.1e-5; straight P1: 1.7 % off). Between frictionless rigid
  plates with multipliers: the Dirichlet force to 1e-10. The same on
  curved hex27 (tests/data/cylinder_octant_hex27.msh: gmsh's hexahedra split
  from tetrahedra, where deal.II's constraints were 0.15 % off too):
  Symmetry = Dirichlet, the force within 1e-3 of E eps pi r^2 / 4
  (measured 9.9e-6), and the rigid plate on the nine-node faces with
  multipliers = Dirichlet to 1e-10.
- A press fit in 3D (tests/data/press_fit_3d.prm): two spherical shells
  meshed separately with curved hex27 (non-matching on r = b, 129 and 39
  nine-node faces), the inner one pressed by a pressure on its inside,
  frictionless mortar with multipliers: all 547 slave nodes closed,
  Lame's thick-sphere pressure to 2.5e-2 RMS (bound 0.04; with the
  standard quadratic functions' dual basis it was 5.2e-2, 8.2e-2 at the
  vertices), the resultant within 1e-2 (measured 2.4e-3); Q1 on the same
  mesh does not fit (49 of 145 closed). The curved run solves with MUMPS
  (Linear solver/Direct solver = Amesos_Mumps): the default direct solve
  of its 29 574 dofs and 1641 multipliers took about 70 s, MUMPS about
  25 s, with the same RMS and resultant to 7 digits.
- Q2 hexahedra (the upper block of tests/data/patch_test_3d.prm) on a rigid
  plane: every vertex, edge middle and face centre of the nine-node faces
  carries the applied pressure, to 1e-12 with multipliers and 1e-8 with
  penalty.
- A press fit (tests/data/press_fit.prm): two rings meshed separately with
  curved cells, the inner one pressed into the outer one by a pressure on
  its inside, frictionless mortar contact with multipliers on the circle
  between them (non-matching): every slave node closed, the pressure
  Lame's (per current length) within 2e-3 on quad9 (measured 9.4e-4) and
  2e-2 on tri6 (measured 1.2e-2); on the straight cells of the same mesh
  (Polynomial degree = 1) the two polygons do not fit and the pressure is
  off by more than 20 % (measured: 14 of its 29 nodes closed, up to 219 %).
- Contact on curved faces, load-controlled Hertz on a rigid plane with
  multipliers: 2D on tests/data/hertz_2d_tri6.msh (curved tri6 of
  benchmarks/peers/hertz_2d.geo) below 3.5 % (measured 2.8 %; the same
  nodes straight: 5.2 %); 3D on tests/data/hertz_3d_tet10.msh (curved tet10
  of hertz_3d.geo, 16236 dofs) below 4.5 % (measured 3.9 %; straight:
  5.7 %) in at most 8 Newton iterations, the contact carrying the
  applied load to 1e-4 (the straight top's facets lose 0.64 % of it).
- The 2D Hertz on the curved mesh with `mpirun -np 2` (distributed mesh)
  gives the serial history, and restarted from a checkpoint every force
  bit for bit.

Cases (argv[4]; without one, both run):
  serial  every run without mpirun.
  mpi     the two MPI comparisons (two cores, one MPI test at a time): the
          quarter disc of curved tri6 at Refinement = 1 with -np 2 on a
          distributed mesh against its serial area to 1e-12; the 2D Hertz on
          curved tri6 (two load steps) with -np 2 against the serial forces
          to 1e-9, each with its serial run.
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi
# ctest: slow-cases serial

import base64
import glob
import math
import os
import shutil
import struct
import sys
import zlib


import hertz_error  # noqa: E402
from tribos_testing import (PARAMETERS, REPOSITORY, setup, run, read_csv,  # noqa: E402
                            check, finish, parts, mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
parameters = PARAMETERS
peers = os.path.join(REPOSITORY, "benchmarks", "peers")
p2 = "Finite element/Polynomial degree=2"


def reaction(folder, key):
    return read_csv(folder + "/history.csv")[-1][key]


# The quarter disc: body force -1e-3 in y, u_y = 0 on y = 0: the reaction
# there is 1e-3 times the area.
def disc(folder, mesh, sets=(), mpi_ranks=0):
    result = run(tribos, tests + "/gmsh_import.prm", folder,
                 ["Scene/Mesh file=%s/quarter_disc_%s.msh" % (tests, mesh),
                  "Scene/Refinement=0", "Materials/Young's modulus=1, 1",
                  "Materials/Poisson's ratio=0.3",
                  "Boundary conditions/Dirichlet=1 : x : 0 ; 2 : y : 0",
                  "Boundary conditions/Body force=0, -1e-3"] + list(sets),
                 mpi_ranks=mpi_ranks)
    return reaction(folder, "RF2_y") / 1e-3, result


# Hertz on a rigid plane, load control.
def hertz(folder, dim, mesh, sets=(), mpi_ranks=0):
    prm = (peers + "/hertz_2d_load.prm" if dim == 2
           else parameters + "/hertz_3d_load.prm")
    run(tribos, prm, folder,
        ["Scene/Name=gmsh", "Scene/Mesh file=%s/%s" % (tests, mesh), p2,
         "Contact/Method=lagrange multiplier", "Output/Write VTU=false"]
        + list(sets), mpi_ranks=mpi_ranks)
    points = hertz_error.read_tribos_contact(
        sorted(glob.glob(folder + "/contact-*.csv"))[-1], dim)
    force = hertz_error.read_tribos_force(folder + "/history.csv")
    factor, radius, young = (2, 1.0, 1.0) if dim == 2 else (4, 10.0, 2e5)
    error = hertz_error.profile_error(points, factor * force, radius,
                                      young / (1 - 0.3 ** 2), dim)
    row = read_csv(folder + "/history.csv")[-1]
    return error, factor * force, row["newton_iterations_all"]


# The MPI part: case mpi.
exact = math.pi / 4
if "mpi" in selected and mpi_part(selected):
    area, _ = disc(out + "/disc_np2", "tri6",
                   [p2, "Parallel/Mesh=distributed", "Scene/Refinement=1"],
                   mpi_ranks=2)
    serial, _ = disc(out + "/disc_tri6_r1", "tri6",
                     [p2, "Scene/Refinement=1"])
    check(abs(area / serial - 1) < 1e-12,
          "quarter disc, curved tri6, -np 2 on a distributed mesh: the "
          "serial area %.10f (to %.1e)" % (area, abs(area / serial - 1)))
    serial = out + "/hertz_2d_np1"
    hertz(serial, 2, "hertz_2d_tri6.msh", ["Time stepping/Number of steps=2"])
    history = read_csv(serial + "/history.csv")
    forces = [k for k in history[0] if k.startswith(("RF", "pair0"))]
    parallel = out + "/hertz_2d_np2"
    hertz(parallel, 2, "hertz_2d_tri6.msh",
          ["Parallel/Mesh=distributed", "Time stepping/Number of steps=2"],
          mpi_ranks=2)
    worst = max(abs(a[k] - b[k]) / max(abs(a[k]), 1e-12)
                for a, b in zip(history, read_csv(parallel + "/history.csv"))
                for k in forces)
    check(worst < 1e-9, "Hertz 2D on curved tri6: -np 2 on a distributed "
          "mesh gives the serial forces (worst relative difference %.1e)"
          % worst)
if "serial" not in selected:
    finish()

# The quarter disc (its -np 2 run: case mpi).
for mesh, bound in (("tri6", 2e-5), ("quad8", 2e-5), ("quad9", 2e-5)):
    area, _ = disc(out + "/disc_" + mesh, mesh, [p2])
    check(abs(area / exact - 1) < bound,
          "quarter disc, curved %s: area %.10f, pi/4 within %.1e (< %.0e)"
          % (mesh, area, abs(area / exact - 1), bound))
    refined, _ = disc(out + "/disc_%s_r2" % mesh, mesh,
                      [p2, "Scene/Refinement=2"])
    check(abs(refined / area - 1) < 1e-12,
          "quarter disc, curved %s, Refinement = 2: the coarse cells' area "
          "%.10f (to %.1e)" % (mesh, refined, abs(refined / area - 1)))
# The default degree follows the mesh: a second-order mesh runs as Q2 with
# its curved geometry (issue 56: the mid-side nodes were dropped).
area, result = disc(out + "/disc_default", "quad9")
check(abs(area / exact - 1) < 2e-5
      and "takes their vertices only" not in result.stderr,
      "quarter disc, quad9, Polynomial degree as meshed (the default): "
      "curved, area within %.1e of pi/4, no warning"
      % abs(area / exact - 1))
area, result = disc(out + "/disc_p1", "quad9",
                    ["Finite element/Polynomial degree=1"])
check(area / exact - 1 < -1e-3
      and "Polynomial degree = 1 takes their vertices only" in result.stderr,
      "quarter disc, quad9 with Polynomial degree = 1: straight cells, area "
      "%.1e short, with the warning" % (1 - area / exact))

# The ball octant: body force -1e-3 in z, u_z = 0 on z = 0.
gmsh_volume = {"tet10": 0.523454964704, "hex20": 0.524305263735,
               "hex27": 0.523553253599}
for mesh, volume in gmsh_volume.items():
    folder = out + "/ball_" + mesh
    run(tribos, tests + "/gmsh_import.prm", folder,
        ["Dimension=3", "Scene/Refinement=0",
         "Scene/Mesh file=%s/ball_octant_%s.msh" % (tests, mesh), p2,
         "Materials/Young's modulus=1, 1", "Materials/Poisson's ratio=0.3",
         "Boundary conditions/Dirichlet=1 : x : 0 ; 2 : y : 0 ; 3 : z : 0",
         "Boundary conditions/Body force=0, 0, -1e-3"])
    v = reaction(folder, "RF3_z") / 1e-3
    check(abs(v / volume - 1) < 1e-9 and abs(v / (math.pi / 6) - 1) < 2e-3,
          "ball octant, curved %s: volume %.10f, gmsh's %.10f to %.1e, "
          "pi/6 within %.1e" % (mesh, v, volume, abs(v / volume - 1),
                                abs(v / (math.pi / 6) - 1)))


# VTU of the curved tet10 ball: its points on the sphere.
def vtu_points(path):
    """The points of a deal.II VTU file (zlib-compressed binary, one
    block: a header of 4 uint32, then the data; Float32 or Float64)."""
    text = open(path).read()
    start = text.find("<Points>")
    tag = text[text.find("<DataArray", start):text.find(">", start + 8)]
    data = text[text.find(">", text.find("<DataArray", start)) + 1:
                text.find("</DataArray>", start)].strip()
    header = struct.unpack("<4I", base64.b64decode(data[:24]))
    raw = zlib.decompress(base64.b64decode(data[24:])[:header[3]])
    fmt = "d" if "Float64" in tag else "f"
    values = struct.unpack("<%d%s" % (len(raw) // struct.calcsize(fmt), fmt),
                           raw)
    return [values[i:i + 3] for i in range(0, len(values), 3)]


on_sphere = {}
for degree in (1, 2):
    folder = "%s/ball_vtu_p%d" % (out, degree)
    run(tribos, tests + "/gmsh_import.prm", folder,
        ["Dimension=3", "Scene/Refinement=0",
         "Scene/Mesh file=%s/ball_octant_tet10.msh" % tests,
         "Finite element/Polynomial degree=%d" % degree,
         "Materials/Young's modulus=1, 1",
         "Boundary conditions/Dirichlet=1 : x : 0 ; 2 : y : 0 ; 3 : z : 0",
         "Boundary conditions/Body force=0, 0, -1e-3",
         "Output/Write VTU=true"])
    points = vtu_points(folder + "/solution-00001.vtu")
    # Float32 points: on the sphere within single precision.
    on_sphere[degree] = len({p for p in points
                             if abs(math.sqrt(sum(x * x for x in p)) - 1)
                             < 1e-6})
check(on_sphere[2] > 3 * on_sphere[1],
      "ball octant, VTU: %d distinct points on the sphere with curved P2 "
      "(vertices and edge middles), %d with P1 (vertices)"
      % (on_sphere[2], on_sphere[1]))

# The cylinder: symmetry planes against Dirichlet conditions.
cylinder = ["Dimension=3", "Scene/Refinement=0",
            "Scene/Mesh file=%s/cylinder_octant_tet10.msh" % tests,
            "Materials/Young's modulus=206.9, 206.9",
            "Materials/Poisson's ratio=0.29"]
planes = {"symmetry": ["Boundary conditions/Symmetry=1, 2, 3",
                       "Boundary conditions/Dirichlet=4 : z : -0.0635*t"],
          "dirichlet": ["Boundary conditions/Dirichlet=1 : x : 0 ; "
                        "2 : y : 0 ; 3 : z : 0 ; 4 : z : -0.0635*t"]}
exact = 206.9 * 0.01 * math.pi * 6.35 ** 2 / 4
for degree in (1, 2):
    force = {}
    for kind, sets in planes.items():
        folder = "%s/cylinder_%s_p%d" % (out, kind, degree)
        run(tribos, tests + "/gmsh_import.prm", folder,
            cylinder + sets + ["Finite element/Polynomial degree=%d" % degree])
        force[kind] = -reaction(folder, "RF4_z")
    difference = abs(force["symmetry"] / force["dirichlet"] - 1)
    check(difference < 1e-10,
          "cylinder octant, tet%d: Symmetry on the three planes gives the "
          "force of Dirichlet planes to %.1e"
          % (4 if degree == 1 else 10, difference))
    error = force["symmetry"] / exact - 1
    check(abs(error) < 1e-4 if degree == 2 else error < -1e-2,
          "cylinder octant, %s: force %.6f, E eps pi r^2 / 4 = %.6f, %.1e"
          % ("curved P2" if degree == 2 else "straight P1", force["symmetry"],
             exact, error))
rigid_plate = ["Boundary conditions/Symmetry=1, 2, 3",
               "Boundary conditions/Dirichlet=", "Contact/Pairs=4 : plate",
               "Contact/Rigid surfaces=plate : plane : 0, 0, 6.35 : "
               "0, 0, -1 : 0, 0, -0.0635*t",
               "Contact/Method=lagrange multiplier"]
plate = out + "/cylinder_plate"
run(tribos, tests + "/gmsh_import.prm", plate, cylinder + [p2] + rigid_plate)
contact = reaction(plate, "pair0_normal_force")
check(abs(contact / force["symmetry"] - 1) < 1e-10,
      "cylinder octant, curved P2 between frictionless rigid plates, "
      "multipliers: the Dirichlet force to %.1e"
      % abs(contact / force["symmetry"] - 1))

# The same cylinder of curved hex27 (Q2): the symmetry planes on gmsh's
# hexahedra (deal.II's constraints were 1.5e-3 off), and a rigid plate on
# the nine-node faces.
hex27 = cylinder[:2] + ["Scene/Mesh file=%s/cylinder_octant_hex27.msh"
                        % tests] + cylinder[3:] + [p2]
force = {}
for kind, sets in planes.items():
    folder = "%s/cylinder_hex27_%s" % (out, kind)
    run(tribos, tests + "/gmsh_import.prm", folder, hex27 + sets)
    force[kind] = -reaction(folder, "RF4_z")
plate = out + "/cylinder_hex27_plate"
run(tribos, tests + "/gmsh_import.prm", plate, hex27 + rigid_plate)
contact = reaction(plate, "pair0_normal_force")
error = force["symmetry"] / exact - 1
check(abs(force["symmetry"] / force["dirichlet"] - 1) < 1e-10 and
      abs(error) < 1e-3 and abs(contact / force["symmetry"] - 1) < 1e-10,
      "cylinder octant, curved hex27 (68 cells): Symmetry = Dirichlet "
      "planes to %.1e; E eps pi r^2 / 4 within %.1e; between rigid plates "
      "(nine-node faces, multipliers) the Dirichlet force to %.1e"
      % (abs(force["symmetry"] / force["dirichlet"] - 1), error,
         abs(contact / force["symmetry"] - 1)))

# Q2 hexahedra on a rigid plane (the upper block of tests/data/patch_test_3d.prm,
# straight): each node of the nine-node faces carries the applied pressure
# (their functions integrate to A/36, A/9 and 4A/9, all positive: the
# node-wise law with those areas is the dual mortar against a plane).
for method, bound in (("lagrange multiplier", 1e-12), ("penalty", 1e-8)):
    folder = "%s/q2_hex_rigid_%s" % (out, method.split()[0])
    run(tribos, tests + "/patch_test_3d.prm", folder,
        [p2, "Contact/Method=" + method, "Contact/Pairs=14 : floor",
         "Contact/Rigid surfaces=floor : plane : 0, 0, 0.5 : 0, 0, 1 : "
         "0, 0, 0"])
    p = [r["CPRESS"] for r in read_csv(folder + "/contact-00001.csv")
         if r["CSTATUS"] != 0]
    spread = max(abs(x - 0.01) for x in p) / 0.01
    check(len(p) == 49 and spread < bound,
          "Q2 hexahedra on a rigid plane, %s: the applied pressure 0.01 at "
          "all %d vertices, edge middles and face centres to %.1e"
          % (method, len(p), spread))


# The press fit: two curved rings in mortar contact (multipliers).
def press_fit(folder, mesh, sets=()):
    run(tribos, tests + "/press_fit.prm", folder,
        ["Scene/Mesh file=%s/press_fit_%s.msh" % (tests, mesh)] + list(sets))
    rows = read_csv(folder + "/contact-00001.csv")
    # Lame's interface pressure, per current length (radius r of the node).
    exact = 0.01 / 3 * (4 / 2.25 - 1) * 1.5
    errors = [r["CPRESS"] / (exact / math.hypot(r["x"], r["y"])) - 1
              for r in rows if r["CSTATUS"] != 0]
    return errors, len(rows)


for mesh, bound in (("quad9", 2e-3), ("tri6", 2e-2)):
    errors, n = press_fit(out + "/press_fit_" + mesh, mesh)
    worst = max(abs(e) for e in errors)
    check(len(errors) == n and worst < bound,
          "press fit of curved %s rings, mortar, multipliers: all %d slave "
          "nodes closed, Lame's pressure within %.1e (< %.0e)"
          % (mesh, n, worst, bound))
errors, n = press_fit(out + "/press_fit_straight", "quad9",
                      ["Finite element/Polynomial degree=1"])
check(len(errors) < n or max(abs(e) for e in errors) > 0.2,
      "press fit on the straight cells of the same mesh (Q1): the two "
      "polygons do not fit, %d of %d slave nodes closed, pressure off by up "
      "to %.0f %%" % (len(errors), n, 100 * max(abs(e) for e in errors)))



# The press fit in 3D: two curved hex27 spherical shells, non-matching on
# r = b, mortar on their nine-node faces with multipliers.
def press_fit_3d(folder, sets=()):
    run(tribos, tests + "/press_fit_3d.prm", folder,
        ["Scene/Mesh file=%s/press_fit_3d_hex27.msh" % tests] + list(sets))
    rows = read_csv(folder + "/contact-00001.csv")
    # Lame's thick sphere, per current area (radius r of the node).
    exact = 0.01 / 7 * (8 / 3.375 - 1)
    errors = [r["CPRESS"] / (exact * 2.25 / (r["x"] ** 2 + r["y"] ** 2 +
                                             r["z"] ** 2)) - 1
              for r in rows if r["CSTATUS"] != 0]
    force = read_csv(folder + "/history.csv")[-1]["pair0_Fz"]
    # The resultant along z: the pressure on the quarter disc under the
    # octant of the sphere r = b.
    force_error = abs(force) / (exact * math.pi * 2.25 / 4) - 1
    rms = math.sqrt(sum(e * e for e in errors) / max(len(errors), 1))
    return errors, len(rows), rms, force_error


errors, n, rms, force_error = press_fit_3d(
    out + "/press_fit_3d_hex27", ["Linear solver/Direct solver=Amesos_Mumps"])
check(len(errors) == n and rms < 0.04 and abs(force_error) < 0.01,
      "press fit of curved hex27 spherical shells, mortar on nine-node "
      "faces, multipliers: all %d slave nodes closed, Lame's pressure to "
      "%.1e RMS (< 0.04; %d %% of the nodes within 10 %%), the resultant "
      "within %.1e (< 1e-2)" % (n, rms, 100 * sum(abs(e) < 0.1
                                                  for e in errors) // n,
                                force_error))
errors, n, rms, force_error = press_fit_3d(
    out + "/press_fit_3d_straight", ["Finite element/Polynomial degree=1"])
check(len(errors) < n or rms > 0.5,
      "press fit in 3D on the straight cells of the same mesh (Q1): the "
      "faceted spheres do not fit, %d of %d slave nodes closed, pressure "
      "%.1f RMS off" % (len(errors), n, rms))

for dim, mesh, bound, load in ((2, "hertz_2d_tri6.msh", 0.035, 0.01),
                               (3, "hertz_3d_tet10.msh", 0.045, 50e3)):
    folder = "%s/hertz_%dd" % (out, dim)
    # 2D in two load steps, with checkpoints (restarted below).
    error, force, newton = hertz(
        folder, dim, mesh,
        ["Output/Checkpoint every=1", "Time stepping/Number of steps=2"]
            if dim == 2 else [])
    check(error < bound and abs(force / load - 1) < 1e-4 and newton <= 8,
          "Hertz %dD on curved %s, multipliers: pressure L2 error %.4f < "
          "%.3f, contact force %.6g (load %g), %d Newton iterations (<= 8)"
          % (dim, mesh, error, bound, force, load, newton))

serial = out + "/hertz_2d"
history = read_csv(serial + "/history.csv")
forces = [k for k in history[0] if k.startswith(("RF", "pair0"))]
restarted = out + "/hertz_2d_restart"
shutil.copytree(serial, restarted)
run(tribos, peers + "/hertz_2d_load.prm", restarted,
    ["Scene/Name=gmsh", "Scene/Mesh file=%s/hertz_2d_tri6.msh" % tests, p2,
     "Contact/Method=lagrange multiplier", "Output/Write VTU=false",
     "Output/Checkpoint every=1", "Time stepping/Number of steps=2"],
    extra=["--restart", serial + "/checkpoint-00001"])
again = read_csv(restarted + "/history.csv")
check(len(again) == len(history) and all(
    a[k] == b[k] for a, b in zip(history, again) for k in forces),
    "Hertz 2D on curved tri6: restarted from its checkpoint, every force "
    "of history.csv bit for bit")
finish()
