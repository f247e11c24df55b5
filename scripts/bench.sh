#!/usr/bin/env bash
# One command for the side-by-side benchmark (issue 8): installs the bench-only packages if
# missing, builds OpenMSS and the model generator, compiles the MuJoCo and Simbody programs of
# bench/peers/, runs every model in every engine (bench/run_bench.py), prints the table and
# writes docs/performance-scaling.png and the generated section of docs/performance.md (between
# its BEGIN/END marks; the hand-written sections around them are kept).
#
#   scripts/bench.sh [--quick]        --quick: N = 10, 100 only (default 10, 100, 1000)
#
# Knobs (environment): OPENMSS_THREADS (OpenMSS's threads, 1 unless set), OPENMSS_BENCH_TIMEOUT
# (s per OpenMSS run, 900), OPENMSS_BENCH_PEER_TIMEOUT
# (s per peer run, 300), OPENMSS_BENCH_PEER_MAX_N (skip peer runs above this N), OPENMSS_BENCH_SIZES
# (e.g. "10,100"), OPENMSS_BENCH_MODELS (e.g. "chain-planar"), OPENMSS_BENCH_BUILD_DIR
# (build-bench), OPENMSS_BENCH_NO_DOCS=1 (print only, leave docs/ alone).
set -euo pipefail
cd "$(dirname "$0")/.."

sizes="${OPENMSS_BENCH_SIZES:-10,100,1000}"
for arg in "$@"; do
  case "$arg" in
    --quick) sizes="${OPENMSS_BENCH_SIZES:-10,100}" ;;
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    *) echo "bench.sh: unknown argument $arg" >&2; exit 64 ;;
  esac
done

# Bench-only packages, asked from apt only when missing (as scripts/install-deps.sh does).
packages=(libmujoco-dev libsimbody-dev python3-matplotlib libbenchmark-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} > 0)); then
  echo "bench.sh: installing ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build="${OPENMSS_BENCH_BUILD_DIR:-build-bench}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DOPENMSS_BUILD_BENCH=ON > /dev/null
cmake --build "$build" -j "${OPENMSS_BENCH_JOBS:-2}" --target openmss openmss-generate

# The peers: plain g++ against the Debian packages. Simbody 3.7's headers do not compile as
# C++20 (ambiguous reversed operator==), so that program is C++17.
peers="$build/bench-peers"
mkdir -p "$peers"
if [[ ! "$peers/mujoco_chain" -nt bench/peers/mujoco_chain.cpp ||
      ! "$peers/mujoco_chain" -nt bench/model_generators.cpp ]]; then
  g++ -std=c++20 -O2 -o "$peers/mujoco_chain" bench/peers/mujoco_chain.cpp \
    bench/model_generators.cpp -lmujoco
fi
if [[ ! "$peers/simbody_chain" -nt bench/peers/simbody_chain.cpp ||
      ! "$peers/simbody_chain" -nt bench/model_generators.cpp ]]; then
  g++ -std=c++17 -O2 -isystem /usr/include/simbody -o "$peers/simbody_chain" \
    bench/peers/simbody_chain.cpp bench/model_generators.cpp $(pkg-config --libs simbody)
fi

docs=(--markdown docs/performance.md --plot docs/performance-scaling.png)
if [[ "${OPENMSS_BENCH_NO_DOCS:-0}" == 1 ]]; then docs=(--markdown "" --plot ""); fi
# The page records the knobs that change what is run, so that the command reproduces it.
knobs=""
for k in OPENMSS_THREADS OPENMSS_BENCH_TIMEOUT OPENMSS_BENCH_PEER_TIMEOUT OPENMSS_BENCH_PEER_MAX_N OPENMSS_BENCH_SIZES OPENMSS_BENCH_MODELS; do
  [[ -n "${!k:-}" ]] && knobs+="$k=${!k} "
done
command="${knobs}scripts/bench.sh $*"
# OpenMSS on one thread, as the peers run, so that the CPU-time ratios compare like with like
# (OPENMSS_THREADS=2 on the command line measures the thread pool instead; docs/performance.md).
export OPENMSS_THREADS="${OPENMSS_THREADS:-1}"
# Debian's interpreter, which python3-matplotlib serves (a pyenv python3 first on PATH does not).
python=/usr/bin/python3
[[ -x "$python" ]] || python=python3
"$python" bench/run_bench.py --openmss "$build/openmss" --generate "$build/bench/openmss-generate" \
  --mujoco "$peers/mujoco_chain" --simbody "$peers/simbody_chain" --sizes "$sizes" \
  --models "${OPENMSS_BENCH_MODELS:-chain-planar,chain-spatial,chain-stiff4,chain-stiff8,fourbar,bushing,bushing-stiff}" \
  --timeout "${OPENMSS_BENCH_TIMEOUT:-900}" --peer-timeout "${OPENMSS_BENCH_PEER_TIMEOUT:-300}" \
  --peer-max-n "${OPENMSS_BENCH_PEER_MAX_N:-1000000}" --command "${command% }" "${docs[@]}"
