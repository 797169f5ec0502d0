// test_embedded_surface.cpp — the extrinsic jet of a metric's embedding against closed forms: the sphere (κ₁ + κ₂ =
// 2/R, outward normal, area factor R²) including points next to the chart's poles, the torus of revolution (κ₁ + κ₂ =
// 1/r + cos v/(R + r cos v)), a circular cylinder as a function graph (1/R); a metric without an embedding is refused.
#include <cmath>

#include <catch2/catch.hpp>

#include "conformesh/embedding/extrinsic/embedded_surface.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh;
using namespace conformesh::embedding;
using intrinsic::makeMetric;

TEST_CASE("sphere: κ₁ + κ₂ = 2/R, outward normal and area factor R², also next to the poles") {
  const double R = 2.0;
  const auto m = makeMetric("sphere", {{"R", R}});
  const EmbeddedSurface s(*m);
  for (double v : {1e-7, 0.3, 1.2, M_PI / 2, 2.9, M_PI - 1e-6})
    for (double u : {0.0, 1.0, 4.0}) {
      const Eigen::Vector3d y = intrinsic::referencePoint(m->domain(), u, v);
      Eigen::Vector3d t1, t2;
      s.referenceFrame(y, t1, t2);
      CHECK(std::abs(t1.dot(t2)) < 1e-15);
      CHECK((t1.cross(t2) - y).norm() < 1e-14);
      const auto j = s.jet(y, t1, t2);
      CHECK((j.position - R * y).norm() < 1e-13);
      CHECK((j.normal - y).norm() < 1e-8);
      CHECK(j.meanCurvature == Approx(2 / R).epsilon(1e-6));
      // With the curvature step the first derivatives carry h²|X‴|/6 ≈ 4e-8 relative; with the first-derivative step
      // (no curvature) ≈ 1e-10 (embedded_surface.h).
      CHECK(j.areaFactor == Approx(R * R).epsilon(1e-7));
      CHECK(s.jet(y, t1, t2, false).areaFactor == Approx(R * R).epsilon(3e-10));
    }
}

TEST_CASE("torus of revolution: κ₁ + κ₂ = 1/r + cos v/(R + r cos v)") {
  const double R = 1.0, r = 0.4;
  const auto m = makeMetric("torus", {{"R", R}, {"r", r}});
  const EmbeddedSurface s(*m);
  for (double v : {0.0, 0.7, 2.0, M_PI, 4.5})
    for (double u : {0.1, 2.5}) {
      const Eigen::Vector3d y = intrinsic::referencePoint(m->domain(), u, v);
      Eigen::Vector3d t1, t2;
      s.referenceFrame(y, t1, t2);
      const auto j = s.jet(y, t1, t2);
      // The sign depends on the chart's orientation; the magnitude and the sign change inside/outside do not.
      const double expected = 1 / r + std::cos(v) / (R + r * std::cos(v));
      CHECK(std::abs(j.meanCurvature) == Approx(expected).epsilon(1e-6));
      CHECK(j.areaFactor == Approx(r * (R + r * std::cos(v))).epsilon(1e-7));
      CHECK(s.jet(y, t1, t2, false).areaFactor == Approx(r * (R + r * std::cos(v))).epsilon(3e-10));
    }
}

TEST_CASE("circular cylinder as a graph: κ₁ + κ₂ = 1/R, and the sign follows the normal") {
  const double R = 1.5;
  const auto m = intrinsic::makeFunctionGraph("cylinder", -1, 1, -0.8, 0.8, [R](double, double y) {
    const double z = std::sqrt(R * R - y * y);
    return intrinsic::HeightJet{z, 0, -y / z, 0, 0, -R * R / (z * z * z)};
  });
  const EmbeddedSurface s(*m);
  for (double y : {-0.7, 0.0, 0.5}) {
    const auto j = s.jet(Eigen::Vector3d(0.2, y, 0), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
    // Upper half-cylinder with the upward normal (x-y chart orientation): it bends away from the normal, κ₁ + κ₂ > 0.
    CHECK(j.normal.z() > 0);
    CHECK(j.meanCurvature == Approx(1 / R).epsilon(1e-6));
    const auto flipped = s.jet(Eigen::Vector3d(0.2, y, 0), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
    CHECK(flipped.meanCurvature == Approx(-1 / R).epsilon(1e-6));
  }
}

TEST_CASE("a metric without an embedding is refused by name") {
  const auto kerr = makeMetric("kerr-newman", {{"a", 0.5}});
  CHECK_THROWS_AS(EmbeddedSurface(*kerr), InputError);
  CHECK_THROWS_WITH(EmbeddedSurface(*kerr), Catch::Contains("kerr-newman") && Catch::Contains("no embedding"));
}
