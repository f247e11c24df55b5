#!/usr/bin/env bash
# Quick start 2: install what is missing, build, and run every test (unit, validation, corpus).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j 2
