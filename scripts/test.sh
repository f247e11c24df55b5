#!/usr/bin/env bash
# Quick start 2: install what is missing, build, and run every test (unit, validation, corpus),
# then a short fuzz run of the language reader. The last line printed is the test count,
# "N passed, N failed, N skipped"; the exit status is non-zero when a test or the fuzz run
# failed. Tests skip only when the real-data corpus (OPENMSS_SHARED_DIR/validation/corpus,
# outside the repository) is absent, and say so.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"$root/scripts/install-python-path.sh"  # import openmss from any folder (docs/python.md)
cd "$root/build"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
ctest_status=0
ctest --output-on-failure -j 2 2>&1 | tee "$log" || ctest_status=$?
# A short fuzz run of the language reader (clang + libFuzzer + sanitizers, ~1.5 min with its
# build); scripts/fuzz.sh 600 is the full run.
fuzz_status=0
"$root/scripts/fuzz.sh" 30 || fuzz_status=$?
if ((fuzz_status != 0)); then echo "fuzz: failed (status $fuzz_status)"; fi
counts_status=0
counts=$("$root/scripts/ctest_counts.sh" "$log") || counts_status=$?
if ((counts_status != 0)); then counts="no ctest summary (ctest status $ctest_status)"; fi
echo "$counts"
if ((ctest_status != 0 || fuzz_status != 0 || counts_status != 0)); then exit 1; fi
