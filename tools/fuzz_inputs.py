#!/usr/bin/env python3
"""Fuzz tribos's input: mutate one entry of a parameter file at a time and
classify what the program does with it.

Each case takes one `set` entry of one of the scenes below and gives it a
hostile value (NaN, infinities, 0, negative, huge, tiny, empty, text,
120 000 characters), or deletes its line, or repeats the line with a
hostile value in the copy. The run gets a time limit. Outcomes:

  input error   exit 1 and the message names the entry (or, for a deleted
                line, is about the scene): the wanted answer to bad input
  unclear       exit 1 but the message does not name the entry
  completed     exit 0: the value was legal (0 friction, a deleted line
                whose default holds); "completed, warned" if tribos
                warned about it (a penalty of 1e-308 E/h)
  no convergence  exit 2: legal input that Newton could not solve; listed
                so that a bad value slipping through shows
  crash         killed by a signal or any other exit status
  hang          no end within the time limit
  half output   exit 1 with a history.csv written (bad input must write
                nothing)

With --meshes N, N more cases run the gmsh scene on a mesh file with one
random defect (a line deleted, repeated or swapped, a number replaced by a
hostile token, a token added or removed, the file cut): a message naming
Scene/Mesh file is an input error; "unknown exception" is unclear.

Writes one CSV row per case and prints the counts per outcome; exit status
1 if any crash, hang, unclear message or half output occurred.

  python3 tools/fuzz_inputs.py build/tribos --cases 160 --out fuzz.csv
"""

import argparse
import collections
import csv
import os
import random
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["tests/data/neo_hookean_stretch.prm", "tests/data/sliding_block.prm",
          "tests/data/sliding_blocks_3d.prm", "parameters/bar_impact.prm",
          "tests/data/ring_2d.prm"]
# Keep every run short: few steps, no VTU.
SHORT = ["Output/Write VTU=false"]
VALUES = ["nan", "inf", "-inf", "0", "-1", "1e308", "-1e308", "1e-308", "",
          "abc", "1, 2, 3, 4, 5, 6, 7", "9" * 120000, "1 : 2 : 3",
          ";;", "1e150", "-0"]


def lines_with_entries(path):
    """Each line of the parameter file at path with what it sets: (the
    entry's Section/.../Entry path, its key, its value), or None."""
    stack = []
    for line in open(path):
        text, entry = line.split("#", 1)[0].strip(), None
        if text.startswith("subsection "):
            stack.append(text[len("subsection "):].strip())
        elif text == "end":
            stack.pop()
        elif text.startswith("set "):
            key, _, value = text[4:].partition("=")
            entry = ("/".join(stack + [key.strip()]), key.strip(),
                     value.strip())
        yield line, entry


def entries(path):
    """The (Section/.../Entry, value) pairs set in the file at path."""
    return [(e[0], e[2]) for _, e in lines_with_entries(path) if e]


def without_line(path, entry, target, repeat=None):
    """A copy of the parameter file without the line that sets entry, or,
    if repeat is a value, with that line followed by a second one that sets
    entry to repeat."""
    lines = []
    for line, found in lines_with_entries(path):
        if found and found[0] == entry:
            if repeat is None:
                continue
            lines.append(line)
            line = "set %s = %s\n" % (found[1], repeat)
        lines.append(line)
    with open(target, "w") as f:
        f.writelines(lines)


def short_run(scene):
    """Overrides that keep a scene's run to a few seconds."""
    sets = list(SHORT)
    steps = {"parameters/bar_impact.prm": 40, "tests/data/ring_2d.prm": 5}
    if scene in steps:
        sets.append("Time stepping/Number of steps=%d" % steps[scene])
    return sets


def classify(result, entry, folder, timed_out):
    if timed_out:
        return "hang"
    code = result.returncode
    text = result.stderr
    last = entry.split("/")[-1]
    if code == 0:
        return "completed, warned" if "WARNING" in text else "completed"
    if code == 2:
        return "no convergence"
    if code == 1:
        if os.path.exists(os.path.join(folder, "history.csv")):
            return "half output"
        if "unknown exception" in text:
            return "unclear"
        if last in text or entry in text or "scene" in text.lower():
            return "input error"
        return "unclear"
    return "crash"


# Mesh files to mutate (Dimension, file): first and second order, MSH 2.2
# and (converted by gmsh where it is installed) 4.1.
MESHES = [(2, "tests/data/two_squares.msh"), (2, "tests/data/square_tagged_sides.msh"),
          (2, "tests/data/triangles.msh"), (2, "tests/data/inclined_square.msh"),
          (2, "tests/data/quarter_disc_tri6.msh"),
          (2, "tests/data/quarter_disc_quad8.msh"),
          (2, "tests/data/quarter_disc_quad9.msh"),
          (3, "tests/data/ball_octant_tet10.msh"),
          (3, "tests/data/ball_octant_hex20.msh"),
          (3, "tests/data/ball_octant_hex27.msh")]
TOKENS = ["0", "-1", "1e18", "4294967296", "9223372036854775808", "nan",
          "inf", "1e999", "abc", "", "2.5", "99", "1 2", "$Nodes",
          "$EndElements", "3.0", "2147483648"]


def mutate_mesh(text, generator):
    """One random defect in a gmsh file's text: a line deleted, repeated or
    swapped with the next, a number replaced by a hostile token, a token
    added or removed, or the file cut. Returns (text, what was done)."""
    lines = text.split("\n")
    i = generator.randrange(len(lines))
    kind = generator.randrange(7)
    if kind == 0:
        return "\n".join(lines[:i] + lines[i + 1:]), "line %d deleted" % (i + 1)
    if kind == 1:
        return ("\n".join(lines[:i + 1] + lines[i:]),
                "line %d repeated" % (i + 1))
    if kind == 2 and i + 1 < len(lines):
        lines[i], lines[i + 1] = lines[i + 1], lines[i]
        return "\n".join(lines), "lines %d and %d swapped" % (i + 1, i + 2)
    if kind == 6:
        cut = generator.randrange(len(text))
        return text[:cut], "cut after %d characters" % cut
    tokens = lines[i].split()
    if not tokens:
        return "\n".join(lines[:i] + lines[i + 1:]), "blank line deleted"
    j = generator.randrange(len(tokens))
    if kind == 3:
        tokens.insert(j, generator.choice(TOKENS))
        what = "token added to line %d" % (i + 1)
    elif kind == 4 and len(tokens) > 1:
        del tokens[j]
        what = "token %d of line %d removed" % (j + 1, i + 1)
    else:
        token = generator.choice(TOKENS)
        what = "line %d token %d <%s> -> <%s>" % (i + 1, j + 1, tokens[j],
                                                 token)
        tokens[j] = token
    lines[i] = " ".join(tokens)
    return "\n".join(lines), what


def mesh_sources(work):
    """MESHES, and their MSH 4.1 versions if gmsh is installed."""
    sources = [(dim, os.path.join(ROOT, path)) for dim, path in MESHES]
    if shutil.which("gmsh"):
        for dim, path in list(sources):
            target = os.path.join(work, os.path.basename(path)[:-4] +
                                  "_41.msh")
            done = subprocess.run(["gmsh", "-0", path, "-format", "msh41",
                                   "-save", "-o", target],
                                  capture_output=True)
            if done.returncode == 0 and os.path.exists(target):
                sources.append((dim, target))
    return sources


def fuzz_meshes(tribos, n_cases, generator, timeout, counts, rows, work):
    """n_cases runs of the gmsh scene on mutated mesh files."""
    prm = os.path.join(ROOT, "tests", "data", "gmsh_import.prm")
    sources = mesh_sources(work)
    for case in range(n_cases):
        dim, source = generator.choice(sources)
        text, mutation = mutate_mesh(open(source).read(), generator)
        mesh = os.path.join(work, "mesh_%03d.msh" % case)
        with open(mesh, "w") as f:
            f.write(text)
        folder = os.path.join(work, "mesh_case_%03d" % case)
        command = [tribos, prm, "--set", "Output/Directory=" + folder,
                   "--set", "Dimension=%d" % dim,
                   "--set", "Scene/Mesh file=" + mesh,
                   "--set", "Scene/Refinement=0",
                   "--set", "Materials/Young's modulus=1",
                   "--set", "Boundary conditions/Dirichlet=",
                   "--set", "Boundary conditions/Body force=" +
                   ", ".join(["0"] * dim)]
        timed_out = False
        try:
            result = subprocess.run(command, capture_output=True, text=True,
                                    timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out, result = True, None
        outcome = classify(result, "Scene/Mesh file", folder, timed_out)
        counts[outcome] += 1
        message = "" if result is None else \
            (result.stderr.strip().splitlines() or [""])[-1][:160]
        rows.append({"case": case, "scene": os.path.basename(source),
                     "entry": "Scene/Mesh file", "value": mutation,
                     "outcome": outcome,
                     "exit": "" if result is None else result.returncode,
                     "message": message})
        print("%3d %-15s %-30s %s" % (case, outcome,
                                      os.path.basename(source), mutation),
              flush=True)
        shutil.rmtree(folder, ignore_errors=True)
        os.remove(mesh)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--cases", type=int, default=160)
    parser.add_argument("--meshes", type=int, default=0,
                        help="also this many runs on mutated gmsh files")
    parser.add_argument("--seed", type=int, default=47)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    tribos = os.path.abspath(args.tribos)
    generator = random.Random(args.seed)
    catalogue = [(scene, entry, value) for scene in SCENES
                 for entry, value in entries(os.path.join(ROOT, scene))
                 if not entry.startswith("Output/")]
    counts = collections.Counter()
    rows = []
    work = tempfile.mkdtemp(prefix="tribos_fuzz_")
    try:
        for case in range(args.cases):
            scene, entry, original = generator.choice(catalogue)
            prm = os.path.join(ROOT, scene)
            folder = os.path.join(work, "case_%03d" % case)
            sets = short_run(scene)
            kind = generator.random()
            if kind < 0.1:
                mutation = "deleted"
                prm = os.path.join(work, "case_%03d.prm" % case)
                without_line(os.path.join(ROOT, scene), entry, prm)
            elif kind < 0.2:
                # The line twice, the second time with a hostile value
                # (the later one counts and must be checked).
                value = generator.choice(VALUES[:12])
                mutation = "repeated, then " + value[:20]
                prm = os.path.join(work, "case_%03d.prm" % case)
                without_line(os.path.join(ROOT, scene), entry, prm, value)
            else:
                mutation = generator.choice(VALUES)
                sets.append("%s=%s" % (entry, mutation))
            command = [tribos, prm, "--set", "Output/Directory=" + folder]
            for s in sets:
                command += ["--set", s]
            timed_out = False
            try:
                result = subprocess.run(command, capture_output=True,
                                        text=True, timeout=args.timeout,
                                        cwd=os.path.dirname(prm))
            except subprocess.TimeoutExpired:
                timed_out, result = True, None
            outcome = classify(result, entry, folder, timed_out)
            counts[outcome] += 1
            message = "" if result is None else \
                (result.stderr.strip().splitlines() or [""])[-1][:160]
            shown = mutation if len(mutation) <= 30 else \
                "%s... (%d chars)" % (mutation[:10], len(mutation))
            rows.append({"case": case, "scene": scene, "entry": entry,
                         "value": shown, "outcome": outcome,
                         "exit": "" if result is None else result.returncode,
                         "message": message})
            print("%3d %-15s %-30s %-40s %s" % (case, outcome, scene,
                                                entry[-40:], shown),
                  flush=True)
            shutil.rmtree(folder, ignore_errors=True)
        fuzz_meshes(tribos, args.meshes, generator, args.timeout, counts,
                    rows, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if args.out:
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
    print("\n" + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
    bad = sum(counts[k] for k in ("crash", "hang", "unclear", "half output"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
