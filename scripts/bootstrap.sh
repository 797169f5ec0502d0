#!/usr/bin/env bash
# bootstrap.sh — the two README commands: install what is missing (Debian 12 packages, as root), build in Release,
# then either run the main job on the built-in default surface (`run`) or the whole test suite through CTest (`test`).
#
#   bash scripts/bootstrap.sh run    # set up, build, remesh the default surface (Kerr horizon, a/M = 0.99)
#   bash scripts/bootstrap.sh test   # set up, build, run every test
#
# Environment: BUILD_DIR (default build), JOBS (default: number of cores).
set -euo pipefail

mode=${1:-run}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
jobs=${JOBS:-$(nproc)}

# Debian 12 packages: compilers and CMake; the design card's libraries; CLI11 and nlohmann-json for the CLI;
# SuiteSparse (CHOLMOD) and SCOTCH (nested dissection) for the Ricci-flow Newton solver; OpenBLAS, which Debian's alternatives then select
# as the BLAS that CHOLMOD's supernodal factorization calls (faster than the reference BLAS or ATLAS's generic build:
# docs/benchmarks.md); HDF5 for sampled metric fields; matplotlib for plots; libcgal-demo for CGAL's data set of real
# meshes that the tests read (made by others, so topology checks are not self-fulfilling); pybind11, NumPy and pytest for
# the Python package (docs/python.md), built for Debian's /usr/bin/python3; pkgconf for the installed package's
# pkg-config test; libjs-three (inlined into `conformesh view` pages) and chromium (the headless test of those pages);
# ninja-build, whose scheduler compiles a library's dependents while the library itself is still being compiled.
packages=(build-essential cmake ninja-build libeigen3-dev libceres-dev libboost-graph-dev libgeographiclib-dev catch2
          libcli11-dev nlohmann-json3-dev libsuitesparse-dev libscotch-dev libopenblas0-pthread libhdf5-dev
          python3-matplotlib libcgal-demo libopenmpi-dev openmpi-bin pybind11-dev python3-pybind11 python3-numpy
          python3-pytest pkgconf libjs-three chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# A new build folder gets Ninja (an existing one keeps the generator it was made with) and unity batches
# (cmake/unity.cmake): from scratch, about half the compile time of one file per translation unit (docs/benchmarks.md).
generator=()
[ -f "$build/CMakeCache.txt" ] || generator=(-G Ninja)
cmake -S "$here" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DCONFORMESH_BUILD_PYTHON=ON \
  -DCONFORMESH_UNITY_BUILD=ON
# `run` builds what the main job needs (the libraries and the conformesh command); `test` builds everything.
if [ "$mode" = run ]; then
  cmake --build "$build" -j "$jobs" --target conformesh
else
  cmake --build "$build" -j "$jobs"
fi

case "$mode" in
  run)
    out="$here/out"
    mkdir -p "$out"
    # The showcase: the horizon of a Kerr black hole at a/M = 0.99, which has no isometric embedding in R^3, meshed
    # intrinsically with the curvature-convergence check (conformesh remesh --help explains every figure).
    "$build/apps/conformesh" remesh kerr-newman --param a=0.99 --eps 0.05 -o "$out/kerr-a0.99.ply" \
      --vtk "$out/kerr-a0.99.vtk"
    echo "bootstrap: wrote $out/kerr-a0.99.ply (the mesh: triangles and edge lengths in the Kerr metric) and"
    echo "  $out/kerr-a0.99.vtk (for ParaView, drawn on its uniformization sphere); next: README.md, docs/quickstart.md"
    ;;
  test)
    cd "$build"
    ctest --output-on-failure -j "$jobs"
    ;;
  *)
    echo "usage: bash scripts/bootstrap.sh run|test" >&2
    exit 2
    ;;
esac
