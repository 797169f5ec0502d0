// test_metric_quadrature.cpp — Gauss–Legendre exactness, adaptive quadrature on rectangles, chart triangles, unions of
// triangles, polygons and predicate regions against closed-form integrals, and the failure report.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

TEST_CASE("Gauss-Legendre rules integrate polynomials of degree 2n-1 exactly") {
  for (int n : {1, 2, 5, 8, 20}) {
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    double sumW = 0, moment = 0;
    const int deg = 2 * n - 2;  // even moment ∫ x^deg = 2/(deg+1)
    for (int i = 0; i < n; ++i) sumW += w[i], moment += w[i] * std::pow(x[i], deg);
    CHECK(sumW == Approx(2).epsilon(1e-14));
    CHECK(moment == Approx(2.0 / (deg + 1)).epsilon(1e-13));
  }
  std::vector<double> x, w;
  REQUIRE_THROWS_AS(gaussLegendre(0, x, w), InputError);
}

TEST_CASE("cached Gauss-Legendre rules equal the computed ones; the G7-K15 pair's degrees and its G7 half") {
  for (int n : {1, 6, 10, 64}) {
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    CHECK(gaussLegendreRule(n).nodes == x);  // bit for bit: the same computation, done once
    CHECK(gaussLegendreRule(n).weights == w);
  }
  REQUIRE_THROWS_AS(gaussLegendreRule(65), InputError);
  using GK = GaussKronrod15;
  // The G7 half: nodes x_1, x_3, x_5, x_7 and their weights are the 7-point Gauss-Legendre rule (descending nodes
  // of gaussLegendre, computed by Newton here, independently of the tables).
  std::vector<double> x, w;
  gaussLegendre(7, x, w);
  for (int j = 0; j < 4; ++j) {
    CHECK(GK::nodes[2 * j + 1] == Approx(x[j]).margin(2e-16));
    CHECK(GK::gaussWeights[j] == Approx(w[j]).margin(4e-16));
  }
  // K15 integrates every monomial of degree ≤ 22 exactly on [−1, 1] (odd ones vanish by symmetry): ∫ x^d = 2/(d+1).
  for (int d = 0; d <= 22; d += 2) {
    double k15 = GK::kronrodWeights[GK::kNodes - 1] * (d == 0 ? 1.0 : 0.0);
    for (int k = 0; k + 1 < GK::kNodes; ++k) k15 += 2 * GK::kronrodWeights[k] * std::pow(GK::nodes[k], d);
    INFO("degree " << d);
    CHECK(k15 == Approx(2.0 / (d + 1)).epsilon(1e-15));
  }
  // and not degree 24 (the pair's degree is 3·7 + 1 = 22 for even moments): the tables are the K15 ones, not better.
  double k24 = 0;
  for (int k = 0; k + 1 < GK::kNodes; ++k) k24 += 2 * GK::kronrodWeights[k] * std::pow(GK::nodes[k], 24);
  CHECK(std::abs(k24 - 2.0 / 25) > 1e-8);
}

TEST_CASE("rectangles: a smooth oscillating integrand to 1e-12") {
  auto f = [](double u, double v) { return std::exp(u) * std::cos(3 * v); };
  const QuadratureResult r = integrateOverRectangle(f, 0, 2, -1, 0.5);
  const double exact = (std::exp(2) - 1) * (std::sin(1.5) - std::sin(-3)) / 3;
  CHECK(r.value == Approx(exact).epsilon(1e-12));
  CHECK(r.errorEstimate < 1e-9);
}

TEST_CASE("chart triangles: polynomial exact, orientation-free, unions add up") {
  auto f = [](double u, double v) { return u * u * v; };
  // ∫ over (0,0),(1,0),(0,1) of u²v = 2!·1!/5! = 1/60.
  const Eigen::Vector2d a(0, 0), b(1, 0), c(0, 1);
  CHECK(integrateOverTriangle(f, a, b, c).value == Approx(1.0 / 60).epsilon(1e-14));
  CHECK(integrateOverTriangle(f, a, c, b).value == Approx(1.0 / 60).epsilon(1e-14));
  // A non-polynomial integrand on two triangles tiling a rectangle equals the rectangle integral.
  auto h = [](double u, double v) { return std::sin(u + 2 * v) / (1 + u * u); };
  const Eigen::Vector2d p(0.2, 0.1), q(1.4, 0.1), s(1.4, 0.9), t(0.2, 0.9);
  const double tri = integrateOverTriangles(h, {{p, q, s}, {p, s, t}}).value;
  CHECK(tri == Approx(integrateOverRectangle(h, 0.2, 1.4, 0.1, 0.9).value).epsilon(1e-12));
}

TEST_CASE("polygons: signed fans of non-convex polygons") {
  // L-shaped hexagon of area 3, clockwise: ∫ 1 = 3, ∫ u = moment about the v axis.
  const std::vector<Eigen::Vector2d> L = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  CHECK(integrateOverPolygon([](double, double) { return 1.0; }, L).value == Approx(3).epsilon(1e-14));
  // ∫ u over [0,2]×[0,1] plus [0,1]×[1,2] = 2 + 0.5.
  CHECK(integrateOverPolygon([](double u, double) { return u; }, L).value == Approx(2.5).epsilon(1e-14));
  REQUIRE_THROWS_WITH(integrateOverPolygon([](double, double) { return 1.0; }, {{0, 0}, {1, 0}}),
                      Catch::Contains("at least 3 vertices"));
}

TEST_CASE("predicate regions: boundary cells carry an honest error bound; failure is reported") {
  auto one = [](double, double) { return 1.0; };
  auto inDisk = [](double u, double v) { return u * u + v * v < 1; };
  QuadratureOptions o;
  o.absoluteTolerance = 2e-2;
  o.relativeTolerance = 0;
  o.gaussPoints = 4;
  o.maxDepth = 40;
  const QuadratureResult r = integrateOverRegion(one, -1, 1, -1, 1, inDisk, o);
  // The boundary cells' floor |cell|·max|f| bounds the true error (the estimate is pessimistic, not optimistic).
  CHECK(std::abs(r.value - M_PI) <= r.errorEstimate);
  CHECK(r.errorEstimate <= 2e-2);
  o.throwOnFailure = true;
  o.absoluteTolerance = 1e-12;
  o.maxDepth = 8;
  REQUIRE_THROWS_AS(integrateOverRegion(one, -1, 1, -1, 1, inDisk, o), ConvergenceError);
  REQUIRE_THROWS_WITH(integrateOverRegion(one, -1, 1, -1, 1, inDisk, o), Catch::Contains("depth limit 8"));
}

TEST_CASE("curvature over chart triangles: a spherical triangle's excess") {
  // The octant triangle of the unit sphere (lon 0..π/2, colat 0..π/2) is a chart triangle with a pole corner; its
  // ∫K dA is its angle excess π/2. Chart triangles with a vertex at the pole (u arbitrary there) cover it exactly when
  // written as the rectangle [0, π/2]² — check both routes.
  const RoundSphereMetric s(1.0);
  const ChartFunction kd = curvatureDensity(s);
  CHECK(integrateOverRectangle(kd, 0, M_PI / 2, 0, M_PI / 2).value == Approx(M_PI / 2).epsilon(1e-12));
  const Eigen::Vector2d a(0, 0), b(M_PI / 2, 0), c(M_PI / 2, M_PI / 2), d(0, M_PI / 2);
  CHECK(integrateOverTriangles(kd, {{a, b, c}, {a, c, d}}).value == Approx(M_PI / 2).epsilon(1e-12));
}
