#!/usr/bin/env bash
# Checks that every relative link and image in README.md and docs/**/*.md resolves: the file
# (or folder) exists and, for a link to a heading (#anchor) of a Markdown file, that heading
# exists (GitHub's anchor rules). Prints each broken link and exits 1 if there is any.
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 - "$@" <<'PY'
import os, re, sys

def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)   # GitHub drops punctuation but keeps - and _
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

files = ["README.md"]
for root, _, names in os.walk("docs"):
    files += [os.path.join(root, n) for n in sorted(names) if n.endswith(".md")]

link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
broken, checked = [], 0
for f in files:
    fence = False
    for no, line in enumerate(open(f, encoding="utf-8"), 1):
        if line.lstrip().startswith("```"):
            fence = not fence
        if fence:
            continue
        for target in link.findall(re.sub(r"`[^`]*`", "", line)):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):   # http:, https:, mailto:
                continue
            checked += 1
            path, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(os.path.dirname(f), path)) if path else f
            if not os.path.exists(dest):
                broken.append(f"{f}:{no}: {target}: no such file")
            elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                broken.append(f"{f}:{no}: {target}: no heading #{anchor} in {dest}")
for b in broken:
    print(b)
print(f"check-doc-links: {checked} links in {len(files)} files, {len(broken)} broken")
sys.exit(1 if broken else 0)
PY
