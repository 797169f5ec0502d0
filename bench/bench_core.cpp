// bench_core.cpp — the intrinsic core at a million faces: read a binary PLY + build the connectivity + all corner
// angles, and Lawson flipping of a randomly perturbed metric. Reports time, flips, and peak resident memory per face
// (the high-water mark is reset through /proc/self/clear_refs before each measured phase).
//
//   cmake -B build-bench -DCMAKE_BUILD_TYPE=Release -DCONFORMESH_BUILD_BENCH=ON
//   cmake --build build-bench -j2 --target bench_core && build-bench/bench/bench_core
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/io/mesh_io.h"

using namespace conformesh::intrinsic;

namespace {

// An n × m torus grid with every vertex moved off the surface by up to `jitter` of the grid spacing: a valid
// piecewise-flat metric with a large fraction of non-Delaunay edges.
MeshData perturbedTorus(int n, int m, double jitter, unsigned seed) {
  MeshData d;
  d.nVertices = n * m;
  d.positions.reserve(d.nVertices);
  std::mt19937 rng(seed);
  const double R = 1.0, r = 0.45, h = 2 * M_PI * r / m;
  std::uniform_real_distribution<double> u(-jitter * h, jitter * h);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double a = 2 * M_PI * i / n, b = 2 * M_PI * j / m;
      d.positions.emplace_back((R + r * std::cos(b)) * std::cos(a) + u(rng),
                               (R + r * std::cos(b)) * std::sin(a) + u(rng), r * std::sin(b) + u(rng));
    }
  d.faces.reserve(2 * n * m);
  auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      d.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      d.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  d.source = "perturbed torus";
  return d;
}

long statusKb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return std::stol(line.substr(std::string(key).size()));
  return -1;
}
void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

const std::string kPly = "/tmp/conformesh_bench_1M.ply";
constexpr int kN = 1000, kM = 500;  // 2 · 1000 · 500 = 1,000,000 faces

void ensurePly() {
  static bool written = false;
  if (written) return;
  writeMesh(perturbedTorus(kN, kM, 0.0, 1), kPly);
  written = true;
}

void BM_ReadBuildAngles1M(benchmark::State& state) {
  ensurePly();
  double bytesPerFace = 0;
  for (auto _ : state) {
    resetPeak();
    const long before = statusKb("VmRSS:");
    const IntrinsicTriangulation tri = toTriangulation(readMesh(kPly));
    const std::vector<double> angles = allCornerAngles(tri);
    benchmark::DoNotOptimize(angles.data());
    bytesPerFace = 1024.0 * (statusKb("VmHWM:") - before) / tri.mesh.nFaces();
  }
  state.counters["faces"] = 2.0 * kN * kM;
  state.counters["peak_bytes_per_face"] = bytesPerFace;
}
BENCHMARK(BM_ReadBuildAngles1M)->Unit(benchmark::kMillisecond)->Iterations(3);

// Reading alone, in each PLY encoding (the ASCII reader parses with std::from_chars).
void BM_ReadPly1M(benchmark::State& state) {
  const auto encoding = static_cast<PlyEncoding>(state.range(0));
  const std::string path = "/tmp/conformesh_bench_1M_" + std::to_string(state.range(0)) + ".ply";
  writeMesh(perturbedTorus(kN, kM, 0.0, 1), path, {encoding});
  for (auto _ : state) benchmark::DoNotOptimize(readMesh(path).faces.data());
  state.SetLabel(encoding == PlyEncoding::Ascii ? "ascii" : "binary");
}
BENCHMARK(BM_ReadPly1M)
    ->Arg(static_cast<int>(PlyEncoding::Ascii))
    ->Arg(static_cast<int>(PlyEncoding::BinaryLittleEndian))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_LawsonFlip1M(benchmark::State& state) {
  const MeshData data = perturbedTorus(kN, kM, 0.3, 2);
  double flips = 0, before = 0;
  for (auto _ : state) {
    state.PauseTiming();
    IntrinsicTriangulation tri = toTriangulation(data);
    state.ResumeTiming();
    const DelaunayReport r = makeDelaunay(tri);
    flips = static_cast<double>(r.flips);
    before = r.nonDelaunayBefore;
  }
  state.counters["faces"] = 2.0 * kN * kM;
  state.counters["non_delaunay_before"] = before;
  state.counters["flips"] = flips;
}
BENCHMARK(BM_LawsonFlip1M)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
