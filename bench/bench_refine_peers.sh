#!/usr/bin/env bash
# bench_refine_peers.sh — conformesh's refinement against CGAL 5.5's Delaunay_mesher_2 and Shewchuk's Triangle on the
# same PSLG (the unit disk as a 64-gon, B = √2: CGAL's aspect bound 0.125, Triangle's -q20.7), calibrated to the same
# vertex counts (20k, 40k, 200k), the tools alternating; prints the minimum CPU time per tool, its ratio to
# conformesh's, the smallest and the mean smallest angle (docs/benchmarks.md).
#
# Triangle is npm `triangle-wasm` 1.0.0 (Triangle compiled to WebAssembly, run by node), installed by this script
# into a bench-only folder ($BENCH_DIR, default build-bench/peers; ignored by git): it is never a build or test
# dependency. Its wasm heap is fixed at 16 MiB, which stops Triangle between 55k and 60k vertices on this PSLG; the
# 200k row then compares conformesh with CGAL only.
#
#   bash bench/bench_refine_peers.sh [BUILD_DIR] [ROUNDS]    # BUILD_DIR configured with -DCONFORMESH_BUILD_BENCH=ON
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build-bench}
rounds=${2:-5}
bench_dir=${BENCH_DIR:-build-bench/peers}
exe="$build/bench/bench_refine_vs_cgal"
[[ -x "$exe" ]] || { echo "bench_refine_peers.sh: $exe not built (target bench_refine_vs_cgal)" >&2; exit 2; }
command -v node >/dev/null || { echo "bench_refine_peers.sh: node not found" >&2; exit 2; }
mkdir -p "$bench_dir"
if [[ ! -f "$bench_dir/node_modules/triangle-wasm/index.js" ]]; then
  echo "installing triangle-wasm@1.0.0 into $bench_dir" >&2
  npm install --silent --no-save --no-package-lock --prefix "$bench_dir" triangle-wasm@1.0.0 >&2
fi
echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(node --version), load $(cut -d' ' -f1-3 /proc/loadavg)"
"$exe" --peers "$bench_dir/node_modules" "$here/triangle_driver.mjs" "$rounds"
