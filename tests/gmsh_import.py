"""Gmsh import: physical tags become body and boundary ids, and the two
bodies (E = 3 each, listed per body id) carry the exact uniaxial force."""

import sys

from tribos_test import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
run(tribos, tests + "/gmsh_import.prm", out,
    ["Scene/Mesh file=%s/two_squares.msh" % tests])
row = read_csv(out + "/history.csv")[-1]
exact = 3.0 * 0.01 / 2.0 * 1.0
check(abs(row["RF2_x"] - exact) < 1e-10 * exact + 1e-14,
      "reaction %.12g, exact %.12g" % (row["RF2_x"], exact))
check(abs(row["RF1_x"] + exact) < 1e-10 * exact + 1e-14,
      "reaction at the fixed end %.12g, exact %.12g" % (row["RF1_x"], -exact))
finish()
