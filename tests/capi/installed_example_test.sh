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
# The FCL module installed in LIBDIR/openmss and opened from there by the installed library
# (user/fcl_module.cpp looks next to the library first): an ELLIPSOID on a BOX, 0.05 s from
# resting on it; free fall would end at 0.0877, the contact holds it above 0.098 (its static
# penetration is (m g / k)^(1/e) = 4.6e-4).
test -f "$libdir/openmss/openmss_fcl.so" || { echo "no $libdir/openmss/openmss_fcl.so"; exit 1; }
cat > "$tmp/fcl.adm" <<'ADM'
fcl
UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND
PART/1, GROUND
MARKER/10, PART=1, QP=-1,-1,-1
GRAPHICS/1, BOX, CORNER=10, X=2, Y=2, Z=1
PART/2, MASS=1, CM=20, IP=0.004,0.004,0.004, QG=0,0,0.1
MARKER/20, PART=2
GRAPHICS/2, ELLIPSOID, CM=20, XSCALE=0.6, YSCALE=0.4, ZSCALE=0.2
CONTACT/1, IGEOM=2, JGEOM=1, IMPACT, STIFFNESS=1e6, DAMPING=100, DMAX=1e-3, EXPONENT=1.5
VARIABLE/1, FUNCTION=DZ(20)
ACCGRAV/KGRAV=-9.81
END
ADM
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror "$source/tests/capi/fcl_contact.c" -o "$tmp/fcl_contact" \
  $(pkg-config --cflags --libs openmss) -Wl,-rpath,"$libdir"
LD_DEBUG=files "$tmp/fcl_contact" "$tmp/fcl.adm" "$tmp/out" > "$tmp/fcl.log" 2> "$tmp/fcl.ld"
cat "$tmp/fcl.log"
grep -q "file=$libdir/openmss/openmss_fcl.so" "$tmp/fcl.ld" ||
  { echo "the module was not opened from $libdir/openmss"; grep openmss_fcl "$tmp/fcl.ld"; exit 1; }
awk '/^height/ { exit !($2 > 0.098) }' "$tmp/fcl.log"
