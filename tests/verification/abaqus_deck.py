"""Abaqus/CalculiX deck import (Scene/Name = abaqus): tests/data/
blocks_on_plate.inp, a block pressed on a plate in plane strain
(tests/data/blocks_on_plate.prm), and blocks_on_plate_3d.inp in 3D
(blocks_on_plate_3d.prm), the decks' sets their body and boundary ids by
default: bodies PLATE 1, BLOCK 2; boundaries BOTTOM 1, TOP 2, BLOCK_BOTTOM
3, PLATE_TOP 4 (the deck's order).

Asserted:
(a) the 2D deck runs; the log gives the ids above; the block's whole
    bottom is in contact; equilibrium: the contact normal force equals the
    reaction at the plate's bottom and minus that at the block's top, and
    the contact resultant those reactions, to 1e-8 relative, in every step;
(b) the same mesh, written by this test as a gmsh MSH 2.2 file from the
    deck's nodes, elements and sets (physical tags: the ids the sets get),
    run with Scene/Name = gmsh gives the same history.csv (numdiff, without
    wall_time): the deck path and the gmsh path build the same model;
(c) the 3D deck runs with the same equilibrium to 1e-8;
(d) bad input ends with exit status 1, a message that says where and no
    history.csv: an unknown element type names the deck's file and line;
    Body sets naming a set the deck lacks, and a Body sets item without
    its id, name the parameter;
(e) second-order decks (one CPE8, one C3D20 with a curved top) run as
    meshed (Q2) on their curved cells: a body force's reaction is the
    cell's exact area or volume, to 1e-8;
(f) the 3D deck with C3D20 cells and mortar at 1000 E/h, whose contact's
    round-off (|R| about 1.2e-7, corrections of 4e-15) lies above the
    relative tolerance (5e-8), converges (it stalled and exited 2 after
    minutes): in equilibrium to 1e-6 (the floor against N ~ 10);
(g) a node coordinate of 1e300 is refused as out of range (it was a
    degenerate cell), and a GENERATE increment beyond its range is
    refused (it gave the first label alone, and the shifted default ids
    were reported as a Contact/Pairs id), each naming the deck's line."""
# ctest: labels quick

import os
import sys

from tribos_testing import (setup, run, read_csv, check, finish, numdiff,
                            strip_columns)

tribos, tests, out = setup(sys.argv)
out = os.path.abspath(out)
deck_2d = os.path.abspath(tests + "/blocks_on_plate.inp")
prm_2d = tests + "/blocks_on_plate.prm"
prm_3d = tests + "/blocks_on_plate_3d.prm"
BODIES = "Body sets = PLATE : 1, BLOCK : 2 (by default)"
BOUNDARIES = ("Boundary sets = BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 3, "
              "PLATE_TOP : 4 (by default)")


def equilibrium(name, folder, dim, n_slave, tolerance=1e-8):
    """Every step of folder/history.csv: the normal force N > 0 equals the
    reaction at BOTTOM (1) and minus that at TOP (2), the contact resultant
    equals both, the horizontal reactions cancel; to tolerance of N."""
    axis = "xyz"[dim - 1]
    rows = read_csv(folder + "/history.csv")
    check(len(rows) == 3, "%s: %d rows (3 steps)" % (name, len(rows)))
    worst, smallest = 0.0, float("inf")
    for row in rows:
        n = row["pair0_normal_force"]
        smallest = min(smallest, n)
        errors = [row["RF1_" + axis] - n, row["RF2_" + axis] + n,
                  row["pair0_F" + axis] - row["RF1_" + axis]]
        errors += [row["RF1_" + a] + row["RF2_" + a] for a in "xyz"[:dim - 1]]
        worst = max(worst, max(abs(e) for e in errors) / max(n, 1e-300))
    last = rows[-1]
    check(smallest > 0 and last["n_active"] == n_slave,
          "%s: in contact, N = %.10g at the end, %d of the %d slave nodes "
          "active" % (name, last["pair0_normal_force"], last["n_active"],
                      n_slave))
    check(worst < tolerance,
          "%s: equilibrium, N = RF1 = -RF2 = contact resultant to %.1e "
          "(<= %.0e)" % (name, worst, tolerance))
    return rows


# (a) The 2D deck, its relative Input deck found beside the parameter file.
plane = out + "/deck_2d"
result = run(tribos, prm_2d, plane)
check(" 2 bodies," in result.stdout and BODIES in result.stdout
      and BOUNDARIES in result.stdout,
      "2D deck: 2 bodies; the log gives the default ids by set name")
# Refinement 1: the block's bottom has 2 x 2 + 1 nodes.
equilibrium("2D deck", plane, 2, 5)


# (b) The same mesh as a gmsh file.
def read_deck(path):
    """The nodes, elements and sets of a deck of the subset the example
    decks use (*NODE; *ELEMENT, TYPE=, ELSET=; *NSET, GENERATE or labels;
    *SURFACE 'element, S<n>'), in the deck's order."""
    nodes, elements, nsets, surfaces = [], [], [], []
    block, current = None, None
    for line in open(path):
        line = line.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            fields = [f.strip() for f in line[1:].split(",")]
            keyword = fields[0].upper()
            options = {}
            for f in fields[1:]:
                key, _, value = f.partition("=")
                options[key.strip().upper()] = value.strip()
            block = None
            if keyword == "NODE":
                block = "node"
            elif keyword == "ELEMENT":
                block, current = "element", (options["TYPE"].upper(),
                                             options["ELSET"])
            elif keyword == "NSET":
                current = (options["NSET"], "GENERATE" in options, [])
                nsets.append(current)
                block = "nset"
            elif keyword == "SURFACE":
                current = (options["NAME"], [])
                surfaces.append(current)
                block = "surface"
            continue
        fields = [f.strip() for f in line.split(",") if f.strip()]
        if block == "node":
            nodes.append((int(fields[0]), [float(x) for x in fields[1:]]))
        elif block == "element":
            elements.append((int(fields[0]), current[0], current[1],
                             [int(n) for n in fields[1:]]))
        elif block == "nset" and current[1]:
            first, last = int(fields[0]), int(fields[1])
            step = int(fields[2]) if len(fields) > 2 else 1
            current[2].extend(range(first, last + 1, step))
        elif block == "nset":
            current[2].extend(int(n) for n in fields)
        elif block == "surface":
            current[1].append((int(fields[0]), int(fields[1][1:])))
    return nodes, elements, nsets, surfaces


def write_msh(deck, path):
    """The 2D deck as MSH 2.2: its nodes and CPE4 cells (gmsh's
    quadrilateral has Abaqus's node order), physical tag the body id of the
    element set; then, as the reader makes them, one line per boundary
    edge of each node set (the edges all of whose nodes it holds, by
    element and face) and per listed face of each surface, physical tag the
    boundary id, in the deck's order of the sets: ids 1, 2, ..."""
    nodes, elements, nsets, surfaces = read_deck(deck)
    body_ids = {}
    for _, _, elset, _ in elements:
        body_ids.setdefault(elset, len(body_ids) + 1)
    # Face S<k> of a CPE4 joins its corners k and k + 1.
    faces = {}
    for e, (_, kind, _, n) in enumerate(elements):
        assert kind == "CPE4", kind
        for k in range(4):
            faces.setdefault(frozenset((n[k], n[(k + 1) % 4])), []).append(
                (e, k))
    index = {label: e for e, (label, _, _, _) in enumerate(elements)}
    lines = []
    boundary = 0
    # The deck lists its node sets before its surfaces.
    for _, _, members in nsets:
        boundary += 1
        held = set(members)
        found = sorted(uses[0] for edge, uses in faces.items()
                       if len(uses) == 1 and edge <= held)
        for e, k in found:
            n = elements[e][3]
            lines.append((boundary, n[k], n[(k + 1) % 4]))
    for _, listed in surfaces:
        boundary += 1
        for label, s in listed:
            n = elements[index[label]][3]
            lines.append((boundary, n[s - 1], n[s % 4]))
    tag = max(label for label, _, _, _ in elements)
    text = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat",
            "$Nodes", str(len(nodes))]
    text += ["%d %r %r 0" % (label, x[0], x[1]) for label, x in nodes]
    text += ["$EndNodes", "$Elements", str(len(elements) + len(lines))]
    text += ["%d 3 2 %d 0 %s" % (label, body_ids[elset],
                                 " ".join(str(n) for n in cell))
             for label, _, elset, cell in elements]
    for i, (physical, a, b) in enumerate(lines):
        text.append("%d 1 2 %d 0 %d %d" % (tag + 1 + i, physical, a, b))
    text += ["$EndElements", ""]
    with open(path, "w") as f:
        f.write("\n".join(text))
    return len(body_ids), boundary


msh = out + "/blocks_on_plate.msh"
n_bodies, n_boundaries = write_msh(deck_2d, msh)
check(n_bodies == 2 and n_boundaries == 4,
      "gmsh file: 2 bodies and 4 boundaries from the deck's sets")
as_gmsh = out + "/gmsh_2d"
run(tribos, prm_2d, as_gmsh, ["Scene/Name=gmsh", "Scene/Mesh file=" + msh])
strip_columns(plane + "/history.csv", out + "/deck_history.csv")
strip_columns(as_gmsh + "/history.csv", out + "/gmsh_history.csv")
# The same triangulation gives the same numbers; the tolerances only
# allow for round-off (forces are about 2, the residuals 1e-12 and less).
numdiff(out + "/deck_history.csv", out + "/gmsh_history.csv",
        relative=1e-10, absolute=1e-12)
print("ok      the deck and its gmsh file give the same history.csv")

# (c) The 3D deck: its block's bottom has 3 x 3 nodes at Refinement 1.
solid = out + "/deck_3d"
result = run(tribos, prm_3d, solid)
check(" 2 bodies," in result.stdout and BODIES in result.stdout
      and BOUNDARIES in result.stdout,
      "3D deck: 2 bodies; the log gives the default ids by set name")
equilibrium("3D deck", solid, 3, 9)


# (d) Bad input.
def refused(name, sets, expected):
    """A run with the --set overrides sets: exit 1, every string of expected
    in the message, no history.csv (and no mention of the gmsh scene's
    Scene/Mesh file)."""
    folder = out + "/" + name
    result = run(tribos, prm_2d, folder, sets, expect_success=False)
    text = result.stdout + result.stderr
    lines = result.stderr.strip().splitlines() or ["(no message)"]
    check(result.returncode == 1 and all(e in text for e in expected)
          and "unknown exception" not in text
          and "Scene/Mesh file" not in text
          and not os.path.exists(folder + "/history.csv"),
          "%s: exit %d, %s" % (name, result.returncode, lines[-1][-200:]))


def deck_with(line, replacement, name):
    """A copy of the 2D deck named name (in out) with its line line
    replaced: (its path, the line's number)."""
    text = open(deck_2d).read().split("\n")
    at = text.index(line)
    text[at] = replacement
    path = out + "/" + name
    with open(path, "w") as f:
        f.write("\n".join(text))
    return path, at


bad_deck, at = deck_with("*ELEMENT, TYPE=CPE4, ELSET=BLOCK",
                         "*ELEMENT, TYPE=S4R, ELSET=BLOCK", "unknown_type.inp")
refused("unknown_element_type", ["Scene/Input deck=" + bad_deck],
        ["Parameter <Scene/Input deck>", "%s:%d:" % (bad_deck, at + 1),
         "element type 'S4R'"])
refused("missing_body_set",
        ["Scene/Input deck=" + deck_2d,
         "Scene/Body sets=PLATE : 1, BLOK : 2"],
        ["Parameter <Scene/Body sets>", "'BLOK' is no element set"])
refused("body_set_without_id",
        ["Scene/Input deck=" + deck_2d, "Scene/Body sets=PLATE, BLOCK : 2"],
        ["Parameter <Scene/Body sets>", "does not read 'set : id'"])


# (e) Second-order decks are curved as a second-order gmsh file is: a body
# force's reaction is the area (volume) of the curved cell. One CPE8, the
# unit square with its top middle node raised by h: area 1 + 2 h / 3 (the
# parabola's); one C3D20, the unit cube with its top edges' middle nodes
# raised by h: volume 1 + 4 h / 3 (the serendipity face's mean height).
# Both run as meshed (Q2, no warning of dropped nodes), Refinement 1
# keeping the coarse cells' geometry.
def curved_deck(path, dim, h):
    """The deck of one second-order cell, node set BOTTOM its bottom face
    (all its nodes); returns the exact area or volume."""
    if dim == 2:
        x = [(0, 0), (1, 0), (1, 1), (0, 1),
             (0.5, 0), (1, 0.5), (0.5, 1 + h), (0, 0.5)]
        kind, bottom, exact = "CPE8", [1, 2, 5], 1 + 2 * h / 3
    else:
        x = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
             (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1),
             (0.5, 0, 0), (1, 0.5, 0), (0.5, 1, 0), (0, 0.5, 0),
             (0.5, 0, 1 + h), (1, 0.5, 1 + h), (0.5, 1, 1 + h),
             (0, 0.5, 1 + h),
             (0, 0, 0.5), (1, 0, 0.5), (1, 1, 0.5), (0, 1, 0.5)]
        kind, bottom, exact = "C3D20", [1, 2, 3, 4, 9, 10, 11, 12], \
            1 + 4 * h / 3
    labels = [str(i + 1) for i in range(len(x))]
    # At most 16 entries a line: the element continues after a comma.
    element = "1, " + ", ".join(labels[:15]) + (
        ",\n" + ", ".join(labels[15:]) if len(labels) > 15 else "")
    with open(path, "w") as f:
        f.write("*NODE\n" + "".join(
            "%d, %s\n" % (i + 1, ", ".join(repr(float(c)) for c in p))
            for i, p in enumerate(x)))
        f.write("*ELEMENT, TYPE=%s, ELSET=CELL\n%s\n" % (kind, element))
        f.write("*NSET, NSET=BOTTOM\n%s\n"
                % ", ".join(str(n) for n in bottom))
    return exact


for dim, prm, h in ((2, prm_2d, 0.2), (3, prm_3d, 0.1)):
    name = "curved_%dd" % dim
    deck = out + "/" + name + ".inp"
    exact = curved_deck(deck, dim, h)
    zero = ", ".join(["0"] * dim)
    result = run(tribos, prm, out + "/" + name,
                 ["Scene/Input deck=" + deck, "Contact/Pairs=",
                  "Boundary conditions/Dirichlet=1 : %s : %s"
                  % ("xyz"[:dim], zero),
                  "Boundary conditions/Body force=%s, -100"
                  % ", ".join(["0"] * (dim - 1)),
                  "Time stepping/Number of steps=1"])
    measure = read_csv(out + "/" + name + "/history.csv")[-1][
        "RF1_" + "xyz"[dim - 1]] / 100
    check(abs(measure / exact - 1) < 1e-8
          and "takes their vertices only" not in result.stderr,
          "%s deck: the curved cell's %s %.12f, exact %.12f (to %.1e, "
          "<= 1e-8), as meshed (Q2)" % ("CPE8" if dim == 2 else "C3D20",
                                        "area" if dim == 2 else "volume",
                                        measure, exact,
                                        abs(measure / exact - 1)))



# (f) The 3D deck with C3D20 cells (a middle node on every edge, shared
# within a body; BOTTOM and TOP list every node of their faces) and
# mortar. Maximum cutbacks = 0: the stall failed the first increment.
def c3d20_deck(source, path):
    """The C3D8 deck source as C3D20; returns the slave nodes' count."""
    nodes, elements, nsets, surfaces = read_deck(source)
    x = dict(nodes)
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
             (0, 4), (1, 5), (2, 6), (3, 7)]
    middle, cells = {}, []
    for label, _, elset, c in elements:
        extra = []
        for a, b in edges:
            key = (elset,) + tuple(sorted((c[a], c[b])))
            if key not in middle:
                middle[key] = 10000 + len(middle)
                x[middle[key]] = [(p + q) / 2
                                  for p, q in zip(x[c[a]], x[c[b]])]
            extra.append(middle[key])
        cells.append((label, elset, c + extra))
    body_of = {n: elset for _, elset, c in cells for n in c}
    sets = {"BOTTOM": [n for n in sorted(x) if body_of.get(n) == "PLATE"
                       and x[n][2] == 0.0],
            "TOP": [n for n in sorted(x) if body_of.get(n) == "BLOCK"
                    and x[n][2] == 2.0]}
    text = ["*NODE"] + ["%d, %r, %r, %r" % (n, *x[n]) for n in sorted(x)]
    for elset in ("PLATE", "BLOCK"):
        text.append("*ELEMENT, TYPE=C3D20, ELSET=%s" % elset)
        for label, e, c in cells:
            if e == elset:
                text += ["%d, %s," % (label, ", ".join(map(str, c[:15]))),
                         ", ".join(map(str, c[15:]))]
    for name, _, _ in nsets:
        members = sets[name]
        text.append("*NSET, NSET=%s" % name)
        text += [", ".join(map(str, members[k:k + 16]))
                 for k in range(0, len(members), 16)]
    for name, listed in surfaces:
        text.append("*SURFACE, NAME=%s" % name)
        text += ["%d, S%d" % face for face in listed]
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")
    return 25  # 5 x 5 nodes on the block's bottom at Refinement 1


quadratic = out + "/blocks_on_plate_c3d20.inp"
n_slave = c3d20_deck(os.path.abspath(tests + "/blocks_on_plate_3d.inp"),
                     quadratic)
folder = out + "/deck_c3d20_mortar"
result = run(tribos, prm_3d, folder,
             ["Scene/Input deck=" + quadratic,
              "Contact/Discretization=mortar",
              "Time stepping/Maximum cutbacks=0"], expect_success=False)
check(result.returncode == 0,
      "C3D20 deck with mortar at 1000 E/h: exit %d (0: Newton accepts the "
      "residual's round-off floor)" % result.returncode)
if result.returncode == 0:
    equilibrium("C3D20 deck, mortar", folder, 3, n_slave, tolerance=1e-6)


# (g) A coordinate out of range, a GENERATE increment beyond its range.
huge, at = deck_with("2, 0.5, 0.0", "2, 1e300, 0.0", "huge_coordinate.inp")
refused("huge_coordinate", ["Scene/Input deck=" + huge],
        ["%s:%d:" % (huge, at + 1), "'1e300' is out of range for a "
         "coordinate"])
generate, at = deck_with("1, 5, 1", "1, 5, 1000000000000",
                         "generate_step.inp")
refused("generate_huge_step", ["Scene/Input deck=" + generate],
        ["%s:%d:" % (generate, at + 1), "the increment exceeds the range"])

# A folded second-order cell (the CPE8's top middle node pulled down
# below its bottom edge, to y = -0.6): refused, the message naming the deck's parameter and file (it
# named Parameter <Scene/Mesh file>, the gmsh scene's, before).
folded = out + "/folded.inp"
curved_deck(folded, 2, -1.6)
refused("folded_cell",
        ["Scene/Input deck=" + folded, "Contact/Pairs=",
         "Boundary conditions/Dirichlet=1 : xy : 0, 0",
         "Boundary conditions/Body force=0, -100",
         "Time stepping/Number of steps=1"],
        ["Parameter <Scene/Input deck> = <%s>: the curved cell" % folded,
         "is folded"])
finish()
