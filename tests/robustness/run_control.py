"""Runs that share or lose their output directory (issue 47).

- Lock: a second run into the Output/Directory of a running one exits 1
  with a message naming the directory and the other process; the first
  run completes with a whole history (every row the header's width, time
  increasing).
- Signals: SIGTERM and SIGINT during a run end it with exit status 143 and
  130, summary.txt saying INTERRUPTED and naming the signal, every row of
  history.csv whole, and no partial (*.part) file left.
- Reuse: a run into a directory that holds an earlier run's checkpoints
  removes them (a restart from them would mix two runs)."""

import csv
import glob
import os
import signal
import subprocess
import sys
import time

from tribos_testing import PARAMETERS, setup, run, check, finish

tribos, tests, out = setup(sys.argv)
prm = PARAMETERS + "/bar_impact.prm"
# Long enough to be interrupted: 20000 implicit steps (about a minute).
long_run = ["Time stepping/Number of steps=20000"]


def start(folder, sets):
    command = [tribos, prm, "--set", "Output/Directory=" + folder]
    for s in sets:
        command += ["--set", s]
    return subprocess.Popen(command, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def wait_for_rows(folder, n_rows, process, timeout=60):
    """Wait until history.csv has n_rows data rows."""
    path = folder + "/history.csv"
    end = time.time() + timeout
    while time.time() < end and process.poll() is None:
        if os.path.exists(path):
            with open(path) as f:
                if sum(1 for _ in f) > n_rows:
                    return True
        time.sleep(0.05)
    return False


def history_is_whole(folder):
    with open(folder + "/history.csv") as f:
        rows = list(csv.reader(f))
    width = len(rows[0])
    times = [float(r[1]) for r in rows[1:]]
    return (all(len(r) == width for r in rows)
            and all(b > a for a, b in zip(times, times[1:])))


# The lock.
shared = out + "/shared"
first = start(shared, ["Time stepping/Number of steps=4000"])
check(wait_for_rows(shared, 2, first), "the first run writes its history")
second = subprocess.run([tribos, prm, "--set", "Output/Directory=" + shared],
                        capture_output=True, text=True)
message = "another tribos run writes there (process %d)" % first.pid
check(second.returncode == 1 and message in second.stderr,
      "a second run into the directory exits 1 naming the other process "
      "(status %d: %s)" % (second.returncode, second.stderr.strip()[-300:]))
first.communicate()
check(first.returncode == 0, "the first run completes (status %d)"
      % first.returncode)
check(history_is_whole(shared), "its history is whole: every row of the "
      "header's width, time increasing")
after = subprocess.run([tribos, prm, "--set", "Output/Directory=" + shared,
                        "--set", "Time stepping/Number of steps=10"],
                       capture_output=True, text=True)
check(after.returncode == 0, "once it has ended, the directory is free")

# Signals.
for number, name, status in ((signal.SIGTERM, "SIGTERM", 143),
                             (signal.SIGINT, "SIGINT", 130)):
    folder = "%s/%s" % (out, name)
    process = start(folder, long_run + ["Output/Write VTU=true",
                                        "Output/Frequency=5"])
    check(wait_for_rows(folder, 20, process),
          "%s: the run writes its history" % name)
    process.send_signal(number)
    stdout, stderr = process.communicate(timeout=60)
    check(process.returncode == status, "%s: exit status %d (got %d)"
          % (name, status, process.returncode))
    summary = open(folder + "/summary.txt").read() \
        if os.path.exists(folder + "/summary.txt") else ""
    check("INTERRUPTED (%s)" % name in summary,
          "%s: summary.txt says INTERRUPTED (%s)" % (name, name))
    check(history_is_whole(folder), "%s: history.csv is whole" % name)
    check(glob.glob(folder + "/**/*.part", recursive=True) == [],
          "%s: no partial file is left" % name)
    check(len(glob.glob(folder + "/*.vtu")) > 0,
          "%s: the VTU files of the converged steps are kept" % name)

# A reused directory loses the earlier run's checkpoints.
reused = out + "/reused"
run(tribos, prm, reused, ["Time stepping/Number of steps=20",
                          "Output/Checkpoint every=5"])
check(len(glob.glob(reused + "/checkpoint-*")) == 4,
      "the first run writes 4 checkpoints")
run(tribos, prm, reused, ["Time stepping/Number of steps=20"])
check(glob.glob(reused + "/checkpoint-*") == [],
      "a run into the same directory removes them")

finish()
