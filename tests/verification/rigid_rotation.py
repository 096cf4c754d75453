"""Objectivity of the contact laws: two neo-Hookean blocks pressed together
with friction (mu = 0.3) and sheared below the stick limit (t in [0,
0.1]), then the whole assembly rotated rigidly by 90 degrees in 90
increments (both blocks' clamped faces follow the rotation): about a point
in 2D, about the inclined axis (1, 2, 2)/3 in 3D (the contact normal turns,
and spins about itself). The contact resultant seen in the co-rotating
frame must stay constant to 1e-6 relative, and every node must stay
stuck, with penalty and with Lagrange multipliers; in 2D also with mortar
(whose slip is the change of the mortar weights, so a rigid motion of both
bodies slips nothing).

Before, penalty drifted 3e-3 in 2D: the stick trial projected the
committed traction onto the turned surface (losing cos(dtheta) per step)
and the slip was the relative motion of the slave node itself, which sees
the penetration g_N n turn with the bodies."""

import math
import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
press_end = 0.1
theta = "pi/2*max(t-%g,0)/%g" % (press_end, 1 - press_end)
s = "min(t/%g,1)" % press_end


def rotation_matrix(axis, angle):
    """Rodrigues' rotation matrix (as nested lists of strings or floats)."""
    k = [a / math.sqrt(sum(b * b for b in axis)) for a in axis]
    if isinstance(angle, str):
        c, n, one = "cos(%s)" % angle, "sin(%s)" % angle, "(1-cos(%s))" % angle
        return [["(%s*%.17g + %s*%.17g + %s*%.17g)" % (
            c, 1.0 if i == j else 0.0,
            n, [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]][i][j],
            one, k[i] * k[j]) for j in range(3)] for i in range(3)]
    c, n = math.cos(angle), math.sin(angle)
    cross = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[c * (i == j) + n * cross[i][j] + (1 - c) * k[i] * k[j]
             for j in range(3)] for i in range(3)]


def rotated_displacement(dim, axis, centre, offset):
    """u(X) = R(theta) (X + offset s - c) + c - X as muparser expressions."""
    R = rotation_matrix(axis, theta)
    names = "xyz"[:dim]
    moved = ["(%s + %g*%s - %g)" % (names[d], offset[d], s, centre[d])
             for d in range(dim)]
    return ", ".join(
        " + ".join("%s*%s" % (R[i][j], moved[j]) for j in range(dim)) +
        " + %g - %s" % (centre[i], names[i]) for i in range(dim))


cases = {
    2: dict(axis=[0, 0, 1], centre=[0.5, 0.5], top=13, bottom=2,
            pairs="12 : 3", offset=[0.002, -0.01],
            scene=["Scene/Two blocks/Lower block size=1, 0.5",
                   "Scene/Two blocks/Upper block size=1, 0.5",
                   "Scene/Two blocks/Lower subdivisions=4, 2",
                   "Scene/Two blocks/Upper subdivisions=3, 2"]),
    3: dict(axis=[1, 2, 2], centre=[0.5, 0.5, 0.5], top=15, bottom=4,
            pairs="14 : 5", offset=[0.002, -0.001, -0.01],
            scene=["Scene/Two blocks/Lower block size=1, 1, 0.5",
                   "Scene/Two blocks/Upper block size=1, 1, 0.5",
                   "Scene/Two blocks/Lower subdivisions=3, 3, 2",
                   "Scene/Two blocks/Upper subdivisions=2, 2, 2"]),
}
for dim, case in cases.items():
    top = rotated_displacement(dim, case["axis"], case["centre"],
                               case["offset"])
    bottom = rotated_displacement(dim, case["axis"], case["centre"],
                                  [0] * dim)
    components = "xyz"[:dim]
    variants = [(m, d) for m in ("penalty", "lagrange multiplier")
                for d in (("node to segment", "mortar") if dim == 2 else
                          ("node to segment",))]
    for method, discretization in variants:
        folder = "%s/%dd_%s_%s" % (out, dim, method.split()[0],
                                   discretization.split()[0])
        run(tribos, tests + "/sliding_block.prm", folder, case["scene"] + [
            "Dimension=%d" % dim, "Scene/Name=two blocks",
            "Materials/Model=neo-Hookean", "Materials/Young's modulus=1",
            "Materials/Poisson's ratio=0.3",
            "Boundary conditions/Dirichlet=%d : %s : %s ; %d : %s : %s"
            % (case["top"], components, top, case["bottom"], components,
               bottom),
            "Contact/Pairs=" + case["pairs"], "Contact/Method=" + method,
            "Contact/Discretization=" + discretization,
            "Contact/Friction coefficient=0.3",
            "Contact/Rigid surfaces=",
            "Time stepping/End time=1", "Time stepping/Number of steps=100",
            "Output/Write VTU=false"])
        rows = [r for r in read_csv(folder + "/history.csv")
                if r["time"] >= press_end - 1e-12]
        reference, worst = None, 0.0
        for r in rows:
            angle = math.pi / 2 * max(r["time"] - press_end, 0) / (
                1 - press_end)
            R = rotation_matrix(case["axis"], angle)
            F = [r["pair0_F" + c] for c in components] + [0.0] * (3 - dim)
            # R^T F: the resultant in the co-rotating frame.
            local = [sum(R[j][i] * F[j] for j in range(3)) for i in range(3)]
            if reference is None:
                reference = local
            worst = max(worst, math.dist(local, reference) /
                        math.hypot(*reference))
        sticking = all(r["n_slip"] == 0 and r["n_stick"] == r["n_active"] > 0
                       for r in rows)
        tangential = math.hypot(*reference[:dim - 1])
        check(len(rows) == 91 and worst < 1e-6 and sticking and
              tangential > 0.02 * abs(reference[dim - 1]),
              "%dD %s, %s: co-rotating contact resultant constant to %.1e "
              "over 90 degrees (tangential/normal %.3f), every node stuck"
              % (dim, method, discretization, worst,
                 tangential / abs(reference[dim - 1])))
finish()
