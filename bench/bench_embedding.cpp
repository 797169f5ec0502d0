// bench_embedding.cpp — the Ceres fit of embedding/isometric_embedding.h on the ellipsoid (a = 1, f = 0.3) at ≈ 20k,
// 50k, 100k and 200k vertices: the icosahedral T0 of discretizeMetric (frequency N: 10N² + 2 vertices, edge lengths =
// geodesic lengths, GeographicLib) fitted from the landmark-MDS start, i.e. without the true positions. Reports wall
// time, the LM iterations and wall seconds of both solves, the final max relative residual, the Procrustes RMS and max
// error against the true surface points and the number of edges whose dihedral angle has the minority sign (a
// round-off residual alone does not tell the convex realization from a polyhedron with popped vertices or a folded
// region: a popped vertex moves by O(κh²), which shows in the max error and the sign count, hardly in the RMS; the
// convex realization has the O(ε²) bulge only), and the process's peak resident set size as counters; one iteration
// each (a fit is long and deterministic). One progress line per LM step goes to stderr. BM_FitEllipsoidCoarseToFine
// reaches the same meshes through coarser ones (embedding/coarse_to_fine.h), with per-level counters.
//
//   cmake -B build-bench -DCMAKE_BUILD_TYPE=Release -DCONFORMESH_BUILD_BENCH=ON
//   cmake --build build-bench -j2 --target bench_embedding && build-bench/bench/bench_embedding
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include <benchmark/benchmark.h>

#include "conformesh/embedding/fit/coarse_to_fine.h"
#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/embedding/extrinsic/mean_curvature_measure.h"
#include "conformesh/embedding/fit/procrustes.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh;

namespace {

// The counters of one fit: the fit's own, the Procrustes error against the true surface points, and the number of
// edges whose dihedral angle has the minority sign.
struct FitFigures {
  double procrustesRms = 0, procrustesMax = 0;
  int minoritySignEdges = 0;
};

FitFigures figuresOf(const intrinsic::MeshData& mesh, const intrinsic::IntrinsicTriangulation& tri,
                     const embedding::EmbeddingResult& fit) {
  FitFigures r;
  const auto aligned = embedding::alignRigid(fit.positions, mesh.positions);
  r.procrustesRms = aligned.rmsError;
  r.procrustesMax = aligned.maxError;
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
  r.minoritySignEdges = std::min(concave, convex);
  return r;
}

void setCounters(benchmark::State& state, const intrinsic::MeshData& mesh, const intrinsic::IntrinsicTriangulation& tri,
                 const embedding::EmbeddingResult& fit) {
  state.counters["vertices"] = tri.mesh.nVertices();
  state.counters["regularized_iterations"] = fit.regularizedIterations;
  state.counters["iterations"] = fit.iterations;
  state.counters["start_s"] = fit.startSeconds;
  state.counters["fit_s"] = fit.fitSeconds;
  state.counters["regularized_s"] = fit.regularizedSeconds;
  state.counters["final_s"] = fit.finalSeconds;
  state.counters["max_rel_residual"] = fit.maxRelativeResidual;
  state.counters["isometric"] = fit.isometric ? 1 : 0;
  const FitFigures f = figuresOf(mesh, tri, fit);
  state.counters["procrustes_rms"] = f.procrustesRms;
  state.counters["procrustes_max"] = f.procrustesMax;
  state.counters["minority_sign_edges"] = f.minoritySignEdges;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_MB"] = usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

// One progress line per LM iteration on stderr, with the seconds since the start: a 200k fit runs for many minutes.
std::function<void(const std::string&)> progressSince(std::chrono::steady_clock::time_point t0) {
  return [t0](const std::string& line) {
    std::fprintf(stderr, "[%8.1f s] %s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                 line.c_str());
  };
}

void BM_FitEllipsoid(benchmark::State& state) {
  const auto metric = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  intrinsic::DiscretizationOptions o;
  o.resolution = static_cast<int>(state.range(0));
  const auto mesh = intrinsic::discretizeMetric(*metric, o);
  const auto tri = intrinsic::toTriangulation(mesh);
  embedding::EmbeddingResult fit;
  embedding::EmbeddingOptions options;
  options.progress = progressSince(std::chrono::steady_clock::now());
  for (auto _ : state) {
    fit = embedding::fitIsometricEmbedding(tri, options);
    benchmark::DoNotOptimize(fit.positions.data());
  }
  setCounters(state, mesh, tri, fit);
}

// Coarse to fine (coarse_to_fine.h, docs/embedding.md): the coarsest frequency is fitted as BM_FitEllipsoid does
// (MDS start, regularized continuation, pure fit); each finer one starts from the previous level's fitted positions
// carried over through the common chart (the unit sphere of the icosahedral T0s), takes one regularized CGNR step at
// each of w = 0.01, 0.001, 1e-4 and then the pure fit (exact SPARSE_NORMAL_CHOLESKY steps). The arguments are the
// frequencies, coarse to fine, 0 for an unused slot. The counters are the last level's, plus per level ℓ: its
// frequency, LM iterations (regularized + final), wall seconds (carry-over + fit), Procrustes max error and
// minority-sign edge count.
void BM_FitEllipsoidCoarseToFine(benchmark::State& state) {
  const auto metric = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  const intrinsic::ChartDomain domain = metric->domain();
  std::vector<int> levels;
  for (int k = 0; k < 3; ++k)
    if (state.range(k) > 0) levels.push_back(static_cast<int>(state.range(k)));
  intrinsic::MeshData mesh;
  intrinsic::IntrinsicTriangulation tri;
  embedding::EmbeddingResult fit;
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    embedding::ChartTriangulation previous;
    for (size_t l = 0; l < levels.size(); ++l) {
      const auto tl = std::chrono::steady_clock::now();
      intrinsic::DiscretizationOptions o;
      o.resolution = levels[l];
      mesh = intrinsic::discretizeMetric(*metric, o);
      tri = intrinsic::toTriangulation(mesh);  // no unreferenced vertices: mesh and tri share vertex indices
      const auto chart = embedding::chartTriangulation(mesh, domain);
      embedding::EmbeddingOptions options;
      options.progress = progressSince(t0);
      if (l > 0) {
        options.initialPositions = embedding::carryPositions(previous, fit.positions, chart.points);
        // The carried-over start is flat inside each coarse face, where the edge lengths do not say to which side a
        // fine vertex should bend (their derivative across the face vanishes): the pure fit from it (w = 0) popped 84
        // edges at 20k. One regularized step per stage (w = 0.01, 0.001, 1e-4; a few CG iterations each) bends the
        // patches smoothly first (docs/embedding.md).
        options.regularizerWeight = 0.01;
        options.maxIterationsRegularized = 1;
      }
      fit = embedding::fitIsometricEmbedding(tri, options);
      const FitFigures f = figuresOf(mesh, tri, fit);
      const std::string p = "L" + std::to_string(l) + "_";
      state.counters[p + "N"] = levels[l];
      state.counters[p + "iterations"] = fit.regularizedIterations + fit.iterations;
      state.counters[p + "s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - tl).count();
      state.counters[p + "procrustes_max"] = f.procrustesMax;
      state.counters[p + "minority_sign_edges"] = f.minoritySignEdges;
      std::fprintf(stderr,
                   "level %zu (N = %d, %d vertices): %d + %d LM steps, residual %.2e, Procrustes RMS %.4e max %.4e, %d "
                   "minority-sign edges\n",
                   l, levels[l], tri.mesh.nVertices(), fit.regularizedIterations, fit.iterations,
                   fit.maxRelativeResidual, f.procrustesRms, f.procrustesMax, f.minoritySignEdges);
      previous = chart;
    }
    benchmark::DoNotOptimize(fit.positions.data());
  }
  setCounters(state, mesh, tri, fit);
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

// Coarse N = 20 (4002 vertices) → 45; 35 (12 252) → 71; 45 → 100 → 141; and 45 → 141, which skips the intermediate
// level and ends at a popped polyhedron (docs/benchmarks.md): a coarse-to-fine step should at most about halve h.
BENCHMARK(BM_FitEllipsoidCoarseToFine)
    ->Args({20, 45, 0})
    ->Args({35, 71, 0})
    ->Args({45, 100, 141})
    ->Args({45, 141, 0})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK_MAIN();
