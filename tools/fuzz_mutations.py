"""What tools/fuzz_inputs.py does to a gmsh file or an Abaqus deck: the
files it mutates, the hostile tokens, keywords and set entries, and the
mutations themselves (one random defect per file)."""

import re

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


# The abaqus scenes: (parameter file, its deck).
DECKS = [("tests/data/blocks_on_plate.prm", "tests/data/blocks_on_plate.inp"),
         ("tests/data/blocks_on_plate_3d.prm",
          "tests/data/blocks_on_plate_3d.inp")]
ELEMENT_TYPES = ["CPE4", "CPE8", "CPE3", "CPS4R", "CAX4", "C3D8", "C3D20",
                 "C3D4", "C3D27", "C3D8I", "S4R", "B31", "SPRINGA", "", "cpe4",
                 "CPE4HX", "T3D2"]
GENERATE_LINES = ["1, 1000000000, 1", "1, 5, 0", "1, 9, 0", "5, 1, 1",
                  "1, 9, -1", "1, 18446744073709551616, 1",
                  "1, 5, 1000000000", "1, 4294967296, 1", "0, 0, 0",
                  "1, 9, 2.5", "1", "1, 2, 3, 4", "1, 9, 4"]
SET_NAMES = ["NOSUCHSET", "", "Eall", "PLATE_TOP", "BOTTOM", "S1", "1e300",
             "plate", "101", "X" * 300, "A B"]
COORDINATES = ["1e300", "-1e300", "1e151", "1e150", "nan", "inf", "1e-320",
               "0x10", "", "1.0.0", "1e999"]
# Keyword lines to add; {self} is the deck's own file.
DECK_KEYWORDS = ["*PART, NAME=P1", "*END PART", "*INSTANCE, NAME=I, PART=P1",
                 "*NGEN, NSET=G", "*ELGEN, ELSET=PLATE", "*SYSTEM",
                 "*INCLUDE, INPUT=missing.inp", "*INCLUDE, INPUT={self}",
                 "*INCLUDE, INPUT=/dev/zero", "*INCLUDE", "*NODE, NSET=BOTTOM",
                 "*ELEMENT, TYPE=CPE4", "*ELEMENT", "*ELEMENT, TYPE=C3D8",
                 "*NSET, NSET=BLOCK, ELSET=PLATE", "*SURFACE, NAME=PLATE_TOP",
                 "*ELSET, ELSET=PLATE, GENERATE", "*SURFACE",
                 "*NSET, NSET=NOSUCH, GENERATE", "*", "*HEADING",
                 "*ELSET, ELSET=EALL, INTERNAL", "*NSET, NSET=Nall", "*STEP",
                 "*ELEMENT, TYPE=CPE4, ELSET=PLATE, ELSET=BLOCK"]
# Hostile Scene/Body sets and Boundary sets of the two decks.
BODY_SETS = ["PLATE : 0, BLOCK : 1", "X : 1", "PLATE : 1, BLOCK : 2147483648",
             "PLATE : 1, PLATE : 2, BLOCK : 3", "PLATE : 1, BLOCK : 1",
             "PLATE : 1", "plate : 1, block : 2", "PLATE : -1, BLOCK : 2",
             "PLATE, BLOCK", "PLATE : 1 : 2, BLOCK : 2",
             "PLATE : 1,, BLOCK : 2",
             ":", "PLATE : nan, BLOCK : 2", "PLATE : 1e3, BLOCK : 2",
             "BOTTOM : 1, BLOCK : 2", "PLATE : 1, BLOCK : 2147483647",
             "PLATE : 1, BLOCK : 2, BLOCK : 2", "SURFACE:PLATE : 1, BLOCK : 2",
             "PLATE:1,BLOCK:2", "PLATE : 1, BLOCK : 2, Eall : 3"]
BOUNDARY_SETS = [
    "BOTTOM : 0, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4", "X : 1",
    "BOTTOM : 2147483648, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4",
    "BOTTOM : 1, BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4",
    "BOTTOM : 1, BOTTOM : 5, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4",
    "BOTTOM : 1, TOP : 2", "BOTTOM : 1, TOP : 1, BLOCK_BOTTOM : 3, "
    "PLATE_TOP : 4", "BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 4, PLATE_TOP : 3",
    "NSET:BOTTOM : 1, NSET:TOP : 2, SURFACE:BLOCK_BOTTOM : 3, "
    "SURFACE:PLATE_TOP : 4",
    "SURFACE:BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4",
    "BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4, Nall : 5",
    "BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4, PLATE : 5",
    "BOTTOM : 2147483647, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4",
    "BOTTOM : 1, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 3",
    "BOTTOM : -1, TOP : 2, BLOCK_BOTTOM : 3, PLATE_TOP : 4",
    "BOTTOM : 1; TOP : 2; BLOCK_BOTTOM : 3; PLATE_TOP : 4"]


def mutate_deck(text, generator, own):
    """One random defect in an Abaqus deck's text (own: the deck's file,
    for an *INCLUDE of itself): one of mutate_mesh's, a field of a data
    line replaced by a hostile token, a node's coordinate made hostile,
    another *ELEMENT TYPE=, a hostile GENERATE line, a set name the deck
    lacks, a hostile keyword line added, a keyword misspelt or commented
    out. Returns (text, what was done)."""
    lines = text.split("\n")
    # The keyword whose data each line is ("" for keyword and comment
    # lines and those before the first keyword).
    block, owner = "", []
    for line in lines:
        if line.startswith("**") or not line.strip():
            owner.append("")
        elif line.startswith("*"):
            block = line
            owner.append("")
        else:
            owner.append(block)
    data = [i for i, b in enumerate(owner) if b]
    keywords = [i for i, line in enumerate(lines)
                if line.startswith("*") and not line.startswith("**")]
    kind = generator.randrange(10)
    if kind <= 1:
        return mutate_mesh(text, generator)
    if kind == 2:
        i = generator.choice(data)
        fields = lines[i].split(",")
        j = generator.randrange(len(fields))
        token = generator.choice(TOKENS + COORDINATES + SET_NAMES)
        what = "line %d field %d <%s> -> <%s>" % (i + 1, j + 1,
                                                 fields[j].strip(), token)
        fields[j] = " " + token if j else token
        lines[i] = ",".join(fields)
    elif kind == 3:
        i = generator.choice([i for i in data if owner[i].upper().split(
            ",")[0].strip() == "*NODE"])
        fields = lines[i].split(",")
        j = generator.randrange(1, len(fields))
        token = generator.choice(COORDINATES)
        what = "line %d coordinate %d <%s> -> <%s>" % (
            i + 1, j, fields[j].strip(), token)
        fields[j] = " " + token
        lines[i] = ",".join(fields)
    elif kind == 4:
        i = generator.choice([i for i in keywords if lines[i].upper().split(
            ",")[0].strip() == "*ELEMENT"])
        name = generator.choice(ELEMENT_TYPES)
        lines[i] = re.sub(r"TYPE=[^,]*", "TYPE=" + name, lines[i])
        what = "line %d *ELEMENT TYPE=%s" % (i + 1, name)
    elif kind == 5:
        sets = [i for i in keywords if re.match(r"\*[NE]SET", lines[i], re.I)]
        i = generator.choice(sets)
        if "GENERATE" not in lines[i].upper():
            lines[i] += ", GENERATE"
        value = generator.choice(GENERATE_LINES)
        lines[i + 1] = value
        what = "line %d GENERATE <%s>" % (i + 2, value)
    elif kind == 6:
        # A name that refers to a set: a keyword's NSET=, ELSET= or NAME=,
        # or the element (set) of a surface's face.
        named = [(i, "keyword") for i in keywords
                 if re.search(r"(NSET|ELSET|NAME)=", lines[i], re.I)] + \
                [(i, "face") for i in data
                 if owner[i].upper().startswith("*SURFACE")]
        i, where = generator.choice(named)
        name = generator.choice(SET_NAMES)
        if where == "face":
            lines[i] = re.sub(r"^[^,]*", name, lines[i])
        else:
            found = list(re.finditer(r"(NSET|ELSET|NAME)=([^,]*)", lines[i],
                                     re.I))
            m = generator.choice(found)
            lines[i] = lines[i][:m.start(2)] + name + lines[i][m.end(2):]
        what = "line %d set name -> <%s>" % (i + 1, name)
    elif kind == 7:
        i = generator.randrange(len(lines) + 1)
        keyword = generator.choice(DECK_KEYWORDS).replace("{self}", own)
        lines.insert(i, keyword)
        what = "line %d <%s> added" % (i + 1, keyword)
    else:
        # One of the keywords tribos reads (the others it skips).
        i = generator.choice([i for i in keywords if re.match(
            r"\*(NODE|ELEMENT|NSET|ELSET|SURFACE)\s*(,|$)", lines[i], re.I)])
        word = re.match(r"\*[^,]*", lines[i]).group(0)
        new = generator.choice(["*" + word, word.lower(), word[:-1],
                                word + "X", "* " + word[1:], word + ","])
        lines[i] = new + lines[i][len(word):]
        what = "line %d keyword <%s> -> <%s>" % (i + 1, word, new)
    return "\n".join(lines), what
