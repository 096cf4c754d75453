"""Implicit dynamics with contact against analytic solutions (issue 19).

Cases (argv[4]):
  bar_<method>   the Signorini bar (parameters/bar_impact.prm) with the
                 enforcement <method>, Newmark and generalized-alpha: contact
                 duration 2L/c within 2 %, force plateau rho c v A within 5 %
                 (its oscillation below 5 %), rebound velocity within 2 %,
                 energy after the rebound within 1 % of the initial.
  sphere         Hertzian impact (parameters/sphere_impact.prm): peak force
                 and contact time within 3 % of Hertz's impact theory;
                 energy after the rebound within 1 %.
  slide          a block sliding to a stop under friction
                 (parameters/block_slide_stop.prm): the energy lost equals
                 the friction law's dissipation within 1 %; stopping
                 distance v0^2 / (2 mu g) within 2 %.
  order          a bar vibrating in its first mode (tests/data/vibrating_bar.prm):
                 the tip displacement at t = 3 against a run with 4800
                 steps converges at order >= 1.8 with Newmark's average
                 acceleration rule and generalized-alpha, at order 1 (0.8
                 to 1.2) with Newmark gamma = 0.6. The reference is one
                 run, Newmark's average acceleration with 4800 steps, for
                 all three: they converge to the same semi-discrete
                 solution, and its error, (120/4800)^2 of the 120-step
                 run's, is below that of the first-order scheme's own
                 4800-step run (1/40 of its 120-step error).
  pushed         a bar at rest whose end is pushed at V for t < 1 and then
                 held (tests/data/pushed_bar.prm, consistent mass): reaction
                 during the push rho c V A within 2 %; after t = 1 kinetic
                 plus strain energy constant to 1e-6 and equal to the work
                 rho c V^2 A within 2 %. (Prescribed dofs followed Newmark's
                 recursion before, from v = 0: their acceleration alternated
                 in sign and grew, and the mean reaction while pushing came
                 out -9.3e-4 instead of 5e-4.)
  ring           the paper's whole ring dropped on its foundation
                 (parameters/ring_drop.prm to t = 8: the impact and the
                 first rebound of the soft outer layer): in contact at some
                 step, kinetic + strain energy + contact work within 1e-3
                 of the initial, integrator balance (energy_error) below
                 1e-6 of it.
  quasi_static   the axisymmetric J2 cylinder loaded slowly (wave transit
                 1e-4 of the loading time): the dynamic plate force equals
                 the quasi-static one within 0.1 % at every step.
"""
# ctest: cases bar_lagrange_multiplier bar_penalty bar_augmented_lagrangian sphere slide quasi_static order pushed ring
# ctest: quick-cases slide pushed

from tribos_testing import PARAMETERS, analytic
import math
import os
import sys
import tribos_testing as tt

tribos, tests, out = tt.setup(sys.argv)
case = sys.argv[4]
parameters = PARAMETERS
failures = []


def check(name, value, reference, bound):
    error = abs(value / reference - 1)
    status = "ok" if error <= bound else "FAILED"
    print("%-6s %-44s %.6g vs %.6g: error %.2e (bound %.0e)"
          % (status, name, value, reference, error, bound))
    if error > bound:
        failures.append(name)


def contact_span(rows):
    active = [r["time"] for r in rows if r["n_active"] > 0]
    return active[0], active[-1]


if case.startswith("bar_"):
    method = case[4:].replace("_", " ")
    duration, force = analytic.signorini_bar(1, 1, 0.01, 1, 0.05)
    for integrator in ("newmark", "generalized alpha"):
        folder = os.path.join(out, integrator.replace(" ", "_"))
        tt.run(tribos, os.path.join(parameters, "bar_impact.prm"), folder,
               ["Contact/Method=" + method,
                "Time stepping/Integrator=" + integrator])
        rows = tt.read_csv(folder + "/history.csv")
        first, last = contact_span(rows)
        check(integrator + ": contact duration", last - first, duration,
              0.02)
        plateau = [r["pair0_normal_force"] for r in rows
                   if first + 0.25 <= r["time"] <= last - 0.25]
        mean = sum(plateau) / len(plateau)
        spread = max(abs(f - mean) for f in plateau)
        check(integrator + ": force plateau", mean, force, 0.05)
        check(integrator + ": force oscillation / plateau",
              1 + spread / mean, 1, 0.05)
        # The bar's mean velocity: momentum over mass (rho L A = 0.05).
        check(integrator + ": rebound velocity",
              rows[-1]["momentum_x"] / 0.05, 0.01, 0.02)
        initial = rows[0]["kinetic_energy"] + rows[0]["strain_energy"]
        check(integrator + ": energy after the rebound",
              rows[-1]["kinetic_energy"] + rows[-1]["strain_energy"], initial,
              0.01)

elif case == "sphere":
    tt.run(tribos, os.path.join(parameters, "sphere_impact.prm"), out)
    rows = tt.read_csv(out + "/history.csv")
    v = 1e-4
    # The mass of the discrete sphere (its polygonal section is a little
    # smaller than the disc) from its kinetic energy before the impact.
    mass = 2 * rows[0]["kinetic_energy"] / v ** 2
    delta, force, time = analytic.hertz_impact(mass, v, 1, 1 / (1 - 0.09))
    first, last = contact_span(rows)
    dt = rows[1]["time"] - rows[0]["time"]
    check("contact time", last - first + dt, time, 0.03)
    check("peak force", max(r["pair0_normal_force"] for r in rows), force,
          0.03)
    check("energy after the rebound",
          rows[-1]["kinetic_energy"] + rows[-1]["strain_energy"],
          rows[0]["kinetic_energy"] + rows[0]["strain_energy"], 0.01)

elif case == "slide":
    tt.run(tribos, os.path.join(parameters, "block_slide_stop.prm"), out)
    rows = tt.read_csv(out + "/history.csv")
    mu, g, v0, mass = 0.3, 1.0, 0.3, 0.25
    initial = 0.5 * mass * v0 ** 2
    end = rows[-1]
    lost = initial + end["external_work"] - end["kinetic_energy"] - \
        end["strain_energy"]
    check("energy lost vs friction dissipation", lost, end["friction_work"],
          0.01)
    check("stopping distance", end["probe0_ux"], v0 ** 2 / (2 * mu * g),
          0.02)
    check("kinetic energy left / initial", 1 + end["kinetic_energy"] /
          initial, 1, 0.01)

elif case == "quasi_static":
    prm = os.path.join(parameters, "cylinder_compression_axisymmetric.prm")
    common = ["Output/Write VTU=false", "Materials/Density=7.8e-6"]
    tt.run(tribos, prm, out + "/static", common)
    tt.run(tribos, prm, out + "/newmark",
           common + ["Time stepping/Integrator=newmark"])
    static = tt.read_csv(out + "/static/history.csv")
    dynamic = tt.read_csv(out + "/newmark/history.csv")
    assert len(static) == len(dynamic) and len(static) > 10
    worst = max(abs(d["pair0_normal_force"] / s["pair0_normal_force"] - 1)
                for s, d in zip(static, dynamic)
                if s["pair0_normal_force"] > 0)
    check("largest relative force difference (+1)", 1 + worst, 1, 1e-3)
    check("final force", dynamic[-1]["pair0_normal_force"],
          static[-1]["pair0_normal_force"], 1e-3)

elif case == "pushed":
    tt.run(tribos, os.path.join(tests, "pushed_bar.prm"), out)
    rows = tt.read_csv(out + "/history.csv")
    rho, c, V, A = 1.0, 1.0, 0.01, 0.05
    push = [r["RF0_x"] for r in rows if 0.25 <= r["time"] <= 0.75]
    check("reaction while pushing", sum(push) / len(push), rho * c * V * A,
          0.02)
    held = [r["kinetic_energy"] + r["strain_energy"] for r in rows
            if r["time"] >= 1.5]
    check("energy after the push: largest / smallest", max(held),
          min(held), 1e-6)
    check("energy after the push", held[-1], rho * c * V ** 2 * A * 1.0,
          0.02)

elif case == "ring":
    tt.run(tribos, os.path.join(parameters, "ring_drop.prm"), out,
           ["Time stepping/End time=8", "Time stepping/Number of steps=160",
            "Output/Write VTU=false"])
    rows = tt.read_csv(out + "/history.csv")
    initial = rows[0]["total_energy"]
    in_contact = sum(1 for r in rows if r["n_active"] > 0)
    print("%-6s %-44s %d of %d" % ("ok" if in_contact else "FAILED",
                                   "steps in contact", in_contact,
                                   len(rows)))
    if in_contact == 0:
        failures.append("steps in contact")
    check("largest total energy change (+1)",
          1 + max(abs(r["total_energy"] / initial - 1) for r in rows), 1,
          1e-3)
    check("largest integrator imbalance (+1)",
          1 + max(abs(r["energy_error"]) for r in rows) / initial, 1, 1e-6)

elif case == "order":
    prm = os.path.join(tests, "vibrating_bar.prm")
    variants = {"newmark": (["Time stepping/Integrator=newmark"], 1.8, 3),
                "generalized alpha": (
                    ["Time stepping/Integrator=generalized alpha"], 1.8, 3),
                "newmark gamma 0.6": (
                    ["Time stepping/Integrator=newmark",
                     "Time stepping/Newmark gamma=0.6",
                     "Time stepping/Newmark beta=0.3025"], 0.8, 1.2)}
    folder = os.path.join(out, "newmark_4800")
    tt.run(tribos, prm, folder, variants["newmark"][0]
           + ["Time stepping/Number of steps=4800"])
    reference = tt.read_csv(folder + "/history.csv")[-1]["probe0_ux"]
    for name, (sets, low, high) in variants.items():
        tip = {}
        for n in (120, 240, 480):
            folder = os.path.join(out, name.replace(" ", "_") + "_%d" % n)
            tt.run(tribos, prm, folder,
                   sets + ["Time stepping/Number of steps=%d" % n])
            tip[n] = tt.read_csv(folder + "/history.csv")[-1]["probe0_ux"]
        errors = [abs(tip[n] - reference) for n in (120, 240, 480)]
        for coarse, fine in zip(errors, errors[1:]):
            order = math.log2(coarse / fine)
            ok = low <= order <= high
            print("%-6s %-20s errors %.3e -> %.3e: order %.2f (in [%g, %g])"
                  % ("ok" if ok else "FAILED", name, coarse, fine, order,
                     low, high))
            if not ok:
                failures.append(name + " order")

else:
    raise SystemExit("unknown case " + case)

if failures:
    raise SystemExit("FAILED: " + ", ".join(failures))
