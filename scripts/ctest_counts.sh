#!/usr/bin/env bash
# Prints "N passed, N failed, N skipped" from a ctest log (ctest's console output), or fails
# when the log has no summary. ctest's own summary line ("100% tests passed, 0 tests failed out
# of 686") counts a skipped test as passed; the skipped ones are those listed as "(Skipped)"
# under "The following tests did not run:" (GoogleTest's GTEST_SKIP, through the
# SKIP_REGULAR_EXPRESSION that gtest_discover_tests sets). Used by scripts/test.sh; tested by
# tests/app/test_counts_test.cpp.
#   scripts/ctest_counts.sh LOG
set -euo pipefail
log=$1
summary=$(grep -E "tests passed, [0-9]+ tests? failed out of [0-9]+" "$log" | tail -n 1 || true)
if [[ -z $summary ]]; then
  echo "ctest_counts.sh: no ctest summary line in $log" >&2
  exit 1
fi
total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
failed=$(sed -E 's/.*, ([0-9]+) tests? failed.*/\1/' <<<"$summary")
# The list of tests that did not run (Skipped, Disabled, ...) ends at the first blank line.
skipped=$(awk '/^The following tests did not run:/ { list = 1; next }
               list && /^[[:space:]]*$/ { list = 0; next }
               list && /^[[:space:]]+[0-9]+ - .* \(Skipped\)[[:space:]]*$/ { n++ }
               END { print n + 0 }' "$log")
echo "$((total - failed - skipped)) passed, $failed failed, $skipped skipped"
