#!/usr/bin/python3
"""The version number has one source, GRASS_VERSION_MAJOR/MINOR/PATCH in grass.h; checks that
everything that states it agrees: the build's library file and grass.pc (CMake reads the
header), and every find_package(grass X.Y) and libgrass.so.N[.N.N] that README.md and
docs/*.md (not docs/records, whose figures are history) write.

    check_versions.py [--build BUILD_DIR]
"""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def header_version():
    text = open(os.path.join(ROOT, "api", "include", "grass", "grass.h"), encoding="utf-8").read()
    parts = []
    for part in ("MAJOR", "MINOR", "PATCH"):
        m = re.search(r"^#define GRASS_VERSION_" + part + r" +(\d+) *$", text, flags=re.M)
        if not m:
            sys.exit(f"check_versions: grass.h has no #define GRASS_VERSION_{part}")
        parts.append(m.group(1))
    return parts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", help="a build directory: its libgrass.so.* and grass.pc are checked too")
    args = parser.parse_args()
    major, minor, patch = header_version()
    full = f"{major}.{minor}.{patch}"
    problems = []

    if args.build:
        pc = open(os.path.join(args.build, "grass.pc"), encoding="utf-8").read()
        m = re.search(r"^Version: *(\S+)", pc, flags=re.M)
        if not m or m.group(1) != full:
            problems.append(f"{args.build}/grass.pc: Version {m.group(1) if m else '(none)'}, grass.h {full}")
        if not os.path.exists(os.path.join(args.build, f"libgrass.so.{full}")):
            problems.append(f"{args.build}: no libgrass.so.{full}")

    docs = [os.path.join(ROOT, "README.md")]
    docs += [os.path.join(ROOT, "docs", n) for n in sorted(os.listdir(os.path.join(ROOT, "docs"))) if n.endswith(".md")]
    checked = 0
    for path in docs:
        for number, line in enumerate(open(path, encoding="utf-8"), 1):
            where = f"{os.path.relpath(path, ROOT)}:{number}"
            for m in re.finditer(r"find_package\(grass +(\d+)\.(\d+)", line):
                checked += 1
                if (m.group(1), m.group(2)) != (major, minor):
                    problems.append(f"{where}: find_package(grass {m.group(1)}.{m.group(2)}), grass.h {full}")
            for m in re.finditer(r"libgrass\.so\.(\d+(?:\.\d+)*)", line):
                checked += 1
                stated = m.group(1).split(".")
                if stated != [major, minor, patch][:len(stated)] or len(stated) == 2:
                    problems.append(f"{where}: libgrass.so.{m.group(1)}, grass.h {full}")
    for p in problems:
        print("check_versions: " + p)
    print(f"check_versions: grass.h {full}; {checked} mentions in the docs checked, {len(problems)} disagree")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
