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

TEST_CASE("ConvergenceOptions::validate needs three increasing target counts of at least 10") {
  ConvergenceOptions o;
  CHECK(o.validate().empty());  // the paper's Table 2
  o.targetVertices = {1000, 2000};
  CHECK_THAT(o.validate(), Catch::Contains("at least three"));
  o.targetVertices = {1000, 2000, 2000};
  CHECK_THAT(o.validate(), Catch::Contains("must increase") && Catch::Contains("level 3's 2000 follows 2000"));
  o.targetVertices = {1000, 2000, 5};
  CHECK_THAT(o.validate(), Catch::Contains("5") && Catch::Contains("too small"));
  const auto metric = makeMetric("ellipsoid", {{"f", 0.3}});
  CHECK_THROWS_WITH(runConvergenceStudy(*metric, o), Catch::Contains("too small"));
}

TEST_CASE("a level no finer than the one before is refused, naming a coarser T0 that works") {
  // The options' T0 (resolution 10) is the icosphere of 10·10² + 2 = 1002 vertices. Refinement only adds vertices, so
  // the targets 500 and 1000 both give T0 itself: two equal points of every log–log fit. The study stops at level 2.
  const auto metric = makeMetric("kerr-newman", {{"a", 0.99}});
  ConvergenceOptions o;
  o.targetVertices = {500, 1000, 2000, 4000};
  REQUIRE(o.remesh.t0Resolution == 10);
  try {
    runConvergenceStudy(*metric, o);
    FAIL("no UnrefinedLevelError");
  } catch (const UnrefinedLevelError& e) {
    const std::string m = e.what();
    INFO(m);
    CHECK_THAT(m, Catch::Contains("level 2 (target 1000 vertices) is not finer than level 1: 1002 vertices"));
    CHECK_THAT(m, Catch::Contains("T0, of 1002 vertices (resolution 10)"));
    // The finest icosphere with at most 500 / 2 vertices: resolution 4, 10·4² + 2 = 162 (resolution 5 has 252).
    CHECK_THAT(m, Catch::Contains("--t0-resolution 4 (a T0 of 162 vertices"));
  }
  // The suggested T0 makes every level a refinement: vertex counts increase and mean circumradii decrease strictly.
  o.remesh.t0Resolution = 4;
  const ConvergenceStudy s = runConvergenceStudy(*metric, o);
  CHECK(s.t0Vertices == 162);
  REQUIRE(s.levels.size() == 4);
  for (size_t i = 1; i < s.levels.size(); ++i) {
    CHECK(s.levels[i].vertices > s.levels[i - 1].vertices);
    CHECK(s.levels[i].quality.meanCircumradius < s.levels[i - 1].quality.meanCircumradius);
  }
  // Mesh size on a fixed area: mean R ~ V^(−1/2), the fitted slope over a factor ~7 in V within ±0.1.
  CHECK(s.orderCircumradiusVsVertices == Approx(-0.5).margin(0.1));
}

TEST_CASE("levels below T0's vertex count do not miscalibrate the finer ones") {
  // Target 500 on a T0 of 1002 vertices returns T0 at any ε above T0's largest circumradius, so that ε must not set
  // the vertices-per-ε² constant (it did: the next targets, 1000 and 2000, then gave T0 again); the next target,
  // 2004 = 2 × 1002, is refined to within the 15 % calibration tolerance.
  const auto metric = makeMetric("kerr-newman", {{"a", 0.99}});
  ConvergenceOptions o;
  o.targetVertices = {500, 2004, 4000};
  const ConvergenceStudy s = runConvergenceStudy(*metric, o);
  REQUIRE(s.levels.size() == 3);
  CHECK(s.levels[0].vertices == s.t0Vertices);
  for (size_t i = 1; i < s.levels.size(); ++i)
    CHECK(std::abs(s.levels[i].vertices - s.levels[i].targetVertices) <=
          o.calibrationTolerance * s.levels[i].targetVertices);
}
