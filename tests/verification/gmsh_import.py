"""Gmsh import: physical tags become body and boundary ids, and the two
bodies (E = 3 each, listed per body id) carry the exact uniaxial force. A
single square whose physical tag is 100 is one body (the log and
summary.txt count distinct body ids, not the largest id + 1)."""
# ctest: labels quick

import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
run(tribos, tests + "/gmsh_import.prm", out,
    ["Scene/Mesh file=%s/two_squares.msh" % tests])
row = read_csv(out + "/history.csv")[-1]
exact = 3.0 * 0.01 / 2.0 * 1.0
check(abs(row["RF2_x"] - exact) < 1e-10 * exact + 1e-14,
      "reaction %.12g, exact %.12g" % (row["RF2_x"], exact))
check(abs(row["RF1_x"] + exact) < 1e-10 * exact + 1e-14,
      "reaction at the fixed end %.12g, exact %.12g" % (row["RF1_x"], -exact))

single = out + "/tag100"
result = run(tribos, tests + "/gmsh_import.prm", single,
             ["Scene/Mesh file=%s/square_tag100.msh" % tests,
              "Materials/Young's modulus=3"])
summary = open(single + "/summary.txt").read()
check(" 1 body," in result.stdout and "\nbodies            1\n" in summary,
      "physical tag 100 alone: 1 body in the log and in summary.txt")
row = read_csv(single + "/history.csv")[-1]
check(abs(row["RF2_x"] - 0.03) < 1e-10 * 0.03,
      "tag 100 carries the uniaxial force %.12g of E = 3" % row["RF2_x"])
finish()
