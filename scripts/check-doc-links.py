#!/usr/bin/env python3
"""The doc link check (scripts/check-doc-links.sh runs it).

1. Markdown: every relative link and image in README.md and docs/**/*.md resolves: the file
   (or folder) exists and, for a link to a heading (#anchor) of a Markdown file, that heading
   exists (GitHub's anchor rules). Fenced blocks and code spans are not links.
2. Code: every path to a guide written in a tracked file that is not Markdown (C, C++, GLSL,
   Python, shell, CMake, scene JSON, --help texts: any text file `git ls-files` lists) must
   exist: a "docs/" path ending in ".md", with an optional "#anchor" (checked like a
   Markdown link's) and optional leading "../" parts, read from the repository root. A
   path counts only where "docs/" does not follow a letter, digit, "_", "-", "." or "/"
   (so "mydocs/" or "x/docs/" are not read) other than the "../" parts.

Prints each broken link or path and exits 1 if there is any.
"""
import os
import re
import subprocess
import sys


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)  # GitHub drops punctuation but keeps - and _
    return s.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen, out, fence = {}, set(), False
        for line in open(path, encoding="utf-8"):
            if line.lstrip().startswith("```"):
                fence = not fence
            if fence:
                continue
            m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                text = re.sub(r"`([^`]*)`", r"\1", m.group(1))
                text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
                base = slug(text)
                n = seen.get(base, 0)
                out.add(base if n == 0 else f"{base}-{n}")
                seen[base] = n + 1
        cache[path] = out
    return cache[path]


def check_target(where, target, dest, broken):
    anchor = target.partition("#")[2]
    if not os.path.exists(dest):
        broken.append(f"{where}: {target}: no such file")
    elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
        broken.append(f"{where}: {target}: no heading #{anchor} in {dest}")


def markdown_links(broken):
    files = ["README.md"]
    for root, _, names in os.walk("docs"):
        files += [os.path.join(root, n) for n in sorted(names) if n.endswith(".md")]
    link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
    checked = 0
    for f in files:
        fence = False
        for no, line in enumerate(open(f, encoding="utf-8"), 1):
            if line.lstrip().startswith("```"):
                fence = not fence
            if fence:
                continue
            for target in link.findall(re.sub(r"`[^`]*`", "", line)):
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                checked += 1
                path = target.partition("#")[0]
                dest = os.path.normpath(os.path.join(os.path.dirname(f), path)) if path else f
                check_target(f"{f}:{no}", target, dest, broken)
    return checked, len(files)


DOC_PATH = re.compile(r"(?<![\w/.-])(?:\.\./)*(docs/[\w./-]*\w\.md(?:#[\w-]+)?)")


def code_paths(broken):
    tracked = subprocess.run(["git", "ls-files", "-z"], check=True, capture_output=True).stdout
    checked = files = 0
    for f in sorted(t.decode() for t in tracked.split(b"\0") if t):
        if f.endswith(".md") or not os.path.isfile(f):
            continue
        try:
            text = open(f, encoding="utf-8").read()
        except UnicodeDecodeError:  # images, fonts, binary records
            continue
        files += 1
        for no, line in enumerate(text.split("\n"), 1):
            for target in DOC_PATH.findall(line):
                checked += 1
                check_target(f"{f}:{no}", target, target.partition("#")[0], broken)
    return checked, files


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    broken = []
    links, md_files = markdown_links(broken)
    paths, code_files = code_paths(broken)
    for b in broken:
        print(b)
    print(f"check-doc-links: {links} links in {md_files} Markdown files, {paths} doc paths in "
          f"{code_files} other files, {len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
