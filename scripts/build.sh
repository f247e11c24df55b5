#!/usr/bin/env bash
# Configures and builds OpenMSS in ./build (Release, 2 jobs: the project's machines have 2 cores).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j 2
