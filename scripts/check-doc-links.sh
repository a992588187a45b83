#!/usr/bin/env bash
# Checks the docs' links (scripts/check-doc-links.py says what exactly): every relative link
# and image in README.md and docs/**/*.md resolves, heading anchors included, and every
# docs/*.md path written in code, scripts, CMake files and --help texts exists. Prints each
# broken link and exits 1 if there is any.
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 scripts/check-doc-links.py "$@"
