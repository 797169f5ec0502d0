// Tests for intrinsic_flips.h: single flips in each geometry against closed forms, Lawson flipping to an intrinsic
// Delaunay triangulation (non-negative cotan weights), and isometry: undoing every flip recovers every original length.
#include <catch2/catch.hpp>

#include <random>

#include "support/test_meshes.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {
int interiorEdge(const IntrinsicTriangulation& tri) {
  for (int e = 0; e < tri.mesh.nEdges(); ++e)
    if (!tri.mesh.isBoundaryEdge(e)) return e;
  return -1;
}
}  // namespace

TEST_CASE("flipping a square's diagonal gives the other diagonal; a non-convex quad refuses") {
  MeshData d;
  d.nVertices = 4;
  d.faces = {{0, 1, 2}, {0, 2, 3}};
  d.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  IntrinsicTriangulation tri = toTriangulation(d);
  const int e = interiorEdge(tri);
  REQUIRE(flipEdge(tri, e));
  CHECK(tri.edgeLengths[e] == Approx(std::sqrt(5.0)).epsilon(1e-15));
  // Dart-shaped quad: vertex 2 pulled inside, so the quad is reflex at 2 and the diagonal 1-3 would leave it.
  d.positions = {{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}};
  IntrinsicTriangulation dart = toTriangulation(d);
  const int e2 = interiorEdge(dart);
  const auto before = dart.edgeLengths;
  CHECK_FALSE(flipEdge(dart, e2));
  CHECK(dart.edgeLengths == before);
}

TEST_CASE("spherical and hyperbolic flips keep the quad: flipping twice is the identity") {
  for (Background g : {Background::Spherical, Background::Hyperbolic}) {
    MeshData d;
    d.nVertices = 4;
    d.faces = {{0, 1, 2}, {0, 2, 3}};
    d.background = g;
    d.edges = {{0, 1, 0.5}, {1, 2, 0.6}, {2, 0, 0.7}, {2, 3, 0.45}, {3, 0, 0.55}};
    IntrinsicTriangulation tri = toTriangulation(d);
    const int e = interiorEdge(tri);
    const double area = totalArea(tri);
    REQUIRE(flipEdge(tri, e));
    CHECK(totalArea(tri) == Approx(area).epsilon(1e-13));  // same quad, same area
    REQUIRE(flipEdge(tri, e));
    CHECK(tri.edgeLengths[e] == Approx(0.7).epsilon(1e-13));
  }
}

TEST_CASE("Lawson flipping: Delaunay at the end, isometric, Gauss–Bonnet and area unchanged") {
  for (auto data : {testing::torusGrid(30, 20), testing::squareGrid(25), testing::icosahedron()}) {
    testing::jitter(data, data.nVertices > 100 ? 0.02 : 0.15, 11);
    IntrinsicTriangulation tri = toTriangulation(data);
    const auto original = tri.edgeLengths;
    const double area = totalArea(tri);
    std::vector<int> flipped;
    DelaunayOptions options;
    options.onFlip = [&](int e) { flipped.push_back(e); };
    const DelaunayReport report = makeDelaunay(tri, options);
    INFO(data.source);
    if (data.nVertices > 100) CHECK(report.nonDelaunayBefore > 0);
    CHECK(report.flips == static_cast<std::int64_t>(flipped.size()));
    CHECK(countNonDelaunayEdges(tri) == 0);
    // Interior edges only: a boundary edge has a single opposite angle, which Delaunay-ness does not constrain.
    for (int e = 0; e < tri.mesh.nEdges(); ++e)
      if (!tri.mesh.isBoundaryEdge(e)) CHECK(cotanWeight(tri, e) > -1e-12);
    tri.mesh.checkInvariants();
    CHECK(totalArea(tri) == Approx(area).epsilon(1e-12));
    CHECK(std::abs(curvatureTotals(tri).gaussBonnetResidual) < 1e-11);
    // Isometry: a flip is undone by flipping the same edge again. Undoing every flip in reverse order must give back
    // the original connectivity and every original length, which holds only if each flip kept the metric of its quad.
    for (auto it = flipped.rbegin(); it != flipped.rend(); ++it) REQUIRE(flipEdge(tri, *it));
    for (int e = 0; e < tri.mesh.nEdges(); ++e) CHECK(tri.edgeLengths[e] == Approx(original[e]).epsilon(1e-11));
  }
}

TEST_CASE("Lawson flipping terminates on cocircular input without flipping") {
  // A regular grid of right isoceles triangles: every interior edge is cocircular (margin exactly 0).
  IntrinsicTriangulation tri = toTriangulation(testing::squareGrid(10));
  const DelaunayReport r = makeDelaunay(tri);
  CHECK(r.flips == 0);
}

TEST_CASE("a randomly perturbed million-face metric: Delaunay after flipping, every original length recoverable") {
  // 2 · 1000 · 500 faces on a torus whose vertices are moved off the surface: a valid but far from Delaunay metric.
  MeshData data = testing::torusGrid(1000, 500, 1.0, 0.45);
  testing::jitter(data, 0.3 * 2 * M_PI * 0.45 / 500, 5);
  IntrinsicTriangulation tri = toTriangulation(data);
  REQUIRE(tri.mesh.nFaces() == 1000000);
  const auto original = tri.edgeLengths;
  std::vector<int> flipped;
  DelaunayOptions options;
  options.onFlip = [&](int e) { flipped.push_back(e); };
  const DelaunayReport report = makeDelaunay(tri, options);
  CHECK(report.nonDelaunayBefore > 100000);
  CHECK(countNonDelaunayEdges(tri) == 0);
  // Isometry, as above: undo every flip and compare every edge with the original metric.
  for (auto it = flipped.rbegin(); it != flipped.rend(); ++it) REQUIRE(flipEdge(tri, *it));
  double worst = 0;
  for (int e = 0; e < tri.mesh.nEdges(); ++e)
    worst = std::max(worst, std::abs(tri.edgeLengths[e] - original[e]) / original[e]);
  // A flip and its undo each cost a few ulps; edges flipped several times accumulate them.
  CHECK(worst < 1e-10);
}
