#!/usr/bin/env python3
"""Fuzz tribos's input: mutate one entry of a parameter file at a time and
classify what the program does with it.

Each case takes one `set` entry of one of the scenes below and gives it a
hostile value (NaN, infinities, 0, negative, huge, tiny, empty, text,
120 000 characters), or deletes its line, or repeats the line with a
hostile value in the copy. The run gets a time limit and a limit of its
address space (RLIMIT_AS, --memory GB; 0: none). Outcomes:

  input error   exit 1 and the message names the entry (or, for a deleted
                line, is about the scene): the wanted answer to bad input
  unclear       exit 1 but the message does not name the entry
  completed     exit 0: the value was legal (0 friction, a deleted line
                whose default holds); "completed, warned" if tribos
                warned about it (a penalty of 1e-308 E/h)
  no convergence  exit 2: legal input that Newton could not solve; listed
                so that a bad value slipping through shows
  crash         killed by a signal or any other exit status
  hang          no end within the time limit, nothing written to its log
                or convergence.csv in its last PROGRESS_SECONDS
  slow          no end within the time limit, but still iterating (a
                legal model that takes longer: not counted as bad)
  half output   exit 1 with a history.csv written (bad input must write
                nothing)
  memory        stopped by the address space limit: std::bad_alloc, "out
                of memory" or "Cannot allocate memory" in the message, a
                SIGKILL, or another signal once the process had mapped
                within 256 MB of the limit (a run must stay within what
                the memory holds; tribos cuts adaptive refinement to it)
  silent wrong  exit 0, but a NaN or infinite number in history.csv or in
                the last contact-NNNNN.csv (its COPEN aside: nan there is
                a node beyond the search distance, by the output
                contract), or, on the sliding block, no equilibrium (below)

Equilibrium (tests/data/sliding_block.prm: one body, held by its top's
Dirichlet condition and pressed on a rigid plane): in statics the internal
forces of a body sum to zero, so the supports' reactions, the contact
forces on it and the applied loads balance: sum of RF<id>_<c> + sum of
pair<i>_F<c> = -(loads) = 0, up to the unbalanced residual of the free
rows, which is at most sqrt(dofs) * residual (history.csv's residual is
their l2 norm). A row of history.csv that misses this by more than that
bound and by more than 1e-6 of its largest force is "silent wrong". It is
checked only where it holds: Integrator static, no Body force, Neumann,
Symmetry (whose reactions history.csv does not give), Stabilization
factor or Axisymmetric, one Dirichlet item (edges shared by two items
count in both) and every pair against a rigid surface (a pair inside the
body puts its force on both sides).

With --meshes N, N more cases run the gmsh scene on a mesh file with one
random defect (a line deleted, repeated or swapped, a number replaced by a
hostile token, a token added or removed, the file cut): a message naming
Scene/Mesh file is an input error; "unknown exception" is unclear.

With --decks N, N runs of the abaqus scene (tests/data/blocks_on_plate.prm,
2D, and blocks_on_plate_3d.prm, 3D) on a copy of their deck with one
random defect: those of the mesh files, or one of the deck's own (a
field of a data line replaced by a hostile token, a node's coordinate
1e300, another *ELEMENT TYPE=, a GENERATE line with a huge, zero or
negative increment, a set name the deck lacks, a hostile keyword line
added such as *PART, *NGEN or an *INCLUDE of the deck itself, a keyword
misspelt or commented out); or, in about a quarter of them, the intact
deck with Scene/Body sets or Boundary sets given hostile items (PLATE : 0,
X : 1, BOTTOM : 2147483648, duplicates, a node set as a body). A message
naming Scene/Input deck, the deck file with a line number, the set
entries, or Contact/Pairs or Boundary conditions/Dirichlet (which use the
ids the sets give) is an input error.

With --adaptive N, N runs of tests/data/sliding_block.prm and (with
Scene/Block/Subdivisions = 2, 2, 2 and 5 steps) tests/data/j2_uniaxial.prm
with Adaptivity/Enable = true and one other Adaptivity entry, taken from
`tribos --print-parameters` (so that new entries are fuzzed too), given a
hostile value: one of those above, or one legal but extreme (Maximum level
20, Refine fraction 0.98, 1 or 0, Strategy fixed number, Initial cycles 20,
Maximum dofs 1 or 0, Every 0 or 1000, Contact zone depth 0 or 1e9).

Writes one CSV row per case and prints the counts per outcome; exit status
1 if any crash, hang, unclear message, half output, memory or silent wrong
outcome occurred.

  python3 tools/fuzz_inputs.py build/tribos [--cases 160] [--meshes N]
      [--decks N] [--adaptive N] [--seed 47] [--timeout 60] [--memory 4]
      [--out fuzz.csv]
"""

import argparse
import collections
import csv
import glob
import math
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import types

from fuzz_mutations import (MESHES, mutate_mesh, DECKS, BODY_SETS,
                            BOUNDARY_SETS, mutate_deck)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["tests/data/neo_hookean_stretch.prm", "tests/data/sliding_block.prm",
          "tests/data/sliding_blocks_3d.prm", "parameters/bar_impact.prm",
          "tests/data/ring_2d.prm"]
# The scene whose equilibrium is checked (see the docstring).
BALANCED = "tests/data/sliding_block.prm"
# Keep every run short: few steps, no VTU.
SHORT = ["Output/Write VTU=false"]
VALUES = ["nan", "inf", "-inf", "0", "-1", "1e308", "-1e308", "1e-308", "",
          "abc", "1, 2, 3, 4, 5, 6, 7", "9" * 120000, "1 : 2 : 3",
          ";;", "1e150", "-0"]
# The outcomes that make the exit status 1.
BAD = ("crash", "hang", "unclear", "half output", "memory", "silent wrong")


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


def effective(path, sets):
    """The entries that the file at path and then the overrides sets
    ("Entry=value") give, as a dict (the last one of an entry counts)."""
    values = dict(entries(path))
    for s in sets:
        key, _, value = s.partition("=")
        values[key.strip()] = value.strip()
    return values


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


#: A run still writing its log or convergence.csv this many seconds
#: before its time limit is slow, not hung.
PROGRESS_SECONDS = 30


def run(command, timeout, memory, work, cwd=None, folder=None):
    """command with its standard input from /dev/null and its address space
    limited to memory bytes (0: no limit), killed with its process group
    after timeout seconds. Returns (result, timed_out, peak): result has
    returncode (None if it timed out), stdout and stderr, and progressing
    (whether, timed out, it had written to its log or to folder's
    convergence.csv within PROGRESS_SECONDS), peak is the largest address
    space (VmPeak) seen while it ran, in bytes."""
    def limit():
        if memory:
            resource.setrlimit(resource.RLIMIT_AS, (memory, memory))

    names = [os.path.join(work, "run.out"), os.path.join(work, "run.err")]
    with open(names[0], "w") as out, open(names[1], "w") as err:
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL,
                                   stdout=out, stderr=err, cwd=cwd,
                                   preexec_fn=limit, start_new_session=True)
    peak, end, timed_out = 0, time.time() + timeout, False
    progressing = False
    while process.poll() is None:
        try:
            with open("/proc/%d/status" % process.pid) as f:
                for line in f:
                    if line.startswith("VmPeak:"):
                        peak = max(peak, int(line.split()[1]) * 1024)
        except (OSError, ValueError):
            pass
        if time.time() > end:
            timed_out = True
            watched = [names[0]] + ([os.path.join(folder, "convergence.csv")]
                                    if folder else [])
            latest = max([os.path.getmtime(w) for w in watched
                          if os.path.exists(w)] + [0])
            progressing = time.time() - latest < PROGRESS_SECONDS
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except OSError:
                pass
            process.wait()
            break
        time.sleep(0.05)
    texts = []
    for name in names:
        with open(name, errors="replace") as f:
            texts.append(f.read())
        os.remove(name)
    result = types.SimpleNamespace(
        returncode=None if timed_out else process.returncode,
        stdout=texts[0], stderr=texts[1], progressing=progressing)
    return result, timed_out, peak


MEMORY_MESSAGES = ("bad_alloc", "out of memory", "Cannot allocate memory")


def classify(result, entry, folder, timed_out, peak=0, memory=0, names=()):
    """The outcome of a run (see the docstring); names are further texts
    or compiled patterns whose presence in the message makes exit 1 an
    input error."""
    if timed_out:
        return "slow" if result.progressing else "hang"
    code = result.returncode
    text = result.stderr
    last = entry.split("/")[-1]
    if code == 0:
        return "completed, warned" if "WARNING" in text else "completed"
    if code == 2:
        return "no convergence"
    if any(m in text for m in MEMORY_MESSAGES) or code == -signal.SIGKILL \
            or (code < 0 and memory and peak > memory - 256 * 2**20):
        return "memory"
    if code == 1:
        if os.path.exists(os.path.join(folder, "history.csv")):
            return "half output"
        if "unknown exception" in text:
            return "unclear"
        if last in text or entry in text or "scene" in text.lower():
            return "input error"
        for name in names:
            if (name in text) if isinstance(name, str) else \
                    name.search(text):
                return "input error"
        return "unclear"
    return "crash"


def non_finite(path, skip=()):
    """Where the CSV file at path holds a NaN or infinite number (the
    columns in skip aside), as a text, or None."""
    with open(path, newline="") as f:
        rows = csv.reader(f)
        header = next(rows, [])
        for n, row in enumerate(rows, 1):
            for name, value in zip(header, row):
                try:
                    number = float(value)
                except ValueError:
                    continue
                if name not in skip and not math.isfinite(number):
                    return "%s = %s in row %d of %s" % (
                        name, value, n, os.path.basename(path))
    return None


def balance_holds(values):
    """Whether the equilibrium of the docstring holds for a run of the
    sliding block with the entries values (the history's columns decide
    the rest: one Dirichlet item)."""
    def zero(text):
        try:
            return all(float(t) == 0 for t in text.split(",") if t.strip())
        except ValueError:
            return False

    if values.get("Time stepping/Integrator", "static") != "static":
        return False
    for entry in ("Boundary conditions/Neumann",
                  "Boundary conditions/Symmetry"):
        if values.get(entry, "").strip():
            return False
    if not zero(values.get("Boundary conditions/Body force", "")) or \
            not zero(values.get("Nonlinear solver/Stabilization factor",
                                "0")) or \
            values.get("Finite element/Axisymmetric", "false") != "false":
        return False
    for item in values.get("Contact/Pairs", "").split(";"):
        fields = item.split(":")
        if item.strip() and (len(fields) < 2 or
                             not re.match(r"[A-Za-z_]", fields[1].strip())):
            return False
    return True


def imbalance(folder):
    """Where history.csv in folder breaks the equilibrium of the docstring,
    as a text, or None (also where it does not apply: several Dirichlet
    items)."""
    with open(os.path.join(folder, "history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    reactions = [i for i, n in enumerate(header)
                 if re.fullmatch(r"RF\d+_[xyz]", n)]
    contacts = [i for i, n in enumerate(header)
                if re.fullmatch(r"pair\d+_F[xyz]", n)]
    axes = sorted(set(header[i][-1] for i in reactions + contacts))
    if len(reactions) > len(axes):
        return None
    dofs = None
    if "dofs" in header:
        column = header.index("dofs")
    else:
        column = None
        for line in open(os.path.join(folder, "summary.txt")):
            if line.split()[:1] == ["dofs"]:
                dofs = float(line.split()[1])
    for n, row in enumerate(rows, 1):
        forces = [float(row[i]) for i in reactions + contacts]
        scale = max([abs(x) for x in forces] + [0.])
        count = float(row[column]) if column is not None else dofs
        if count is None:
            return None
        residual = float(row[header.index("residual")])
        allowed = max(1e-6 * scale, math.sqrt(count) * residual)
        for axis in axes:
            total = sum(float(row[i]) for i in reactions + contacts
                        if header[i][-1] == axis)
            if abs(total) > allowed:
                return ("reactions + contact forces = %.6g in %s, row %d "
                        "(largest force %.6g, allowed %.3g)" %
                        (total, axis, n, scale, allowed))
    return None


def wrong_answer(folder, values=None):
    """Why the output of a completed run in folder is wrong (see "silent
    wrong" in the docstring), or None. values: the run's entries, if the
    equilibrium of the sliding block is to be checked."""
    history = os.path.join(folder, "history.csv")
    if not os.path.exists(history):
        return "exit 0 without history.csv"
    found = non_finite(history)
    contact = sorted(glob.glob(os.path.join(folder, "contact-*.csv")))
    if not found and contact:
        found = non_finite(contact[-1], skip=("COPEN",))
    if not found and values is not None and balance_holds(values):
        found = imbalance(folder)
    return found


def judge(result, entry, folder, timed_out, peak, memory, names=(),
          values=None):
    """(outcome, message) of a run whose output is in folder: classify()'s,
    and "silent wrong" for a completed run whose output is wrong."""
    outcome = classify(result, entry, folder, timed_out, peak, memory, names)
    # A hang shows how far it came: its last line of progress.
    text = result.stdout if timed_out else result.stderr
    message = (text.strip().splitlines() or [""])[-1][:160]
    if outcome.startswith("completed"):
        why = wrong_answer(folder, values)
        if why:
            outcome, message = "silent wrong", why
    return outcome, message


class Campaign:
    """The runs of one fuzz campaign: each case run, judged, counted, kept
    as a CSV row and printed."""

    def __init__(self, tribos, timeout, memory, work):
        self.tribos, self.timeout, self.memory = tribos, timeout, memory
        self.work = work
        self.counts = collections.Counter()
        self.rows = []

    def case(self, case, prm, sets, folder, scene, entry, mutation,
             names=(), cwd=None, values=None, width=30):
        """Run tribos on prm with the overrides sets into folder, judge it
        (entry the one fuzzed, names the others a message may name) and
        record it; mutation as shown (cut to width characters)."""
        command = [self.tribos, prm, "--set", "Output/Directory=" + folder]
        for s in sets:
            command += ["--set", s]
        result, timed_out, peak = run(command, self.timeout, self.memory,
                                      self.work, cwd=cwd, folder=folder)
        outcome, message = judge(result, entry, folder, timed_out, peak,
                                 self.memory, names, values=values)
        self.counts[outcome] += 1
        shown = mutation if len(mutation) <= width else \
            "%s... (%d chars)" % (mutation[:10], len(mutation))
        self.rows.append({"case": case, "scene": scene, "entry": entry,
                          "value": shown, "outcome": outcome,
                          "exit": "" if timed_out else result.returncode,
                          "message": message})
        print("%3d %-15s %-30s %-40s %s" % (case, outcome, scene,
                                            entry[-40:], shown), flush=True)
        shutil.rmtree(folder, ignore_errors=True)


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


def fuzz_meshes(campaign, n_cases, generator):
    """n_cases runs of the gmsh scene on mutated mesh files."""
    prm = os.path.join(ROOT, "tests", "data", "gmsh_import.prm")
    sources = mesh_sources(campaign.work)
    for case in range(n_cases):
        dim, source = generator.choice(sources)
        text, mutation = mutate_mesh(open(source).read(), generator)
        mesh = os.path.join(campaign.work, "mesh_%03d.msh" % case)
        with open(mesh, "w") as f:
            f.write(text)
        campaign.case(case, prm,
                      ["Dimension=%d" % dim, "Scene/Mesh file=" + mesh,
                       "Scene/Refinement=0", "Materials/Young's modulus=1",
                       "Boundary conditions/Dirichlet=",
                       "Boundary conditions/Body force=" +
                       ", ".join(["0"] * dim)],
                      os.path.join(campaign.work, "mesh_case_%03d" % case),
                      os.path.basename(source), "Scene/Mesh file", mutation,
                      width=80)
        os.remove(mesh)


def fuzz_decks(campaign, n_cases, generator):
    """n_cases runs of the abaqus scene on mutated decks or with hostile
    set entries."""
    work = campaign.work
    for case in range(n_cases):
        scene, source = generator.choice(DECKS)
        prm, source = os.path.join(ROOT, scene), os.path.join(ROOT, source)
        deck = os.path.join(work, "deck_%03d.inp" % case)
        sets = ["Scene/Input deck=" + deck]
        if generator.random() < 0.25:
            deck = source
            sets = ["Scene/Input deck=" + deck]
            entry = generator.choice(["Scene/Body sets",
                                      "Scene/Boundary sets"])
            items = BODY_SETS if entry.endswith("Body sets") else \
                BOUNDARY_SETS
            mutation = generator.choice(items + VALUES[:12])
            sets.append("%s=%s" % (entry, mutation))
        else:
            entry = "Scene/Input deck"
            text, mutation = mutate_deck(open(source).read(), generator, deck)
            with open(deck, "w") as f:
                f.write(text)
        names = ["Scene/Input deck", "Scene/Body sets", "Scene/Boundary sets",
                 "Contact/Pairs", "Boundary conditions/Dirichlet",
                 re.compile(re.escape(os.path.basename(deck)) +
                            r"(:| line | at line |, line )\d+")]
        campaign.case(case, prm, sets,
                      os.path.join(work, "deck_case_%03d" % case),
                      os.path.basename(scene), entry, mutation, names,
                      cwd=work, width=60)
        if deck != source:
            os.remove(deck)


# The adaptive scenes and the overrides that make them one.
ADAPTIVE = [("tests/data/sliding_block.prm", []),
            ("tests/data/j2_uniaxial.prm",
             ["Scene/Block/Subdivisions=2, 2, 2",
              "Time stepping/Number of steps=5"])]
# Legal but extreme values of Adaptivity entries.
EXTREMES = {"Maximum level": ["20"], "Minimum level": ["20"],
            "Refine fraction": ["0.98", "1", "0"],
            "Coarsen fraction": ["1", "0.98"],
            "Strategy": ["fixed number"], "Initial cycles": ["20"],
            "Maximum dofs": ["1", "0"], "Every": ["0", "1000"],
            "Contact zone depth": ["0", "1e9"],
            "Closing gap factor": ["0", "1e9"],
            "Contact indicator weight": ["0", "1"],
            "Bulk indicator": ["none"], "Redo on contact growth": ["false"]}


def adaptivity_entries(tribos, timeout, memory, work):
    """The entries of the Adaptivity section but Enable, as --print-
    parameters (deal.II's .prm format) lists them."""
    result, timed_out, _ = run([tribos, "--print-parameters", "prm"],
                               timeout, memory, work)
    if timed_out or result.returncode != 0:
        raise SystemExit("tribos --print-parameters failed: %s" %
                         ("timeout" if timed_out else result.stderr[-300:]))
    listing = os.path.join(work, "parameters.prm")
    with open(listing, "w") as f:
        f.write(result.stdout)
    found = [e for e, _ in entries(listing)
             if e.startswith("Adaptivity/") and e != "Adaptivity/Enable"]
    os.remove(listing)
    if not found:
        raise SystemExit("tribos --print-parameters lists no Adaptivity "
                         "entries")
    return found


def fuzz_adaptivity(campaign, n_cases, generator):
    """n_cases adaptive runs with one hostile Adaptivity entry."""
    if n_cases <= 0:
        return
    catalogue = adaptivity_entries(campaign.tribos, campaign.timeout,
                                   campaign.memory, campaign.work)
    for case in range(n_cases):
        scene, extra = generator.choice(ADAPTIVE)
        entry = generator.choice(catalogue)
        extremes = EXTREMES.get(entry.split("/")[-1], [])
        if extremes and generator.random() < 0.5:
            mutation = generator.choice(extremes)
        else:
            mutation = generator.choice(VALUES)
        prm = os.path.join(ROOT, scene)
        sets = SHORT + extra + ["Adaptivity/Enable=true",
                                "%s=%s" % (entry, mutation)]
        campaign.case(case, prm, sets,
                      os.path.join(campaign.work, "adaptive_case_%03d" % case),
                      scene, entry, mutation, cwd=os.path.dirname(prm),
                      values=effective(prm, sets) if scene == BALANCED
                      else None)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("tribos")
    parser.add_argument("--cases", type=int, default=160)
    parser.add_argument("--meshes", type=int, default=0,
                        help="also this many runs on mutated gmsh files")
    parser.add_argument("--decks", type=int, default=0,
                        help="also this many runs on mutated Abaqus decks")
    parser.add_argument("--adaptive", type=int, default=0,
                        help="also this many adaptive runs with a hostile "
                        "Adaptivity entry")
    parser.add_argument("--seed", type=int, default=47)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--memory", type=float, default=4,
                        help="address space limit of each run in GB "
                        "(0: none)")
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    tribos = os.path.abspath(args.tribos)
    memory = int(args.memory * 2**30)
    generator = random.Random(args.seed)
    catalogue = [(scene, entry, value) for scene in SCENES
                 for entry, value in entries(os.path.join(ROOT, scene))
                 if not entry.startswith("Output/")]
    work = tempfile.mkdtemp(prefix="tribos_fuzz_")
    campaign = Campaign(tribos, args.timeout, memory, work)
    try:
        for case in range(args.cases):
            scene, entry, original = generator.choice(catalogue)
            prm = os.path.join(ROOT, scene)
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
            campaign.case(case, prm, sets,
                          os.path.join(work, "case_%03d" % case), scene,
                          entry, mutation, cwd=os.path.dirname(prm),
                          values=effective(prm, sets) if scene == BALANCED
                          else None)
        fuzz_meshes(campaign, args.meshes, generator)
        fuzz_decks(campaign, args.decks, generator)
        fuzz_adaptivity(campaign, args.adaptive, generator)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    counts, rows = campaign.counts, campaign.rows
    if args.out and rows:
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
    print("\n" + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
    bad = sum(counts[k] for k in BAD)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
