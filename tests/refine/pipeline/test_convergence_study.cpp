// Tests for convergence_study.h: the paper's claims measured by log–log fits over a sweep of meshes (Theorem 3.4,
// §6): e_G falls at least linearly in the mean circumradius, the mean circumradius like 1/√vertices, the area error
// like ε²; and on every mesh the smallest angle (original metric) is ≥ 20.7°, no triangle of the map back is inverted,
// and Gauss–Bonnet holds to 1e-9. The mean smallest angle is not bounded by any theorem; with the default smoothing
// pass (ConvergenceOptions::remesh.refinement.smoothingPasses = 1, vertex_smoothing.h) every mesh of the studies in
// docs/studies.md has it ≥ 46.7° (unsmoothed it scatters by ±1° between nearby ε and dips to 44.7°–46°), so each mesh
// is held to issue 6's 46°, and the sweep's average to the paper's 46.5°. Both are regression bounds calibrated on the
// sweeps of docs/studies.md (no theorem bounds the mean smallest angle above the refinement's 20.7°), not derived.
#include <catch2/catch.hpp>

#include "support/gauss_bonnet_bound.h"

#include <cmath>

#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/refine/pipeline/convergence_study.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using namespace conformesh::refine;

TEST_CASE("convergence sweeps on the ellipsoid and the Kerr horizon at a/M = 0.95") {
  for (const auto& [name, params] : {std::pair<std::string, std::map<std::string, double>>{"ellipsoid", {{"f", 0.3}}},
                                     {"kerr-newman", {{"a", 0.95}}}}) {
    const auto metric = makeMetric(name, params);
    ConvergenceOptions o;
    o.targetVertices = {2000, 4000, 8000, 16000};
    const ConvergenceStudy s = runConvergenceStudy(*metric, o);
    INFO(s.metric << ": e_G order " << s.orderErrorVsCircumradius << ", circumradius order "
                  << s.orderCircumradiusVsVertices << ", area order " << s.orderAreaVsCircumradius);
    CHECK(s.orderErrorVsCircumradius >= 0.9);
    CHECK(s.orderCircumradiusVsVertices == Approx(-0.5).margin(0.1));
    CHECK(s.orderAreaVsCircumradius >= 1.8);
    double meanOfMeans = 0;
    for (const ConvergenceLevel& L : s.levels) {
      INFO(L.vertices << " vertices");
      CHECK(L.quality.minAngleDeg >= 20.7);
      const double kRegressionMeanMinAngleDeg = 46;  // calibrated on docs/studies.md's sweeps (see above)
      CHECK(L.quality.meanMinAngleDeg >= kRegressionMeanMinAngleDeg);
      meanOfMeans += L.quality.meanMinAngleDeg / s.levels.size();
      CHECK(L.invertedTriangles == 0);
      CHECK(std::abs(L.quality.gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(L.quality.triangles));
    }
    const double kRegressionSweepMeanDeg = 46.5;  // the paper's figure, met by docs/studies.md's sweeps
    CHECK(meanOfMeans >= kRegressionSweepMeanDeg);
  }
}

TEST_CASE("ConvergenceOptions::validate needs two target counts of at least 10") {
  ConvergenceOptions o;
  CHECK(o.validate().empty());  // the paper's Table 2
  o.targetVertices = {1000};
  CHECK_THAT(o.validate(), Catch::Contains("at least two"));
  o.targetVertices = {1000, 5};
  CHECK_THAT(o.validate(), Catch::Contains("5") && Catch::Contains("too small"));
  const auto metric = makeMetric("ellipsoid", {{"f", 0.3}});
  CHECK_THROWS_WITH(runConvergenceStudy(*metric, o), Catch::Contains("too small"));
}
