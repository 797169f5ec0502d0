// bench_curvature_measure.cpp — the cost of the Gaussian-curvature-measure check (gaussianCurvatureMeasure, paper
// eq. 5, balls of radius 0.05·√area) against the vertex count, on `conformesh remesh ellipsoid --param f=0.3` outputs
// (the pipeline with the CLI's defaults). Prints per ε: vertices, the check's CPU time, its wall time, e_G to 17
// digits and an FNV-1a hash of the bits of every per-vertex discrete, smooth and absolute-scale value, so that two
// builds can be compared for bit-identical results; then the fitted slope of log time against log V.
//
// Each size runs the patches (default), the ball-by-ball reference, and the patches again, alternating, and prints the
// largest per-vertex difference of the two algorithms relative to the ball's |φ_M|(B).
//
//   build/bench/bench_curvature_measure [--patches-only] [EPS ...]   # default: 0.0267 0.0119 0.00727 (≈ 10k-125k V)
//   build/bench/bench_curvature_measure --patches-only 0.0026        # ≈ 10⁶ V (issue #24's target): the remesh alone
//                                                                     # takes minutes, the reference hours
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

namespace {

double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// FNV-1a over the bytes of the per-vertex arrays, in order.
std::uint64_t hashResult(const conformesh::intrinsic::CurvatureMeasureResult& c) {
  std::uint64_t h = 1469598103934665603ull;
  for (const std::vector<double>* a : {&c.discrete, &c.smooth, &c.absoluteScale})
    for (double x : *a) {
      unsigned char b[sizeof x];
      std::memcpy(b, &x, sizeof x);
      for (unsigned char byte : b) h = (h ^ byte) * 1099511628211ull;
    }
  return h;
}

struct Timed {
  conformesh::intrinsic::CurvatureMeasureResult result;
  double cpu = 0, wall = 0;
};

Timed timedCheck(const conformesh::refine::RemeshResult& r, const conformesh::intrinsic::SmoothMetric& metric,
                 conformesh::intrinsic::BallSweepAlgorithm algorithm) {
  conformesh::intrinsic::CurvatureMeasureOptions co;
  co.algorithm = algorithm;
  Timed t;
  const double c0 = cpuSeconds();
  const auto w0 = std::chrono::steady_clock::now();
  t.result = conformesh::intrinsic::gaussianCurvatureMeasure(r.mesh, r.reference, metric, co);
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  t.cpu = cpuSeconds() - c0;
  return t;
}

// Least-squares slope of log y against log x.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0, sxx = 0, sxy = 0;
  const size_t n = x.size();
  for (size_t i = 0; i < n; ++i) mx += std::log(x[i]) / n, my += std::log(y[i]) / n;
  for (size_t i = 0; i < n; ++i) {
    const double dx = std::log(x[i]) - mx;
    sxx += dx * dx, sxy += dx * (std::log(y[i]) - my);
  }
  return sxy / sxx;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace conformesh;
  using intrinsic::BallSweepAlgorithm;
  std::vector<double> eps;
  bool withReference = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--patches-only") == 0)
      withReference = false;
    else
      eps.push_back(std::atof(argv[i]));
  }
  if (eps.empty()) eps = {0.0267, 0.0119, 0.00727};
  const auto metric = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  std::printf(
      "| eps | vertices | ball by ball: CPU s | wall s | patches: CPU s | wall s | e_G ball by ball | e_G patches | "
      "max |Δφ|/|φ|(B) | hash patches |\n|---|---:|---:|---:|---:|---:|---|---|---|---|\n");
  std::vector<double> vs, tOld, tNew;
  for (double e : eps) {
    refine::RemeshOptions o;
    o.epsilon = e;
    const refine::RemeshResult r = refine::remeshMetric(*metric, o);
    const int n = r.mesh.mesh.nVertices();
    // Alternating: patches, ball by ball, patches again (the two patch runs' times both printed as a range).
    const Timed a = timedCheck(r, *metric, BallSweepAlgorithm::Patches);
    Timed b;
    double maxDiff = 0;
    if (withReference) {
      b = timedCheck(r, *metric, BallSweepAlgorithm::BallByBall);
      for (int v = 0; v < n; ++v) {
        const double s = std::max(b.result.absoluteScale[v], 1e-300);
        maxDiff = std::max({maxDiff, std::abs(a.result.discrete[v] - b.result.discrete[v]) / s,
                            std::abs(a.result.smooth[v] - b.result.smooth[v]) / s});
      }
    }
    const Timed a2 = timedCheck(r, *metric, BallSweepAlgorithm::Patches);
    std::printf("| %g | %d | %.3f | %.3f | %.3f–%.3f | %.3f–%.3f | %.17g | %.17g | %.2e | %016llx |\n", e, n, b.cpu,
                b.wall, std::min(a.cpu, a2.cpu), std::max(a.cpu, a2.cpu), std::min(a.wall, a2.wall),
                std::max(a.wall, a2.wall), b.result.meanAbsoluteError, a.result.meanAbsoluteError, maxDiff,
                static_cast<unsigned long long>(hashResult(a.result)));
    std::fflush(stdout);
    vs.push_back(n);
    tNew.push_back(std::min(a.cpu, a2.cpu));
    tOld.push_back(b.cpu);
  }
  if (vs.size() >= 2) {
    if (withReference) std::printf("fitted slope of log(CPU time) vs log(V), ball by ball: %.3f\n", logLogSlope(vs, tOld));
    std::printf("fitted slope of log(CPU time) vs log(V), patches: %.3f\n", logLogSlope(vs, tNew));
  }
  return 0;
}
