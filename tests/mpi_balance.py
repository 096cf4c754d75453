"""MPI load balance of the contact work (issue 17), `mpirun -np 2`.

The 3D mortar sphere on a block (parameters/hertz_3d.prm with the block,
Contact refinements = 2): METIS' plain partition puts the whole sphere, the
slave, on one process, so that process does all the contact work (half the
run) while the other waits.

* summary.txt must show it: the contact time of a process is its own work,
  not the wait for the others in the collective steps. Before, both
  processes reported the slowest one's time (max/min 1.003).
* Parallel/Contact cell weight spreads the slave cells over both
  processes, and the history is the unweighted one's to 1e-8 (a partition
  changes round-off only).
* The weight with a shared mesh is refused with a message naming it."""

import re
import sys

from tribos_test import setup, run, strip_columns, numdiff, check, finish

tribos, tests, out = setup(sys.argv)
prm = tests + "/../parameters/hertz_3d.prm"
sphere_on_block = ["Output/Write VTU=false",
                   "Scene/Cylinder over block/With block=true",
                   "Scene/Cylinder over block/Contact refinements=2",
                   "Contact/Pairs=10 : 5",
                   "Boundary conditions/Symmetry=12, 13, 0, 2",
                   "Boundary conditions/Dirichlet=11 : z : -0.02*t ; "
                   "4 : xyz : 0, 0, 0",
                   "Contact/Penalty factor=1000*E/h",
                   "Contact/Discretization=mortar"]


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
run(tribos, prm, plain, sphere_on_block, mpi_ranks=2)
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
    sphere_on_block + ["Parallel/Contact cell weight=%d" % suggested],
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

bad = run(tribos, prm, out + "/bad",
          ["Parallel/Mesh=shared", "Parallel/Contact cell weight=5"],
          expect_success=False)
check(bad.returncode == 1 and
      "Parallel/Contact cell weight" in bad.stdout + bad.stderr,
      "a weight with a shared mesh: exit 1 naming the parameter")
finish()
