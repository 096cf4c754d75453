"""Locking: plane-strain compression of a J2-plastic block between rough
platens (tests/data/j2_barrelling.prm, 20 %, Refinement = 1). Plain Q1 locks
under the isochoric plastic flow; the F-bar element and Q2 do not. Asserts
the F-bar tangent (global finite-difference check in every iteration of a
short run) to 1e-6, F-bar within 6 % of Q2 and plain Q1 more than 30 % above
Q2. (The rough-platen corners are singular, so Q2 itself still changes by
5 % from this mesh to the next.) A case without singular points: the
plane-strain necking strip (parameters/necking_bar.prm without
axisymmetry: a strip with a 1.8 % thinner middle, pulled 8 mm in total,
past the load maximum while the neck forms): there F-bar agrees with Q2
within 1 % and plain Q1 does not (it delays the neck). The same for the
axisymmetric bar (parameters/necking_bar.prm as it is, 8 mm elongation),
whose F-bar takes the 3D volume change with the hoop stretch: its tangent
is checked by finite differences as well."""

import re
import sys

from tribos_testing import PARAMETERS, setup, run, read_csv, check, finish

tribos, tests, out = setup(sys.argv)
prm = tests + "/j2_barrelling.prm"

result = run(tribos, prm, out + "/check", [
    "Finite element/F-bar=true", "Nonlinear solver/Check tangent=true",
    "Time stepping/End time=0.4", "Time stepping/Number of steps=4"])
errors = [float(e) for e in re.findall(r"relative error (\S+)", result.stdout)]
check(len(errors) > 5 and max(errors) < 1e-6,
      "F-bar tangent vs finite differences: max %.2e over %d checks"
      % (max(errors), len(errors)))

forces = {}
for name, sets in (("Q1", []), ("Q1 F-bar", ["Finite element/F-bar=true"]),
                   ("Q2", ["Finite element/Polynomial degree=2"])):
    run(tribos, prm, out + "/" + name.replace(" ", "_"),
        sets + ["Scene/Refinement=1"])
    forces[name] = abs(read_csv(out + "/" + name.replace(" ", "_") +
                                "/history.csv")[-1]["RF3_y"])
print("top force at 20 %% compression: Q1 %.4f, Q1 F-bar %.4f, Q2 %.4f"
      % (forces["Q1"], forces["Q1 F-bar"], forces["Q2"]))
fbar = abs(forces["Q1 F-bar"] - forces["Q2"]) / forces["Q2"]
q1 = abs(forces["Q1"] - forces["Q2"]) / forces["Q2"]
check(fbar < 0.06, "F-bar vs Q2: %.1f %%" % (100 * fbar))
check(q1 > 0.3, "plain Q1 vs Q2: %.1f %% (locking)" % (100 * q1))

strip = {}
q1_degree = "Finite element/Polynomial degree=1"
for name, sets in (("Q1", [q1_degree]),
                   ("Q1 F-bar", [q1_degree, "Finite element/F-bar=true"]),
                   ("Q2", ["Finite element/Polynomial degree=2"])):
    folder = out + "/strip_" + name.replace(" ", "_")
    run(tribos, PARAMETERS + "/necking_bar.prm", folder, sets + [
        "Finite element/Axisymmetric=false", "Time stepping/End time=%r"
        % (40 / 70), "Time stepping/Number of steps=40",
        "Output/Write VTU=false"])
    strip[name] = abs(read_csv(folder + "/history.csv")[-1]["RF3_y"])
print("necking strip, force at 8 mm elongation: Q1 %.4f, Q1 F-bar %.4f, "
      "Q2 %.4f" % (strip["Q1"], strip["Q1 F-bar"], strip["Q2"]))
fbar = abs(strip["Q1 F-bar"] - strip["Q2"]) / strip["Q2"]
q1 = abs(strip["Q1"] - strip["Q2"]) / strip["Q2"]
check(fbar < 0.01, "necking strip: F-bar vs Q2 %.2f %% < 1 %%" % (100 * fbar))
check(q1 > 0.02, "necking strip: plain Q1 vs Q2 %.2f %% (locking)"
      % (100 * q1))
# Axisymmetric: the hoop stretch enters the centre's volume change.
bar = PARAMETERS + "/necking_bar.prm"
q1_fbar = [q1_degree, "Finite element/F-bar=true"]
result = run(tribos, bar, out + "/bar_check", q1_fbar + [
    "Nonlinear solver/Check tangent=true", "Time stepping/End time=0.1",
    "Time stepping/Number of steps=7", "Output/Write VTU=false"])
errors = [float(e) for e in re.findall(r"relative error (\S+)", result.stdout)]
check(len(errors) > 5 and max(errors) < 1e-6,
      "axisymmetric F-bar tangent vs finite differences: max %.2e over %d "
      "checks" % (max(errors), len(errors)))
bar_force = {}
for name, sets in (("Q1", [q1_degree]), ("Q1 F-bar", q1_fbar),
                   ("Q2", ["Finite element/Polynomial degree=2"])):
    folder = out + "/bar_" + name.replace(" ", "_")
    run(tribos, bar, folder, sets + [
        "Time stepping/End time=%r" % (40 / 70),
        "Time stepping/Number of steps=40", "Output/Write VTU=false"])
    bar_force[name] = abs(read_csv(folder + "/history.csv")[-1]["RF3_y"])
print("axisymmetric necking bar, force at 8 mm elongation: Q1 %.4f, "
      "Q1 F-bar %.4f, Q2 %.4f"
      % (bar_force["Q1"], bar_force["Q1 F-bar"], bar_force["Q2"]))
fbar = abs(bar_force["Q1 F-bar"] - bar_force["Q2"]) / bar_force["Q2"]
q1 = abs(bar_force["Q1"] - bar_force["Q2"]) / bar_force["Q2"]
check(fbar < 0.01, "axisymmetric bar: F-bar vs Q2 %.2f %% < 1 %%"
      % (100 * fbar))
check(q1 > 0.05, "axisymmetric bar: plain Q1 vs Q2 %.2f %% (locking)"
      % (100 * q1))
finish()
