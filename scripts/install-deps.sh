#!/usr/bin/env bash
# Installs the Debian 12 packages OpenMSS needs to build and test. Idempotent: it asks apt
# only for what is missing, so a second run costs nothing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev          # dense linear algebra in the numerical core
  libsuitesparse-dev     # KLU: sparse LU of large Newton matrices (solvers/klu_linear_solver), AMD: the supernodal LU's ordering (solvers/supernodal_linear_solver), UMFPACK and CHOLMOD: bench/factor_matrix.cpp; SPQR: rank of large constraint Jacobians (mechanics/sparse_constraint_jacobian)
  libsundials-dev        # IDA (DSTIFF) and CVODE's Adams method (ABAM) integrators
  libxml2-dev            # the results file (.res, XML): output/results_file*.cpp
  libfcl-dev libccd-dev  # FCL (libccd GJK/MPR, meshes): CONTACT's library narrow phase (mechanics/contact/fcl_narrow_phase.cpp)
  libgtest-dev libgmock-dev  # unit and validation tests
  gfortran               # FORTRAN-77 user subroutines of the tests (tests/user/*.f); the FORTRAN unit of SAVSUB/RELSUB (src/user/fortran_units)
  libbenchmark-dev       # micro-benchmarks in bench/
  libmujoco-dev          # the MuJoCo peers of bench/contact_pile.py and bench/walking_foot.py (bench/peers/)
  clang-14 libclang-rt-14-dev  # libFuzzer and sanitizer runtimes for scripts/fuzz.sh
  # The Python package openmss (python/, docs/python.md), run by Debian's /usr/bin/python3,
  # and its tests; pybind11-dev and python3-dev for its in-process extension (openmss._native).
  python3 python3-numpy python3-pandas python3-matplotlib python3-pytest
  pybind11-dev python3-dev
  chromium python3-pil  # the viewer's browser test (tests/viewer): headless Chromium, PNG reading
  # Design studies (python/openmss/study, docs/studies.md): Dask (LocalCluster, dask-scheduler,
  # dask-worker), the study file reader and the progress bar; psutil (a Dask dependency) finds
  # a LocalCluster's worker processes in python/tests/test_study_worker_kill.py.
  python3-distributed python3-yaml python3-tqdm python3-psutil
)
# node and npm install three.js for the viewer (viewer/package-lock.json, `npm ci` at configure
# time): Debian's, only when no node is on the machine.
command -v node >/dev/null 2>&1 || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
