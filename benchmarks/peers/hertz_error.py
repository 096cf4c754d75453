#!/usr/bin/env python3
"""Hertz pressure error of a contact solution, independent of the code that
produced it: it takes (r, pressure) samples, r the distance from the first
contact point along the contact line (2D, r = |x|) or in the contact plane
(3D, r = sqrt(x^2 + y^2)).

Definition (the one tribos uses in tests/tribos_testing/__init__.py, hertz_compare):
the Hertz a and p0 follow from the load P that the run's contact force
carries (full model, i.e. times the symmetry factor), and

    profile error = sqrt( sum_i (p_i - p_H(r_i))^2 / sum_i p_i^2 )

over the samples with p_i > 0 (nodes in contact), p_H(r) = p0 sqrt(1 -
r^2/a^2) (0 for r > a). It is a nodal (discrete) relative L2 error, not
an integral; on a mesh that is uniform over the contact zone it is close
to the integral one. Also printed: a and p0 from a least-squares fit of
p^2 = p0^2 (1 - r^2/a^2) to the same samples (tribos's hertz_fit), and,
2D only, an integrated relative L2 error (trapezoidal rule over all
samples along the line, contact or not, relative to the exact profile's
L2 norm) for information.

Library use (the GetFEM script does this):

    import hertz_error
    a, p0 = hertz_error.hertz(P, R, e_star, dim)
    err = hertz_error.profile_error(points, P, R, e_star, dim)

Command line, on a tribos run (contact-NNNNN.csv: columns pair, body, x, y,
z, CPRESS, ..., X, Y, Z; history.csv: pair0_normal_force):

    python3 hertz_error.py --dim 2 --contact OUT/contact-00001.csv \\
        --history OUT/history.csv --scale 2 --radius 1 --young 1 --nu 0.3

--scale is the symmetry factor (2: 2D quarter x >= 0; 4: 3D quarter
sphere); --load P (full model) replaces --history. --reference uses the
reference positions X, Y instead of the current x, y (tribos's default is
the current ones). Standard library only.
"""

import argparse
import csv
import math


def hertz(P, radius, e_star, dim):
    """Hertz half-width (2D, P per unit thickness) or contact radius (3D)
    and peak pressure for the full load P."""
    if dim == 2:
        a = math.sqrt(4.0 * P * radius / (math.pi * e_star))
        return a, 2.0 * P / (math.pi * a)
    a = (3.0 * P * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    return a, 3.0 * P / (2.0 * math.pi * a * a)


def hertz_pressure(r, a, p0):
    return p0 * math.sqrt(max(0.0, 1.0 - (r / a) ** 2))


def profile_error(points, P, radius, e_star, dim):
    """tribos's nodal relative L2 error over the samples with p > 0."""
    a, p0 = hertz(P, radius, e_star, dim)
    closed = [(r, p) for r, p in points if p > 0]
    num = sum((p - hertz_pressure(r, a, p0)) ** 2 for r, p in closed)
    den = sum(p * p for r, p in closed)
    return math.sqrt(num / den)


def integrated_error_2d(points, P, radius, e_star):
    """Trapezoidal L2 error along the line over all samples (2D), relative
    to the exact profile's L2 norm over [0, a]; the samples must cover the
    contact zone and a little beyond."""
    a, p0 = hertz(P, radius, e_star, 2)
    pts = sorted(points)
    num = 0.0
    for (r1, q1), (r2, q2) in zip(pts, pts[1:]):
        e1 = q1 - hertz_pressure(r1, a, p0)
        e2 = q2 - hertz_pressure(r2, a, p0)
        num += 0.5 * (r2 - r1) * (e1 * e1 + e2 * e2)
    # int_0^a p0^2 (1 - r^2/a^2) dr = 2/3 p0^2 a
    return math.sqrt(num / (2.0 / 3.0 * p0 * p0 * a))


def fit(points):
    """p0 and a of the least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to
    the samples with p > 0 (as tribos's hertz_fit)."""
    closed = [(r, p) for r, p in points if p > 0]
    n = len(closed)
    sx = sum(r ** 2 for r, p in closed)
    sy = sum(p ** 2 for r, p in closed)
    sxx = sum(r ** 4 for r, p in closed)
    sxy = sum(r ** 2 * p ** 2 for r, p in closed)
    slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    intercept = (sy - slope * sx) / n
    return math.sqrt(intercept), math.sqrt(-intercept / slope)


def extent(points):
    """Largest r among the samples with p > 0."""
    return max(r for r, p in points if p > 0)


def report(points, P, radius, e_star, dim):
    """A dict of the comparison: Hertz a, p0; fitted a, p0; largest r in
    contact; number of samples in contact; profile error; (2D) integrated
    error."""
    a, p0 = hertz(P, radius, e_star, dim)
    p0_fit, a_fit = fit(points)
    out = dict(P=P, a=a, p0=p0, a_fit=a_fit, p0_fit=p0_fit,
               r_contact=extent(points),
               n_contact=sum(1 for r, p in points if p > 0),
               p_max=max(p for r, p in points),
               profile_error=profile_error(points, P, radius, e_star, dim))
    if dim == 2:
        out["integrated_error"] = integrated_error_2d(points, P, radius,
                                                      e_star)
    return out


def read_tribos_contact(path, dim, reference=False, pair=None):
    """(r, CPRESS) of every row of a tribos contact-NNNNN.csv (optionally
    of one pair), r from the current (x, y) or reference (X, Y) position."""
    xn, yn = ("X", "Y") if reference else ("x", "y")
    points = []
    with open(path) as f:
        for row in csv.DictReader(f):
            if pair is not None and int(float(row["pair"])) != pair:
                continue
            x, y = float(row[xn]), float(row[yn])
            r = math.hypot(x, y) if dim == 3 else abs(x)
            points.append((r, float(row["CPRESS"])))
    return points


def read_tribos_force(path, column="pair0_normal_force"):
    """The contact normal force of the last row of a tribos history.csv."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return float(rows[-1][column])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dim", type=int, choices=(2, 3), required=True)
    parser.add_argument("--contact", required=True,
                        help="tribos contact-NNNNN.csv")
    parser.add_argument("--history", help="tribos history.csv (for P)")
    parser.add_argument("--load", type=float,
                        help="full-model load P instead of --history")
    parser.add_argument("--scale", type=float, default=1.0,
                        help="symmetry factor applied to the history force")
    parser.add_argument("--radius", type=float, required=True)
    parser.add_argument("--young", type=float, required=True)
    parser.add_argument("--nu", type=float, required=True)
    parser.add_argument("--pair", type=int)
    parser.add_argument("--reference", action="store_true")
    args = parser.parse_args()
    if args.load is not None:
        P = args.load
    elif args.history:
        P = read_tribos_force(args.history) * args.scale
    else:
        parser.error("give --history or --load")
    e_star = args.young / (1.0 - args.nu ** 2)
    points = read_tribos_contact(args.contact, args.dim, args.reference,
                                 args.pair)
    for key, value in report(points, P, args.radius, e_star,
                             args.dim).items():
        print("%-17s %.6g" % (key, value))


if __name__ == "__main__":
    main()
