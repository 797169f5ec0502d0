// test_metric_discretization.cpp — T0 of the built-in families: closed triangulations of the right topology, Gauss–
// Bonnet exact, total area converging to the smooth area at second order, chart-curve edge lengths converging to the
// exact geodesic distances of GeographicLib's GeodesicExact at the claimed order (relative error O(h²)), and
// well-shaped triangles at the poles and for strong flattening. Orders are least-squares slopes of log error against
// log h over four resolutions.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
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
