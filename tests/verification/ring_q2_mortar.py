"""The paper's ring on a foundation on the paper's own mesh (64 x 2 ring
elements) with Q2 and mortar contact (Finite element/Polynomial degree =
2, Contact/Discretization = mortar, Lagrange multipliers, quadratic dual
basis): all 81 steps complete, the ring lifts off in the middle and
touches on both sides at the end, the contact closes exactly, and the
foundation reaction is within 5 % of the refined solution at the paper's
steps 10, 20, 44, 60 and 80 (our steps 11, 21, 45, 61, 81; step 1 closes
the gap). The refined solution (tests/data/ring_refined.reference.csv) is Q2
mortar with multipliers on the mesh refined once (128 x 4 ring elements,
21 764 dofs), written by benchmarks/ring_study.sh to
doc/data/ring_q2_lagrange_multiplier_r1.csv; penalty 1e5 on that mesh
agrees to 1.3e-4, the Q1 ring refined twice (256 x 8, the same number of
dofs) lies 2.6-3.1 % above it over the whole curve (doc/ring.md).
Q1 on the same 64 x 2 mesh (node to segment) is run too: one element per
layer locks in bending and overestimates the force by more than 35 %; Q2
must be at least five times closer. With mpirun -np 2 (if found) the
serial reactions to 1e-8 at every step through t = 45 (the first touch,
the spread of the contact zone to its largest, 29 active nodes at step 37,
and the start of the lift-off).

Refined once (128 x 4), through t = 79: this run stopped at t = 78 when
the mortar search paired Q2's curved segments by their chords only (a
face the curve overlaps but the chord does not entered the element late);
it must complete.

Cases (argv[4]; without one, both run):
  serial  every run without mpirun.
  mpi     Q2 mortar to t = 45 serially and with -np 2 (two cores, one MPI
          test at a time): an MPI = serial comparison, which needs no more
          than the first 45 steps, at the 81-step run's step size.
"""
# ctest: cases serial mpi
# ctest: mpirun-cases mpi
# ctest: slow-cases serial

import csv
import math
import os
import sys

from tribos_testing import (PARAMETERS, setup, run, read_csv, check, finish,
                            parts, mpi_part)

tribos, tests, out = setup(sys.argv)
selected = parts(sys.argv, ("serial", "mpi"))
prm = PARAMETERS + "/ring_on_foundation.prm"
reference = {int(r["step"]): float(r["RF12_y"]) for r in
             csv.DictReader(open(tests + "/ring_refined.reference.csv"))}
size = math.pi * 100 / 64  # outer element length of the ring


def errors(history):
    by_step = {h["step"]: h["RF12_y"] for h in history}
    return {s: (by_step[s] - f) / f for s, f in reference.items()}


q2_mortar = ["Contact/Method=lagrange multiplier",
             "Contact/Discretization=mortar",
             "Finite element/Polynomial degree=2"]
# The MPI part (case mpi): Q2 mortar under MPI (middle nodes, their dofs
# and multipliers on two processes) gives the serial history, through
# t = 45 at the same step size.
if "mpi" in selected and mpi_part(selected):
    through_45 = q2_mortar + ["Time stepping/End time=45",
                              "Time stepping/Number of steps=45",
                              "Output/Write VTU=false"]
    run(tribos, prm, out + "/q2_mortar_45", through_45)
    run(tribos, prm, out + "/q2_mortar_45_np2", through_45, mpi_ranks=2)
    # Compared at the times both runs reached: every nominal step, and
    # the increments of cutbacks both took. Round-off can decide whether a
    # retried increment converges or is cut (step 2's extrapolated start
    # fails in both; its plain retry converges serially and is cut once at
    # -np 2), which changes the increments but not the solution at a time.
    serial = {round(h["time"], 9): h["RF12_y"]
              for h in read_csv(out + "/q2_mortar_45/history.csv")}
    parallel = {round(p["time"], 9): p["RF12_y"]
                for p in read_csv(out + "/q2_mortar_45_np2/history.csv")}
    common = sorted(set(serial) & set(parallel))
    difference = max(abs(parallel[t] - serial[t]) / max(abs(serial[t]), 1.)
                     for t in common)
    check(all(float(step) in common for step in range(1, 46)) and
          difference < 1e-8,
          "Q2 mortar, mpirun -np 2: the serial reactions to %.1e at the %d "
          "times both reached (every nominal step through t = 45 among "
          "them)" % (difference, len(common)))
if "serial" not in selected:
    finish()

folder = out + "/q2_mortar"
run(tribos, prm, folder, q2_mortar)
history = read_csv(folder + "/history.csv")
check(history[-1]["step"] == 81 and history[-1]["time"] == 81,
      "Q2 mortar: all 81 steps (%d Newton iterations, %d cutbacks)"
      % (sum(h["newton_iterations"] for h in history),
         sum(h["cutbacks"] for h in history)))
nodes = read_csv(folder + "/contact-00081.csv")
middle = [n for n in nodes if abs(n["x"]) < 30]
check(len(middle) > 5 and all(n["CSTATUS"] == 0 for n in middle) and
      min(n["COPEN"] for n in middle) > 1,
      "Q2 mortar: lifted off in the middle (gap at x = 0: %.3f)"
      % min(middle, key=lambda n: abs(n["x"]))["COPEN"])
left = [n for n in nodes if n["x"] < -30 and n["CSTATUS"] > 0]
right = [n for n in nodes if n["x"] > 30 and n["CSTATUS"] > 0]
check(len(left) >= 2 and len(right) >= 2,
      "Q2 mortar: in contact on both sides (%d left, %d right)"
      % (len(left), len(right)))
penetration = max(h["max_penetration"] for h in history)
check(penetration < 1e-10 * size,
      "Q2 mortar: max penetration %.1e < 1e-10 x element size" % penetration)
q2 = errors(history)
for step, error in sorted(q2.items()):
    check(abs(error) <= 0.05,
          "Q2 mortar, paper step %d: foundation reaction %.1f, refined %.1f "
          "(%+.2f %%)" % (step - 1, reference[step] * (1 + error),
                          reference[step], 100 * error))

folder = out + "/q1_node_to_segment"
run(tribos, prm, folder, ["Contact/Method=lagrange multiplier"])
q1 = errors(read_csv(folder + "/history.csv"))
worst_q1 = max(abs(e) for e in q1.values())
worst_q2 = max(abs(e) for e in q2.values())
check(worst_q1 > 0.35 and worst_q2 < worst_q1 / 5,
      "Q1 on the same mesh is off by up to %.1f %% (locking), Q2 mortar by "
      "%.1f %%" % (100 * worst_q1, 100 * worst_q2))
folder = out + "/q2_mortar_refined"
run(tribos, prm, folder, ["Contact/Method=lagrange multiplier",
                          "Contact/Discretization=mortar",
                          "Finite element/Polynomial degree=2",
                          "Scene/Refinement=1", "Time stepping/End time=79",
                          "Time stepping/Number of steps=79",
                          "Output/Write VTU=false"])
history = read_csv(folder + "/history.csv")
check(history[-1]["time"] == 79,
      "Q2 mortar 128 x 4 through t = 79 (%d Newton iterations, %d "
      "cutbacks)" % (sum(h["newton_iterations"] for h in history),
                     sum(h["cutbacks"] for h in history)))
finish()
