"""Runs that stay within their memory and stop when asked, whatever their
input (the issue's defects B and C). The runs are started directly, not
by the fork server: each gets a limit of its address space (RLIMIT_AS)
of its own, set relative to what a small run of the same program maps
(the libraries, MPI, the threads' arenas), which differs from machine to
machine.

Cases (argv[4]; without one, all run):
  ids         body ids are names, not sizes: the Abaqus deck
              tests/data/blocks_on_plate.inp with Scene/Body sets = PLATE :
              1, BLOCK : 2147483647 (the largest allowed id) runs within
              the small run's address space + 300 MB and 60 s, and its
              history.csv equals the run with BLOCK : 2 (1e-12; the wall
              time aside). Before: a material per id up to the largest (6 GB
              in 43 s without a limit; std::bad_alloc under one).
  adaptivity  Adaptivity with Maximum level 20, Strategy fixed number,
              Refine fraction 0.98 and 20 initial cycles (all allowed; 832
              262 cells and 6 GB in 185 s) on the homogeneous stretch
              (tests/data/neo_hookean_stretch.prm), within the small run's
              address space + 200 MB: every refinement is cut to what the
              memory holds, with a warning, and the run completes (exit 0)
              within 120 s. Before: std::bad_alloc (exit 1).
  signal      a SIGTERM during the setup of a large mesh (the sliding block
              refined 7 times, 524 288 cells: about 7 s of setup, sent
              once the process holds 450 MB) ends the
              run at the next stage of its setup: exit 143, "during the
              setup" on stderr, the output directory as it was (a file of
              the user's kept, no summary.txt, no history.csv). Before: the
              signal waited for the first Newton iteration (a setup that
              outgrew the memory never reached one, so that timeout did not
              stop it).
"""
# ctest: cases ids adaptivity signal

import os
import resource
import signal
import subprocess
import sys
import time

from tribos_testing import setup, check, finish, read_csv, parts

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("ids", "adaptivity", "signal"))


def start(prm, folder, sets, address_space=None):
    """tribos on prm into folder with the overrides sets, its address space
    limited to address_space bytes if given; the process and its start."""
    command = [tribos, prm, "--set", "Output/Directory=" + folder]
    for s in sets:
        command += ["--set", s]

    def limit():
        if address_space is not None:
            resource.setrlimit(resource.RLIMIT_AS,
                               (address_space, address_space))

    process = subprocess.Popen(command, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True,
                               preexec_fn=limit, start_new_session=True)
    return process, time.time()


def finish_run(process, timeout):
    """(status, stdout, stderr, largest address space in bytes) of
    process, killed if it has not ended within timeout seconds."""
    largest, end = 0, time.time() + timeout
    while process.poll() is None and time.time() < end:
        try:
            with open("/proc/%d/status" % process.pid) as f:
                for line in f:
                    if line.startswith("VmPeak:"):
                        largest = max(largest, int(line.split()[1]) * 1024)
        except OSError:
            pass
        time.sleep(0.05)
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        raise SystemExit("FAILED  the run did not end within %d s" % timeout)
    stdout, stderr = process.communicate()
    return process.returncode, stdout, stderr, largest


def run_limited(prm, folder, sets, address_space=None, timeout=60):
    process, begun = start(prm, folder, sets, address_space)
    status, stdout, stderr, largest = finish_run(process, timeout)
    return status, stdout, stderr, largest, time.time() - begun


def without_wall_time(folder):
    rows = read_csv(folder + "/history.csv")
    for row in rows:
        row.pop("wall_time", None)
    return rows


if "ids" in selected:
    deck = tests + "/blocks_on_plate.prm"
    small = out + "/ids_small"
    status, _, stderr, baseline, _ = run_limited(
        deck, small, ["Scene/Body sets=PLATE : 1, BLOCK : 2"])
    check(status == 0, "body ids 1, 2: exit 0 (%s)" % stderr.strip()[-300:])
    large = out + "/ids_large"
    limit = baseline + 300 * 2**20
    status, _, stderr, largest, seconds = run_limited(
        deck, large, ["Scene/Body sets=PLATE : 1, BLOCK : 2147483647"],
        address_space=limit)
    check(status == 0,
          "body ids 1, 2147483647 within %.0f MB of address space: exit 0 in "
          "%.1f s (got %d: %s)" % (limit / 2**20, seconds, status,
                                  stderr.strip()[-300:]))
    a = without_wall_time(large) if status == 0 else []
    b = without_wall_time(small)
    check(len(a) == len(b) and all(
        abs(x[k] - y[k]) <= 1e-12 * max(abs(y[k]), 1.) for x, y in zip(a, b)
        for k in y),
          "its history.csv equals the run with body id 2 (%d rows)" % len(b))

if "adaptivity" in selected:
    stretch = tests + "/neo_hookean_stretch.prm"
    small = out + "/adaptivity_small"
    status, _, stderr, baseline, _ = run_limited(stretch, small, [])
    check(status == 0, "the stretch: exit 0 (%s)" % stderr.strip()[-300:])
    limit = baseline + 200 * 2**20
    folder = out + "/adaptivity_issue"
    status, stdout, stderr, largest, seconds = run_limited(
        stretch, folder,
        ["Adaptivity/Enable=true", "Adaptivity/Maximum level=20",
         "Adaptivity/Strategy=fixed number", "Adaptivity/Refine fraction=0.98",
         "Adaptivity/Initial cycles=20"], address_space=limit, timeout=120)
    cells = [int(line.split(": ")[1].split()[0]) for line in
             stdout.splitlines() if "adapted the mesh" in line]
    check(status == 0 and "was limited to about" in stderr,
          "Maximum level 20, fixed number 0.98, 20 initial cycles within "
          "%.0f MB of address space: exit 0 in %.1f s, the refinement "
          "limited with a warning, at most %d cells (got %d: %s)"
          % (limit / 2**20, seconds, max(cells, default=0), status,
             stderr.strip()[-300:]))
    summary = open(folder + "/summary.txt").read() \
        if os.path.exists(folder + "/summary.txt") else ""
    check("was limited to about" in summary,
          "summary.txt lists the warning")

if "signal" in selected:
    folder = out + "/signal"
    os.makedirs(folder)
    with open(folder + "/notes.txt", "w") as f:
        f.write("the user's\n")
    process, begun = start(tests + "/sliding_block.prm", folder,
                           ["Scene/Refinement=7", "Output/Write VTU=false"])
    # Within the setup, whatever the machine's speed: once the process
    # holds 450 MB (the libraries and MPI take about 330; the mesh's cells,
    # dofs and matrix grow it to 760 over the next 6 s of the setup).
    resident = 0
    while process.poll() is None and resident < 450 * 2**20 and \
            time.time() < begun + 60:
        try:
            with open("/proc/%d/status" % process.pid) as f:
                for line in f:
                    if line.startswith("VmRSS:"):
                        resident = int(line.split()[1]) * 1024
        except OSError:
            pass
        time.sleep(0.02)
    process.send_signal(signal.SIGTERM)
    sent = time.time()
    status, stdout, stderr, _ = finish_run(process, 60)
    check("2D scene" not in stdout,
          "the signal arrived during the setup (no header printed)")
    check(status == 143 and "during the setup" in stderr,
          "SIGTERM during the setup: exit 143 %.1f s after it, "
          "'during the setup' (got %d: %s)"
          % (time.time() - sent, status, stderr.strip()[-300:]))
    check(sorted(os.listdir(folder)) == ["notes.txt"] and
          open(folder + "/notes.txt").read() == "the user's\n",
          "the output directory as it was: %s" % sorted(os.listdir(folder)))

finish()
