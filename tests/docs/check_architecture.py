#!/usr/bin/env python3
"""Checks that docs/architecture.md names every source unit of the library's folders, and
names nothing that does not exist.

Usage: check_architecture.py [repository root]   (default: the root above this script)

Sources: the files that `git ls-files` lists under api/, backend_gl/, backend_vk/,
integration/, test_hosts/ and tools/ whose names end in .c .h .cpp .hpp .inl .glsl .vert .frag .comp .py or .cmake,
or are called CMakeLists.txt.

A *name* is a span of the page in backticks (`...`). A name is expanded before matching:
  - `a.hpp/.cpp` (an extension list) stands for a.hpp and a.cpp;
  - `a.vert/.frag` likewise; `volume.vert/.frag` stands for volume.vert and volume.frag;
  - `a.*` stands for every source whose file name is a + "." + any extension;
  - a trailing "/" marks a folder;
  - a name holding "<" is a placeholder (`integration/<engine>/`) and is not matched.

A source S is *named* when one of these holds:
  1. its repository path appears as a name (after expansion), e.g. `api/src/plan/quadtree.*`;
  2. it lies in a table row whose first cell holds a folder name F/ (F a repository path),
     S lies under F, and the row holds a name equal to S's path relative to F or to S's
     file name (after expansion), e.g. the row of `backend_vk/` holding `vk_record.cpp`.
Every folder that holds a source must appear as a folder name (`F/`) somewhere on the page.

In the other direction, the page fails when it names what does not exist:
  - a name that starts with one of the roots above, samples/, tests/, scripts/, cmake/ or
    docs/ must match a tracked file or folder (after expansion);
  - in a row whose first cell holds a folder name F/ under the roots, every other name
    that looks like a file name (it has a source extension or ends in .*) must match a
    tracked file under F;
  - elsewhere, such a bare file name must match some tracked file of the repository.

Prints each fault and exits 1 if there is any.
"""
import os
import re
import subprocess
import sys

ROOTS = ("api/", "backend_gl/", "backend_vk/", "integration/", "test_hosts/", "tools/")
CHECKED_PREFIXES = ROOTS + ("samples/", "tests/", "scripts/", "cmake/", "docs/")
EXTS = (".c", ".h", ".cpp", ".hpp", ".inl", ".glsl", ".vert", ".frag", ".comp", ".py", ".cmake")
FILE_LIKE = re.compile(r"^[\w./-]*\w\.(?:\*|c|h|cpp|hpp|inl|glsl|vert|frag|comp|py|cmake|txt)$")


def is_source(path):
    return path.startswith(ROOTS) and (path.endswith(EXTS) or os.path.basename(path) == "CMakeLists.txt")


def expand(name):
    """The names a backticked span stands for: `a.hpp/.cpp` -> a.hpp, a.cpp."""
    parts = name.split("/.")
    if len(parts) > 1 and "." in parts[0]:
        stem = parts[0].rsplit(".", 1)[0]
        return [parts[0]] + [stem + "." + p for p in parts[1:]]
    return [name]


def matches(name, candidate):
    """Whether `name` (a path or file name, maybe ending in .*) stands for candidate."""
    if name.endswith(".*"):
        stem = name[:-2]
        return candidate.startswith(stem + ".") and "/" not in candidate[len(stem) + 1:]
    return candidate == name


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    tracked = subprocess.run(["git", "ls-files"], cwd=root, check=True, capture_output=True,
                             text=True).stdout.split("\n")
    tracked = [t for t in tracked if t and os.path.exists(os.path.join(root, t))]
    folders = set()
    for t in tracked:
        d = os.path.dirname(t)
        while d:
            folders.add(d + "/")
            d = os.path.dirname(d)
    sources = sorted(t for t in tracked if is_source(t))
    basenames = {os.path.basename(t) for t in tracked}

    page = os.path.join(root, "docs", "architecture.md")
    lines = open(page, encoding="utf-8").read().split("\n")
    faults = []
    all_names = set()          # expanded names anywhere on the page
    row_names = []             # (folder, [expanded names]) per table row with a folder first cell

    def exists(name):
        if name.endswith("/"):
            return name in folders
        if name.endswith(".*"):
            return any(matches(name, t) for t in tracked)
        return name in tracked or name.rstrip("/") + "/" in folders

    for no, line in enumerate(lines, 1):
        spans = [e for s in re.findall(r"`([^`]+)`", line) for e in expand(s.strip())]
        all_names.update(spans)
        folder = None
        if line.lstrip().startswith("|"):
            first = line.strip().strip("|").split("|")[0]
            heads = [s for s in re.findall(r"`([^`]+)`", first) if s.endswith("/")]
            if heads and heads[0].startswith(ROOTS):
                folder = heads[0]
                row_names.append((folder, spans))
        for name in spans:
            if "<" in name:
                continue
            if name.startswith(CHECKED_PREFIXES):
                if not exists(name):
                    faults.append(f"docs/architecture.md:{no}: `{name}` does not exist")
            elif FILE_LIKE.match(name):
                if folder:
                    if not any(t.startswith(folder) and (matches(name, t[len(folder):]) or
                                                         matches(name, os.path.basename(t)))
                               for t in tracked):
                        faults.append(f"docs/architecture.md:{no}: `{name}` is not a file under {folder}")
                elif not any(matches(name, b) for b in basenames) and not any(
                        matches(name, t) for t in tracked):
                    faults.append(f"docs/architecture.md:{no}: `{name}` is not a file of the repository")

    for s in sources:
        named = any(matches(n, s) for n in all_names)
        if not named:
            for folder, names in row_names:
                if s.startswith(folder):
                    rel, base = s[len(folder):], os.path.basename(s)
                    if any(matches(n, rel) or matches(n, base) for n in names):
                        named = True
                        break
        if not named:
            faults.append(f"{s}: not named in docs/architecture.md")
    for d in sorted({os.path.dirname(s) + "/" for s in sources}):
        if d not in all_names:
            faults.append(f"{d}: folder not named in docs/architecture.md")

    for f in faults:
        print(f)
    print(f"check_architecture: {len(sources)} sources, {len(faults)} faults")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
