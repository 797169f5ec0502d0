#!/usr/bin/env bash
# bench_pipeline.sh — the whole pipeline (`conformesh remesh`) per stage, with peak memory, at output sizes from ~2·10⁴
# to ~10⁶ vertices, and the paper's own 22k-vertex Utah-teapot patch (its rectangle chart flattened keeping the
# boundary). Prints a Markdown table (docs/benchmarks.md). Usage: bench/bench_pipeline.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
cli="$build/apps/conformesh"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| input | eps | vertices | discretize s | uniformize s | refine s | pull back s | wall s | peak MiB | min angle° | mean min angle° |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
while read -r family params eps; do
  /usr/bin/time -f "%e %M" -o "$out/time" "$cli" -q remesh "$family" $params --eps "$eps" --t0-resolution 10 \
    --no-check -o "$out/mesh.ply" --json >"$out/report.json"
  read -r wall kb <"$out/time"
  /usr/bin/python3 - "$out/report.json" "$family $params" "$eps" "$wall" "$kb" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); q = j["quality"]; s = j["seconds"]
print("| %s | %s | %d | %.3f | %.3f | %.3f | %.3f | %s | %.0f | %.2f | %.2f |" % (
    sys.argv[2], sys.argv[3], q["vertices"], s["discretize"], s["uniformize"], s["refine"], s["pull_back"],
    sys.argv[4], int(sys.argv[5]) / 1024, q["min_angle_deg"], q["mean_min_angle_deg"]))
PY
done <<'CASES'
ellipsoid --param=f=0.3 0.0180
kerr-newman --param=a=0.95 0.0330
kerr-newman --param=a=0.99 0.0330
teapot-patch --param=patch=4 0.011853
ellipsoid --param=f=0.3 0.0058
ellipsoid --param=f=0.3 0.0026
CASES
