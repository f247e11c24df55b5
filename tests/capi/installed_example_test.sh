#!/bin/sh
# The embedding example built against the installed library, as a user builds it
# (docs/embedding.md): `cmake --install` into a fresh prefix, then the C compiler with
# `pkg-config --cflags --libs openmss` and nothing else from the build tree. The program closes
# the PID loop around examples/embedding/pendulum_plant.adm and compares it with the same loop
# written in one data set (pendulum_pid.adm); it exits 3 when they differ by more than 1e-8.
# Also checks the library's SONAME and that it exports only the C API's openmss_* functions.
# Usage: installed_example_test.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
source=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
libdir=$(dirname "$(find "$tmp/prefix" -name openmss.pc)")/..
PKG_CONFIG_PATH=$(dirname "$(find "$tmp/prefix" -name openmss.pc)")
export PKG_CONFIG_PATH
test "$(pkg-config --modversion openmss)" != ""
soname=$(readelf -d "$libdir/libopenmss.so" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')
test "$soname" = "libopenmss.so.1" || { echo "SONAME is '$soname'"; exit 1; }
# Every defined dynamic symbol (functions, weak template instantiations, data), except the
# linker's own markers and the version node (type A, OPENMSS_1 of src/capi/openmss.map).
exported=$(nm -D --defined-only "$libdir/libopenmss.so" |
  awk '$2 != "A" && $3 !~ /^(_init|_fini|_edata|_end|__bss_start)$/ {print $3}')
foreign=$(printf '%s\n' "$exported" | grep -v '^openmss_' || true)
test -z "$foreign" || { echo "exported beyond the C API:"; printf '%s\n' "$foreign" | head; exit 1; }
echo "exports: $(printf '%s\n' "$exported" | wc -l) openmss_* functions; SONAME $soname"
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror "$source/examples/embedding/pid_loop.c" -o "$tmp/pid_loop" \
  $(pkg-config --cflags --libs openmss) -lm -Wl,-rpath,"$libdir"
mkdir "$tmp/out"
"$tmp/pid_loop" "$source/examples/embedding/pendulum_plant.adm" "$tmp/out" \
  --compare "$source/examples/embedding/pendulum_pid.adm" | tee "$tmp/run.log"
grep -q "compared 514 values at 257 sample times" "$tmp/run.log"
test -s "$tmp/out/pendulum_plant.msg"
