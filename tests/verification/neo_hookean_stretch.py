"""Verification: uniaxial stretch of a neo-Hookean block against the
analytic homogeneous solution (2D plane strain and 3D), and quadratic
convergence of Newton (observed order >= 1.8 near convergence)."""
# ctest: labels quick

import math
import sys

from tribos_testing.analytic import neo_hookean_stress
from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
E, nu = 1.0, 0.3


def analytic_force(stretch, dim):
    """The block's cross section is 1: the stress is the force (lateral
    stretch free in both directions in 3D, plane strain in 2D)."""
    return neo_hookean_stress(stretch, E, nu, dim - 1)


for dim, sets in ((2, []), (3, ["Dimension=3",
                                "Boundary conditions/Symmetry=0, 2, 4"])):
    folder = "%s/%dd" % (out, dim)
    run(tribos, tests + "/neo_hookean_stretch.prm", folder, sets)
    for row in read_csv(folder + "/history.csv"):
        stretch = 1 + 0.6 * row["time"]
        exact = analytic_force(stretch, dim)
        error = abs(row["RF1_x"] - exact) / abs(exact)
        check(error < 1e-8, "%dD stretch %.2f: reaction %.10g, analytic "
              "%.10g, relative error %.2e < 1e-8"
              % (dim, stretch, row["RF1_x"], exact, error))

    # Newton's observed order where the residual is still well above
    # round-off (relative residual > 1e-13).
    rows = read_csv(folder + "/convergence.csv")
    orders = [r["order"] for r in rows
              if not math.isnan(r["order"]) and r["relative_residual"] > 1e-13]
    print("%dD residual sequence of increment 2: %s" % (dim, ", ".join(
        "%.3e" % r["residual"] for r in rows if r["increment"] == 2)))
    check(len(orders) > 0 and max(orders) >= 1.8,
          "%dD observed Newton orders %s: max >= 1.8"
          % (dim, ", ".join("%.2f" % o for o in orders)))

finish()
