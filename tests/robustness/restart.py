"""Restart (Output/Checkpoint every, tribos --restart DIR): a run that goes
on from a checkpoint reproduces the uninterrupted run's history.csv and
last contact-NNNNN.csv,
restarted in a copy of the first run's output directory, whose history it
truncates to the checkpoint and continues. On as many processes as the
first run, every digit of both files, residuals and iteration counts
included, whatever BLAS kernels run (issue 73: the contact couplings of
the sparsity pattern are part of the checkpoint); on another number, to
Newton's tolerance (NEWTON_AGREEMENT). Serial: frictional penalty,
Lagrange multipliers and augmented Lagrangian (2D sliding block), J2
plasticity with the plate (axisymmetric cylinder: the plastic history),
dynamics with friction (block sliding to a stop: velocities, energies).
MPI (only if mpirun is found): a frictional 3D two-block scene run with
np 2 and restarted with np 1, 2 and 3 from its step-2 checkpoint, and
with np 2 from the serial run's; with Lagrange multipliers from np 2 to 3. Bad restarts (no checkpoint,
another mesh; the same cells on a moved mesh, other materials, an end time
before the checkpoint, a checkpoint with one byte changed) exit 1 with a
message and leave the output alone.
Every entry that defines the model is compared (the global friction
coefficient, the mortar basis and each entry of Adaptivity were accepted
with exit 0 and another history after the checkpoint): each one that
differs is refused, named with both values; what a restart may change
(End time and Number of steps with the same step size, the linear
solver, the output, a number written otherwise) is accepted and continues
the uninterrupted history. A checkpoint of another format is refused.

Cases (argv[4]; without one, all run):
  core    the frictional penalty slide restarted, the bad restarts from its
          checkpoint, and the history.csv restarts (Output/Probes added, a
          malformed row)
  serial  the other serial restarts (multipliers, augmented Lagrangian, J2,
          dynamics), the discretization change and the swapped mesh tags
  mpi     the restarts under mpirun (two cores, one MPI test at a time);
          skipped if mpirun is not found
"""
# ctest: cases core serial mpi
# ctest: quick-cases core
# ctest: mpirun-cases mpi

import math
import os
import shutil
import subprocess
import sys

from tribos_testing import (PARAMETERS, setup, run, strip_columns, numdiff,
                            check, finish, read_csv, parts, mpi_part,
                            restart_identical, restart_agrees,
                            NEWTON_AGREEMENT)

tribos, tests, out = setup(sys.argv)
parameters = PARAMETERS
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all", "energy_error")
selected = parts(sys.argv, ("core", "serial", "mpi"))


def compare(reference, restarted, name, same_processes=True):
    """On as many processes as the run that wrote the checkpoint, the
    restart is that run to the last digit (every column of history.csv but
    the wall time, the last contact CSV); on another number, every solve
    rounds otherwise and the two agree to Newton's tolerance."""
    if same_processes:
        check(restart_identical(reference, restarted),
              "%s: the restarted history.csv and last contact CSV equal the "
              "uninterrupted run's in every digit (residuals and Newton "
              "iterations included)" % name)
        return
    restart_agrees(reference, restarted)
    print("ok      %s: the restarted history.csv and last contact CSV equal "
          "the uninterrupted run's to %g (Newton's tolerance)"
          % (name, NEWTON_AGREEMENT))


def restarted(tribos, prm, reference, step, sets, name, ranks=0,
              from_folder=None):
    folder = reference + "_restart_%s" % name
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(reference, folder)
    source = from_folder or reference
    command = ["--restart", "%s/checkpoint-%05d" % (source, step)]
    run(tribos, prm, folder, list(sets), mpi_ranks=ranks, extra=command)
    return folder


cases = [
    ("sliding_penalty", tests + "/sliding_block.prm", 4, []),
    ("sliding_lagrange", tests + "/sliding_block.prm", 4,
     ["Contact/Method=lagrange multiplier"]),
    ("sliding_augmented", tests + "/sliding_block.prm", 4,
     ["Contact/Method=augmented lagrangian"]),
    ("cylinder_j2", parameters + "/cylinder_compression_axisymmetric.prm", 10,
     ["Output/Write VTU=false"]),
    ("dynamics_friction", parameters + "/block_slide_stop.prm", 60, []),
]
for name, prm, step, sets in cases:
    if ("core" if name == "sliding_penalty" else "serial") not in selected:
        continue
    reference = out + "/" + name
    run(tribos, prm, reference,
        sets + ["Output/Checkpoint every=%d" % step])
    check(os.path.exists("%s/checkpoint-%05d/state.bin" % (reference, step)),
          "%s: checkpoint of step %d written" % (name, step))
    compare(reference, restarted(tribos, prm, reference, step, sets, "1"),
            name)

if "mpi" in selected and mpi_part(selected, "the restarts under mpirun"):
    prm = tests + "/sliding_blocks_3d.prm"
    sets = ["Output/Write VTU=false"]
    serial, parallel = out + "/blocks_np1", out + "/blocks_np2"
    run(tribos, prm, serial, sets + ["Output/Checkpoint every=2"])
    run(tribos, prm, parallel, sets + ["Output/Checkpoint every=2"],
        mpi_ranks=2)
    for ranks in (1, 2, 3):
        compare(parallel, restarted(tribos, prm, parallel, 2, sets,
                                    "np%d" % ranks, ranks=ranks),
                "3D sliding blocks, np 2 -> np %d" % ranks,
                same_processes=ranks == 2)
    compare(serial, restarted(tribos, prm, serial, 2, sets, "np2", ranks=2),
            "3D sliding blocks, np 1 -> np 2", same_processes=False)
    # Lagrange multipliers, owned with their slave nodes, onto 3 processes.
    sets = sets + ["Contact/Method=lagrange multiplier"]
    parallel = out + "/blocks_lagrange_np2"
    run(tribos, prm, parallel, sets + ["Output/Checkpoint every=2"],
        mpi_ranks=2)
    compare(parallel, restarted(tribos, prm, parallel, 2, sets, "np3",
                                ranks=3),
            "3D sliding blocks, Lagrange multipliers, np 2 -> np 3",
            same_processes=False)

if "core" in selected:
    # Bad restarts: a clear message, exit 1, the earlier output untouched.
    reference = out + "/sliding_penalty"
    before = open(reference + "/history.csv").read()
    # A copy of the step-4 checkpoint with one byte of its state changed (past
    # the header: before issue 47 it was read without complaint).
    corrupt = out + "/corrupt_checkpoint"
    shutil.rmtree(corrupt, ignore_errors=True)
    shutil.copytree(reference + "/checkpoint-00004", corrupt)
    with open(corrupt + "/state.bin", "r+b") as f:
        data = bytearray(f.read())
        data[len(data) // 2] ^= 0x01
        f.seek(0)
        f.write(data)
    for name, sets, directory, message in [
            ("missing", [], out + "/no_such_checkpoint", "no checkpoint there"),
            ("other mesh", ["Scene/Refinement=1"],
             reference + "/checkpoint-00004", "cells"),
            # The same cells and dofs on a moved mesh, other materials, other
            # pairs, an end time before the checkpoint's t = 1 (all accepted
            # before issue 47; the last "completed" doing nothing).
            ("moved mesh", ["Scene/Block/Lower corner=0, 0.1",
                            "Scene/Block/Upper corner=1, 0.6"],
             reference + "/checkpoint-00004", "the mesh differs"),
            ("other material", ["Materials/Young's modulus=50"],
             reference + "/checkpoint-00004", "Materials/Young's modulus"),
            ("end time before the checkpoint", ["Time stepping/End time=0.5"],
             reference + "/checkpoint-00004", "nothing is left to do"),
            ("changed byte", [], corrupt, "checksum"),
            # Issue 56: another method or discretization on the same mesh (the
            # contact state belongs to the other one; accepted before).
            ("other method", ["Contact/Method=augmented lagrangian"],
             reference + "/checkpoint-00004",
             "Contact/Method <penalty> there, <augmented lagrangian> here"),
            # Issue 58: a fixed mesh's checkpoint with Adaptivity.
            ("adaptivity added", ["Adaptivity/Enable=true"],
             reference + "/checkpoint-00004",
             "written without Adaptivity/Enable"),
            # Every entry that defines the model, named with both values (the
            # first two were accepted: exit 0, another history; the same mu
            # as a pair key was refused).
            ("global friction coefficient",
             ["Contact/Friction coefficient=0.5"],
             reference + "/checkpoint-00004",
             "Contact/Friction coefficient <0.3> there, <0.5> here"),
            ("mortar basis", ["Contact/Mortar basis=standard"],
             reference + "/checkpoint-00004",
             "Contact/Mortar basis <dual> there, <standard> here"),
            ("two entries", ["Contact/Friction coefficient=0.5",
                             "Materials/Density=2"],
             reference + "/checkpoint-00004",
             "2 other values of entries that define the model: "
             "Contact/Friction coefficient <0.3> there, <0.5> here; "
             "Materials/Density <0> there, <2> here"),
            # End time and Number of steps may change, but not so that the
            # next step ends before the checkpoint's t = 1.
            ("step 5 before the checkpoint",
             ["Time stepping/Number of steps=48"],
             reference + "/checkpoint-00004", "not after it"),
            # Nor so that the checkpoint's step would end elsewhere (the
            # steps after it would be numbered as other times): 6 steps put
            # step 4's end at t = 2.
            ("step 4 ending elsewhere", ["Time stepping/Number of steps=6"],
             reference + "/checkpoint-00004", "step 4 ends at t = 2.000e+00")]:
        result = run(tribos, tests + "/sliding_block.prm", reference, sets,
                     expect_success=False, extra=["--restart", directory])
        check(result.returncode == 1 and message in result.stderr and
              open(reference + "/history.csv").read() == before,
              "bad restart (%s): exit 1, message <%s>, output kept"
              % (name, message))

    # What a restart may change: the end (the same step size, four more
    # steps), the linear solver, the output, a number written otherwise.
    # The history goes on from the uninterrupted one's.
    longer = out + "/longer"
    shutil.rmtree(longer, ignore_errors=True)
    shutil.copytree(reference, longer)
    result = run(tribos, tests + "/sliding_block.prm", longer,
                 ["Time stepping/End time=4", "Time stepping/Number of steps=16",
                  "Linear solver/Type=direct", "Output/Checkpoint every=0",
                  "Contact/Friction coefficient=0.30"],
                 extra=["--restart", reference + "/checkpoint-00004"])
    rows = read_csv(longer + "/history.csv")
    ref = read_csv(reference + "/history.csv")
    # (The load factor is t / End time.)
    kept = [k for k in ref[0] if k not in noisy + ("load_factor",)]
    check(len(rows) > len(ref) and rows[-1]["time"] == 4 and
          all(abs(r[k] - q[k]) <= 1e-10 * max(abs(q[k]), 1e-4)
              for r, q in zip(rows, ref) for k in kept),
          "restart with End time 4 and 16 steps, another linear solver and "
          "output, mu written 0.30: accepted, the uninterrupted history "
          "(%d rows) continued to t = 4 (%d rows)" % (len(ref), len(rows)))

    # A checkpoint of another format (format 4 recorded neither the
    # increments rejected for accuracy (format 6), nor the
    # contact couplings nor every entry): refused, naming the format.
    old = out + "/format_4_checkpoint"
    shutil.rmtree(old, ignore_errors=True)
    shutil.copytree(reference + "/checkpoint-00004", old)
    with open(old + "/state.bin", "r+b") as f:
        data = bytearray(f.read())
        at = data.index(b"tribos checkpoint") + len("tribos checkpoint")
        data[at:at + 4] = (4).to_bytes(4, "little")
        f.seek(0)
        f.write(data)
    result = run(tribos, tests + "/sliding_block.prm", reference, [],
                 expect_success=False, extra=["--restart", old])
    check(result.returncode == 1 and
          "not a tribos checkpoint of format 6" in result.stderr and
          open(reference + "/history.csv").read() == before,
          "a checkpoint of format 4: exit 1, the format named, output kept")

    # Issue 56: history.csv on restart. A restart that adds Output/Probes keeps
    # the earlier rows (it dropped rows 1-30: the header differed), the new
    # columns empty there; a malformed earlier row is refused before any file
    # of the earlier run is removed (it said "ERROR: stol" after checkpoints
    # and contact files beyond the restart's step were deleted).
    probes = out + "/probes"
    shutil.rmtree(probes, ignore_errors=True)
    shutil.copytree(reference, probes)
    run(tribos, tests + "/sliding_block.prm", probes,
        ["Output/Probes=0, 0"], extra=["--restart",
                                       reference + "/checkpoint-00004"])
    rows = read_csv(probes + "/history.csv")
    ref = read_csv(reference + "/history.csv")
    n_kept = len([r for r in ref if r["step"] <= 4])
    check("probe0_ux" in open(probes + "/history.csv").readline() and
          len(rows) == len(ref) and
          all(r["time"] == q["time"] for r, q in zip(rows, ref)) and
          all(math.isnan(r["probe0_ux"]) for r in rows[:n_kept]) and
          not math.isnan(rows[-1]["probe0_ux"]),
          "restart adding Output/Probes: %d rows as before, the %d earlier ones "
          "kept (probe columns empty there)" % (len(rows), n_kept))
    malformed = out + "/malformed_history"
    shutil.rmtree(malformed, ignore_errors=True)
    shutil.copytree(reference, malformed)
    lines = open(malformed + "/history.csv").read().splitlines(True)
    lines[2] = "1,x" + lines[2][3:]
    open(malformed + "/history.csv", "w").write("".join(lines))
    files = sorted(os.listdir(malformed))
    result = run(tribos, tests + "/sliding_block.prm", malformed, [],
                 expect_success=False,
                 extra=["--restart", malformed + "/checkpoint-00004"])
    check(result.returncode == 1 and "its line 3" in result.stderr and
          sorted(os.listdir(malformed)) == files,
          "restart with a malformed history.csv row: exit 1, the line named, "
          "no file removed")
if "serial" in selected:
    # Each entry of Adaptivity that was accepted (exit 0, another history
    # after the checkpoint), named with both values; the output untouched.
    adaptive = out + "/adaptive"
    sets = ["Adaptivity/Enable=true", "Adaptivity/Maximum level=2"]
    run(tribos, tests + "/sliding_block.prm", adaptive,
        sets + ["Output/Checkpoint every=5"])
    before = open(adaptive + "/history.csv").read()
    for entry, there, here in [("Maximum level", "2", "3"),
                               ("Refine fraction", "0.3", "0.5"),
                               ("Every", "1", "2"),
                               ("Contact zone depth", "0.25", "0.5"),
                               ("Strategy", "fixed fraction", "fixed number"),
                               ("Maximum dofs", "0", "100000")]:
        result = run(tribos, tests + "/sliding_block.prm", adaptive,
                     sets + ["Adaptivity/%s=%s" % (entry, here)],
                     expect_success=False,
                     extra=["--restart", adaptive + "/checkpoint-00005"])
        message = "Adaptivity/%s <%s> there, <%s> here" % (entry, there, here)
        check(result.returncode == 1 and message in result.stderr and
              open(adaptive + "/history.csv").read() == before,
              "bad restart (adaptive, %s): exit 1, <%s>, output kept"
              % (entry, message))

    # Issue 56: another discretization of a pair between two deformable
    # bodies (a rigid surface is always met node to surface).
    patch = out + "/patch"
    run(tribos, tests + "/patch_test.prm", patch,
        ["Time stepping/Number of steps=2", "Output/Checkpoint every=1"])
    before = open(patch + "/history.csv").read()
    result = run(tribos, tests + "/patch_test.prm", patch,
                 ["Time stepping/Number of steps=2",
                  "Contact/Discretization=mortar"], expect_success=False,
                 extra=["--restart", patch + "/checkpoint-00001"])
    check(result.returncode == 1 and
          "Contact/Discretization <node to segment> there, <mortar> here" in
          result.stderr and open(patch + "/history.csv").read() == before,
          "bad restart (node to segment -> mortar): exit 1, output kept")

    # Issue 56: the same mesh file with two boundaries' or two bodies' tags
    # swapped (a restart took it; its contact force was 0 afterwards).
    squares = out + "/two_squares"
    run(tribos, tests + "/gmsh_import.prm", squares,
        ["Scene/Mesh file=%s/two_squares.msh" % tests,
         "Time stepping/Number of steps=4", "Output/Checkpoint every=2"])
    text = open(tests + "/two_squares.msh").read()
    swaps = {"boundary ids": ("1 1 2 1 1 1 4", "1 1 2 2 1 1 4",
                              "2 1 2 2 2 3 6", "2 1 2 1 2 3 6"),
             "body ids": ("3 3 2 1 1 1 2 5 4", "3 3 2 2 1 1 2 5 4",
                          "4 3 2 2 2 2 3 6 5", "4 3 2 1 2 2 3 6 5")}
    before = open(squares + "/history.csv").read()
    for name, (a, a_swapped, b, b_swapped) in swaps.items():
        mesh = "%s/swapped_%s.msh" % (out, name.split()[0])
        with open(mesh, "w") as f:
            f.write(text.replace(a, a_swapped).replace(b, b_swapped))
        result = run(tribos, tests + "/gmsh_import.prm", squares,
                     ["Scene/Mesh file=" + mesh,
                      "Time stepping/Number of steps=4"],
                     expect_success=False,
                     extra=["--restart", squares + "/checkpoint-00002"])
        check(result.returncode == 1 and "ids changed" in result.stderr and
              open(squares + "/history.csv").read() == before,
              "bad restart (%s swapped in the mesh): exit 1, output kept" % name)

finish()
