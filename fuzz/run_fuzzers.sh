#!/usr/bin/env bash
# run_fuzzers.sh — builds the OBJ, OFF and PLY reader fuzzers with clang++ (libFuzzer + AddressSanitizer +
# UndefinedBehaviorSanitizer) straight from the reader sources, generates a seed corpus and a dictionary per format, and
# runs each fuzzer for a bounded time. Exits non-zero if any fuzzer finds a crash, a leak, a hang or a property
# violation (see fuzz_check.h); the offending input is left in the output directory as crash-*/leak-*/timeout-*.
#
# Usage: fuzz/run_fuzzers.sh [SECONDS_PER_FUZZER (default 60)] [OUTPUT_DIR (default build-fuzz)]
# Environment: CXX_FUZZ (default clang++), FUZZ_JOBS (parallel fuzzing jobs per target, default 1),
#              FUZZ_TARGETS (default "obj off ply"), FUZZ_NO_REBUILD=1 (reuse the binaries already in OUTPUT_DIR).
set -euo pipefail

SECONDS_PER=${1:-60}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$(mkdir -p "${2:-$ROOT/build-fuzz}" && cd "${2:-$ROOT/build-fuzz}" && pwd)
CXX=${CXX_FUZZ:-clang++}
JOBS=${FUZZ_JOBS:-1}
TARGETS=${FUZZ_TARGETS:-obj off ply}

command -v "$CXX" >/dev/null || { echo "run_fuzzers.sh: $CXX not found (libFuzzer needs clang++)" >&2; exit 2; }

INCLUDES=(-I"$ROOT/intrinsic/include" -I"$ROOT/intrinsic/src" -I"$ROOT/fuzz" -I/usr/include/eigen3)
SAN=(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
COMMON=(-std=c++17 -O1 -g "${SAN[@]}" "${INCLUDES[@]}")
# The readers and everything they call (backgroundFromString lives in triangle_geometry.cpp).
SOURCES=(io/mesh_io io/obj_io io/off_io io/ply_io mesh/triangle_geometry)

if [ "${FUZZ_NO_REBUILD:-0}" = 1 ] && [ -x "$OUT/make_seeds" ]; then
  echo "== reusing the fuzzers built in $OUT (FUZZ_NO_REBUILD=1)"
else
echo "== compiling readers with coverage instrumentation in $OUT"
mkdir -p "$OUT/obj-files"
OBJECTS=()
for s in "${SOURCES[@]}"; do
  "$CXX" "${COMMON[@]}" -fsanitize=fuzzer-no-link -c "$ROOT/intrinsic/src/$s.cpp" -o "$OUT/obj-files/${s##*/}.o"
  OBJECTS+=("$OUT/obj-files/${s##*/}.o")
done
for t in $TARGETS; do
  "$CXX" "${COMMON[@]}" -fsanitize=fuzzer "$ROOT/fuzz/fuzz_$t.cpp" "${OBJECTS[@]}" -o "$OUT/fuzz_$t"
done
"$CXX" "${COMMON[@]}" "$ROOT/fuzz/make_seeds.cpp" "${OBJECTS[@]}" -o "$OUT/make_seeds"
fi

echo "== seed corpus and dictionaries"
rm -rf "$OUT/seeds"
"$OUT/make_seeds" "$OUT/seeds"
printf '%s\n' '"v "' '"f "' '"vt "' '"vn "' '"/"' '"//"' '"-1"' '"# geometry spherical"' '"usemtl"' '"\x0a"' \
  '"nan"' '"1e308"' > "$OUT/obj.dict"
printf '%s\n' '"OFF"' '"COFF"' '"NOFF"' '"STOFF"' '"4OFF"' '"BINARY"' '"#"' '"\x0a"' '"-1"' '"nan"' '"inf"' \
  > "$OUT/off.dict"
printf '%s\n' '"ply\x0a"' '"format ascii 1.0\x0a"' '"format binary_little_endian 1.0\x0a"' \
  '"format binary_big_endian 1.0\x0a"' '"element "' '"property "' '"list "' '"uchar "' '"int "' '"uint "' '"float "' \
  '"double "' '"char "' '"short "' '"ushort "' '"vertex_indices"' '"vertex_index"' '"edge_index"' '"vertex1"' \
  '"vertex2"' '"length"' '"end_header\x0a"' '"comment geometry hyperbolic\x0a"' '"vertex "' '"face "' '"edge "' \
  '"\xff\xff\xff\xff"' '"\x7f\xf8\x00\x00\x00\x00\x00\x00"' > "$OUT/ply.dict"

status=0
for t in $TARGETS; do
  echo "== fuzz_$t for $SECONDS_PER s"
  mkdir -p "$OUT/corpus_$t"
  log="$OUT/fuzz_$t.log"
  set +e
  parallel=()
  [ "$JOBS" -gt 1 ] && parallel=(-jobs="$JOBS" -workers="$JOBS")
  (cd "$OUT" && ASAN_OPTIONS=detect_leaks=1 ./"fuzz_$t" -max_total_time="$SECONDS_PER" -timeout=10 -rss_limit_mb=2048 \
     -max_len=8192 "${parallel[@]}" -print_final_stats=1 -dict="$OUT/$t.dict" \
     "$OUT/corpus_$t" "$OUT/seeds/$t") > "$log" 2>&1
  rc=$?
  # With -jobs, libFuzzer writes each job's output to fuzz-N.log in the working directory.
  if [ "$JOBS" -gt 1 ]; then cat "$OUT"/fuzz-*.log >> "$log" 2>/dev/null; rm -f "$OUT"/fuzz-*.log; fi
  execs=$(grep -h 'stat::number_of_executed_units' "$log" | awk '{s += $2} END {print s + 0}')
  cov=$(grep -h -o 'cov: [0-9]*' "$log" | tail -1 || true)
  set -e
  echo "   exit $rc, $execs executions, $cov, corpus $(ls "$OUT/corpus_$t" | wc -l) files (log: $log)"
  if [ $rc -ne 0 ]; then
    status=1
    grep -h -E 'ERROR|SUMMARY|violated|Test unit written|deadly signal' "$log" | head -20 || true
  fi
done
exit $status
