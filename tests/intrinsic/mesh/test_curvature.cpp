// Tests for curvature.h: angle deficits against closed forms and Gauss–Bonnet (with the background area term) to
// round-off on closed, bounded, spherical and Δ-complex triangulations.
#include <catch2/catch.hpp>

#include <cmath>

#include "support/test_meshes.h"
#include "conformesh/intrinsic/mesh/curvature.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

TEST_CASE("regular icosahedron: every deficit is π/3, total 4π") {
  const IntrinsicTriangulation tri = toTriangulation(testing::icosahedron());
  for (double k : vertexCurvatures(tri)) CHECK(k == Approx(M_PI / 3).epsilon(1e-14));
  const CurvatureTotals t = curvatureTotals(tri);
  CHECK(t.eulerCharacteristic == 2);
  CHECK(std::abs(t.gaussBonnetResidual) < 1e-13);
}

TEST_CASE("flat square grid: interior deficits vanish, boundary turning is π/2 at the corners and sums to 2π") {
  const IntrinsicTriangulation tri = toTriangulation(testing::squareGrid(8));
  const std::vector<double> k = vertexCurvatures(tri);
  int corners = 0;
  for (int v = 0; v < tri.mesh.nVertices(); ++v) {
    if (std::abs(k[v] - M_PI / 2) < 1e-12) ++corners;
    else CHECK(std::abs(k[v]) < 1e-13);
  }
  CHECK(corners == 4);
  const CurvatureTotals t = curvatureTotals(tri);
  CHECK(t.boundaryTurning == Approx(2 * M_PI).epsilon(1e-14));
  CHECK(std::abs(t.gaussBonnetResidual) < 1e-12);
}

TEST_CASE("torus grid: Gauss–Bonnet gives zero total curvature with deficits of both signs") {
  const IntrinsicTriangulation tri = toTriangulation(testing::torusGrid(40, 24));
  const std::vector<double> k = vertexCurvatures(tri);
  CHECK(*std::min_element(k.begin(), k.end()) < -1e-3);  // inner equator: negative curvature
  CHECK(*std::max_element(k.begin(), k.end()) > 1e-3);   // outer equator: positive
  CHECK(std::abs(curvatureTotals(tri).gaussBonnetResidual) < 1e-12);
}

TEST_CASE("spherical octahedron: flat vertices, the background term carries all curvature") {
  // Six vertices ±e_i of the unit sphere, every edge a quarter great circle; in the spherical background each vertex
  // has four right angles, so no deficit, and K·Area = 4π = 2πχ.
  MeshData d;
  d.nVertices = 6;
  d.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  d.background = Background::Spherical;
  const int pairs[12][2] = {{0, 2}, {2, 1}, {1, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4},
                            {0, 5}, {1, 5}, {2, 5}, {3, 5}};
  for (auto& p : pairs) d.edges.push_back({p[0], p[1], M_PI / 2});
  const IntrinsicTriangulation tri = toTriangulation(d);
  for (double k : vertexCurvatures(tri)) CHECK(std::abs(k) < 1e-14);
  const CurvatureTotals t = curvatureTotals(tri);
  CHECK(t.backgroundTerm == Approx(4 * M_PI).epsilon(1e-14));
  CHECK(std::abs(t.gaussBonnetResidual) < 1e-13);
}

TEST_CASE("one-vertex flat torus: the single vertex has angle sum 2π") {
  const IntrinsicTriangulation tri = toTriangulation(testing::oneVertexTorus(1.0, 1.7));
  CHECK(std::abs(vertexCurvatures(tri)[0]) < 1e-14);
  CHECK(std::abs(curvatureTotals(tri).gaussBonnetResidual) < 1e-14);
}
