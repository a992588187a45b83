#!/usr/bin/env python3
"""Checks that the core's folders depend one way (docs/architecture.md, "Layers").

Usage: check_layers.py [repository root]   (default: the root above this script)

The folders of api/src/ lie in layers, bottom up (LAYERS). A file under api/src/F/ may
include "G/..." only when G is F or G lies in a lower layer: folders of one layer know
nothing of each other. The backends (backend_gl/, backend_vk/) lie above the context,
beside entry/: they may include any folder of api/src/ but entry/ (the C entry points),
and they never include each other. An include that runs back up (or sideways) fails,
named with its file, line and the include.

Prints each fault and exits 1 if there is any.
"""
import os
import re
import sys

# Bottom up. The foundation needs nothing above it; the context owns every concept's
# state; entry/ holds the C entry points, on top.
LAYERS = [
    ("foundation",),
    ("patch", "maps", "timing"),
    ("bake", "mesh"),
    ("dynamics",),
    ("plan",),
    ("context",),
    ("entry",),
]
RANK = {folder: rank for rank, layer in enumerate(LAYERS) for folder in layer}

BACKENDS = ("backend_gl", "backend_vk")
SOURCE = re.compile(r"\.(c|h|cpp|hpp|inl)$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def sources(root, top):
    for base, dirs, files in os.walk(os.path.join(root, top)):
        dirs.sort()
        for name in sorted(files):
            if SOURCE.search(name):
                path = os.path.join(base, name)
                yield os.path.relpath(path, root).replace(os.sep, "/")


def includes(root, path):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m and "/" in m.group(1):
                yield number, m.group(1)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    core = os.path.join(root, "api", "src")
    faults = []
    for folder in sorted(os.listdir(core)):
        if os.path.isdir(os.path.join(core, folder)) and folder not in RANK:
            faults.append(f"api/src/{folder}/: a folder of no layer; add it to LAYERS in {__file__}")
    checked = 0
    for path in sources(root, "api/src"):
        folder = path.split("/")[2]
        if folder not in RANK:
            continue
        for number, target in includes(root, path):
            checked += 1
            to = target.split("/")[0]
            if to == folder:
                continue
            if to not in RANK:
                faults.append(f"{path}:{number}: #include \"{target}\": {to}/ is no folder of api/src")
            elif RANK[to] >= RANK[folder]:
                if RANK[to] == RANK[folder]:
                    why = f"runs sideways: {folder}/ and {to}/ lie in one layer"
                else:
                    why = f"runs back up: {folder}/ lies below {to}/"
                faults.append(f"{path}:{number}: #include \"{target}\" {why}")
    for backend in BACKENDS:
        for path in sources(root, backend):
            for number, target in includes(root, path):
                checked += 1
                to = target.split("/")[0]
                if to == "entry" or to in BACKENDS or (to not in RANK and not target.startswith(backend + "/")):
                    faults.append(
                        f"{path}:{number}: #include \"{target}\": a backend includes the core's folders but entry/, "
                        "and no other backend")
    for fault in faults:
        print(fault)
    order = " < ".join(", ".join(layer) for layer in LAYERS)
    if faults:
        print(f"{len(faults)} include(s) against the layers ({order})")
        return 1
    print(f"{checked} includes between folders follow the layers ({order})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
