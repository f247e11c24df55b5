#!/usr/bin/env bash
# Measures every integrator on every ADAMS validation case (docs/integrators.md): worst
# normalised error against ADAMS, steps, Jacobian evaluations and run time, as a Markdown table.
# Usage: scripts/integrator_table.sh [build-dir] [end-time]   (defaults: build, 5.0)
# The runs use each case's .acf settings (ERROR=1e-4, HMAX=1e-5, DTOUT=0.01) with the method
# replaced; end-time 5.0 is the .acf's own END. Run times depend on the machine and its load.
# The methods are those of everyIntegratorOnEveryCase() in tests/validation/adams_joints_test.cpp
# (GSTIFF ... ABAM, and MERSON, the explicit OpenMSS extension). A third argument filters the
# methods, e.g. 'MERSON' (matched against the test name's suffix).
set -euo pipefail
build="${1:-build}"
end="${2:-5.0}"
method="${3:-}"
echo "| case | integrator | worst error | steps | Jacobians | run time (s) |"
echo "|---|---|---|---|---|---|"
OPENMSS_INTEGRATOR_END="$end" "$build/tests/test_validation" \
    --gtest_filter="SharedData/AdamsJointByIntegrator.*${method:+_$method}" 2>&1 |
  grep '^TABLE |' | sed 's/^TABLE //; s/$/ |/'
