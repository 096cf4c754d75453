"""The output directory (issue 56).

(1) A fresh run removes only the numbered series of an earlier run there
    (solution-NNNNN.vtu/.pvtu and rank pieces, contact-NNNNN.csv,
    checkpoint-NNNNN/); a user's contact-notes.txt, solution-report.pdf
    and checkpoint-important/ stay (they were deleted: the prefixes alone
    were matched).
(2) The console piped into a program that closes it (tribos ... | head -2):
    the run goes on to its end and its summary (it was killed by SIGPIPE).
(3) A VTU file that cannot be written (its temporary file on /dev/full, a
    full disk): a clear message naming the file, exit 1, no partial
    file left (deal.II's "output stream error" and the .part file were)."""
# ctest: labels quick

import os
import subprocess
import sys

from tribos_testing import skip, setup, run, check, finish

tribos, tests, out = setup(sys.argv)
prm = tests + "/neo_hookean_stretch.prm"

# (1)
folder = out + "/kept"
os.makedirs(folder + "/checkpoint-important", exist_ok=True)
os.makedirs(folder + "/checkpoint-00099", exist_ok=True)
user_files = ["contact-notes.txt", "solution-report.pdf",
              "checkpoint-important/notes.txt", "solution-0001.vtu",
              "contact-00001.csv.bak"]
stale = ["solution-00099.vtu", "solution-00099.0001.vtu",
         "solution-00099.pvtu", "contact-00099.csv",
         "checkpoint-00099/state.bin", "solution-00098.vtu.part"]
for name in user_files + stale:
    with open(os.path.join(folder, name), "w") as f:
        f.write("x\n")
run(tribos, prm, folder, ["Output/Write VTU=true"])
check(all(os.path.exists(os.path.join(folder, n)) for n in user_files),
      "fresh run: the user's files stay (%s)" % ", ".join(user_files))
check(not any(os.path.exists(os.path.join(folder, n)) for n in stale) and
      not os.path.exists(folder + "/checkpoint-00099"),
      "fresh run: the earlier run's series are removed")

# (2)
piped = out + "/piped"
command = "'%s' '%s' --set Output/Directory='%s' | head -2 > /dev/null; " \
          "exit ${PIPESTATUS[0]}" % (tribos, prm, piped)
result = subprocess.run(["bash", "-c", command], capture_output=True,
                        text=True)
summary = open(piped + "/summary.txt").read() \
    if os.path.exists(piped + "/summary.txt") else ""
check(result.returncode == 0 and "completed" in summary,
      "console piped into head -2: exit %d, summary %s"
      % (result.returncode, "completed" if "completed" in summary else
         "missing"))

# (3)
if os.path.exists("/dev/full"):
    full = out + "/full"
    os.makedirs(full, exist_ok=True)
    part = full + "/solution-00000.vtu.part"
    if os.path.lexists(part):
        os.remove(part)
    os.symlink("/dev/full", part)
    result = run(tribos, prm, full, ["Output/Write VTU=true"],
                 expect_success=False)
    check(result.returncode == 1 and
          "Cannot write <%s/solution-00000.vtu> (disk full?)" % full
          in result.stderr and not os.path.lexists(part) and
          not os.path.exists(full + "/solution-00000.vtu"),
          "VTU on a full disk: exit %d, the file named, no partial file"
          % result.returncode)
else:
    skip("VTU on a full disk: no /dev/full")
finish()
