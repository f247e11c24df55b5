#!/usr/bin/env bash
# Quick start 2: install what is missing, build, and run every test (unit, validation, corpus),
# then a short fuzz run of the language reader.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "$root/build"
log=$(mktemp)
ctest --output-on-failure -j 2 | tee "$log"
# A short fuzz run of the language reader (clang + libFuzzer + sanitizers, ~1.5 min with its
# build); scripts/fuzz.sh 600 is the full run.
"$root/scripts/fuzz.sh" 30
# Repeat the test count last, in the plain "N passed, N failed" form.
summary=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$log" | tail -n 1)
total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
failed=$(sed -E 's/.*, ([0-9]+) tests failed.*/\1/' <<<"$summary")
rm -f "$log"
echo "ctest: $((total - failed)) passed, $failed failed"
