// bench_embedding.cpp — the Ceres fit of embedding/isometric_embedding.h on the ellipsoid (a = 1, f = 0.3) at ≈ 20k,
// 50k, 100k and 200k vertices: the icosahedral T0 of discretizeMetric (frequency N: 10N² + 2 vertices, edge lengths =
// geodesic lengths, GeographicLib) fitted from the landmark-MDS start, i.e. without the true positions. Reports wall
// time, the LM iterations and wall seconds of both solves, the final max relative residual, the Procrustes RMS and max
// error against the true surface points and the number of edges whose dihedral angle has the minority sign (a
// round-off residual alone does not tell the convex realization from a polyhedron with popped vertices or a folded
// region: a popped vertex moves by O(κh²), which shows in the max error and the sign count, hardly in the RMS; the
// convex realization has the O(ε²) bulge only), and the process's peak resident set size as counters; one iteration
// each (a fit is long and deterministic). One progress line per LM step goes to stderr.
//
//   cmake -B build-bench -DCMAKE_BUILD_TYPE=Release -DCONFORMESH_BUILD_BENCH=ON
//   cmake --build build-bench -j2 --target bench_embedding && build-bench/bench/bench_embedding
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include <benchmark/benchmark.h>

#include "conformesh/embedding/isometric_embedding.h"
#include "conformesh/embedding/mean_curvature_measure.h"
#include "conformesh/embedding/procrustes.h"
#include "conformesh/intrinsic/mesh_data.h"
#include "conformesh/intrinsic/metric_discretization.h"
#include "conformesh/intrinsic/metric_families.h"

using namespace conformesh;

namespace {

void BM_FitEllipsoid(benchmark::State& state) {
  const auto metric = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  intrinsic::DiscretizationOptions o;
  o.resolution = static_cast<int>(state.range(0));
  const auto mesh = intrinsic::discretizeMetric(*metric, o);
  const auto tri = intrinsic::toTriangulation(mesh);
  embedding::EmbeddingResult fit;
  // One progress line per LM iteration on stderr, with the seconds since the start: a 200k fit runs for many minutes.
  embedding::EmbeddingOptions options;
  const auto t0 = std::chrono::steady_clock::now();
  options.progress = [&](const std::string& line) {
    std::fprintf(stderr, "[%8.1f s] %s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                 line.c_str());
  };
  for (auto _ : state) {
    fit = embedding::fitIsometricEmbedding(tri, options);
    benchmark::DoNotOptimize(fit.positions.data());
  }
  state.counters["vertices"] = tri.mesh.nVertices();
  state.counters["regularized_iterations"] = fit.regularizedIterations;
  state.counters["iterations"] = fit.iterations;
  state.counters["start_s"] = fit.startSeconds;
  state.counters["fit_s"] = fit.fitSeconds;
  state.counters["regularized_s"] = fit.regularizedSeconds;
  state.counters["final_s"] = fit.finalSeconds;
  state.counters["max_rel_residual"] = fit.maxRelativeResidual;
  state.counters["isometric"] = fit.isometric ? 1 : 0;
  const auto aligned = embedding::alignRigid(fit.positions, mesh.positions);
  state.counters["procrustes_rms"] = aligned.rmsError;
  state.counters["procrustes_max"] = aligned.maxError;
  // The right fit of the ellipsoid's lengths is a convex polyhedron (at 20k: every dihedral angle of one sign, the fit
  // from the true positions alike), so an edge of the other sign marks a popped vertex or a fold — at round-off
  // residual — which raises the Procrustes max error by O(κh²) but the RMS hardly. The minority count is taken: a
  // mirror image flips every sign.
  int concave = 0, convex = 0;
  for (int e = 0; e < tri.mesh.nEdges(); ++e) {
    const double beta = embedding::signedDihedralAngle(tri.mesh, fit.positions, e);
    concave += beta < 0;
    convex += beta > 0;
  }
  state.counters["minority_sign_edges"] = std::min(concave, convex);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_MB"] = usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace

// N = 45: 20 252 vertices; N = 71: 50 412; N = 100: 100 002; N = 141: 198 812.
BENCHMARK(BM_FitEllipsoid)
    ->Arg(45)
    ->Arg(71)
    ->Arg(100)
    ->Arg(141)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK_MAIN();
