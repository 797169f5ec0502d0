#!/usr/bin/env bash
# bench_build.sh — the from-scratch build of what `bootstrap.sh run` needs (the conformesh target: the three libraries
# and the command), one file per translation unit with Make (bootstrap.sh before unity builds) against unity batches
# with Ninja (bootstrap.sh now), the two alternating; prints wall and CPU (user + sys of the build and its children)
# per run (docs/benchmarks.md, "Build time"). ccache is disabled, so every run compiles everything.
#
#   bash bench/bench_build.sh [ROUNDS] [JOBS]    # default 1 round, nproc jobs; scratch folders in $BENCH_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
rounds=${1:-1}
jobs=${2:-$(nproc)}
scratch=${BENCH_DIR:-/tmp/conformesh-bench-build}
export CCACHE_DISABLE=1
command -v ninja >/dev/null || { echo "bench_build.sh: ninja not found (apt-get install ninja-build)" >&2; exit 2; }

# build_once NAME CMAKE_ARGS...: configure a new folder, build the conformesh target, print one row.
build_once() {
  local name=$1; shift
  local dir="$scratch/$name"
  rm -rf "$dir"
  local t0; t0=$(date +%s.%N)
  local times; times=$( { /usr/bin/time -f "%U %S" bash -c "cmake -S '$here' -B '$dir' -DCMAKE_BUILD_TYPE=Release \
      -DCONFORMESH_BUILD_PYTHON=ON $* >/dev/null && cmake --build '$dir' -j $jobs --target conformesh >/dev/null"; } 2>&1 )
  local t1; t1=$(date +%s.%N)
  read -r user sys <<<"$(tail -1 <<<"$times")"
  printf "%-28s wall %6.1f s   cpu %6.1f s   load %s\n" "$name" "$(echo "$t1 - $t0" | bc)" "$(echo "$user + $sys" | bc)" \
    "$(cut -d' ' -f1 /proc/loadavg)"
}

echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(c++ --version | head -1), $jobs jobs, $(nproc) cores"
for ((r = 1; r <= rounds; ++r)); do
  build_once "make, one file per unit" -G "'Unix Makefiles'"
  build_once "ninja, unity batches" -G Ninja -DCONFORMESH_UNITY_BUILD=ON
done
rm -rf "$scratch"
