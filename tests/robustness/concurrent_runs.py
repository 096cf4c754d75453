"""Concurrent runs: eight tribos processes (MPI singletons) and one
mpirun -np 2 started at the same moment, five rounds, as a parameter sweep
or ctest -j does. Each singleton has an Open MPI session directory of its
own; with the shared default one, singletons started together raced on
creating it ("A call to mkdir was unable to create the desired directory
... File exists") and died in MPI_Init. Asserts that every run exits 0 and
writes its summary, and that no session directory is left behind.

    concurrent_runs.py TRIBOS TESTS OUT"""
# ctest: mpirun

import glob
import os
import shutil
import subprocess
import sys
import tempfile

from tribos_testing import skip, setup, mpi_available, check, finish

N_SINGLETONS = 8
N_ROUNDS = 5

if __name__ == "__main__":
    tribos, tests, out = setup(sys.argv)
    prm = os.path.join(tests, "patch_test.prm")
    with_mpi = mpi_available()
    if not with_mpi:
        skip("the concurrent mpirun -np 2 run: mpirun not found")
    # A temporary directory of the test's own: what the runs leave there
    # is theirs.
    tmp = tempfile.mkdtemp(prefix="tribos-concurrent-")
    env = dict(os.environ, TMPDIR=tmp)
    failures = []
    n_runs = 0
    for r in range(N_ROUNDS):
        runs = []
        for i in range(N_SINGLETONS + (1 if with_mpi else 0)):
            folder = os.path.join(out, "round%d_run%d" % (r, i))
            command = [tribos, prm, "--set", "Output/Directory=" + folder,
                       "--set", "Output/Write VTU=false"]
            if i == N_SINGLETONS:
                command = [os.environ.get("MPIEXEC", "mpirun"), "-np",
                           "2"] + command
            runs.append((folder, subprocess.Popen(
                command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                text=True, env=env)))
        for folder, process in runs:
            output = process.communicate(timeout=300)[0]
            n_runs += 1
            if process.returncode != 0 or not os.path.exists(
                    os.path.join(folder, "summary.txt")):
                failures.append("%s: exit %d\n%s" % (
                    folder, process.returncode, output[-2000:]))
    for f in failures:
        print(f)
    check(not failures,
          "%d of %d concurrent runs (%d rounds of %d singletons%s) exit 0 "
          "with a summary" % (n_runs - len(failures), n_runs, N_ROUNDS,
                              N_SINGLETONS,
                              " and mpirun -np 2" if with_mpi else ""))
    left = glob.glob(os.path.join(tmp, "tribos-mpi-*"))
    check(not left, "%d singleton session directories left behind"
          % len(left))
    shutil.rmtree(tmp, ignore_errors=True)
    finish()
