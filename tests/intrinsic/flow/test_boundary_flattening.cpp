// Tests for boundary_flattening.h: the flat conformal metric of a disk that keeps its boundary. Checked from the output
// lengths alone: interior angle sums 2π, boundary edges unchanged, λ = 0 on the boundary, Gauss–Bonnet for the
// polygon (Σ boundary turning = 2π), an already flat disk left as it is, the corners of a Bézier patch keeping the
// smooth corner angle at the order of the discretization, the layout matching the lengths, and bad input named.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

#include "conformesh/intrinsic/flow/boundary_flattening.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {

struct Discretized {
  IntrinsicTriangulation tri;
  std::vector<Eigen::Vector2d> chart;  // per vertex of tri
};

Discretized discretize(const SmoothMetric& metric, int resolution) {
  DiscretizationOptions o;
  o.resolution = resolution;
  const MeshData data = discretizeMetric(metric, o);
  ConversionReport report;
  Discretized d;
  d.tri = toTriangulation(data, &report);
  d.chart.resize(d.tri.mesh.nVertices());
  for (int v = 0; v < data.nVertices; ++v)
    if (report.vertexMap[v] != kInvalid)
      d.chart[report.vertexMap[v]] = {data.vertexProperties.at("u")[v], data.vertexProperties.at("v")[v]};
  return d;
}

// Every property of the flattening that follows from its definition, checked on its lengths.
void checkFlattening(const IntrinsicTriangulation& input, const Uniformization& u) {
  const HalfedgeMesh& m = u.uniform.mesh;
  REQUIRE(u.uniform.background == Background::Euclidean);
  REQUIRE(u.report.target == UniformizationTarget::FlatKeepBoundary);
  const std::vector<double> sums = angleSums(u.uniform);
  double turning = 0;
  for (int v = 0; v < m.nVertices(); ++v) {
    if (m.isBoundaryVertex(v)) {
      CHECK(u.lambda[v] == 0.0);  // held exactly: Dirichlet data
      turning += M_PI - sums[v];
    } else {
      // Flat inside: the flow's tolerance 1e-10 rad on every angle sum, re-measured from the output lengths.
      CHECK(std::abs(sums[v] - 2 * M_PI) < 1e-10);
    }
  }
  // Gauss–Bonnet for a flat disk: the polygon turns by 2πχ = 2π (round-off of ~10³ angle sums).
  CHECK(std::abs(turning - 2 * M_PI) < 1e-9);
  // Boundary edges are never flipped and keep u = 0 at both ends: their lengths are the input's (Euclidean chords).
  for (const std::vector<int>& loop : m.boundaryLoops())
    for (int h : loop) CHECK(u.uniform.length(h) == Approx(input.edgeLengths[m.edge(h)]).epsilon(1e-14));
  // The layout realizes the lengths (the metric is flat and the disk simply connected).
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    CHECK((u.positions[m.tail(h)] - u.positions[m.tip(h)]).norm() == Approx(u.uniform.edgeLengths[e]).epsilon(1e-9));
  }
}

}  // namespace

TEST_CASE("boundary flattening: a flat disk is its own flattening") {
  // A graph of height 0 is the flat square [-2, 2]²: u = 0 solves the problem, and the solution is unique.
  const auto flat = makeMetric("gaussian-bump", {{"height", 0.0}});
  const Discretized d = discretize(*flat, 12);
  const Uniformization u = flattenKeepingBoundary(d.tri);
  checkFlattening(d.tri, u);
  for (double l : u.lambda) CHECK(std::abs(l) < 1e-12);
  CHECK(totalArea(u.uniform) == Approx(16.0).epsilon(1e-12));
}

TEST_CASE("boundary flattening: curved disks — a spherical cap, a Gaussian bump, a teapot patch") {
  for (const auto& metric : {makeMetric("spherical-cap", {}), makeMetric("gaussian-bump", {}),
                             makeMetric("teapot-patch", {{"patch", 4.0}})}) {
    INFO(metric->description());
    const Discretized d = discretize(*metric, 16);
    const Uniformization u = flattenKeepingBoundary(d.tri);
    checkFlattening(d.tri, u);
    // λ is bounded (the point of keeping the boundary); for a cap of positive curvature the flat metric is larger
    // inside: Δλ = −K < 0 with λ = 0 on the boundary gives λ > 0 (maximum principle).
    if (metric->family() == "spherical-cap")
      for (int v = 0; v < d.tri.mesh.nVertices(); ++v)
        if (!d.tri.mesh.isBoundaryVertex(v)) CHECK(u.lambda[v] > 0);
  }
}

TEST_CASE("boundary flattening: the corners of a Bézier patch keep the smooth corner angle") {
  // The smooth flat metric is conformal with a bounded factor, so its corner angles are the patch's own:
  // cos α = g_uv / √(g_uu g_vv) at the chart's corners. The discrete corner angle (Σθ at the corner vertex) must
  // converge to it as T0 is refined; first order is what a piecewise-linear conformal map gives near a corner.
  const auto patch = makeMetric("teapot-patch", {{"patch", 4.0}});
  const std::array<Eigen::Vector2d, 4> corners{
      {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 1)}};
  std::vector<double> h, err;
  for (int resolution : {8, 16, 32}) {
    const Discretized d = discretize(*patch, resolution);
    const Uniformization u = flattenKeepingBoundary(d.tri);
    const std::vector<double> sums = angleSums(u.uniform);
    double worst = 0;
    int found = 0;
    for (int v = 0; v < d.tri.mesh.nVertices(); ++v)
      for (const Eigen::Vector2d& c : corners) {
        if ((d.chart[v] - c).norm() > 1e-12) continue;
        ++found;
        const Eigen::Matrix2d g = patch->g(c.x(), c.y());
        const double alpha = std::acos(g(0, 1) / std::sqrt(g(0, 0) * g(1, 1)));
        // Ruppert's termination argument needs input angles of at least 60° (docs/refinement.md).
        CHECK(sums[v] > M_PI / 3);
        INFO("corner " << c.transpose() << " smooth angle " << alpha * 180 / M_PI << " flat " << sums[v] * 180 / M_PI);
        CHECK(std::abs(sums[v] - alpha) < 0.05);
        worst = std::max(worst, std::abs(sums[v] - alpha));
      }
    REQUIRE(found == 4);
    h.push_back(1.0 / resolution);
    err.push_back(worst);
  }
  INFO("corner angle errors " << err[0] << " " << err[1] << " " << err[2]);
  CHECK(err[2] < 0.02);  // about 1° at the finest T0 (~10³ vertices)
  CHECK(fitLogLogSlope(h, err) > 0.9);
}

TEST_CASE("boundary flattening: surfaces that are not disks are named") {
  SECTION("a closed sphere") {
    const IntrinsicTriangulation sphere = toTriangulation(makeIcosphere());
    CHECK_THROWS_WITH(flattenKeepingBoundary(sphere),
                      Catch::Contains("topological disk") && Catch::Contains("genus 0 with 0 boundary loop"));
  }
  SECTION("an annulus") {
    const MeshData annulus = makeAnnulus();
    CHECK_THROWS_WITH(flattenKeepingBoundary(toTriangulation(annulus)),
                      Catch::Contains("topological disk") && Catch::Contains("2 boundary loop"));
  }
}
