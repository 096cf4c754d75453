"""Newton accepts an iterate only when its residual is converged: by the
residual test (|R| <= 1e-8 of the force scale), or, where round-off stops
the residual from falling (a Newton correction below 1e-12 of the
displacement), only below the stated round-off bound 1e-10 E_max A (A the
area scale V^((d-1)/d) of the model).

The frictional ironing of tests/data/ironing_2d.prm with the paper's tangent
(linear convergence) and both bodies translated rigidly by 3e4 (100000
element sizes): the displacements are huge, so a correction of 1e-12 of
them (about 1e-6) is reached while the residual is still well above the
round-off floor (about 6e-10 here). Before, such an iterate was accepted
as stagnated (accepted residuals up to 1.6e-8, seven times the bound);
now Newton goes on until one of the two tests holds."""

import math
import sys

from tribos_testing import setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
shift = 3e4
run(tribos, tests + "/ironing_2d.prm", out, [
    "Contact/Tangent=paper",
    "Boundary conditions/Dirichlet=11 : xy : %g + if(t < 1, 0, 0.25*(t - 1)), "
    "-0.05*min(t, 1) ; 2 : xy : %g, 0" % (shift, shift)])
E_max, volume = 10.0, 4.0 * 1.0 + math.pi / 2   # block 4 x 1, half disc R = 1
bound = 1e-10 * E_max * math.sqrt(volume)
rows = read_csv(out + "/convergence.csv")
last = {}
for r in rows:
    last[r["increment"]] = r
bad = [(r["increment"], r["residual"], r["relative_residual"])
       for r in last.values()
       if r["relative_residual"] > 1e-8 and r["residual"] > bound]
check(len(last) == 12 and not bad,
      "every accepted iterate meets the residual test or |R| <= %.2e "
      "(worst %.2e)" % (bound, max(r["residual"] for r in last.values())))
history = read_csv(out + "/history.csv")
check(history[-1]["time"] == 3, "the translated ironing completes")
finish()
