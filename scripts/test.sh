#!/usr/bin/env bash
# Quick start 2: install what is missing, build, and run every test (unit, validation, corpus).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j 2
# A short fuzz run of the language reader (clang + libFuzzer + sanitizers, ~1.5 min with its
# build); scripts/fuzz.sh 600 is the full run.
"$root/scripts/fuzz.sh" 30
