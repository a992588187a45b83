#!/usr/bin/python3
"""Copies the C example of README.md from the C99 sample host, so the two cannot drift.

The regions of samples/c99_host/grass_c99_host.c between `/* [readme:NAME] */` and
`/* [readme:end] */` (in file order, dedented) replace the block of README.md between the
`<!-- readme-example:begin -->` and `<!-- readme-example:end -->` lines.

    /usr/bin/python3 scripts/readme-example.py           rewrite README.md
    /usr/bin/python3 scripts/readme-example.py --check   exit 1 (with a diff) if README.md differs
"""
import difflib
import os
import re
import sys
import textwrap

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLE = "samples/c99_host/grass_c99_host.c"
BEGIN = "<!-- readme-example:begin: generated from " + SAMPLE + " by scripts/readme-example.py -->"
END = "<!-- readme-example:end -->"


def example():
    source = open(os.path.join(ROOT, SAMPLE), encoding="utf-8").read()
    regions = re.findall(r"^[ \t]*/\* \[readme:(?!end)\w+\] \*/\n(.*?)^[ \t]*/\* \[readme:end\] \*/\n", source,
                         flags=re.S | re.M)
    if not regions:
        sys.exit(f"readme-example: no [readme:...] regions in {SAMPLE}")
    body = "\n".join(textwrap.dedent(r) for r in regions)
    return f"```c\n#include <grass/grass_gl.h>\n#include <EGL/egl.h>   /* the sample's GL loader */\n\n{body}```\n"


def main():
    check = "--check" in sys.argv[1:]
    path = os.path.join(ROOT, "README.md")
    readme = open(path, encoding="utf-8").read()
    start, stop = readme.find(BEGIN), readme.find(END)
    if start < 0 or stop < start:
        sys.exit(f"readme-example: README.md lacks the lines\n{BEGIN}\n{END}")
    wanted = readme[:start + len(BEGIN)] + "\n" + example() + readme[stop:]
    if wanted == readme:
        return 0
    if check:
        sys.stdout.writelines(difflib.unified_diff(readme.splitlines(True), wanted.splitlines(True),
                                                   "README.md", "README.md from " + SAMPLE))
        print(f"readme-example: README.md's C example differs from {SAMPLE}; "
              "run /usr/bin/python3 scripts/readme-example.py")
        return 1
    open(path, "w", encoding="utf-8").write(wanted)
    print("readme-example: README.md updated")
    return 0


if __name__ == "__main__":
    sys.exit(main())
