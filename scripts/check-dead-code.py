#!/usr/bin/env python3
"""Finds the library's functions that have no callers.

The library's objects are compiled with -ffunction-sections (CMakeLists.txt), so each function
lies in its own section. This script links them once more into a throw-away shared library with
--gc-sections: the linker keeps what the exported C API (the only default-visibility symbols)
reaches, and --print-gc-sections names every function it dropped. A dropped function of ours is
a function without callers, unless
  - it is also inlined somewhere in its own object (DWARF DW_TAG_inlined_subroutine): GCC emits
    an out-of-line copy of a function with external linkage even when every call is inlined;
  - it is on the allow-list below, with the reason it is kept. An allowed function is made a
    root of the second link (--require-defined), so the helpers only it calls are kept too.
Limits: inline functions and templates in headers (COMDAT sections) are never reported; a
virtual function is kept by its vtable, called or not; a function inlined only into dead
functions counts as called until those are removed (run again). Needs debug info (-g).

Usage: check-dead-code.py --cxx <c++ compiler> [--link-option <opt>]... <object files>
(an argument may hold several, ';'-separated: CMake's $<TARGET_OBJECTS:...>)
Exit status 0 when nothing is found, 1 with the list otherwise.
"""
import argparse
import re
import subprocess
import sys
import tempfile

# Functions the library does not call but keeps, each with its reason (the demangled name up to
# its parameter list).
ALLOWED = {
    "grass::alpha_coverage": "the slice-mip test's measure of alpha coverage (slice_baking_test)",
    "grass::build_box_mips": "the plain box filter the slice-mip test compares the coverage-keeping mips with",
    "grass::rasterize_slice_layer": "one slice layer on its own, for the slice-mip test (slice_baking_test)",
    "grass::write_mesh_blades": "a mesh field's blades in their GPU layout (issue 36): the backends' mesh draw "
                                "is still to come; mesh_field_test checks the layout",
    "grass::mirror_bits": "CPU reference of the shaders' mirrored tiling, checked by frame_plan_test",
    "grass::run_interaction_pass": "CPU reference of the interaction compute pass (interaction_pass_test, "
                                   "fuzz_responsive)",
    "grass::tier_blade_opacity": "CPU reference of the shaders' tier cross-fade, checked by tier_transitions_test",
}

REMOVED = re.compile(r"removing unused section '\.text(?:\.unlikely|\.hot|\.startup)?\.([^']+)' in file '([^']+)'")


def gc_link(cxx, link_options, objects, roots):
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [cxx, "-shared", "-o", tmp + "/libgrass-gc.so", *objects, "-lm", *link_options,
               "-Wl,--gc-sections", "-Wl,--print-gc-sections"]
        cmd += ["-Wl,--require-defined=" + r for r in sorted(roots)]
        run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("check-dead-code: the gc link failed:\n" + " ".join(cmd[:3]) + " ...\n" + run.stderr[-4000:])
    removed = {}
    for line in run.stderr.splitlines():
        m = REMOVED.search(line)
        if m and "[" not in m.group(1):  # a bracket names a COMDAT group: an inline function or template
            removed.setdefault(m.group(1), m.group(2))
    return removed


def demangle(names):
    out = subprocess.run(["c++filt"], input="\n".join(names) + "\n", capture_output=True, text=True, check=True)
    return dict(zip(names, out.stdout.splitlines()))


def inlined_names(obj, cache={}):
    """The linkage names of the functions inlined somewhere in obj (from its DWARF)."""
    if obj in cache:
        return cache[obj]
    dump = subprocess.run(["readelf", "--debug-dump=info", "--wide", obj], capture_output=True, text=True,
                          check=True).stdout
    dies, order, current = {}, [], None
    for line in dump.splitlines():
        m = re.match(r"\s*<\d+><([0-9a-f]+)>: Abbrev Number: \d+ \((\w+)\)", line)
        if m:
            current = {"tag": m.group(2)}
            dies[int(m.group(1), 16)] = current
            order.append(current)
            continue
        m = re.match(r"\s*<[0-9a-f]+>\s+(DW_AT_\w+)\s*:\s*(.*)$", line)
        if m and current is not None:
            current[m.group(1)] = m.group(2)

    def linkage(die, depth=0):
        if die is None or depth > 8:
            return None
        if "DW_AT_linkage_name" in die:
            return die["DW_AT_linkage_name"].split(": ")[-1].strip()
        for ref in ("DW_AT_abstract_origin", "DW_AT_specification"):
            m = re.search(r"<0x([0-9a-f]+)>", die.get(ref, ""))
            if m:
                return linkage(dies.get(int(m.group(1), 16)), depth + 1)
        return None

    names = set()
    if not any("DW_AT_name" in d for d in order):
        sys.exit("check-dead-code: " + obj + " has no debug info; build with -g (RelWithDebInfo or Debug)")
    for die in order:
        if die["tag"] == "DW_TAG_inlined_subroutine":
            name = linkage(die)
            if name:
                names.add(name)
    cache[obj] = names
    return names


def uncalled(removed):
    return {name: obj for name, obj in removed.items() if name not in inlined_names(obj)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cxx", required=True)
    parser.add_argument("--link-option", action="append", default=[])
    parser.add_argument("objects", nargs="+")
    args = parser.parse_args()
    # ctest passes CMake's $<TARGET_OBJECTS:...> lists as one argument each, ';'-separated.
    args.objects = [o for arg in args.objects for o in arg.split(";") if o]

    first = uncalled(gc_link(args.cxx, args.link_option, args.objects, set()))
    names = demangle(sorted(first))
    roots, used_allow = set(), set()
    for mangled, readable in names.items():
        key = readable.split("(")[0]
        if key in ALLOWED:
            roots.add(mangled)
            used_allow.add(key)
    found = uncalled(gc_link(args.cxx, args.link_option, args.objects, roots)) if roots else first
    names = demangle(sorted(found))
    failed = False
    for mangled in sorted(found, key=lambda n: (found[n], names[n])):
        print("no caller: %s  (%s)" % (names[mangled], found[mangled].rsplit("/", 1)[-1]))
        failed = True
    for key in sorted(set(ALLOWED) - used_allow):
        print("allow-list entry '%s' is called now or gone: remove it from scripts/check-dead-code.py" % key)
        failed = True
    if failed:
        print("check-dead-code: remove the functions above with their declarations, or allow-list them with "
              "a reason (scripts/check-dead-code.py)")
        return 1
    print("check-dead-code: every function of the %d objects is reached from the exported API (%d allowed)" %
          (len(args.objects), len(used_allow)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
