// bench_ricci_flow.cpp — time, Newton steps, Cholesky factorizations, flips and peak memory of `uniformize` on closed
// genus-0, genus-1 and genus-2 surfaces at ~10k, ~100k and ~1M vertices (generated: box surface → sphere, torus of
// revolution → flat torus, genus-2 slab → hyperbolic). Run one case per process for a meaningful peak RSS;
// docs/benchmarks.md has the command.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>

#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/flow/uniformization.h"

using namespace conformesh::intrinsic;

namespace {

// Generated inputs with about `target` vertices.
IntrinsicTriangulation input(int genus, long target) {
  if (genus == 1) {
    TorusOptions o;  // R = 1, r = 0.4: n/m = 2.5 keeps triangles well shaped
    o.m = static_cast<int>(std::lround(std::sqrt(target / 2.5)));
    o.n = static_cast<int>(std::lround(2.5 * o.m));
    return toTriangulation(makeTorus(o));
  }
  // Box (g = 0) and genus-2 slab: about 14 N² resp. 50 N² vertices.
  GenusSurfaceOptions o;
  o.genus = genus;
  o.resolution = static_cast<int>(std::lround(std::sqrt(target / (genus == 0 ? 14.0 : 50.0))));
  return toTriangulation(makeGenusSurface(o));
}

void BM_Uniformize(benchmark::State& state) {
  const int genus = static_cast<int>(state.range(0));
  const IntrinsicTriangulation tri = input(genus, state.range(1));
  Uniformization u;
  for (auto _ : state) {
    u = uniformize(tri);
    benchmark::DoNotOptimize(u.lambda.data());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["vertices"] = tri.mesh.nVertices();
  state.counters["newton_steps"] = u.report.newtonSteps;
  state.counters["flips"] = static_cast<double>(u.report.flips);
  state.counters["factorizations"] = u.report.factorizations;
  state.counters["cg_iterations"] = u.report.cgIterations;
  state.counters["residual"] = u.report.maxResidual;
  state.counters["peak_MB"] = usage.ru_maxrss / 1024.0;
}

}  // namespace

BENCHMARK(BM_Uniformize)
    ->ArgNames({"genus", "vertices"})
    ->ArgsProduct({{0, 1, 2}, {10000, 100000, 1000000}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK_MAIN();
