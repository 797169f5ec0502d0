#!/usr/bin/env bash
# compare_outputs.sh — runs a fixed set of conformesh commands with two binaries and compares every file they write,
# byte for byte. For refactors that must not change behaviour (docs/contributing.md).
#
#   bash scripts/compare_outputs.sh OLD_BINARY NEW_BINARY [MESH_DIR] [WORK_DIR]
#
# MESH_DIR holds CGAL's meshes as the test build extracts them (default build/tests/data/meshes). Exit status 0 when
# every file is identical, 1 when one differs (each is named), 2 for a usage error. Timings in the text reports are
# not compared: lines with seconds are dropped from text reports, keys and columns named "seconds" from JSON and CSV.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: compare_outputs.sh OLD_BINARY NEW_BINARY [MESH_DIR] [WORK_DIR]" >&2; exit 2; }
old=$(realpath "$1"); new=$(realpath "$2")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
meshes=$(realpath "${3:-$here/build/tests/data/meshes}")
work=${4:-$(mktemp -d)}
cgal="cow knot1 elk eight double-torus-example elephant 3torus patch-01 nefertiti blade mech-holes-shark blobby handle
      head blobby_3cc"

run_all() {  # $1 = binary, $2 = output folder
  local cm=$1 out=$2
  mkdir -p "$out" && cd "$out" || exit 2
  "$cm" -q remesh kerr-newman --param a=0.99 --eps 0.05 -o kerr99.ply --vtk kerr99.vtk --json > kerr99.json 2> kerr99.err
  for m in $cgal; do
    "$cm" -q uniformize "$meshes/$m.off" -o "uni-$m.ply" --json > "uni-$m.json" 2> "uni-$m.err"
  done
  "$cm" -q uniformize "$meshes/cow.off" -o uni-cow-c.ply --correspondence uni-cow-map.json > /dev/null 2>&1
  "$cm" -q discretize kerr-newman --param a=0.95 -r 8 -o kerr-t0.ply > /dev/null 2>&1
  "$cm" -q uniformize kerr-t0.ply -o kerr-uniform.ply > /dev/null 2>&1
  "$cm" -q refine kerr-uniform.ply --eps 0.1 -o kerr-refined.ply --json > refine.json 2> refine.err
  "$cm" -q generate disk --rings 3 -o disk.ply > /dev/null 2>&1
  "$cm" -q refine disk.ply --eps 0.02 --ratio 1.12 --segment-rule chew -o disk-chew.ply > refine-chew.txt 2>&1
  "$cm" -q remesh "$meshes/eight.off" --eps 0.02 --refine-in uniformized -o eight.ply --vtk eight.vtk --json > eight.json \
    2> eight.err
  "$cm" -q remesh "$meshes/eight.off" --eps 0.02 --refine-in input -o eight-input.ply --json > eight-input.json 2>&1
  "$cm" -q layout "$meshes/double-torus-example.off" -o double-torus.svg --tiles 2 > layout.txt 2>&1
  "$cm" -q layout "$meshes/knot1.off" -o knot1-layout.ply > layout-knot.txt 2>&1
  "$cm" -q convergence teapot-patch --vertices 300,600,1200 --t0-resolution 4 -o teapot --no-plot --json \
    > teapot-stdout.json 2> teapot.err
  for f in *.txt *.err; do grep -v -E '[0-9.]+ ?s\b|elapsed|time' "$f" > "$f.filtered" || true; rm -f "$f"; done
  /usr/bin/python3 - <<'PY'
import csv, glob, json
def strip(x):  # wall-clock figures are not outputs
    if isinstance(x, dict): return {k: strip(v) for k, v in x.items() if 'second' not in k}
    if isinstance(x, list): return [strip(v) for v in x]
    return x
for f in glob.glob('*.json'):
    try: data = json.load(open(f))
    except ValueError: continue
    json.dump(strip(data), open(f, 'w'), indent=1, sort_keys=True)
for f in glob.glob('*.csv'):
    rows = list(csv.reader(open(f)))
    keep = [i for i, h in enumerate(rows[0]) if 'second' not in h]
    csv.writer(open(f, 'w', newline='')).writerows([[r[i] for i in keep] for r in rows])
PY
}

( run_all "$old" "$work/old" )
( run_all "$new" "$work/new" )
status=0; count=0
while IFS= read -r f; do
  count=$((count + 1))
  if [ ! -f "$work/new/$f" ]; then echo "missing in new: $f"; status=1
  elif ! cmp -s "$work/old/$f" "$work/new/$f"; then echo "differs: $f"; status=1; fi
done < <(cd "$work/old" && find . -type f | sort)
[ "$(cd "$work/new" && find . -type f | wc -l)" = "$count" ] || { echo "the new binary wrote other files"; status=1; }
echo "compare_outputs: $count files compared in $work, $([ $status = 0 ] && echo 'all identical' || echo 'differences above')"
exit $status
