#!/usr/bin/env python3
"""Checks docs/ARCHITECTURE.md against the CMake graph: every target of the product is in the
module table and in the layers, and every link goes from a layer to one below it."""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# Build helpers, not modules: the warning flags and the generated OpenGL loader.
HELPERS = {"pool_warnings", "pool_glad"}


def cmake_graph():
    """Targets (add_library/add_executable outside tests/) and their links to other targets."""
    files = subprocess.run(["git", "ls-files", "*CMakeLists.txt"], cwd=ROOT, check=True,
                           capture_output=True, text=True).stdout.split()
    text = "\n".join((ROOT / f).read_text() for f in files if not f.startswith("tests/"))
    text = re.sub(r"#[^\n]*", "", text)
    targets = set(re.findall(r"add_(?:library|executable)\(\s*([A-Za-z0-9_-]+)", text))
    links = {}
    for name, args in re.findall(r"target_link_libraries\(\s*([A-Za-z0-9_-]+)([^)]*)\)", text):
        links.setdefault(name, set()).update(a for a in args.split() if a in targets)
    return targets - HELPERS, {n: l - HELPERS for n, l in links.items() if n in targets}


def short(target):
    return target[len("pool_"):] if target.startswith("pool_") else target


def documented():
    """The module table's targets and the layers' rows (0: programs, at the top)."""
    doc = (ROOT / "docs/ARCHITECTURE.md").read_text()
    table = set()
    for line in doc.splitlines():
        if line.startswith("| `"):
            table.update(re.findall(r"`([a-z][A-Za-z0-9_-]*)`", line.split("|")[1]))
    block = doc.split("The same graph in layers", 1)[1].split("```", 2)[1]
    rows = {}
    for line in block.strip().splitlines():
        label, *names = line.split()
        row = 0 if label == "programs" else int(label)
        for name in names:
            rows[name] = row
    return table, rows


def main():
    targets, links = cmake_graph()
    table, rows = documented()
    problems = []
    for t in sorted(targets):
        if t not in table:
            problems.append(f"{t}: a CMake target missing from the module table")
        if short(t) not in rows:
            problems.append(f"{t}: a CMake target missing from the layers")
    for name in sorted(table - targets):
        problems.append(f"{name}: in the module table but no CMake target")
    for name in sorted(set(rows) - {short(t) for t in targets}):
        problems.append(f"{name}: in the layers but no CMake target")
    for t, deps in sorted(links.items()):
        for d in sorted(deps):
            if short(t) in rows and short(d) in rows and rows[short(t)] >= rows[short(d)]:
                problems.append(f"{t} links {d}: layer {rows[short(t)]} may use only layers "
                                f"below it (larger numbers), not {rows[short(d)]}")
    for p in problems:
        print(f"fence 'architecture': {p} (docs/ARCHITECTURE.md)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
