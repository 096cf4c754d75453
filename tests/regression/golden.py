"""Golden outputs: small contact scenes that pin the behaviour of every
enforcement method (penalty, Lagrange multipliers, augmented Lagrangian),
with and without friction, 2D and 3D, one- and two-pass, rigid, faceted and
smoothed deformable masters, mortar, axisymmetric, and the defaults
untouched. Each case's history.csv
and its last contact-NNNNN.csv are compared with tests/regression/golden/<case>.history.csv
and tests/regression/golden/<case>.contact.csv.

Tolerances: every number through numdiff at 1e-6 relative and 1e-10
absolute (the runs converge the residual to 1e-8 of the forces, so a
different but equally valid round-off path moves a result by about 1e-9
relative; 1e-6 leaves room for that and catches any change of the
physics); the final residual and the wall time (round-off and clock) are
left out; Newton iterations may differ by one per increment (an iteration
more or less where a residual lands next to the tolerance). Set
TRIBOS_UPDATE_REFERENCES=1 to rewrite the references after a change that
is understood and intended.

    golden.py TRIBOS TESTS OUT CASE"""
# ctest: labels quick

import os
import shutil
import sys

from tribos_testing import (updating_references, reference_updated, PARAMETERS, setup, run, strip_columns, numdiff, read_csv, check,
                         finish)

LM = ["Contact/Method=lagrange multiplier"]
AL = ["Contact/Method=augmented lagrangian"]
IRONING = ["Time stepping/End time=2", "Time stepping/Number of steps=8"]
AXISYMMETRIC = ["Finite element/F-bar=true",
                "Contact/Friction coefficient=0.3",
                "Contact/Pairs=3, 4 : plate",
                "Contact/Tangential penalty factor=5*E/h",
                "Time stepping/End time=4", "Time stepping/Number of steps=4",
                "Output/Write VTU=false"]
HERTZ_3D = ["Linear solver/Type=direct",
            "Scene/Cylinder over block/Indenter refinements=1",
            "Scene/Cylinder over block/Contact refinements=2",
            "Scene/Cylinder over block/Refinement radius=0.15",
            "Output/Write VTU=false"]

# Every case but the defaults' names its penalty form and master
# smoothing: the primal penalty and the faceted master, as they were pinned
# before the defaults became automatic (Contact::resolve_pairs()); a case's
# own overrides come after and win.
PINNED = ["Contact/Penalty formulation=primal",
          "Contact/Master smoothing=none"]

# case: (parameter file relative to tests/, overrides)
CASES = {
    "penalty_friction_rigid_2d": ("sliding_block.prm", []),
    "lagrange_friction_rigid_2d": ("sliding_block.prm", LM),
    "augmented_friction_rigid_2d": ("sliding_block.prm", AL),
    "penalty_friction_deformable_2d": ("ironing_2d.prm", IRONING),
    "lagrange_friction_deformable_2d": ("ironing_2d.prm", IRONING + LM),
    "penalty_friction_smoothed_2d": (
        "ironing_2d.prm", IRONING + ["Contact/Master smoothing=averaged normals"]),
    "penalty_two_pass_2d": ("patch_test.prm", ["Contact/Passes=two-pass"]),
    "penalty_friction_mortar_2d": (
        "ironing_2d.prm", IRONING + ["Contact/Discretization=mortar"]),
    "lagrange_friction_mortar_2d": (
        "ironing_2d.prm", IRONING + LM + ["Contact/Discretization=mortar"]),
    "penalty_friction_3d": ("sliding_blocks_3d.prm", []),
    "lagrange_friction_3d": ("sliding_blocks_3d.prm", LM),
    "penalty_friction_mortar_3d": (
        "sliding_blocks_3d.prm", ["Contact/Discretization=mortar"]),
    "lagrange_friction_mortar_3d": (
        "sliding_blocks_3d.prm", LM + ["Contact/Discretization=mortar"]),
    "augmented_frictionless_rigid_3d": (os.path.join(PARAMETERS, "hertz_3d.prm"),
                                         HERTZ_3D + AL),
    "lagrange_frictionless_rigid_3d": (os.path.join(PARAMETERS, "hertz_3d.prm"),
                                        HERTZ_3D + LM),
    "penalty_friction_axisymmetric": (
        os.path.join(PARAMETERS, "cylinder_compression_axisymmetric.prm"), AXISYMMETRIC),
    "lagrange_friction_axisymmetric": (
        os.path.join(PARAMETERS, "cylinder_compression_axisymmetric.prm"),
        AXISYMMETRIC + LM),
    # The defaults untouched (automatic: the mixed penalty and, node to
    # segment against a deformable master, the smoothed master).
    "defaults_friction_deformable_2d": ("ironing_2d.prm", IRONING),
    "defaults_friction_3d": ("sliding_blocks_3d.prm", []),
}
DEFAULTS = ("defaults_friction_deformable_2d", "defaults_friction_3d")

if __name__ == "__main__":
    tribos, tests, out = setup(sys.argv)
    case = sys.argv[4]
    prm, sets = CASES[case]
    run(tribos, os.path.join(tests, prm), out,
        (sets if case in DEFAULTS else PINNED + sets))
    contact = sorted(f for f in os.listdir(out) if f.startswith("contact-"))[-1]
    reference = os.path.join(os.path.dirname(os.path.abspath(__file__)), "golden", case)
    if updating_references():
        os.makedirs(os.path.dirname(reference), exist_ok=True)
        strip_columns(out + "/history.csv", reference + ".history.csv",
                      drop=("wall_time",))
        shutil.copy(os.path.join(out, contact), reference + ".contact.csv")
        reference_updated(reference + ".*")
        finish()

    noisy = ("wall_time", "residual", "newton_iterations",
             "newton_iterations_all")
    strip_columns(out + "/history.csv", out + "/result.csv", drop=noisy)
    strip_columns(reference + ".history.csv", out + "/reference.csv",
                  drop=noisy)
    numdiff(out + "/result.csv", out + "/reference.csv", relative=1e-6,
            absolute=1e-10)
    print("ok      history.csv matches %s.history.csv within 1e-6" % case)
    numdiff(os.path.join(out, contact), reference + ".contact.csv",
            relative=1e-6, absolute=1e-10)
    print("ok      %s matches %s.contact.csv within 1e-6" % (contact, case))

    result_rows = read_csv(out + "/history.csv")
    reference_rows = read_csv(reference + ".history.csv")
    check(len(result_rows) == len(reference_rows),
          "%d converged increments, reference %d"
          % (len(result_rows), len(reference_rows)))
    check(all(abs(a["newton_iterations"] - b["newton_iterations"]) <= 1
              for a, b in zip(result_rows, reference_rows)),
          "Newton iterations per increment within +-1 of the reference "
          "(%d in all, reference %d)"
          % (sum(r["newton_iterations"] for r in result_rows),
             sum(r["newton_iterations"] for r in reference_rows)))
    finish()
