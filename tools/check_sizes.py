#!/usr/bin/env python3
"""The size rules of doc/architecture.md: no source file over 600 lines, no
function over about 150. Lists what breaks them and exits 1 if anything
does.

    python3 tools/check_sizes.py [--function-lines N] [--file-lines N]

Functions are found the way clang-format lays them out with the project's
.clang-format: a body opens with '{' alone on a line after the signature
and closes with '}' at the same indentation."""
import argparse
import os
import re
import sys

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("--function-lines", type=int, default=150)
parser.add_argument("--file-lines", type=int, default=600)
args = parser.parse_args()
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
found = 0
for folder in ("source", "include"):
    for directory, _, files in os.walk(os.path.join(root, folder)):
        for name in sorted(files):
            if not name.endswith((".cc", ".h")):
                continue
            path = os.path.join(directory, name)
            shown = os.path.relpath(path, root)
            lines = open(path).read().split("\n")
            if len(lines) > args.file_lines:
                print("%s: %d lines (> %d)" % (shown, len(lines),
                                               args.file_lines))
                found += 1
            i = 1
            while i < len(lines):
                opening = re.match(r"^( {0,4})\{$", lines[i])
                if opening and re.search(r"(\)|const|override|noexcept)\s*$",
                                         lines[i - 1]):
                    end = i + 1
                    while end < len(lines) and lines[end] != opening.group(1) + "}":
                        end += 1
                    start = i - 1
                    while start > 0 and "(" not in lines[start]:
                        start -= 1
                    if end - i - 1 > args.function_lines:
                        print("%s:%d: %s ... %d lines (> %d)"
                              % (shown, start + 1, lines[start].strip()[:60],
                                 end - i - 1, args.function_lines))
                        found += 1
                    i = end
                i += 1
sys.exit(1 if found else 0)
