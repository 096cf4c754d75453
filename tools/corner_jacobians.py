#!/usr/bin/env python3
"""Element quality of a 3D tribos solution: the scaled Jacobian at the eight
corners of every hexahedron in the deformed configuration (reference points
plus the `displacement` field of a solution-*.vtu written by tribos).

    python3 tools/corner_jacobians.py output/upsetting/solution-00020.vtu [N]

Prints the N worst cells (default 5): minimum scaled corner Jacobian
det[e1 e2 e3] / (|e1| |e2| |e3|) (1 for a cube, 0 for a flat corner,
negative for an inverted one), the cell's centre in the reference
configuration and the deformed position of its worst corner. A negative
value means the trilinear map is no longer one-to-one near that corner; the
Gauss points follow as the deformation grows (doc/robustness.md, frictional
upsetting). Standard library only (tools/vtu.py reads the VTU).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu import read_arrays  # noqa: E402


# VTK hexahedron: for each corner, its three edge neighbours in right-handed
# order (bottom face 0-3 counter-clockwise, top face 4-7 above it).
NEIGHBOURS = {0: (1, 3, 4), 1: (2, 0, 5), 2: (3, 1, 6), 3: (0, 2, 7),
              4: (7, 5, 0), 5: (4, 6, 1), 6: (5, 7, 2), 7: (6, 4, 3)}


def scaled_jacobian(e):
    det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
    lengths = 1.
    for v in e:
        lengths *= sum(x * x for x in v) ** 0.5
    return det / lengths


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    arrays = read_arrays(sys.argv[1])
    n_worst = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    points = arrays["Points"][0]
    if "displacement" not in arrays:
        sys.exit("no 'displacement' field in " + sys.argv[1])
    u, n_components = arrays["displacement"]
    connectivity = arrays["connectivity"][0]
    offsets = arrays["offsets"][0]
    if n_components != 3 or offsets[0] != 8:
        sys.exit("expected a 3D hexahedral mesh")
    cells, start = [], 0
    for cell, end in enumerate(offsets):
        ids = connectivity[start:end]
        start = end
        reference = [points[3 * i:3 * i + 3] for i in ids]
        x = [[points[3 * i + d] + u[3 * i + d] for d in range(3)] for i in ids]
        worst, corner = min(
            (scaled_jacobian([[x[j][d] - x[i][d] for d in range(3)]
                              for j in NEIGHBOURS[i]]), i) for i in range(8))
        centre = [sum(p[d] for p in reference) / 8 for d in range(3)]
        cells.append((worst, cell, centre, x[corner]))
    cells.sort()
    print("min scaled corner Jacobian, cell, reference centre, worst corner "
          "(deformed)")
    for worst, cell, centre, corner in cells[:n_worst]:
        print("%9.4f  %5d  (%s)  (%s)" % (
            worst, cell, ", ".join("%.3g" % c for c in centre),
            ", ".join("%.3g" % c for c in corner)))


if __name__ == "__main__":
    main()
