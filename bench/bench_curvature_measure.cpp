// bench_curvature_measure.cpp — the cost of the Gaussian-curvature-measure check (gaussianCurvatureMeasure, paper
// eq. 5, balls of radius 0.05·√area) against the vertex count, on `conformesh remesh ellipsoid --param f=0.3` outputs
// (the pipeline with the CLI's defaults). Prints per ε: vertices, the check's CPU time, its wall time, e_G to 17
// digits and an FNV-1a hash of the bits of every per-vertex discrete, smooth and absolute-scale value, so that two
// builds can be compared for bit-identical results; then the fitted slope of log time against log V.
//
//   build/bench/bench_curvature_measure [EPS ...]     # default: 0.0267 0.0119 0.00727 (≈ 10k, 50k, 135k vertices)
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

}  // namespace

int main(int argc, char** argv) {
  using namespace conformesh;
  std::vector<double> eps;
  for (int i = 1; i < argc; ++i) eps.push_back(std::atof(argv[i]));
  if (eps.empty()) eps = {0.0267, 0.0119, 0.00727};
  const auto metric = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  std::printf("| eps | vertices | check CPU s | check wall s | e_G | hash |\n|---|---:|---:|---:|---|---|\n");
  std::vector<double> logV, logT;
  for (double e : eps) {
    refine::RemeshOptions o;
    o.epsilon = e;
    const refine::RemeshResult r = refine::remeshMetric(*metric, o);
    const intrinsic::CurvatureMeasureOptions co;
    const double c0 = cpuSeconds();
    const auto w0 = std::chrono::steady_clock::now();
    const intrinsic::CurvatureMeasureResult c = intrinsic::gaussianCurvatureMeasure(r.mesh, r.reference, *metric, co);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    const double cpu = cpuSeconds() - c0;
    const int n = r.mesh.mesh.nVertices();
    std::printf("| %g | %d | %.3f | %.3f | %.17g | %016llx |\n", e, n, cpu, wall, c.meanAbsoluteError,
                static_cast<unsigned long long>(hashResult(c)));
    std::fflush(stdout);
    logV.push_back(std::log(double(n)));
    logT.push_back(std::log(cpu));
  }
  if (logV.size() >= 2) {  // least-squares slope of log CPU time against log V
    double mv = 0, mt = 0, svv = 0, svt = 0;
    for (size_t i = 0; i < logV.size(); ++i) mv += logV[i] / logV.size(), mt += logT[i] / logV.size();
    for (size_t i = 0; i < logV.size(); ++i) svv += (logV[i] - mv) * (logV[i] - mv), svt += (logV[i] - mv) * (logT[i] - mt);
    std::printf("fitted slope of log(check CPU time) vs log(V): %.3f\n", svt / svv);
  }
  return 0;
}
