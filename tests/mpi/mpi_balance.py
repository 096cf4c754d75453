"""MPI load balance of the contact work (issue 17), `mpirun -np 2`.

The 3D mortar sphere on a block (parameters/hertz_3d.prm with the block,
Contact refinements = 2, pressed to half the file's depth in two steps:
the partition and the slave nodes do not depend on the load, and the
file's first step of 0.5 cut back once): METIS' plain partition puts the whole sphere, the
slave, on one process, so that process does all the contact work (half the
run) while the other waits.

* summary.txt must show it: the contact time of a process is its own work,
  not the wait for the others in the collective steps. Before, both
  processes reported the slowest one's time (max/min 1.003).
* Parallel/Contact cell weight spreads the slave cells over both
  processes, and the history is the unweighted one's to 1e-8 (a partition
  changes round-off only).
* Parallel/Rebalance threshold = 2: after step 1 the run partitions its
  mesh again with the measured work of each slave node and goes on from
  that step's state; the history and the last contact file are the plain
  run's to 1e-8, and the contact time's max/min falls tenfold or more
  (the weights come from measured times, so the partition varies from
  run to run; 244 before, 1.3 to 2.5 after in development runs).
* The weight with a shared mesh, and a threshold of 0.5, are refused with
  a message naming the parameter."""
# ctest: mpirun

import os
import re
import sys

from tribos_testing import (require_mpi, PARAMETERS, setup, run, strip_columns, numdiff, check, finish,
                         sphere_on_block)

tribos, tests, out = setup(sys.argv)
require_mpi()
prm = PARAMETERS + "/hertz_3d.prm"
mortar_sphere = ["Output/Write VTU=false", "Time stepping/End time=0.5"] \
    + sphere_on_block(2, "mortar")


def balance(folder):
    """(contact time min, max; slave nodes min, max; suggested weight)."""
    text = open(folder + "/summary.txt").read()
    time = re.search(r"balance contact\s+min ([\d.e+-]+) s, max ([\d.e+-]+) s",
                     text)
    nodes = re.search(r"balance slave nodes min (\d+), max (\d+)", text)
    weight = re.search(r"contact cell weight (\d+) would balance", text)
    if not (time and nodes and weight):
        raise SystemExit("%s/summary.txt: no contact balance" % folder)
    return (float(time.group(1)), float(time.group(2)), int(nodes.group(1)),
            int(nodes.group(2)), int(weight.group(1)))


plain, weighted = out + "/plain", out + "/weighted"
run(tribos, prm, plain, mortar_sphere, mpi_ranks=2)
t_min, t_max, n_min, n_max, suggested = balance(plain)
print("plain partition: contact time %.4f / %.4f s, slave nodes %d / %d, "
      "suggested weight %d" % (t_min, t_max, n_min, n_max, suggested))
check(n_min == 0 and n_max > 50,
      "plain partition: one process owns every slave node (the case this "
      "test is about)")
check(t_max > 10 * t_min,
      "plain partition: the process without slave nodes reports a tenth of "
      "the other's contact time or less (its own work, not the wait)")
check(5 <= suggested <= 100,
      "plain partition: the suggested weight (%d) is a slave node's contact "
      "work in cells' assembly" % suggested)

run(tribos, prm, weighted,
    mortar_sphere + ["Parallel/Contact cell weight=%d" % suggested],
    mpi_ranks=2)
w_min, w_max, m_min, m_max, _ = balance(weighted)
print("weighted partition: contact time %.4f / %.4f s, slave nodes %d / %d"
      % (w_min, w_max, m_min, m_max))
check(m_min > 0.5 * m_max,
      "weight %d: the slave nodes are spread over both processes" % suggested)
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all")
for folder in (plain, weighted):
    strip_columns(folder + "/history.csv", folder + "/h.csv", drop=noisy)
numdiff(weighted + "/h.csv", plain + "/h.csv", relative=1e-8, absolute=1e-8)
print("ok      the weighted partition's history equals the plain one's")

rebalanced = out + "/rebalanced"
result = run(tribos, prm, rebalanced,
             mortar_sphere + ["Parallel/Rebalance threshold=2"],
             mpi_ranks=2)
r_min, r_max, s_min, s_max, _ = balance(rebalanced)
print("rebalanced after step 1: contact time %.4f / %.4f s, slave nodes "
      "%d / %d" % (r_min, r_max, s_min, s_max))
summary = open(rebalanced + "/summary.txt").read()
check("rebalance after step 1" in result.stdout and
      "rebalanced        1 time(s), the last after step 1" in summary,
      "threshold 2: the run rebalanced once, after step 1, and says so")
check(r_min > 0 and r_max / r_min < 0.1 * t_max / t_min,
      "rebalanced: the contact time's max/min (%.2f) is a tenth of the plain "
      "run's (%.0f) or less" % (r_max / max(r_min, 1e-300), t_max / t_min))
check(not os.path.exists(rebalanced + "/rebalance"),
      "rebalanced: the state written for the rebalance is removed")
strip_columns(rebalanced + "/history.csv", rebalanced + "/h.csv", drop=noisy)
numdiff(rebalanced + "/h.csv", plain + "/h.csv", relative=1e-8,
        absolute=1e-8)
numdiff(rebalanced + "/contact-00002.csv", plain + "/contact-00002.csv",
        relative=1e-8, absolute=1e-10)
print("ok      the rebalanced run's history and contact file equal the "
      "plain run's")

for sets, entry in ((["Parallel/Mesh=shared", "Parallel/Contact cell weight=5"],
                     "Parallel/Contact cell weight"),
                    (["Parallel/Rebalance threshold=0.5"],
                     "Parallel/Rebalance threshold")):
    bad = run(tribos, prm, out + "/bad", sets, expect_success=False)
    check(bad.returncode == 1 and entry in bad.stdout + bad.stderr,
          "%s: exit 1 naming <%s>" % (", ".join(sets), entry))
finish()
