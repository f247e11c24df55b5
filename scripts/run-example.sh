#!/usr/bin/env bash
# Quick start 1: install what is missing, build, and run the bundled piston-compressor example.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"$root/scripts/install-python-path.sh"  # import openmss from any folder (docs/python.md)
mkdir -p "$root/out/piston"
"$root/build/openmss" run "$root/examples/piston/piston.acf" --outdir "$root/out/piston"
