// test_metric_discretization.cpp — T0 of the built-in families: closed triangulations of the right topology, Gauss–
// Bonnet exact, total area converging to the smooth area at second order, chart-curve edge lengths converging to the
// exact geodesic distances of GeographicLib's GeodesicExact at the claimed order (relative error O(h²)), and
// well-shaped triangles at the poles and for strong flattening. Orders are least-squares slopes of log error against
// log h over four resolutions.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {

struct Built {
  MeshData data;
  IntrinsicTriangulation tri;
  DiscretizationReport report;
};

Built build(const SmoothMetric& m, int N, bool exact = true) {
  Built b;
  DiscretizationOptions o;
  o.resolution = N;
  o.exactGeodesics = exact;
  b.data = discretizeMetric(m, o, &b.report);
  b.tri = toTriangulation(b.data);
  return b;
}

// Area convergence to `exactArea` with orders measured over the resolutions, plus topology and Gauss–Bonnet checks.
double areaOrder(const SmoothMetric& m, double exactArea, const std::vector<int>& Ns, int chi, int boundaryLoops) {
  std::vector<double> h, err;
  for (int N : Ns) {
    const Built b = build(m, N);
    INFO(m.description() << " N=" << N);
    CHECK(b.tri.mesh.eulerCharacteristic() == chi);
    CHECK(static_cast<int>(b.tri.mesh.boundaryLoops().size()) == boundaryLoops);
    const CurvatureTotals ct = curvatureTotals(b.tri);
    CHECK(std::abs(ct.gaussBonnetResidual) < 1e-10);
    CHECK(b.data.vertexProperties.at("u").size() == static_cast<size_t>(b.data.nVertices));
    CHECK(b.data.comments.at(0).find(m.description()) != std::string::npos);
    h.push_back(1.0 / N);
    err.push_back(std::abs(totalArea(b.tri) - exactArea) / exactArea);
    std::cout << m.description() << " N=" << N << " V=" << b.report.vertices << " area rel.err=" << err.back()
              << " min angle=" << b.report.minAngle * 180 / M_PI << " deg\n";
  }
  const double p = fitLogLogSlope(h, err);
  std::cout << m.description() << ": area order " << p << "\n";
  return p;
}

}  // namespace

TEST_CASE("sphere: icosahedral T0, area at second order, no pole fans") {
  const RoundSphereMetric s(1.5);
  CHECK(areaOrder(s, 4 * M_PI * 1.5 * 1.5, {4, 8, 16, 32}, 2, 0) == Approx(2).margin(0.1));
  const Built b = build(s, 8);
  CHECK(b.report.vertices == 10 * 64 + 2);
  CHECK(b.report.exactLengths == b.report.edges);
  CHECK(b.report.minAngle > 50 * M_PI / 180);  // geodesic icosphere: near equilateral everywhere
  CHECK(b.data.positions.size() == static_cast<size_t>(b.data.nVertices));
}

TEST_CASE("ellipsoid: chart-curve lengths converge to GeodesicExact at relative order 2, area at order 2") {
  for (double f : {0.3, 0.9}) {
    const EllipsoidMetric e(1.0, f);
    std::vector<double> h, err;
    for (int N : {4, 8, 16, 32}) {
      const Built b = build(e, N, /*exact=*/false);
      double worst = 0;
      int shorter = 0;
      const auto& us = b.data.vertexProperties.at("u");
      const auto& vs = b.data.vertexProperties.at("v");
      for (const EdgeRecord& r : b.data.edges) {
        const double s = *e.geodesicDistance({us[r.v0], vs[r.v0]}, {us[r.v1], vs[r.v1]});
        shorter += r.length < s * (1 - 1e-12);  // a curve is never shorter than the geodesic
        worst = std::max(worst, (r.length - s) / s);
      }
      CHECK(shorter == 0);
      h.push_back(1.0 / N);
      err.push_back(worst);
      std::cout << e.description() << " N=" << N << " max rel. (chart curve - geodesic)/geodesic = " << worst
                << ", min angle " << b.report.minAngle * 180 / M_PI << " deg\n";
      // The conformal chart keeps triangles well shaped even at f = 0.9 (b = a/10).
      CHECK(b.report.minAngle > 40 * M_PI / 180);
    }
    const double p = fitLogLogSlope(h, err);
    std::cout << e.description() << ": edge-length order " << p << "\n";
    CHECK(p == Approx(2).margin(0.25));
    CHECK(areaOrder(e, e.area(), {4, 8, 16, 32}, 2, 0) == Approx(2).margin(0.15));
  }
}

TEST_CASE("chart-curve lengths against closed forms, both rules, to the 1e-12 they promise") {
  DiscretizationOptions halving;  // discretize's rule: 10 nodes, 1e-13
  DiscretizationOptions kronrod;  // the pull-back's: G7-K15, 1e-12 (metric_remesh.cpp)
  kronrod.curveRule = DiscretizationOptions::CurveRule::GaussKronrod15;
  kronrod.lengthTolerance = 1e-12;
  double worst = 0;
  auto check = [&](const SmoothMetric& m, const Eigen::Vector3d& xa, const Eigen::Vector3d& xb, double exact,
                   const char* what) {
    for (const DiscretizationOptions* o : {&halving, &kronrod}) {
      const double rel = std::abs(chartCurveLength(m, xa, xb, *o) / exact - 1);
      INFO(what << (o == &kronrod ? " (G7-K15)" : " (halving)") << ": relative error " << rel);
      CHECK(rel <= 1e-12);
      worst = std::max(worst, rel);
    }
  };
  // Arcs of at least 0.05 rad: on shorter ones the closed forms' own round-off (endpoints rounded to 1e-16 of their
  // size, E(φb) − E(φa) cancelling) exceeds 1e-12 of the arc. Sphere of radius R: a great arc of angle α has length Rα.
  const RoundSphereMetric sphere(2.5);
  const ChartDomain ds = sphere.domain();
  for (double alpha : {0.05, 0.3, 1.0, 2.5}) {
    const Eigen::Vector3d xa = referencePoint(ds, 0.3, 1.1);
    const Eigen::Vector3d axis = xa.cross(Eigen::Vector3d(0.2, 0.5, 0.9)).normalized();
    const Eigen::Vector3d xb = std::cos(alpha) * xa + std::sin(alpha) * axis.cross(xa);
    check(sphere, xa, xb, 2.5 * alpha, "sphere great arc");
  }
  // Ellipsoid f = 0.3: a meridian arc from geographic latitude φa to φb is a·|E(π/2 − βb, e) − E(π/2 − βa, e)| with
  // β = atan((1 − f) tan φ) the parametric latitude (the meridian x = a cos β, z = b sin β); its chart points are
  // θ = π/2 − χ(φ), χ = asin tanh(atanh sin φ − e atanh(e sin φ)) (closed forms, no inversion). An equator arc of Δλ
  // has length aΔλ.
  const double a = 1.3, f = 0.3, e = std::sqrt(f * (2 - f));
  const EllipsoidMetric ell(a, f);
  const ChartDomain de = ell.domain();
  auto theta = [&](double phi) {
    return M_PI / 2 - std::asin(std::tanh(std::atanh(std::sin(phi)) - e * std::atanh(e * std::sin(phi))));
  };
  auto meridian = [&](double phi) { return a * std::ellint_2(e, M_PI / 2 - std::atan((1 - f) * std::tan(phi))); };
  for (auto [pa, pb] : {std::pair{0.1, 0.3}, {-0.4, -0.1}, {0.7, 1.0}, {-0.2, 0.9}, {1.2, 1.5}}) {
    check(ell, referencePoint(de, 0.7, theta(pa)), referencePoint(de, 0.7, theta(pb)),
          std::abs(meridian(pa) - meridian(pb)), "ellipsoid meridian");
  }
  for (double dl : {0.05, 0.1, 1.5})
    check(ell, referencePoint(de, 0.2, M_PI / 2), referencePoint(de, 0.2 + dl, M_PI / 2), a * dl, "ellipsoid equator");
  // Bicubic patch of the paraboloid z = u² + v² (test_metric_families.cpp): the line v = 0 is the parabola z = u²,
  // of length √5/2 + asinh(2)/4 over u ∈ [0, 1]; the diagonal u = v = t has speed √(2 + 16t²).
  BezierControlNet net;
  const double c[4] = {0, 0, 1.0 / 3, 1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) net[i][j] = {i / 3.0, j / 3.0, c[i] + c[j]};
  const auto patch = makeBezierPatch("paraboloid", net);
  check(*patch, {0, 0, 0}, {1, 0, 0}, std::sqrt(5.0) / 2 + std::asinh(2.0) / 4, "parabola");
  check(*patch, {0, 0, 0}, {1, 1, 0}, std::sqrt(2.0) * (1.5 + std::asinh(2 * std::sqrt(2.0)) / (4 * std::sqrt(2.0))),
        "paraboloid diagonal");
  std::cout << "chart-curve lengths: worst relative error against closed forms " << worst << "\n";
}

TEST_CASE("Kerr-Newman: closed T0 for every spin up to extremal, area 8 pi M r+ at second order") {
  for (double chi : {0.5, 0.95, 1.0}) {
    const KerrNewmanMetric k(1.0, chi, 0.0);
    CHECK(areaOrder(k, k.area(), {4, 8, 16, 32}, 2, 0) == Approx(2).margin(0.15));
    const Built b = build(k, 8);
    CHECK(b.data.positions.empty());  // no embedding
    CHECK(b.report.minAngle > 30 * M_PI / 180);
  }
}

TEST_CASE("torus: glued periodic grid of genus 1, area at second order") {
  const TorusMetric t(3, 1);
  CHECK(areaOrder(t, 4 * M_PI * M_PI * 3, {4, 8, 16, 32}, 0, 0) == Approx(2).margin(0.15));
  const Built b = build(t, 8);
  CHECK(b.tri.mesh.components().at(0).genus == 1);
}

TEST_CASE("disks: spherical cap and hyperbolic disk, area at second order, exact boundary") {
  const SphericalCapMetric cap(1.0, 1.2);
  CHECK(areaOrder(cap, 2 * M_PI * (1 - std::cos(1.2)), {4, 8, 16, 32}, 1, 1) == Approx(2).margin(0.15));
  const HyperbolicDiskMetric hd(1.5);
  CHECK(areaOrder(hd, 4 * M_PI * std::sinh(0.75) * std::sinh(0.75), {4, 8, 16, 32}, 1, 1) == Approx(2).margin(0.15));
}

TEST_CASE("flat torus and graph: grids") {
  const FlatTorusMetric ft(0.5, std::sqrt(3.0) / 2, 1.0);
  const Built b = build(ft, 6);
  CHECK(b.tri.mesh.eulerCharacteristic() == 0);
  CHECK(totalArea(b.tri) == Approx(std::sqrt(3.0) / 2).epsilon(1e-13));  // flat: T0 is exact
  CHECK(b.report.minAngle == Approx(M_PI / 3).epsilon(1e-12));           // equilateral lattice, short diagonals
  auto bump = makeMetric("gaussian-bump");
  const Built g = build(*bump, 16);
  CHECK(g.tri.mesh.eulerCharacteristic() == 1);
  CHECK(std::abs(curvatureTotals(g.tri).gaussBonnetResidual) < 1e-10);
}

TEST_CASE("bad resolutions are rejected with the metric named") {
  DiscretizationOptions o;
  o.resolution = 2;
  REQUIRE_THROWS_WITH(discretizeMetric(TorusMetric(3, 1), o),
                      Catch::Contains("torus") && Catch::Contains("resolution"));
  o.resolution = 0;
  REQUIRE_THROWS_AS(discretizeMetric(RoundSphereMetric(1), o), InputError);
}
