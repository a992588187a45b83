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

# 1. CMake: find_package(grass) from the prefix.
cmake -S "$here/consumer" -B "$scratch/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_BUILD_RPATH="$libdir" >"$scratch/cmake-configure.log"
cmake --build "$scratch/cmake-build" >"$scratch/cmake-build.log"
"$scratch/cmake-build/consumer"

# 2. pkg-config: the compiler and linker flags from grass.pc.
export PKG_CONFIG_PATH=$libdir/pkgconfig
version=$(pkg-config --modversion grass)
echo "install_test: pkg-config finds grass $version"
# shellcheck disable=SC2046
cc -std=c99 -pedantic -Wall -Wextra -Werror "$here/consumer/consumer.c" -o "$scratch/consumer-pc" \
  $(pkg-config --cflags --libs grass) -Wl,-rpath,"$libdir"
"$scratch/consumer-pc"
echo "install_test: both consumers ran against $prefix"
