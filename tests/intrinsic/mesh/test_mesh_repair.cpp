// test_mesh_repair.cpp — repairMesh on constructed meshes, each with one defect (duplicate vertices, a face repeating
// a vertex, a collinear face, a duplicate face, a pinched vertex, a non-manifold edge, an inconsistent orientation,
// a metric-only mesh), each result checked to be a manifold that toTriangulation accepts without reorienting, with the
// Euler characteristic derived by hand; requireNoRepairNeeded's errors; and CGAL's polygon_mesh.off (three pinched
// vertices), where the result's χ is the input's V − E + F plus one per extra fan (splitting a vertex into k fans adds
// k − 1 vertices and changes no edge or face).
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <utility>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/mesh_repair.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;

namespace {

// The regular octahedron: 6 vertices, 8 faces, outward orientation.
MeshData octahedron() {
  MeshData d;
  d.source = "octahedron";
  d.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  d.nVertices = 6;
  d.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return d;
}

// The result must be accepted by toTriangulation as it is: no reorientation, no unreferenced vertex.
MeshSummary checkedSummary(const MeshData& d) {
  ConversionReport conv;
  const IntrinsicTriangulation tri = toTriangulation(d, &conv);
  CHECK(conv.build.reorientedFaces == 0);
  CHECK(conv.unreferencedVerticesRemoved == 0);
  return summarize(tri);
}

std::string errorOf(const MeshData& d) {
  try {
    requireNoRepairNeeded(d);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("repair: a clean mesh is left as it is") {
  RepairReport r;
  const MeshData out = repairMesh(octahedron(), {}, &r);
  CHECK_FALSE(r.changedAnything());
  CHECK(out.faces == octahedron().faces);
  CHECK(errorOf(octahedron()).empty());
}

TEST_CASE("repair: a polygon soup (every face its own three vertices) is merged into the closed octahedron") {
  const MeshData o = octahedron();
  MeshData soup = o;
  soup.positions.clear(), soup.faces.clear();
  for (const auto& f : o.faces) {
    const int b = static_cast<int>(soup.positions.size());
    for (int k = 0; k < 3; ++k) soup.positions.push_back(o.positions[f[k]] * (1 + 1e-13 * k));  // within 1e-10·diag
    soup.faces.push_back({b, b + 1, b + 2});
  }
  soup.nVertices = 24;
  RepairReport r;
  const MeshSummary s = checkedSummary(repairMesh(soup, {}, &r));
  CHECK(r.mergedVertices.count == 18);  // 24 corners onto 6 vertices
  CHECK(r.mergeDistance == Approx(1e-10 * 2 * std::sqrt(3.0)).epsilon(1e-12));
  CHECK(s.vertices == 6);
  CHECK(s.eulerCharacteristic == 2);  // 6 − 12 + 8
  CHECK(s.boundaryLoops == 0);
  // Without merging, the soup is 8 separate triangles: χ = 8, 8 boundary loops.
  RepairOptions none;
  none.mergeTolerance = -1;
  const MeshSummary apart = checkedSummary(repairMesh(soup, none));
  CHECK(apart.eulerCharacteristic == 8);
  CHECK(apart.components.size() == 8);
}

TEST_CASE("repair: a face repeating a vertex and a zero-area face are dropped") {
  MeshData d = octahedron();
  d.faces.push_back({0, 0, 4});
  CHECK_THAT(errorOf(d), Contains("degenerate face 8 (0, 0, 4); `--repair` would fix it") && Contains("`--repair`"));
  RepairReport r;
  CHECK(checkedSummary(repairMesh(d, {}, &r)).eulerCharacteristic == 2);
  CHECK(r.degenerateFaces.count == 1);

  // A unit square in two triangles with a midpoint 4 on its bottom side, and the sliver (0, 4, 1) on that side: its
  // lengths 0.5 + 0.5 = 1 break the strict triangle inequality. Dropped, the rest is a disk: χ = 5 − 8 + 3... with the
  // sliver's edges gone: vertices 5, edges 7, faces 3, χ = 1, one boundary loop.
  MeshData sq;
  sq.source = "square";
  sq.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0, 0}};
  sq.nVertices = 5;
  sq.faces = {{0, 4, 2}, {4, 1, 2}, {0, 2, 3}, {0, 1, 4}};
  CHECK_THROWS_WITH(toTriangulation(sq), Contains("triangle inequality"));
  const MeshSummary s = checkedSummary(repairMesh(sq, {}, &r));
  CHECK(r.degenerateFaces.count == 1);
  CHECK(r.degenerateFaces.examples.at(0) == "face 3 (0, 1, 4)");
  CHECK(s.faces == 3);
  CHECK(s.eulerCharacteristic == 1);
  CHECK(s.boundaryLoops == 1);
  CHECK(s.totalArea == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("repair: a duplicate face (same vertices, either orientation) is dropped") {
  MeshData d = octahedron();
  d.faces.push_back({4, 2, 0});  // face 0 reversed: its edges would be in three faces
  CHECK_THROWS_WITH(toTriangulation(d), Contains("non-manifold edge"));
  CHECK_THAT(errorOf(d), Contains("duplicate face 8 (4, 2, 0) repeats face 0"));
  RepairReport r;
  const MeshSummary s = checkedSummary(repairMesh(d, {}, &r));
  CHECK(r.duplicateFaces.count == 1);
  CHECK(r.nonManifoldEdges.count == 0);
  CHECK(s.faces == 8);
  CHECK(s.eulerCharacteristic == 2);
}

TEST_CASE("repair: a doubled triangle (a face and its copy alone) is a closed surface and is kept") {
  MeshData d;
  d.source = "pillow";
  d.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  d.nVertices = 3;
  d.faces = {{0, 1, 2}, {0, 2, 1}};
  RepairReport r;
  const MeshSummary s = checkedSummary(repairMesh(d, {}, &r));
  CHECK_FALSE(r.changedAnything());
  CHECK(s.eulerCharacteristic == 2);  // 3 − 3 + 2
}

TEST_CASE("repair: coincident vertices inside a surface are not merged (that would pinch it)") {
  // Two octahedra touching at a point: the second's vertex 1 (index 7) sits exactly on the first's vertex 0.
  MeshData d = octahedron();
  const MeshData o = octahedron();
  for (int v = 0; v < 6; ++v) d.positions.push_back(o.positions[v] + Eigen::Vector3d(2, 0, 0));
  d.nVertices = 12;
  for (auto f : o.faces) {
    for (int& v : f) v += 6;
    d.faces.push_back(f);
  }
  REQUIRE(d.positions[7] == d.positions[0]);
  RepairReport r;
  const MeshSummary s = checkedSummary(repairMesh(d, {}, &r));
  CHECK_FALSE(r.changedAnything());
  CHECK(s.components.size() == 2);
  CHECK(s.eulerCharacteristic == 4);
}

TEST_CASE("repair: a pinched vertex gets one vertex per fan") {
  // Two octahedra sharing vertex 0 (the second translated by −2 along x, its vertex 1 there being the shared one).
  MeshData d = octahedron();
  const MeshData o = octahedron();
  for (int v = 0; v < 6; ++v) d.positions.push_back(o.positions[v] + Eigen::Vector3d(2, 0, 0));
  d.nVertices = 12;
  for (auto f : o.faces) {
    for (int& v : f) v = v == 1 ? 0 : v + 6;
    d.faces.push_back(f);
  }
  CHECK_THROWS_WITH(toTriangulation(d), Contains("pinched vertex 0"));
  CHECK_THAT(errorOf(d), Contains("pinched vertex 0 (fan of face 9)"));
  RepairReport r;
  const MeshData out = repairMesh(d, {}, &r);
  const MeshSummary s = checkedSummary(out);
  CHECK(r.pinchedVertices.count == 1);
  CHECK(s.vertices == 12);  // 11 used + 1 copy; the second octahedron's unused vertex 7 is removed
  CHECK(r.unreferencedVertices.count == 1);
  CHECK(s.components.size() == 2);
  CHECK(s.eulerCharacteristic == 4);  // two spheres
  CHECK(out.positions.back() == d.positions[0]);  // the copy sits where the original does
}

TEST_CASE("repair: a non-manifold edge is cut into boundary") {
  // Three triangles on edge (0, 1): two are kept glued (the first, and the first running the other way), the third
  // is cut off with its own copies of 0 and 1. Result: a quad (χ = 1) and a triangle (χ = 1), two boundary loops.
  MeshData d;
  d.source = "book";
  d.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  d.nVertices = 5;
  d.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  CHECK_THROWS_WITH(toTriangulation(d), Contains("non-manifold edge"));
  CHECK_THAT(errorOf(d), Contains("non-manifold edge (0, 1) in 3 faces"));
  RepairReport r;
  const MeshData out = repairMesh(d, {}, &r);
  const MeshSummary s = checkedSummary(out);
  CHECK(r.nonManifoldEdges.count == 1);
  CHECK(r.pinchedVertices.count == 2);  // vertices 0 and 1 of the cut-off face
  CHECK(s.vertices == 7);
  CHECK(s.components.size() == 2);
  CHECK(s.eulerCharacteristic == 2);
  CHECK(s.boundaryLoops == 2);

  // Four faces on one edge: two tetrahedra {0,1,2,3} and {0,1,4,5} sharing edge (0, 1). Round 0 keeps face 0 and
  // the first face running (0, 1) the other way, face 1 — both of the first tetrahedron, which stays closed; faces 4
  // and 6 are cut, so the second tetrahedron's corners at 0 and at 1 form fans of their own and get copies 0', 1',
  // along which faces 4 and 6 are glued again. By hand: two spheres, V = 4 + 4, E = 6 + 6, F = 8, χ = 4, no boundary.
  MeshData t;
  t.source = "two tetrahedra";
  t.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0.3, 1}, {0.5, -1, 0}, {0.5, -0.3, -1}};
  t.nVertices = 6;
  t.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {1, 0, 4}, {0, 5, 4}, {0, 1, 5}, {1, 4, 5}};
  const MeshSummary st = checkedSummary(repairMesh(t, {}, &r));
  CHECK(r.nonManifoldEdges.count == 1);
  CHECK(r.pinchedVertices.count == 2);
  CHECK(st.components.size() == 2);
  CHECK(st.vertices == 8);
  CHECK(st.eulerCharacteristic == 4);
  CHECK(st.boundaryLoops == 0);
}

TEST_CASE("repair: an inconsistently oriented face is turned") {
  MeshData d = octahedron();
  std::swap(d.faces[3][1], d.faces[3][2]);
  RepairReport r;
  const MeshData out = repairMesh(d, {}, &r);
  CHECK(r.reorientedFaces.count == 1);
  CHECK(r.reorientedFaces.examples.at(0) == "face 3");
  CHECK(out.faces == octahedron().faces);
  CHECK_FALSE(r.neededForTriangulation());  // toTriangulation reorients by itself
}

TEST_CASE("repair: a metric-only mesh keeps its lengths through a vertex split") {
  // Two triangles pinched at vertex 0, given by edge lengths (3-4-5 and 1-1-1).
  MeshData d;
  d.source = "lengths";
  d.nVertices = 5;
  d.faces = {{0, 1, 2}, {0, 3, 4}};
  d.edges = {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}, {0, 3, 1}, {3, 4, 1}, {4, 0, 1}};
  RepairReport r;
  const MeshData out = repairMesh(d, {}, &r);
  const MeshSummary s = checkedSummary(out);
  CHECK(r.pinchedVertices.count == 1);
  CHECK(s.totalArea == Approx(6 + std::sqrt(3.0) / 4).epsilon(1e-15));
  CHECK(out.edges.size() == 6);
}

TEST_CASE("repair: options are validated; a Δ-complex is refused") {
  RepairOptions o;
  CHECK(o.validate().empty());
  o.mergeTolerance = 0.1;
  CHECK_THAT(o.validate(), Contains("mergeTolerance") && Contains("0.1"));
  CHECK_THROWS_WITH(repairMesh(octahedron(), o), Contains("repair options"));
  o = {};
  o.degenerateTolerance = -1;
  CHECK_THAT(o.validate(), Contains("degenerateTolerance"));
  MeshData delta = octahedron();
  delta.cornerEdges.assign(8, {0, 0, 0});
  CHECK_THROWS_WITH(repairMesh(delta), Contains("Δ-complex"));
}

TEST_CASE("repair: CGAL's polygon_mesh.off (pinched vertices) is refused with the hint, and repaired") {
  const MeshData d = readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/polygon_mesh.off");
  CHECK_THROWS_WITH(toTriangulation(d), Contains("pinched vertex 4113"));
  CHECK_THAT(errorOf(d), Contains("pinched vertex 4113") && Contains("(3 in all)") && Contains("`--repair`"));
  std::set<std::pair<int, int>> edges;
  std::set<int> used;
  for (const auto& f : d.faces)
    for (int k = 0; k < 3; ++k) {
      edges.insert({std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])});
      used.insert(f[k]);
    }
  const int chiIn = static_cast<int>(used.size()) - static_cast<int>(edges.size()) + static_cast<int>(d.faces.size());
  RepairReport r;
  const MeshSummary s = checkedSummary(repairMesh(d, {}, &r));
  CHECK(r.pinchedVertices.count == 3);
  CHECK(r.nonManifoldEdges.count == 0);
  CHECK(s.faces == static_cast<int>(d.faces.size()));
  CHECK(s.eulerCharacteristic == chiIn + r.pinchedVertices.count);
}
