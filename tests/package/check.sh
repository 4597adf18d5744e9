#!/bin/sh
# The library as a package: install rasterd's build tree into an empty prefix, build tests/package against it
# with find_package(raster), and check that its PNG of a scene is byte for byte the one `rasterd render`
# writes. Usage: check.sh BUILD_DIR SOURCE_DIR RASTERD [EXTRA_FLAGS] (flags for the consumer's compiler and
# linker: a sanitizer build's library needs its runtime).
set -eu
build=$1 src=$2 rasterd=$3 flags=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log"
cmake -S "$src/tests/package" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" >"$tmp/configure.log"
cmake --build "$tmp/consumer" >"$tmp/build.log"
scene="$src/examples/star.json"
"$tmp/consumer/consumer" "$scene" "$tmp/consumer.png"
"$rasterd" render "$scene" -o "$tmp/cli.png"
cmp "$tmp/consumer.png" "$tmp/cli.png"
echo "package: find_package(raster) from $tmp/prefix renders $(wc -c <"$tmp/consumer.png") bytes, as rasterd does"
