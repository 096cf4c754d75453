"""The test suite's serial runs are children of `tribos --fork-server`
(include/tribos/base/fork_server.h; ctest sets TRIBOS_TEST_FORK_SERVER=1):
a forked run must be the run a fresh process makes. The same runs both
ways: a frictional slide with a checkpoint every step (history.csv without
the wall time, every contact-NNNNN.csv, convergence.csv and the
checkpoints' files byte for byte, the console output but for its times),
a bad input (exit status 1 and the same message), an output directory
given relative to the driver's working directory, and a variable of the
environment set after the server started (it must reach the run: Open
MPI told to use a transport layer that does not exist fails the run's
MPI_Init, as in a fresh process)."""
# ctest: labels quick

import filecmp
import os
import re
import sys

from tribos_testing import setup, run, check, finish, strip_columns

tribos, tests, out = setup(sys.argv)


def both(name, prm, sets, expect_success=True):
    """The run in a fresh process and forked: (fresh, forked) results and
    output folders."""
    results, folders = [], []
    for how in ("0", "1"):
        os.environ["TRIBOS_TEST_FORK_SERVER"] = how
        folder = "%s/%s_%s" % (out, name, "forked" if how == "1" else "fresh")
        results.append(run(tribos, prm, folder, sets,
                           expect_success=expect_success))
        folders.append(folder)
    return results, folders


def without_times(text, folder):
    """Console output with its times, memory figures and output folder
    blanked."""
    return re.sub(r"[0-9.e+-]+ ?(s|MB)\b", "#", text.replace(folder, "#"))


# A slide with friction and a checkpoint every step.
(fresh, forked), (a, b) = both(
    "slide", tests + "/sliding_block.prm",
    ["Time stepping/Number of steps=3", "Output/Checkpoint every=1",
     "Output/Write VTU=false"])
for folder in (a, b):
    strip_columns(folder + "/history.csv", folder + "/h.csv")
files = sorted(f for f in os.listdir(a)
               if f.startswith("contact-") or f in ("h.csv",
                                                    "convergence.csv"))
checkpoints = sorted(os.path.relpath(os.path.join(root, f), a)
                     for root, _, names in os.walk(a)
                     if os.path.basename(root).startswith("checkpoint-")
                     for f in names)
differing = [f for f in files + checkpoints
             if not filecmp.cmp(a + "/" + f, b + "/" + f, shallow=False)]
check(fresh.returncode == forked.returncode == 0 and len(files) >= 5 and
      len(checkpoints) >= 3 and not differing,
      "a forked run writes what a fresh process writes, byte for byte "
      "(%d files, %d checkpoint files; differing: %s)"
      % (len(files), len(checkpoints), differing or "none"))
check(without_times(fresh.stdout, a) == without_times(forked.stdout, b) and
      fresh.stderr == forked.stderr,
      "and prints the same (times aside)")

# Bad input.
(fresh, forked), _ = both("bad", tests + "/sliding_block.prm",
                          ["Contact/Method=penalties"], expect_success=False)
check(fresh.returncode == forked.returncode == 1 and
      "Contact/Method" in forked.stderr and fresh.stderr == forked.stderr,
      "bad input: exit status %d forked, %d fresh, the same message"
      % (forked.returncode, fresh.returncode))

# A relative output directory: the run's working directory is the
# driver's at the run, not the server's at its start.
os.environ["TRIBOS_TEST_FORK_SERVER"] = "1"
os.makedirs(out + "/here")
os.chdir(out + "/here")
run(tribos, tests + "/patch_test.prm", "relative")
check(os.path.exists(out + "/here/relative/history.csv"),
      "forked: the output directory relative to the driver's directory")

# The environment at the run, not the server's at its start.
os.environ["OMPI_MCA_pml"] = "no_such_component"
(fresh, forked), _ = both("environment", tests + "/patch_test.prm", [],
                          expect_success=False)
del os.environ["OMPI_MCA_pml"]
check(fresh.returncode != 0 and forked.returncode == fresh.returncode and
      "no_such_component" in forked.stderr,
      "a variable set after the server started reaches the forked run "
      "(OMPI_MCA_pml = no_such_component: exit status %d forked, %d fresh)"
      % (forked.returncode, fresh.returncode))
finish()
