#!/usr/bin/env bash
# Applies the project's code style (.clang-format, Debian's clang-format-15) to every C, C++
# and header file that git tracks; with --check, changes nothing and fails on any file whose
# format differs (scripts/test.sh runs the check).
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format=${CLANG_FORMAT:-clang-format-15}
if ! command -v "$clang_format" >/dev/null; then
  echo "format: $clang_format not found (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
mapfile -t files < <(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' '*.inl' | grep -v '^tests/abi/.*_0_3\.h$')
if [[ ${1:-} == --check ]]; then
  "$clang_format" --dry-run -Werror "${files[@]}"
  echo "format: ${#files[@]} files follow .clang-format"
else
  "$clang_format" -i "${files[@]}"
fi
