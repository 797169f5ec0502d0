// test_mesh_components.cpp — splitComponents on a surface built of three disjoint generated surfaces (a sphere, a
// torus, a disk, joined by hand): each component's topology, its vertex and face maps back to the input, every edge
// length kept, Gauss–Bonnet 2πχ per component to round-off; concatenateMeshData: offsets, the `component` property and
// the area of the concatenation equal to the sum of its parts'.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/mesh_components.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "support/test_meshes.h"

using namespace conformesh::intrinsic;
using conformesh::testing::joinByHand;
using conformesh::InputError;

namespace {

std::vector<MeshData> threeSurfaces() {
  TorusOptions torus;
  torus.n = 20;
  torus.m = 8;
  return {makeIcosphere({2, 1.0}), makeTorus(torus), makeDisk()};
}

}  // namespace

TEST_CASE("splitComponents: a sphere, a torus and a disk, each with its maps, lengths and Gauss–Bonnet") {
  const std::vector<MeshData> parts = threeSurfaces();
  const IntrinsicTriangulation joined = toTriangulation(joinByHand(parts));
  const std::vector<MeshComponent> comps = splitComponents(joined);
  REQUIRE(comps.size() == 3);
  const int chi[] = {2, 0, 1};
  int vertexOffset = 0, faceOffset = 0;
  for (int i = 0; i < 3; ++i) {
    const MeshComponent& c = comps[i];
    const IntrinsicTriangulation alone = toTriangulation(parts[i]);
    INFO("component " << i);
    CHECK(c.topology.eulerCharacteristic == chi[i]);
    REQUIRE(c.triangulation.mesh.nVertices() == alone.mesh.nVertices());
    REQUIRE(c.triangulation.mesh.nFaces() == alone.mesh.nFaces());
    // Parts were joined in order, so the maps are the offsets.
    for (std::size_t v = 0; v < c.vertices.size(); ++v) CHECK(c.vertices[v] == vertexOffset + static_cast<int>(v));
    for (std::size_t f = 0; f < c.faces.size(); ++f) CHECK(c.faces[f] == faceOffset + static_cast<int>(f));
    // Every corner's length is the input's at the mapped face and corner.
    double worst = 0;
    for (int f = 0; f < c.triangulation.mesh.nFaces(); ++f)
      for (int k = 0; k < 3; ++k) {
        CHECK(c.vertices[c.triangulation.mesh.faceVertex(f, k)] == joined.mesh.faceVertex(c.faces[f], k));
        worst = std::max(worst, std::abs(c.triangulation.length(3 * f + k) - joined.length(3 * c.faces[f] + k)));
      }
    CHECK(worst == 0.0);
    const CurvatureTotals t = curvatureTotals(c.triangulation);
    CHECK(t.eulerCharacteristic == chi[i]);
    // Σ of ≤ 10³ angle deficits, each with round-off ~1e-15.
    CHECK(std::abs(t.gaussBonnetResidual) < 1e-11);
    CHECK(std::abs(t.interiorDeficit + t.boundaryTurning - 2 * M_PI * chi[i]) < 1e-11);
    vertexOffset += c.triangulation.mesh.nVertices();
    faceOffset += c.triangulation.mesh.nFaces();
  }
}

TEST_CASE("splitComponents: a connected surface is one component, the input itself") {
  const IntrinsicTriangulation sphere = toTriangulation(makeIcosphere({1, 1.0}));
  const std::vector<MeshComponent> comps = splitComponents(sphere);
  REQUIRE(comps.size() == 1);
  CHECK(comps[0].triangulation.edgeLengths == sphere.edgeLengths);
  CHECK(comps[0].vertices.size() == static_cast<std::size_t>(sphere.mesh.nVertices()));
}

TEST_CASE("concatenateMeshData: offsets, the component property, area the sum of the parts'") {
  std::vector<MeshData> parts;
  double areaSum = 0;
  for (const MeshData& p : threeSurfaces()) {
    const IntrinsicTriangulation t = toTriangulation(p);
    areaSum += totalArea(t);
    parts.push_back(fromTriangulation(t));
    parts.back().positions = p.positions;
    parts.back().vertexProperties["x"].assign(p.nVertices, 1.5);
  }
  parts[1].vertexProperties["only_in_one"].assign(parts[1].nVertices, 2.0);
  const MeshData merged = concatenateMeshData(parts);
  CHECK(merged.nVertices == parts[0].nVertices + parts[1].nVertices + parts[2].nVertices);
  CHECK(merged.positions.size() == static_cast<std::size_t>(merged.nVertices));
  CHECK(merged.vertexProperties.count("only_in_one") == 0);
  REQUIRE(merged.vertexProperties.at("x").size() == static_cast<std::size_t>(merged.nVertices));
  const std::vector<double>& component = merged.vertexProperties.at("component");
  CHECK(component.front() == 0.0);
  CHECK(component[parts[0].nVertices] == 1.0);
  CHECK(component.back() == 2.0);
  const IntrinsicTriangulation back = toTriangulation(merged);
  CHECK(back.mesh.components().size() == 3);
  // The same face areas summed in another grouping: relative round-off ~1e-15 · F.
  CHECK(totalArea(back) == Approx(areaSum).epsilon(1e-12));
  parts[2].positions.clear();
  CHECK_THROWS_AS(concatenateMeshData(parts), InputError);
}
