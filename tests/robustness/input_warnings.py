"""Suspicious but legal input runs (exit status 0) and warns on stderr and in
summary.txt, naming the entry: a parameter file that sets nothing; a
penalty below 1e-3 E/h or above 1e8 E/h (relative or absolute; the mixed
form's below only); a contact
pair whose slave never comes within the search distance of its master;
a self-contact surface no node of which faces a face of it within the
search distance;
a model that nothing loads (no load, no nonzero Dirichlet value, no moving
rigid surface; with contact pairs judged at the run's end, so that bodies
meshed overlapping are not); a body without support or contact surface;
Master smoothing = automatic on a master the averaged normals cannot take
(the faces, with a warning). The log names what the automatic defaults
chose for each pair (two bodies, rigid, self, explicit values).
Sensible input warns about nothing."""

import sys

from tribos_testing import setup, run, check, finish

tribos, tests, out = setup(sys.argv)
block = tests + "/sliding_block.prm"
cases = [
    ("empty_file", tests + "/bad_input/empty.prm", [],
     "sets no entry"),
    ("soft_penalty", block, ["Contact/Penalty factor=1e-4*E/h"],
     "Contact/Penalty factor"),
    ("stiff_penalty", block, ["Contact/Penalty factor=1e9*E/h"],
     "Contact/Penalty factor"),
    ("stiff_absolute_penalty", block, ["Contact/Penalty factor=1e12"],
     "outside [1e-3, 1e8] E/h"),
    ("soft_tangential_penalty", block,
     ["Contact/Tangential penalty factor=1e-5*E/h"],
     "Contact/Tangential penalty factor"),
    # The mixed form solves the same penalty law: 1e-6 E/h let the block
    # sink through its whole stroke without a word.
    ("soft_mixed_penalty", block,
     ["Contact/Penalty formulation=mixed",
      "Contact/Penalty factor=1e-6*E/h"],
     "Contact/Penalty factor"),
    # Issue 47: nothing loads or prescribes anything (ran to "completed"
    # silently before); a body that nothing holds.
    ("nothing_loaded", tests + "/ironing_2d.prm",
     ["Boundary conditions/Dirichlet=", "Time stepping/Number of steps=2",
      "Time stepping/End time=0.2"],
     "nothing loads the model"),
    ("body_not_held", tests + "/ironing_2d.prm",
     ["Boundary conditions/Dirichlet=2 : xy : 0, 0",
      "Boundary conditions/Neumann=3 : 0, -0.01*t", "Contact/Pairs=",
      "Time stepping/Number of steps=1", "Time stepping/End time=0.1",
      "Nonlinear solver/Stabilization factor=1e-3"],
     "nothing holds its rigid-body motion"),
    ("never_near", block,
     ["Contact/Rigid surfaces=plane : plane : 0, -1, 0 : 0, 1, 0 : 0, 0",
      "Contact/Search distance=0.1"],
     "no slave node came within the search distance"),
    # Issue 59: a self-contact surface whose nodes face none of its faces
    # within the search distance (the U's slot is 1 wide).
    ("self_contact_out_of_reach", tests + "/self_contact_u.prm",
     ["Contact/Search distance=0.5", "Time stepping/Number of steps=1",
      "Time stepping/End time=0.1"],
     "no node of its surface faces a face of it within"),
    ("self_contact_out_of_reach_mortar", tests + "/self_contact_u.prm",
     ["Contact/Search distance=0.5", "Contact/Discretization=mortar",
      "Time stepping/Number of steps=1", "Time stepping/End time=0.1"],
     "no node of its surface faces a face of it within"),
    ("self_contact_not_held", tests + "/self_contact_u.prm",
     ["Boundary conditions/Dirichlet=", "Boundary conditions/Neumann=",
      "Time stepping/Number of steps=1", "Time stepping/End time=0.1",
      "Nonlinear solver/Stabilization factor=1e-3"],
     "nothing holds its rigid-body motion"),
    # Master smoothing = automatic on a master with a vertex of 16 faces
    # (more than the averaged normals take): the faces, with a warning.
    ("smoothing_fallback", tests + "/fan_master.prm", [],
     "the master is met as its faces (Contact/Master smoothing = "
     "automatic)"),
]
# Only the pressing (t <= 1): a friction drag at 1e9 E/h does not converge
# (which is the warning's point).
short = ["Time stepping/End time=1", "Time stepping/Number of steps=2"]
for name, prm, sets, expected in cases:
    folder = out + "/" + name
    result = run(tribos, prm, folder, sets + (short if prm == block else []))
    summary = open(folder + "/summary.txt").read()
    warnings = [l for l in result.stderr.splitlines() if "WARNING" in l]
    check(result.returncode == 0 and any(expected in w for w in warnings) and
          expected in summary,
          "%s: runs, warns <%s>" % (name, warnings[0] if warnings else ""))

# The log names what automatic chose for each pair: the fallback's pair
# is plain node to segment, its penalty in mixed form (two bodies).
log = run(tribos, tests + "/fan_master.prm", out + "/smoothing_fallback_log")
check("contact pair <3 : 2>: penalty (mixed), node to segment, 4 slave "
      "nodes" in log.stdout,
      "the fallback's pair named in the log: penalty (mixed), node to "
      "segment, without the smoothed master")
ironing = tests + "/ironing_2d.prm"
for name, prm, sets, choice in (
        ("two bodies", ironing, [],
         "penalty (mixed), node to segment, smoothed master"),
        ("rigid", block, [], "penalty (primal), node to rigid surface"),
        ("self", tests + "/self_contact_u.prm", [],
         "penalty (primal), node to segment,"),
        ("explicit", ironing, ["Contact/Penalty formulation=primal",
                               "Contact/Master smoothing=none"],
         "penalty (primal), node to segment,")):
    log = run(tribos, prm, out + "/automatic_" + name.replace(" ", "_"),
              ["Time stepping/Number of steps=1",
               "Time stepping/End time=0.01"] + sets)
    line = [l for l in log.stdout.splitlines() if "contact pair <" in l]
    check(len(line) == 1 and choice in line[0],
          "automatic defaults, %s: <%s>" % (name, line[0] if line else ""))

# Bodies meshed overlapping are loaded by their contact: the 2D Abaqus
# deck with its block lowered by 0.01 and both sets held in place (a
# contact force of about 1.4e3) warned that nothing loads the model.
lines, in_nodes = [], False
for line in open(tests + "/blocks_on_plate.inp").read().split("\n"):
    if line.startswith("*"):
        in_nodes = line.upper().startswith("*NODE")
    f = [x.strip() for x in line.split(",")]
    if in_nodes and len(f) == 3 and f[0].isdigit() and int(f[0]) > 100:
        line = "%s, %s, %r" % (f[0], f[1], float(f[2]) - 0.01)
    lines.append(line)
overlap = out + "/overlap.inp"
with open(overlap, "w") as f:
    f.write("\n".join(lines))
result = run(tribos, tests + "/blocks_on_plate.prm", out + "/overlap",
             ["Scene/Input deck=" + overlap,
              "Boundary conditions/Dirichlet=1 : xy : 0, 0 ; 2 : xy : 0, 0"])
check("nothing loads" not in result.stderr,
      "a meshed overlap is loaded by its contact: no 'nothing loads' warning")

result = run(tribos, block, out + "/sensible")
check("WARNING" not in result.stderr and
      "warning" not in open(out + "/sensible/summary.txt").read(),
      "sensible input: no warning")
# A self-contact surface that spans two bodies is their contact with each
# other: the patch test's upper block held only by it is held.
result = run(tribos, tests + "/patch_test.prm", out + "/self_contact_two_bodies",
             ["Boundary conditions/Symmetry=0, 2",
              "Contact/Pairs=3, 12 : 3, 12"])
check("nothing holds" not in result.stderr,
      "a self-contact surface spanning two bodies holds them: no warning")
# Pairs near the overlapping ones refused (tests/robustness/bad_input.sh)
# that are legal: with one pass, penalty may sum an interface written both
# ways; two slave ids that meet at a corner node against one master (each
# pair gives the node the area of its own faces).
for name, pairs in (("swapped_one_pass", "12 : 3 ; 3 : 12"),
                    ("corner_slaves", "12 : 3 ; 10 : 3")):
    result = run(tribos, tests + "/patch_test.prm", out + "/" + name,
                 ["Contact/Pairs=" + pairs])
    check(result.returncode == 0,
          "Pairs = %s runs (not an overlap)" % pairs)
finish()
