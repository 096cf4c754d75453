"""MPI, the distributed contact search with a finite Contact/Search
distance: each process receives only the master nodes within the search
distance (plus three face sizes; mortar: and five slave face sizes) of the
slave nodes it evaluates and builds
its search tree over their faces (exchange_master_nodes). The frictional
ironing (2D, node to segment, mortar and mortar with the master's
averaged normals, Search distance = 0.1) and the
frictional 3D blocks (Search distance = 0.05, master faces passing to
another process while they slide) at `mpirun -np 2` and `-np 3` give the
serial history and last contact-NNNNN.csv to 1e-8 (slave nodes beyond the
search distance: COPEN nan in both); the serial history equals the one
with no search limit (the nodes beyond 0.1 are open either way); and the
most values a process receives per search in the ironing is below the
whole master surface's on a block three times as wide (which it receives
with no limit)."""
# ctest: mpirun

import os
import re
import sys

from tribos_testing import require_mpi, setup, run, strip_columns, numdiff, check, finish

tribos, tests, out = setup(sys.argv)
require_mpi()
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all", "chattering_nodes")


def exchanged(folder):
    """The most values one process received in one search (summary.txt)."""
    text = open(folder + "/summary.txt").read()
    found = re.search(r"master exchange\s+max ([\d.e+]+) values", text)
    check(found is not None, "%s: summary.txt reports the master exchange"
          % os.path.basename(folder))
    return float(found.group(1))


def last_contact(folder):
    return sorted(f for f in os.listdir(folder) if f.startswith("contact-"))[-1]


# The faceted master (the defaults would smooth it) and the primal
# penalty, except where a case says otherwise.
faceted = ["Contact/Master smoothing=none",
           "Contact/Penalty formulation=primal"]
cases = [("ironing_nts", "ironing_2d", "0.1", faceted),
         ("ironing_mortar", "ironing_2d", "0.1",
          faceted + ["Contact/Discretization=mortar"]),
         # The element also reads the master nodes beyond its segments.
         ("ironing_mortar_smoothed", "ironing_2d", "0.1",
          ["Contact/Discretization=mortar",
           "Contact/Master smoothing=averaged normals"]),
         ("blocks_3d", "sliding_blocks_3d", "0.05", faceted),
         # The defaults: node to segment on the smoothed 3D master (its
         # faces' neighbours exchanged too), the mixed penalty.
         ("blocks_3d_defaults", "sliding_blocks_3d", "0.05", [])]
for name, scene, distance, sets in cases:
    prm = "%s/%s.prm" % (tests, scene)
    sets = sets + ["Output/Write VTU=false"]
    local = sets + ["Contact/Search distance=" + distance]
    serial = out + "/" + name + "_np1"
    run(tribos, prm, serial, local)
    strip_columns(serial + "/history.csv", serial + "/h.csv", drop=noisy)
    unlimited = out + "/" + name + "_unlimited"
    run(tribos, prm, unlimited, sets)
    strip_columns(unlimited + "/history.csv", unlimited + "/h.csv",
                  drop=noisy)
    numdiff(serial + "/h.csv", unlimited + "/h.csv", relative=1e-8,
            absolute=1e-8)
    print("ok      %s: Search distance = %s gives the history of no limit"
          % (name, distance))
    for ranks in (2, 3):
        parallel = out + "/%s_np%d" % (name, ranks)
        run(tribos, prm, parallel, local, mpi_ranks=ranks)
        strip_columns(parallel + "/history.csv", parallel + "/h.csv",
                      drop=noisy)
        numdiff(parallel + "/h.csv", serial + "/h.csv", relative=1e-8,
                absolute=1e-8)
        numdiff(parallel + "/" + last_contact(serial),
                serial + "/" + last_contact(serial), relative=1e-8,
                absolute=1e-10)
        print("ok      %s: np %d history and %s equal the serial ones"
              % (name, ranks, last_contact(serial)))
    if scene == "sliding_blocks_3d":
        summary = open(out + "/%s_np3/summary.txt" % name).read()
        changes = re.search(r"(\d+) master face changes of process",
                            summary)
        check(changes is not None and int(changes.group(1)) > 0,
              "%s: np 3 pairs slave nodes with master faces that change "
              "process" % name)
    if scene == "ironing_2d":
        # On a block three times as wide (the slave's reach, with mortar
        # 5 slave segments more, spans the 4-wide block).
        wide = ["Scene/Cylinder over block/Block width=12",
                "Scene/Cylinder over block/Block subdivisions=96, 4",
                "Time stepping/End time=1.25", "Time stepping/Number of steps=5"]
        near, whole = out + "/%s_wide_np2" % name, \
            out + "/%s_wide_whole_np2" % name
        run(tribos, prm, near, local + wide, mpi_ranks=2)
        run(tribos, prm, whole, sets + wide, mpi_ranks=2)
        received, everything = exchanged(near), exchanged(whole)
        check(0 < received < 0.6 * everything,
              "%s, block width 12: np 2 receives at most %g values per "
              "search, below 0.6 of the whole master surface's %g"
              % (name, received, everything))
finish()
