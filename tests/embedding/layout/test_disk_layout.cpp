// test_disk_layout.cpp — circle-domain layouts. The planar unit disk of makeDisk (boundary vertices on the unit circle)
// is already a discrete circle domain, so its normalized layout reproduces it to round-off (solutions are unique up to
// Möbius maps, which the normalization removes). A spherical cap of angular radius α, discretized from the
// `spherical-cap` family at several resolutions, converges to its exact conformal map onto the unit disk —
// stereographic projection, z = tan(r/2R)/tan(α/2) · e^{iφ} in geodesic polar coordinates (r, φ) — at the order of a
// log–log fit. Bad choices are named.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/embedding/layout/disk_layout.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh::embedding;
using namespace conformesh::intrinsic;

TEST_CASE("the planar unit disk is its own circle domain") {
  const MeshData data = makeDisk({6, 1.0});
  const Uniformization u = uniformize(toTriangulation(data));
  // Vertex 0 is the centre, vertex 1 the first vertex of ring 1, on the +x axis (makeDisk).
  REQUIRE(data.positions[0].norm() == 0);
  REQUIRE(std::abs(data.positions[1].y()) < 1e-15);
  const DiskLayout d = layoutDisk(u, {0, 1});
  CHECK(d.minSignedArea > 0);
  REQUIRE(d.circles.size() == 1);
  CHECK(std::abs(d.circles[0].radius - 1) < 1e-10);
  CHECK(d.circles[0].deviation < 1e-10);
  double err = 0;
  for (std::size_t v = 0; v < data.positions.size(); ++v)
    err = std::max(err, (d.points[v] - data.positions[v].head<2>()).norm());
  CHECK(err < 1e-10);
}

TEST_CASE("a spherical cap converges to its stereographic image, normalized to the unit disk") {
  const double R = 1, alpha = 1.2;
  const auto metric = makeMetric("spherical-cap", {{"R", R}, {"alpha", alpha}});
  std::vector<double> hs, errors;
  for (int n : {4, 8, 16, 32}) {
    DiscretizationOptions o;
    o.resolution = n;
    const MeshData data = discretizeMetric(*metric, o);
    const IntrinsicTriangulation input = toTriangulation(data);
    const std::vector<double>& us = data.vertexProperties.at("u");
    const std::vector<double>& vs = data.vertexProperties.at("v");
    // The pole (v = 0) goes to 0; a vertex of the first ring with the smallest |u| fixes the direction.
    int centre = -1, direction = -1;
    for (int v = 0; v < static_cast<int>(vs.size()); ++v)
      if (vs[v] == 0) centre = v;
    REQUIRE(centre >= 0);
    const int h0 = input.mesh.vertexHalfedge(centre);
    int h = h0;
    do {
      const int w = input.mesh.tip(h);
      if (direction < 0 ||
          std::abs(std::remainder(us[w], 2 * M_PI)) < std::abs(std::remainder(us[direction], 2 * M_PI)))
        direction = w;
      h = input.mesh.nextOutgoing(h);
    } while (h != h0);
    const Uniformization u = uniformize(input);
    const DiskLayout d = layoutDisk(u, {centre, direction});
    CHECK(d.minSignedArea > 0);
    // Exact map, rotated so that the direction vertex lies on +x as in the layout.
    const double turn = us[direction];
    double err = 0;
    for (int v = 0; v < static_cast<int>(vs.size()); ++v) {
      const double rho = std::tan(vs[v] / (2 * R)) / std::tan(alpha / 2);
      const Eigen::Vector2d exact(rho * std::cos(us[v] - turn), rho * std::sin(us[v] - turn));
      err = std::max(err, (d.points[v] - exact).norm());
    }
    double meanEdge = 0;
    for (double l : input.edgeLengths) meanEdge += l;
    hs.push_back(meanEdge / input.edgeLengths.size());
    errors.push_back(err);
  }
  const double order = fitLogLogSlope(hs, errors);
  WARN("spherical cap: max point errors " << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3]
                                          << ", order " << order);
  CHECK(order > 1.8);  // measured 1.95
}

TEST_CASE("layoutDisk reports bad choices and wrong targets") {
  const Uniformization u = uniformize(toTriangulation(makeDisk({3, 1.0})));
  const int boundary = u.uniform.mesh.nVertices() - 1;  // the last ring is the boundary
  CHECK_THROWS_WITH(layoutDisk(u, {boundary, -1}),
                    Catch::Contains("centre vertex " + std::to_string(boundary)) && Catch::Contains("on the boundary"));
  CHECK_THROWS_WITH(layoutDisk(u, {0, 999}), Catch::Contains("vertex 999 out of range"));
  const Uniformization sphere = uniformize(toTriangulation(makeIcosphere({1, 1.0})));
  CHECK_THROWS_WITH(layoutDisk(sphere), Catch::Contains("found target sphere"));
}
