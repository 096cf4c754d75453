"""MPI: output that one process cannot write ends the run with the error
message and a non-zero exit status instead of hanging.

tribos' output is written by the first process (the CSV files, the
summary) or by each process (its VTU piece). Before the fix a write that
failed on one process raised there alone: that process unwound through its
timers' section ends, each a collective step, the others waited in their
next collective step, and the run hung; when the failed process was not the
first one, its message was not printed either. The three cases, each on 2
processes and, for reference, on one:

* Output/Directory cannot be created (a path through /dev/null): the
  first process found it alone; now every process agrees on the failure
  (exit status 1, the message once);
* history.csv cannot be written (a link to /dev/full, a full disk): the
  same;
* the second process cannot write its VTU piece (a directory of that name
  is in the way): a failure of one process in the middle of a run, which
  the processes cannot agree on in advance; the failed process waits for
  the others a few seconds, then prints its message and aborts the run
  (exit status 1), and the files written so far are kept.
"""
# ctest: mpirun

import os
import sys

from tribos_testing import require_mpi, setup, run_or_hang, check, finish, mpi_available

tribos, tests, out = setup(sys.argv)
prm = tests + "/patch_test.prm"


def run_failing(folder, ranks, sets=()):
    result = run_or_hang(tribos, prm, folder, sets, ranks, timeout=90)
    return result.returncode, result.stdout


require_mpi()

for ranks in (0, 2):
    label = "%d process(es)" % max(ranks, 1)

    # The output directory cannot be created.
    status, output = run_failing("/dev/null/tribos", ranks)
    check(status == 1 and output.count("Output/Directory") == 1
          and "cannot create the directory" in output,
          "%s, Output/Directory under /dev/null: exit status %d, the "
          "message %d time(s)" % (label, status,
                                  output.count("Output/Directory")))

    # history.csv on a full disk.
    folder = out + "/full_disk_np%d" % ranks
    os.makedirs(folder)
    os.symlink("/dev/full", folder + "/history.csv")
    status, output = run_failing(folder, ranks)
    message = "Cannot write to <%s/history.csv> (disk full?)" % folder
    check(status == 1 and output.count(message) == 1,
          "%s, history.csv on a full disk: exit status %d, the message "
          "%d time(s)" % (label, status, output.count(message)))

# The second process cannot write its VTU piece of step 0.
folder = out + "/piece"
piece = folder + "/solution-00000.0001.vtu.part"
os.makedirs(piece + "/in_the_way")
status, output = run_failing(folder, 2, ["Output/Write VTU=true"])
check(status == 1 and ("Cannot write <%s>" % piece) in output
      and "on process 1 of 2 only" in output,
      "2 processes, the second one's VTU piece cannot be written: exit "
      "status %d, its message printed: %s" % (
          status, ("Cannot write <%s>" % piece) in output))
check(os.path.isfile(folder + "/history.csv")
      and os.path.isfile(folder + "/solution-00000.0000.vtu"),
      "2 processes: the files written before the failure are kept")
finish()
