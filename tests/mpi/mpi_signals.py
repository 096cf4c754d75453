"""MPI: a signal stops a run under mpirun between two Newton iterations.
SIGTERM sent to the ranks (mpirun's children) ends the run with their
status 143, which mpirun passes on, and summary.txt says INTERRUPTED
(SIGTERM). SIGTERM sent to mpirun itself reaches the ranks too (Open MPI
4.1 sends them SIGCONT, SIGTERM, then SIGKILL, odls_base_sigkill_timeout
= 1 s apart), but mpirun exits 1 whatever they return: Open MPI's
status for a job it was told to abort, not tribos's (README, exit
status)."""
# ctest: mpirun

import os
import signal
import subprocess
import sys
import time

from tribos_testing import require_mpi, setup, check, finish

tribos, tests, out = setup(sys.argv)
require_mpi()
prm = tests + "/sliding_block.prm"


def children(pid):
    """The processes whose parent is pid (from /proc)."""
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid:
                found.append(int(entry))
    return found


for target, status in (("ranks", 143), ("mpirun", 1)):
    folder = out + "/" + target
    # (Ten seconds between Open MPI's SIGTERM and its SIGKILL, not 1: a
    # loaded machine may need more than one to reach the next iteration.)
    mpirun = subprocess.Popen(
        [os.environ.get("MPIEXEC", "mpirun"), "--mca",
         "odls_base_sigkill_timeout", "10", "-np", "2", tribos, prm,
         "--set", "Output/Directory=" + folder,
         "--set", "Time stepping/Number of steps=40000"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    history = folder + "/history.csv"
    start = time.time()
    while time.time() - start < 60 and (
            not os.path.exists(history) or
            len(open(history).read().splitlines()) < 20):
        time.sleep(0.2)
    for pid in children(mpirun.pid) if target == "ranks" else [mpirun.pid]:
        os.kill(pid, signal.SIGTERM)
    mpirun.communicate(timeout=60)
    summary = open(folder + "/summary.txt").read() \
        if os.path.exists(folder + "/summary.txt") else ""
    check(mpirun.returncode == status and
          "INTERRUPTED (SIGTERM)" in summary,
          "SIGTERM to %s: mpirun exits %d (expected %d), summary.txt says "
          "INTERRUPTED (SIGTERM)" % (target, mpirun.returncode, status))
finish()
