#!/usr/bin/env python3
"""Writes fan_master.msh (gmsh 2.2): a master whose flat top face has a
vertex shared by 16 triangles, more than the 12 that Contact/Master
smoothing = averaged normals takes, under a small block of six
tetrahedra. Physical groups: volumes 1 master, 2 block; surfaces 1 the
master's underside, 2 its top, 3 the block's bottom, 4 its top.
tests/robustness/input_warnings.py (Master smoothing = automatic falls
back to the faces) and bad_input.sh (averaged normals refused).

    python3 fan_master.py   # in tests/data
"""
# The master: centre C, 16 rim points on the square's edge, bottom apex B
xs = [-1, -0.5, 0, 0.5, 1, 1, 1, 1, 1, 0.5, 0, -0.5, -1, -1, -1, -1]
ys = [-1, -1, -1, -1, -1, -0.5, 0, 0.5, 1, 1, 1, 1, 1, 0.5, 0, -0.5]
nodes = [(0, 0, 0)] + [(x, y, 0) for x, y in zip(xs, ys)] + [(0, 0, -0.5)]
C, B = 1, 18
rim = lambda i: 2 + i % 16
tets, tris = [], []
def oriented(t):
    p = [nodes[k - 1] for k in t]
    a, b, d = ([p[j][i] - p[0][i] for i in range(3)] for j in (1, 2, 3))
    v = (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
         + a[2] * (b[0] * d[1] - b[1] * d[0]))
    return t if v > 0 else (t[1], t[0], t[2], t[3])
for i in range(16):
    tets.append((1, oriented((C, rim(i), rim(i + 1), B))))
    tris.append((2, (C, rim(i), rim(i + 1))))
    tris.append((1, (B, rim(i + 1), rim(i))))
# block: cube [-0.2, 0.2]^2 x [0, 0.2], six tets (Kuhn)
base = len(nodes)
cube = [(x, y, z) for z in (0, 0.2) for y in (-0.2, 0.2) for x in (-0.2, 0.2)]
nodes += cube
c = lambda k: base + 1 + k  # k = x + 2y + 4z bits
for path in ((1, 2), (2, 1), (1, 4), (4, 1), (2, 4), (4, 2)):
    a = 0; b = path[0]; d = path[0] + path[1]; e = 7
    tets.append((2, oriented((c(a), c(b), c(d), c(e)))))
tris.append((3, (c(0), c(1), c(3)))); tris.append((3, (c(0), c(3), c(2))))
tris.append((4, (c(4), c(5), c(7)))); tris.append((4, (c(4), c(7), c(6))))
with open("fan_master.msh", "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
    for k, p in enumerate(nodes):
        f.write("%d %.17g %.17g %.17g\n" % ((k + 1,) + tuple(p)))
    f.write("$EndNodes\n$Elements\n%d\n" % (len(tris) + len(tets)))
    n = 0
    for tag, t in tris:
        n += 1
        f.write("%d 2 2 %d %d %s\n" % (n, tag, tag, " ".join(map(str, t))))
    for tag, t in tets:
        n += 1
        f.write("%d 4 2 %d %d %s\n" % (n, tag, tag, " ".join(map(str, t))))
    f.write("$EndElements\n")
