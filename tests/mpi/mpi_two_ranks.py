"""MPI: `mpirun -np 2` gives the same history as the serial run (reactions
and contact forces to 1e-8 relative) on a 3D and a 2D multi-body scene and
three contact scenes (friction on a rigid plane; deformable non-matching
interface; 3D frictional sliding of two blocks, whose contact pattern
changes: MUMPS' solver was destroyed after the matrix it referred to, and
the run crashed); also with Lagrange multipliers (owned with their slave
node, MUMPS) on four of them; the same contact-NNNNN.csv, reports the load
balance (min and max over the processes of their own assembly and contact
time) in summary.txt, and writes the parallel VTU set (.pvtu plus one piece
per rank). The same with Parallel/Mesh = shared (every process holds the
whole mesh). On the distributed mesh, the 2D block and the 3D blocks with
penalty and with multipliers are tests/mpi/mpi_methods.py's np 2 runs,
which carry these checks.

Cases (argv[4]; without one, both run):
  core  the 3D frictional sliding of two blocks with multipliers on the
        shared mesh (the quick set's MPI test)
  rest  every other scene
"""
# ctest: mpirun
# ctest: cases core rest
# ctest: quick-cases core

import os
import sys

from tribos_testing import (require_mpi, setup, run, strip_columns, numdiff,
                            check, finish, parts)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("core", "rest"))
require_mpi()
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all")
lagrange = ["Contact/Method=lagrange multiplier"]
cases = [(name, name, []) for name in ("cylinder_3d", "ring_2d",
                                       "sliding_block", "patch_test",
                                       "sliding_blocks_3d")]
cases += [(name + "_lagrange", name, lagrange)
          for name in ("sliding_block", "patch_test", "ring_2d",
                       "sliding_blocks_3d")]
cases += [(label + "_shared", name, sets + ["Parallel/Mesh=shared"])
          for label, name, sets in cases]
# Run by mpi_methods.py, with these checks.
cases = [c for c in cases if c[0] not in (
    "sliding_block", "sliding_block_lagrange", "sliding_blocks_3d",
    "sliding_blocks_3d_lagrange")]
for label, name, sets in cases:
    if ("core" if label == "sliding_blocks_3d_lagrange_shared" else "rest") \
            not in selected:
        continue
    prm = "%s/%s.prm" % (tests, name)
    name = label
    serial, parallel = out + "/" + name + "_serial", out + "/" + name + "_np2"
    run(tribos, prm, serial, sets)
    run(tribos, prm, parallel, sets + ["Output/Write VTU=true"], mpi_ranks=2)
    strip_columns(serial + "/history.csv", serial + "/h.csv", drop=noisy)
    strip_columns(parallel + "/history.csv", parallel + "/h.csv", drop=noisy)
    numdiff(parallel + "/h.csv", serial + "/h.csv", relative=1e-8,
            absolute=1e-8)
    print("ok      %s: np 2 history equals the serial one" % name)
    contact = [f for f in sorted(os.listdir(serial)) if f.startswith("contact-")]
    for f in contact[-1:]:
        numdiff(parallel + "/" + f, serial + "/" + f, relative=1e-8,
                absolute=1e-10)
        print("ok      %s: %s equals the serial one" % (name, f))
    summary = open(parallel + "/summary.txt").read()
    check("balance assembly  min" in summary and
          "balance contact   min" in summary,
          "%s: summary.txt reports the load balance over the processes"
          % name)
    pieces = [f for f in os.listdir(parallel) if f.endswith(".vtu")]
    check(os.path.exists(parallel + "/solution-00001.pvtu") and
          "solution-00001.0001.vtu" in pieces,
          "%s: .pvtu record and per-rank pieces written" % name)
finish()
