#!/usr/bin/env bash
# A source written against grass.h 0.3 (tests/abi/source_0_3_host.c), against the current
# headers: with GRASS_ENABLE_DEPRECATED it compiles under -Werror except for deprecation
# warnings, one naming the new name for each 0.3 name; without the macro it is refused with
# an error naming the macro, never compiled as an implicit declaration.
# Usage: source_0_3_compiles.sh <C compiler> <include dir> <source>
set -euo pipefail
cc=$1
include=$2
source=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
flags=(-std=c99 -Wall -Wextra -Wpedantic -Werror -Werror=implicit-function-declaration -fsyntax-only "-I$include" -DGRASS_ABI_TEST_EGL)

if ! "$cc" "${flags[@]}" -DGRASS_ENABLE_DEPRECATED -Wno-error=deprecated-declarations "$source" \
  2>"$scratch/with.log"; then
  cat "$scratch/with.log"
  echo "source_0_3_compiles: refused with GRASS_ENABLE_DEPRECATED"
  exit 1
fi
for rename in grass_context_backend:grass_get_context_backend:0.4 grass_last_error:grass_get_last_error:0.4 \
  grass_gl_default_desc:grass_default_gl_desc:0.4 grass_vk_default_desc:grass_default_vk_desc:0.4 \
  grass_vk_default_record_desc:grass_default_vk_record_desc:0.4 \
  grass_library_version:grass_get_library_version:0.5 grass_vk_prepare_frame:grass_vk_prepare:0.5; do
  IFS=: read -r old new version <<<"$rename"
  if ! grep -q "$old was renamed $new in grass $version" "$scratch/with.log"; then
    cat "$scratch/with.log"
    echo "source_0_3_compiles: no deprecation warning for $old naming $new"
    exit 1
  fi
done
if grep -v -e 'Wdeprecated-declarations' "$scratch/with.log" | grep -q 'warning:'; then
  cat "$scratch/with.log"
  echo "source_0_3_compiles: a warning other than a deprecation"
  exit 1
fi

if "$cc" "${flags[@]}" "$source" 2>"$scratch/without.log"; then
  echo "source_0_3_compiles: compiled without GRASS_ENABLE_DEPRECATED"
  exit 1
fi
for old in grass_context_backend grass_last_error grass_gl_default_desc grass_vk_default_desc \
  grass_vk_default_record_desc grass_library_version grass_vk_prepare_frame; do
  if ! grep -q "$old was renamed .* define GRASS_ENABLE_DEPRECATED" "$scratch/without.log"; then
    cat "$scratch/without.log"
    echo "source_0_3_compiles: without the macro, no error for $old that names GRASS_ENABLE_DEPRECATED"
    exit 1
  fi
done
echo "source_0_3_compiles: warns with GRASS_ENABLE_DEPRECATED, refused clearly without it"
