#!/usr/bin/python3
"""File and function size figures for the tracked C and C++ files (Python standard library only).

Usage: scripts/code-stats.py [folder ...]   (default: the whole repository)

Method:
- Files: every tracked *.c, *.cpp, *.h, *.hpp (git ls-files), optionally limited to the given
  folders; a file's size is its number of lines.
- Functions: estimated, not parsed. A function opens on a line that ends with "{" and holds a ")"
  (so "f(...) {", "f(...) const {", "-> T {", or the last line of a constructor's initialiser list);
  lines that open control blocks (if, for, while, switch, else, do, try, catch), lambdas ("](" or
  "= [") and namespace, class, struct, enum, union or extern blocks are skipped. The signature is
  followed back over the lines before the opener that end in neither ";", "{" nor "}" (nor are
  blank, comments, preprocessor lines or access labels); the first of them gives the indentation.
  Only indentation 0 (top level) and 2 (class members) count. The body runs to the first later
  line that is that indentation followed by "}"; its size is the number of lines strictly between
  the opener and that brace. One-line bodies ("{ return x; }") open no block and are not counted.
- Figures: count, median, p90 (nearest rank) and max of each.
"""

import re
import statistics
import subprocess
import sys
from pathlib import Path

EXTENSIONS = ("*.c", "*.cpp", "*.h", "*.hpp")
CONTROL = re.compile(r"^\s*(\}\s*)?(if|for|while|switch|else|do|try|catch)\b")
BLOCKS = re.compile(r"^\s*(namespace|class|struct|enum|union|extern)\b")
LABEL = re.compile(r"^\s*(public|private|protected)\s*:\s*$")


def tracked_files(root, folders):
    """The tracked C and C++ files under `folders` (all when empty), relative to `root`."""
    args = ["git", "-C", str(root), "ls-files", "--", *EXTENSIONS]
    names = subprocess.run(args, check=True, capture_output=True, text=True).stdout.split()
    if folders:
        prefixes = tuple(f.rstrip("/") + "/" for f in folders)
        names = [n for n in names if n.startswith(prefixes)]
    return names


def indent_of(line):
    """The number of leading spaces."""
    return len(line) - len(line.lstrip(" "))


def is_boundary(line):
    """Whether `line` cannot belong to a signature that continues on the next line."""
    s = line.strip()
    return (
        not s
        or s.endswith((";", "{", "}"))
        or s.startswith(("//", "/*", "*", "#"))
        or LABEL.match(line) is not None
    )


def signature_indent(lines, opener):
    """The indentation of the first line of the signature that ends on line `opener`."""
    first = opener
    while first > 0 and not is_boundary(lines[first - 1]):
        first -= 1
    return indent_of(lines[first]), lines[first]


def is_opener(line):
    """Whether `line` may open a function body (see the method above)."""
    s = line.rstrip()
    if not s.endswith("{") or ")" not in s or s.lstrip().startswith(("//", "#")):
        return False
    if CONTROL.match(s) or "](" in s or "= [" in s:
        return False
    return True


def function_sizes(lines):
    """Body sizes, in lines, of the functions found in `lines`."""
    sizes = []
    for i, line in enumerate(lines):
        if not is_opener(line):
            continue
        indent, first = signature_indent(lines, i)
        if indent not in (0, 2) or BLOCKS.match(first) or CONTROL.match(first):
            continue
        close = " " * indent + "}"
        for j in range(i + 1, len(lines)):
            if lines[j].rstrip() == close:
                sizes.append(j - i - 1)
                break
    return sizes


def p90(values):
    """The 90th percentile, nearest rank."""
    ordered = sorted(values)
    rank = max(1, -(-9 * len(ordered) // 10))
    return ordered[rank - 1]


def summary(name, values):
    """One line: count, median, p90 and max of `values`."""
    if not values:
        return f"{name}: none"
    return (
        f"{name}: {len(values)}  median {statistics.median(values):g}  "
        f"p90 {p90(values)}  max {max(values)}"
    )


def main():
    root = Path(__file__).resolve().parent.parent
    names = tracked_files(root, sys.argv[1:])
    file_lines, bodies = [], []
    for name in names:
        lines = (root / name).read_text(encoding="utf-8", errors="replace").splitlines()
        file_lines.append(len(lines))
        bodies.extend(function_sizes(lines))
    print(summary("files (lines)", file_lines))
    print(summary("functions (body lines)", bodies))


if __name__ == "__main__":
    main()
