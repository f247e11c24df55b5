#!/usr/bin/env bash
# Fuzzes the language reader (fuzz/reader_fuzzer.cpp) with libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer for SECONDS (default 600). Configures and builds a separate clang
# build in build-fuzz/, seeds a temporary corpus with every .adm/.acf of the validation data
# (tests/validation/adams-joints, and ../shared/validation/corpus when it is there),
# prints libFuzzer's summary and exits non-zero on any crash, leak, timeout or sanitizer
# report. Reproducers are kept in build-fuzz/artifacts/.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
seconds=${1:-600}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
shared="$root/../shared/validation"

cxx=$(command -v clang++-14 || command -v clang++ || true)
if [[ -z $cxx ]]; then
  echo "fuzz.sh: clang++ not found (install clang-14 and libclang-rt-14-dev)" >&2
  exit 1
fi

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER="$cxx" -DOPENMSS_BUILD_FUZZ=ON -DOPENMSS_BUILD_TESTS=OFF \
  -DOPENMSS_BUILD_BENCH=OFF -DOPENMSS_WERROR=OFF >/dev/null
cmake --build "$build" --target reader_fuzzer -j "${FUZZ_BUILD_JOBS:-2}"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/corpus" "$build/artifacts"
seeds=0
for dir in "$shared/corpus" "$root/tests/validation/adams-joints"; do
  [[ -d $dir ]] || continue
  while IFS= read -r -d '' f; do
    cp "$f" "$work/corpus/$(printf '%03d' "$seeds")-$(basename "$f")"
    seeds=$((seeds + 1))
  done < <(find "$dir" -type f \( -iname '*.adm' -o -iname '*.acf' \) -print0 | sort -z)
done
echo "fuzz.sh: $seeds seed files; fuzzing for $seconds s"

# -max_len: the largest seeds are ~370 kB; reading is linear, but shorter inputs give many
# more executions per second (with the sanitizers a 64 kB input reads in ~20 ms), and the
# first 8 kB of a seed still hold dozens of statements of every kind.
status=0
"$build/fuzz/reader_fuzzer" "$work/corpus" \
  -dict="$root/fuzz/reader.dict" -max_total_time="$seconds" -max_len=8192 -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/" \
  >"$work/log" 2>&1 || status=$?
grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^Done |^stat::|ERROR|SUMMARY|WARNING: (Leak|Address)|crash-|leak-|timeout-' \
  "$work/log" || true
if ((status != 0)); then
  echo "fuzz.sh: the fuzzer failed (status $status); full log follows" >&2
  tail -n 80 "$work/log" >&2
  exit "$status"
fi
if grep -q 'runtime error:' "$work/log"; then
  echo "fuzz.sh: UndefinedBehaviorSanitizer report" >&2
  grep -m 5 'runtime error:' "$work/log" >&2
  exit 1
fi
echo "fuzz.sh: no crash, leak or sanitizer report in $seconds s"
