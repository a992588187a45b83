#!/usr/bin/env bash
# Installs the built library into a fresh prefix and builds an out-of-tree consumer against
# it twice, as users would: with CMake (find_package(grass), grass::grass) and with
# pkg-config (grass.pc). Each consumer runs from the installed tree alone.
# Usage: install_test.sh <build dir> <scratch dir>
set -euo pipefail
build=$1
scratch=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$scratch"
mkdir -p "$scratch"
prefix=$scratch/prefix

cmake --install "$build" --prefix "$prefix" >"$scratch/install.log"
for f in include/grass/grass.h include/grass/grass_gl.h include/grass/grass_vk.h; do
  [[ -f $prefix/$f ]] || { echo "install_test: $f was not installed"; exit 1; }
done
libdir=$(dirname "$(find "$prefix" -name 'libgrass.so' | head -n 1)")
[[ -n $libdir && -e $libdir/libgrass.so ]] || { echo "install_test: libgrass.so was not installed"; exit 1; }
soname=$(objdump -p "$libdir/libgrass.so" | awk '/SONAME/ {print $2}')
major=$(awk '/#define GRASS_VERSION_MAJOR/ {print $3}' "$prefix/include/grass/grass.h")
[[ $soname == "libgrass.so.$major" ]] || { echo "install_test: soname $soname, header major $major"; exit 1; }

header_version=$(awk '/#define GRASS_VERSION_(MAJOR|MINOR|PATCH) / {printf "%s%s", sep, $3; sep="."}' \
  "$prefix/include/grass/grass.h")
unset LD_LIBRARY_PATH

# 1. CMake: find_package(grass) from the prefix, as the README says: CMake puts the
# library's folder in the program's build run path, so it runs with no environment.
cmake -S "$here/consumer" -B "$scratch/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  >"$scratch/cmake-configure.log"
cmake --build "$scratch/cmake-build" >"$scratch/cmake-build.log"
"$scratch/cmake-build/consumer"

# 2. pkg-config: the compiler and linker flags from grass.pc, whose version is the header's.
export PKG_CONFIG_PATH=$libdir/pkgconfig
version=$(pkg-config --modversion grass)
echo "install_test: pkg-config finds grass $version"
[[ $version == "$header_version" ]] || { echo "install_test: grass.pc says $version, grass.h $header_version"; exit 1; }
# The README's command: the run path at link time.
# shellcheck disable=SC2046
cc -std=c99 -pedantic -Wall -Wextra -Werror "$here/consumer/consumer.c" $(pkg-config --cflags --libs grass) \
  -Wl,-rpath,"$libdir" -o "$scratch/consumer-pc"
"$scratch/consumer-pc"
# Without it the loader cannot find the library (the README says so and why) ...
# shellcheck disable=SC2046
cc -std=c99 -pedantic -Wall -Wextra -Werror "$here/consumer/consumer.c" $(pkg-config --cflags --libs grass) \
  -o "$scratch/consumer-pc-no-rpath"
if "$scratch/consumer-pc-no-rpath" 2>"$scratch/no-rpath.log"; then
  echo "install_test: a consumer without a run path found libgrass in $libdir; the README says it cannot"
  exit 1
fi
grep -q "libgrass.so.$major: cannot open shared object file" "$scratch/no-rpath.log" || {
  cat "$scratch/no-rpath.log"
  echo "install_test: a consumer without a run path failed otherwise than the README says"
  exit 1
}
# ... unless LD_LIBRARY_PATH names its folder.
LD_LIBRARY_PATH=$libdir "$scratch/consumer-pc-no-rpath"
echo "install_test: both consumers ran against $prefix (pkg-config: with a run path, and with LD_LIBRARY_PATH)"
