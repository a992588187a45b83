#!/usr/bin/env bash
# A source that uses grass_collider.centre, the 0.5 development name of center
# (tests/abi/source_centre_host.c), against the current headers: with GRASS_ENABLE_DEPRECATED
# it compiles as C11 and as C++ under -Werror except for one deprecation warning per use,
# naming the new name; without the macro, and in C99 (no anonymous unions), it is refused
# with the compiler's "no member named centre" that suggests center (docs/migrating.md).
# Usage: source_centre_compiles.sh <C compiler> <C++ compiler> <include dir> <source>
set -euo pipefail
cc=$1
cxx=$2
include=$3
source=$4
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
flags=(-Wall -Wextra -Wpedantic -Werror -fsyntax-only "-I$include")
fail() {
  cat "$2"
  echo "source_centre_compiles: $1"
  exit 1
}

for build in "c:$cc -std=c11" "c++:$cxx -x c++ -std=c++17"; do
  name=${build%%:*}
  read -r -a compiler <<<"${build#*:}"
  log="$scratch/$name-with.log"
  if ! "${compiler[@]}" "${flags[@]}" -DGRASS_ENABLE_DEPRECATED -Wno-error=deprecated-declarations "$source" \
    2>"$log"; then
    fail "$name: refused with GRASS_ENABLE_DEPRECATED" "$log"
  fi
  uses=$(grep -c 'centre was renamed center in grass 0.5' "$log" || true)
  [[ $uses -ge 4 ]] || fail "$name: $uses deprecation warnings naming center, not one per assignment (4)" "$log"
  if grep -v -e 'Wdeprecated-declarations' "$log" | grep -q 'warning:'; then
    fail "$name: a warning other than a deprecation" "$log"
  fi
  log="$scratch/$name-without.log"
  if "${compiler[@]}" "${flags[@]}" "$source" 2>"$log"; then
    fail "$name: compiled without GRASS_ENABLE_DEPRECATED" "$log"
  fi
  grep -q "centre.*did you mean.*center" "$log" || fail "$name: without the macro, no error suggesting center" "$log"
done
log="$scratch/c99.log"
if "$cc" -std=c99 "${flags[@]}" -DGRASS_ENABLE_DEPRECATED "$source" 2>"$log"; then
  fail "c99: compiled, but C99 has no anonymous unions (the documented limit changed?)" "$log"
fi
grep -q "centre.*did you mean.*center" "$log" || fail "c99: no error suggesting center" "$log"
echo "source_centre_compiles: warns with GRASS_ENABLE_DEPRECATED (C11, C++), refused clearly without it and in C99"
