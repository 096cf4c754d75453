"""Gmsh files, read by tribos's own reader (issue 56): every malformed file
is refused with exit status 1, a message that names the file's line, and
no output; nothing crashes, hangs or reports "unknown exception" (deal.II's
reader and libgmsh crashed, hung or silently changed the mesh on several
of these). Legal files the earlier readers failed on run: MSH 4.1 node
tags of 2^31 and more give the same result as small tags. A second-order
mesh runs with Q2 by default (Polynomial degree = as meshed). A node
coordinate beyond the input's range (1e300) is refused as such, at its
line (it was reported as a degenerate cell).

Each case is the two squares of tests/data/two_squares.msh (two bodies side by
side, uniaxial tension: the exact reaction is 0.015) written with one
defect."""

import os
import sys

from tribos_testing import setup, run_or_hang, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = tests + "/gmsh_import.prm"
exact = 3.0 * 0.01 / 2.0

NODES = ["1 0 0 0", "2 1 0 0", "3 2 0 0", "4 0 1 0", "5 1 1 0", "6 2 1 0"]
ELEMENTS = ["1 1 2 1 1 1 4", "2 1 2 2 2 3 6", "3 3 2 1 1 1 2 5 4",
            "4 3 2 2 2 2 3 6 5"]


def msh2(nodes=NODES, elements=ELEMENTS, n_nodes=None, n_elements=None,
         version="2.2"):
    """An MSH 2 file of the given node and element lines."""
    return "\n".join(
        ["$MeshFormat", version + " 0 8", "$EndMeshFormat", "$Nodes",
         str(len(nodes) if n_nodes is None else n_nodes)] + nodes +
        ["$EndNodes", "$Elements",
         str(len(elements) if n_elements is None else n_elements)] +
        elements + ["$EndElements", ""])


def msh41(tags, n_header=None):
    """The two squares in MSH 4.1 with node tags tags (one per node)."""
    t = [str(x) for x in tags]
    n = len(t) if n_header is None else n_header
    return "\n".join([
        "$MeshFormat", "4.1 0 8", "$EndMeshFormat",
        "$Entities", "0 2 2 0",
        "1 0 0 0 0 1 0 1 1 0", "2 2 0 0 2 1 0 1 2 0",
        "1 0 0 0 1 1 0 1 1 0", "2 1 0 0 2 1 0 1 2 0",
        "$EndEntities",
        "$Nodes", "1 %d %s %s" % (n, min(tags), max(tags)),
        "2 1 0 6"] + t + [" ".join(p.split()[1:]) for p in NODES] + [
        "$EndNodes",
        "$Elements", "4 4 1 4",
        "1 1 1 1", "1 %s %s" % (t[0], t[3]),
        "1 2 1 1", "2 %s %s" % (t[2], t[5]),
        "2 1 3 1", "3 %s %s %s %s" % (t[0], t[1], t[4], t[3]),
        "2 2 3 1", "4 %s %s %s %s" % (t[1], t[2], t[5], t[4]),
        "$EndElements", ""])


folder = out + "/meshes"
os.makedirs(folder, exist_ok=True)


def write(name, text):
    path = "%s/%s.msh" % (folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def refused(name, text, expected, sets=()):
    """The file is refused: exit 1, the message holds expected (with the
    line where one is given), no history.csv."""
    path = write(name, text)
    result = run_or_hang(tribos, prm, out + "/" + name,
                         ["Scene/Mesh file=" + path] + list(sets), timeout=60)
    message = result.stdout.strip().splitlines()
    message = message[-1] if message else ""
    check(result.returncode == 1 and expected in result.stdout
          and "unknown exception" not in result.stdout
          and not os.path.exists(out + "/" + name + "/history.csv"),
          "%s: exit %d, %s" % (name, result.returncode,
                               message[-160:] if message else "(no message)"))


def reaction(name, text, sets=()):
    """The file runs: its reaction RF2_x."""
    path = write(name, text)
    result = run_or_hang(tribos, prm, out + "/" + name,
                         ["Scene/Mesh file=" + path] + list(sets), timeout=60)
    if result.returncode != 0:
        print(result.stdout)
        return float("nan")
    return read_csv(out + "/" + name + "/history.csv")[-1]["RF2_x"]


# Legal files: MSH 2.2 and 4.1, small and huge node tags, the same result.
for name, text in (("msh22", msh2()),
                   ("msh41", msh41(range(1, 7))),
                   ("msh41_tags_2e31", msh41(range(2**31, 2**31 + 6))),
                   ("msh41_tags_2e63",
                    msh41([2**63 + 7 * i for i in range(6)]))):
    force = reaction(name, text)
    check(abs(force - exact) < 1e-10 * exact,
          "%s runs: reaction %.12g, exact %.12g" % (name, force, exact))

# Item 3: wrong content accepted (a node defined twice, the second won; a
# short element count read fewer cells; an element line missing a node
# took one from the next line; a 3D mesh ran its surface as a 2D mesh).
twice = NODES + ["5 1.05 1 0"]
refused("node_twice", msh2(nodes=twice), "node tag 5 is defined twice")
refused("element_count_short", msh2(n_elements=3),
        "more entries than announced")
refused("element_count_long", msh2(n_elements=5),
        "lists fewer entries than it announces")
refused("element_missing_node",
        msh2(elements=ELEMENTS[:2] + ["3 3 2 1 1 1 2 5"] + ELEMENTS[3:]),
        "its line needs 9 numbers")
lines = open(tests + "/quarter_disc_tri6.msh").read().split("\n")
count = lines.index("$Elements") + 1
lines[count] = str(int(lines[count]) - 3)
refused("tri6_element_count_short", "\n".join(lines),
        "more entries than announced")
refused("tet10_with_dimension_2", open(tests + "/ball_octant_tet10.msh").read(),
        "but Dimension = 2")

# Items 6 and 7: crashes and hangs. An MSH 4.1 $Nodes header that
# announces fewer nodes than its blocks list; an element line with one
# token too many; a six-node triangle with five nodes.
refused("msh41_nodes_header_short", msh41(range(1, 7), n_header=5),
        "the blocks list more than the 5 nodes")
refused("element_extra_token",
        msh2(elements=ELEMENTS[:2] + ["3 3 2 1 1 1 2 5 4 6"] + ELEMENTS[3:]),
        "its line needs 9 numbers")
tri6 = ["1 9 2 1 1 1 2 5 7 8"]
refused("tri6_short", msh2(nodes=NODES + ["7 0.5 0 0", "8 1 0.5 0"],
                           elements=tri6),
        "its line needs 11 numbers")

# Item 10: what gave "unknown exception", bad_alloc or a late failure.
refused("unknown_type",
        msh2(elements=ELEMENTS[:2] + ["3 99 2 1 1 1 2 5 4"] + ELEMENTS[3:]),
        "element type 99")
refused("missing_node",
        msh2(elements=ELEMENTS[:2] + ["3 3 2 1 1 1 2 5 40"] + ELEMENTS[3:]),
        "refers to node 40")
refused("msh30", msh2(version="3.0"), "tribos reads ASCII MSH 2.0, 2.1, 2.2")
refused("huge_count", msh2(n_nodes=10**18),
        "the section lists fewer entries than it announces")
refused("nan_coordinate",
        msh2(nodes=NODES[:4] + ["5 nan 1 0"] + NODES[5:]),
        "where a coordinate is expected (a finite number)")
# A coordinate beyond the input's range (1e150) overflowed the geometry
# and was reported as a degenerate cell at the element's line.
refused("huge_coordinate",
        msh2(nodes=NODES[:4] + ["5 1e300 1 0"] + NODES[5:]),
        "huge_coordinate.msh:10: '1e300' is out of range for a coordinate")
refused("zero_area",
        msh2(nodes=NODES[:4] + ["5 1 0 0", "6 2 0 0"]),
        "is degenerate (zero area")
refused("twisted",
        msh2(elements=ELEMENTS[:2] + ["3 3 2 1 1 1 5 2 4"] + ELEMENTS[3:]),
        "inverted or twisted")
xz = [" ".join([p.split()[0], p.split()[1], "0", p.split()[2]])
      for p in NODES]
refused("plane_xz", msh2(nodes=xz), "must lie in the x-y plane")
refused("negative_physical",
        msh2(elements=ELEMENTS[:2] + ["3 3 2 -1 1 1 2 5 4"] + ELEMENTS[3:]),
        "physical")
finish()
