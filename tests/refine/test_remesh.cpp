// Tests for remesh.h: the whole pipeline on smooth metrics of each topology — the output is a homeomorphic image of
// the surface (no inverted triangle), its lengths come from the original metric (Gauss–Bonnet exact, area close to
// the smooth area), its circumradii respect ε, and its angles, measured with its own lengths, respect the shape bound.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "conformesh/intrinsic/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric_families.h"
#include "conformesh/intrinsic/metric_quadrature.h"
#include "conformesh/refine/remesh.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using namespace conformesh::refine;

namespace {
RemeshResult run(const SmoothMetric& m, double eps, int t0 = 10) {
  RemeshOptions o;
  o.epsilon = eps;
  o.t0Resolution = t0;
  return remeshMetric(m, o);
}
}  // namespace

TEST_CASE("remesh: closed surfaces of genus 0 and 1, and disks") {
  struct Case {
    std::unique_ptr<SmoothMetric> metric;
    double eps;
  };
  std::vector<Case> cases;
  cases.push_back({makeMetric("ellipsoid", {{"f", 0.3}}), 0.04});
  cases.push_back({makeMetric("kerr-newman", {{"a", 0.99}}), 0.08});
  cases.push_back({makeMetric("torus", {{"R", 1.0}, {"r", 0.4}}), 0.04});
  cases.push_back({makeMetric("spherical-cap", {}), 0.05});
  for (const Case& c : cases) {
    const SmoothMetric& m = *c.metric;
    INFO(m.description());
    const RemeshResult r = run(m, c.eps);
    const int chi = m.domain().eulerCharacteristic();
    CHECK(r.mesh.mesh.eulerCharacteristic() == chi);
    CHECK(r.invertedTriangles == 0);
    // Gauss–Bonnet with the output's own lengths: Σ deficits + Σ turning = 2πχ.
    CHECK(std::abs(curvatureTotals(r.mesh).gaussBonnetResidual) < 1e-9);
    // Lengths are the metric's: the mesh area is the smooth area up to the O(ε²) of chords against arcs.
    const double area = metricArea(m).value;
    CHECK(std::abs(totalArea(r.mesh) - area) < 0.02 * area);
    // Quality in the original metric: the refinement's 20.7° bound survives the pull-back.
    CHECK(r.quality.minAngleDeg >= 20.7);
    CHECK(r.quality.meanMinAngleDeg >= 40);
    CHECK(r.mesh.mesh.nVertices() > r.t0Vertices);
  }
}

TEST_CASE("remesh: the conformal factor grades the mesh so that circumradii are at most ε in the original metric") {
  // Kerr with a = 0 is the round sphere of radius r₊ = 2M: the smooth λ ≡ log 2, so the uniformized bound ε·e^(−λ)
  // pulls back to ε. T0's lengths are arcs 2θ of that sphere while the flow compares chords (Penner lengths), so the
  // discrete λ is log 2 + log((θ/2)/sin(θ/2)) ≈ log 2 + θ²/24: below 1.7e-3 for T0's edges (θ ≤ 0.2 at resolution 10).
  const auto m = makeMetric("kerr-newman", {{"a", 0.0}});
  const double eps = 0.1;
  const RemeshResult r = run(*m, eps);
  for (double l : r.lambda) CHECK(l == Approx(std::log(2.0)).margin(1.7e-3));
  CHECK(r.quality.maxCircumradius <= 1.05 * eps);
  CHECK(r.quality.meanCircumradius > 0.5 * eps);
}

TEST_CASE("remesh: bad parameters are named") {
  const auto m = makeMetric("sphere", {});
  RemeshOptions o;
  o.epsilon = 0;
  REQUIRE_THROWS_WITH(remeshMetric(*m, o), Catch::Contains("--eps"));
  o.epsilon = NAN;
  REQUIRE_THROWS_WITH(remeshMetric(*m, o), Catch::Contains("--eps"));
}
