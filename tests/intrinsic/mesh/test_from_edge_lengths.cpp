// test_from_edge_lengths.cpp — fromEdgeLengths (from_edge_lengths.h): faces + per-corner lengths → triangulation.
//
// Closed forms: the regular unit tetrahedron has area √3 and angle defect π at each vertex (three angles π/3), the
// spherical octahedron with sides π/2 covers the unit sphere (area 4π, no defects). The icosphere's lengths computed
// from positions per corner must give the triangulation toTriangulation builds from the positions, edge for edge and
// bit for bit. Each kind of bad input must raise InputError naming the source, face, side and values.
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/from_edge_lengths.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;
using conformesh::InputError;

namespace {
const std::vector<std::array<int, 3>> kTetra = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
const std::vector<std::array<int, 3>> kOcta = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                               {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
std::vector<std::array<double, 3>> constant(size_t n, double l) {
  return std::vector<std::array<double, 3>>(n, {l, l, l});
}
}  // namespace

TEST_CASE("fromEdgeLengths: regular tetrahedron and spherical octahedron match their closed forms", "[mesh][lengths]") {
  const auto tet = fromEdgeLengths(kTetra, constant(4, 1.0));
  CHECK(tet.mesh.nVertices() == 4);
  CHECK(tet.mesh.nEdges() == 6);
  // Heron's formula rounds to a few ulps of √3/4 per face; 1e-14 is ~ 60 ulps of √3.
  CHECK(totalArea(tet) == Approx(std::sqrt(3.0)).epsilon(1e-14));
  for (double k : vertexCurvatures(tet)) CHECK(k == Approx(M_PI).epsilon(1e-14));

  FromEdgeLengthsOptions sphere;
  sphere.background = Background::Spherical;
  const auto oct = fromEdgeLengths(kOcta, constant(8, M_PI / 2), sphere);
  CHECK(oct.background == Background::Spherical);
  CHECK(totalArea(oct) == Approx(4 * M_PI).epsilon(1e-13));  // eight octants, each of area π/2 (Girard: 3·π/2 − π)
  for (double k : vertexCurvatures(oct)) CHECK(std::abs(k) < 1e-13);  // four right angles per vertex
}

TEST_CASE("fromEdgeLengths: per-corner lengths of an icosphere give toTriangulation's triangulation",
          "[mesh][lengths]") {
  const MeshData ico = makeIcosphere({2, 1.0});
  std::vector<std::array<double, 3>> lengths;
  for (const auto& f : ico.faces)
    lengths.push_back({(ico.positions[f[0]] - ico.positions[f[1]]).norm(),
                       (ico.positions[f[1]] - ico.positions[f[2]]).norm(),
                       (ico.positions[f[2]] - ico.positions[f[0]]).norm()});
  FromEdgeLengthsOptions exact;
  exact.relativeTolerance = 0;  // |p − q| and |q − p| are bit-equal, so exact agreement must hold
  const auto a = fromEdgeLengths(ico.faces, lengths, exact);
  const auto b = toTriangulation(ico);
  REQUIRE(a.mesh.nEdges() == b.mesh.nEdges());
  for (int e = 0; e < a.mesh.nEdges(); ++e) CHECK(a.edgeLengths[e] == b.edgeLengths[e]);
}

TEST_CASE("fromEdgeLengths: bad input names the source, face, side and values", "[mesh][lengths][errors]") {
  FromEdgeLengthsOptions o;
  o.source = "horizon.dat";
  auto lengths = constant(4, 1.0);
  auto expectError = [&](const std::vector<std::array<int, 3>>& faces, const std::vector<std::array<double, 3>>& l,
                         const std::string& what) {
    REQUIRE_THROWS_AS(fromEdgeLengths(faces, l, o), InputError);
    REQUIRE_THROWS_WITH(fromEdgeLengths(faces, l, o), Contains("horizon.dat") && Contains(what));
  };
  lengths[2][1] = std::numeric_limits<double>::quiet_NaN();
  expectError(kTetra, lengths, "face 2 side 1 (vertices 3, 2): length nan, expected a finite positive number");
  lengths[2][1] = -1;
  expectError(kTetra, lengths, "face 2 side 1 (vertices 3, 2): length -1");
  lengths[2][1] = 1 + 1e-9;
  expectError(kTetra, lengths, "face 3 side 0 (vertices 2, 3) has length 1 but face 2 gives that edge 1.000000001");
  lengths[2][1] = 1 + 1e-13;  // within the default 1e-12: accepted, the edge gets the mean
  CHECK_NOTHROW(fromEdgeLengths(kTetra, lengths, o));
  expectError({{0, 1, 2}}, {{3, 1, 1}}, "triangle inequality");  // one triangle (a disk) with sides 3, 1, 1
  expectError(kTetra, constant(3, 1.0), "expected one length triple per face (4 faces), found 3");
  expectError({}, {}, "no faces");
  expectError({{0, 1, -2}}, constant(1, 1.0), "face 0: negative vertex index -2");
  // three faces on the edge (0, 1): not a manifold
  expectError({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, constant(3, 1.0), "");
  o.relativeTolerance = -1;
  expectError(kTetra, constant(4, 1.0), "relativeTolerance must be in [0, 1), found -1");
}
