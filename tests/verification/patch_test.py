"""Contact patch test (tests/data/patch_test.prm): two stacked blocks with
non-matching meshes (upper 3 cells across, lower 5), the lower one on
rollers, the upper one loaded by a uniform pressure p on its top. Exact
solution: uniform compression, a flat loaded surface and, at every node of
both sides of the interface, the contact force p times the node's tributary
length.

Measured from the VTU (contact_force on every node, slave and master; the
displacement of the loaded top) for: one-pass with the coarse side as
slave, one-pass with the fine side as slave, two-pass penalty with k = 1000
and 1e6 (eps_N = k E/h), and one-pass Lagrange multipliers both ways:

  force error   max over the interface nodes of both bodies of
                |F_y - p A| / (p A), A the node's tributary length;
  flatness      (max - min) / |mean| of u_y on the loaded top.

Asserted: equilibrium (the total contact force is p times the width to
1e-8, Newton's residual tolerance) for every variant; two-pass penalty passes the patch test as the
penalty grows (force error and flatness below 2e-5 at k = 1e6 and at least
100 times smaller than at k = 1000: the remaining error is the penalty's
O(1/k)); one-pass node-to-segment fails it by a finite amount, whatever the
penalty (above 1 % with either side as slave, with penalty and with
multipliers alike). The measured values are a regression (numdiff against
tests/data/patch_test.reference.csv) and are reported in doc/contact.md."""
# ctest: labels quick

import os
import shutil
import sys

from tribos_testing import updating_references, reference_updated, setup, run, read_csv, check, finish, numdiff

from vtu import nodal_values  # noqa: E402

tribos, tests, out = setup(sys.argv)
p, width = 0.01, 1.0
interface, top = 0.5, 1.0
cells = {0: 5, 1: 3}  # cells across the lower (body 0) and upper body

variants = [
    ("one-pass coarse slave", ["Contact/Pairs=12 : 3"]),
    ("one-pass fine slave", ["Contact/Pairs=3 : 12"]),
    ("two-pass k=1e3", ["Contact/Passes=two-pass"]),
    ("two-pass k=1e6", ["Contact/Passes=two-pass",
                        "Contact/Penalty factor=1e6*E/h"]),
    ("lagrange coarse slave", ["Contact/Pairs=12 : 3",
                               "Contact/Method=lagrange multiplier"]),
    ("lagrange fine slave", ["Contact/Pairs=3 : 12",
                             "Contact/Method=lagrange multiplier"]),
]
# The paper's node to segment: the faceted master and the primal penalty
# (the defaults, automatic, would smooth the master and solve the penalty
# in mixed form; the mixed form is compared below).
node_to_segment = ["Contact/Master smoothing=none",
                   "Contact/Penalty formulation=primal"]
lines = ["variant,total_force_error,max_node_force_error,"
         "rms_node_force_error,top_flatness"]
measured = {}
for name, sets in variants:
    folder = out + "/" + name.replace(" ", "_").replace("=", "")
    run(tribos, tests + "/patch_test.prm", folder,
        node_to_segment + sets + ["Output/Write VTU=true"])
    vtu = folder + "/solution-00001.vtu"
    # The blocks share one material: tell them apart by the cell's place.
    forces = nodal_values(
        vtu, "contact_force",
        lambda arrays, cell, corners: int(
            sum(c[1] for c in corners) / len(corners) > interface))
    errors = []
    for x, f, body in forces:
        if abs(x[1] - interface) > 1e-9:
            continue
        h = width / cells[int(body)]
        at_end = abs(x[0]) < 1e-9 or abs(x[0] - width) < 1e-9
        exact = p * (0.5 * h if at_end else h)
        # Upward on the upper body, downward on the lower one.
        fy = f[1] if body == 1 else -f[1]
        errors.append(abs(fy - exact) / exact)
    displacement = nodal_values(vtu, "displacement")
    uy = [u[1] for x, u, _ in displacement if abs(x[1] - top) < 1e-9]
    mean = sum(uy) / len(uy)
    flatness = (max(uy) - min(uy)) / abs(mean)
    # Equilibrium from history.csv (doubles; the VTU holds floats): the
    # vertical resultant on the upper body, slave force of the first pass
    # minus that of the second (which acts on the lower body).
    history = read_csv(folder + "/history.csv")[-1]
    resultant = history["pair0_Fy"] - history.get("pair1_Fy", 0.0)
    if "fine" in name:
        resultant = -resultant
    force_error = abs(resultant - p * width) / (p * width)
    rms = (sum(e * e for e in errors) / len(errors)) ** 0.5
    measured[name] = (max(errors), flatness)
    print("%-22s nodes %2d  total force error %.1e  node force error max "
          "%.4f rms %.4f  top flatness %.2e" % (name, len(errors), force_error,
                                               max(errors), rms, flatness))
    check(len(errors) == cells[0] + cells[1] + 2 and force_error < 1e-8,
          "%s: equilibrium, total contact force = p x width (%.1e)"
          % (name, force_error))
    lines.append("%s,%.6e,%.6e,%.6e,%.6e" % (
        name, force_error if force_error > 1e-12 else 0.0, max(errors), rms,
        flatness))

soft, stiff = measured["two-pass k=1e3"], measured["two-pass k=1e6"]
check(stiff[0] < 2e-5 and stiff[1] < 2e-5,
      "two-pass, k = 1e6: passes (force error %.1e, flatness %.1e)" % stiff)
check(stiff[0] * 100 < soft[0] and stiff[1] * 100 < soft[1],
      "two-pass: the error falls with the penalty, O(1/k) (k = 1e3: %.1e, "
      "%.1e)" % soft)
for name in ("one-pass coarse slave", "one-pass fine slave",
             "lagrange coarse slave", "lagrange fine slave"):
    check(measured[name][0] > 0.01,
          "%s: node-to-segment fails the patch test (force error %.3f)"
          % (name, measured[name][0]))

# The penalty in mixed form takes both passes too (it was refused, as
# multipliers are): each pass's traction unknowns are its own, and the
# solution is the primal form's, node by node (to Newton's tolerance).
pressures = {}
for form in ("primal", "mixed"):
    folder = out + "/two_pass_" + form
    run(tribos, tests + "/patch_test.prm", folder,
        ["Contact/Passes=two-pass", "Contact/Master smoothing=none",
         "Contact/Penalty formulation=" + form])
    pressures[form] = {(round(r["X"], 9), round(r["Y"], 9), r["pair"]):
                       r["CPRESS"]
                       for r in read_csv(folder + "/contact-00001.csv")
                       if r["CSTATUS"] > 0}
largest = max(pressures["primal"].values())
worst = max(abs(pressures["mixed"].get(k, 0.) - v)
            for k, v in pressures["primal"].items()) / largest
check(len(pressures["mixed"]) == len(pressures["primal"]) > 0 and
      worst < 1e-6,
      "two-pass, penalty in mixed form: %d closed nodes as the primal form, "
      "their pressures the primal form's to %.1e of the largest (bound 1e-6)"
      % (len(pressures["mixed"]), worst))

result = out + "/patch_test.csv"
with open(result, "w") as f:
    f.write("\n".join(lines) + "\n")
reference = tests + "/patch_test.reference.csv"
if updating_references():
    shutil.copy(result, reference)
    reference_updated(reference)
    finish()
numdiff(result, reference, relative=1e-4, absolute=1e-8)
print("ok      the measured errors match tests/data/patch_test.reference.csv")
finish()
