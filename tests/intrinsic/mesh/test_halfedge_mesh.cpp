// Tests for halfedge_mesh.h: construction and validation from face lists, topology (χ, genus, boundary loops,
// components), Δ-complexes with self-loops, and the invariants of flip / splitFace / splitEdge.
#include <catch2/catch.hpp>

#include <random>

#include "support/test_meshes.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/halfedge_mesh.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;

namespace {
HalfedgeMesh build(const testing::MeshData& d, BuildReport* r = nullptr) {
  return HalfedgeMesh::fromFaces(d.faces, d.nVertices, d.source, r, d.cornerEdges);
}
}  // namespace

TEST_CASE("tetrahedron: counts, Euler characteristic, genus 0, no boundary") {
  const HalfedgeMesh m = HalfedgeMesh::fromFaces({{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}, 4);
  m.checkInvariants();
  CHECK(m.nVertices() == 4);
  CHECK(m.nEdges() == 6);
  CHECK(m.nFaces() == 4);
  const auto comps = m.components();
  REQUIRE(comps.size() == 1);
  CHECK(comps[0].eulerCharacteristic == 2);
  CHECK(comps[0].genus == 0);
  CHECK(comps[0].boundaryLoops == 0);
  for (int v = 0; v < 4; ++v) CHECK(m.vertexDegree(v) == 3);
}

TEST_CASE("icosahedron and torus grid: χ and genus") {
  CHECK(build(testing::icosahedron()).components()[0].genus == 0);
  const HalfedgeMesh t = build(testing::torusGrid(7, 5));
  t.checkInvariants();
  const auto c = t.components();
  REQUIRE(c.size() == 1);
  CHECK(c[0].eulerCharacteristic == 0);
  CHECK(c[0].genus == 1);
  CHECK(t.nEdges() == 3 * 35);
}

TEST_CASE("disk: one boundary loop walked in order") {
  const int n = 6;
  const HalfedgeMesh m = build(testing::squareGrid(n));
  m.checkInvariants();
  const auto loops = m.boundaryLoops();
  REQUIRE(loops.size() == 1);
  CHECK(loops[0].size() == 4 * n);
  for (size_t i = 0; i < loops[0].size(); ++i) {
    const int h = loops[0][i], g = loops[0][(i + 1) % loops[0].size()];
    CHECK(m.twin(h) == kInvalid);
    CHECK(m.tip(h) == m.tail(g));  // consecutive boundary halfedges chain up
  }
  const auto c = m.components();
  CHECK(c[0].eulerCharacteristic == 1);
  CHECK(c[0].genus == 0);
  CHECK(c[0].boundaryLoops == 1);
}

TEST_CASE("two components are reported separately") {
  const HalfedgeMesh m = HalfedgeMesh::fromFaces({{0, 1, 2}, {3, 4, 5}, {3, 5, 6}}, 7);
  const auto c = m.components();
  REQUIRE(c.size() == 2);
  CHECK(c[0].faces + c[1].faces == 3);
  CHECK(c[0].boundaryLoops == 1);
  CHECK(c[1].boundaryLoops == 1);
}

TEST_CASE("inconsistently oriented input is reoriented") {
  BuildReport report;
  // Tetrahedron with one face reversed.
  const HalfedgeMesh m = HalfedgeMesh::fromFaces({{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 3, 2}}, 4, "t", &report);
  m.checkInvariants();
  CHECK(report.reorientedFaces == 1);
  CHECK(m.components()[0].genus == 0);
}

TEST_CASE("bad connectivity is rejected with the element named") {
  SECTION("Möbius strip is not orientable") {
    // A strip of 5 quads (10 triangles) whose ends are glued with a half twist.
    std::vector<std::array<int, 3>> f;
    const int n = 5;
    // Vertices 0..n-1 on the top edge, n..2n-1 on the bottom edge; the last quad joins top n-1 to bottom 0.
    for (int i = 0; i < n - 1; ++i) {
      f.push_back({i, i + 1, n + i + 1});
      f.push_back({i, n + i + 1, n + i});
    }
    f.push_back({n - 1, n, 0});  // twisted closing quad: top(n-1)-bottom(0), bottom(n-1)-top(0)
    f.push_back({n - 1, 0, 2 * n - 1});
    REQUIRE_THROWS_WITH(HalfedgeMesh::fromFaces(f, 2 * n, "moebius.off"),
                        Contains("moebius.off") && Contains("not orientable"));
  }
  SECTION("non-manifold edge") {
    REQUIRE_THROWS_WITH(HalfedgeMesh::fromFaces({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, 5, "fin.obj"),
                        Contains("fin.obj") && Contains("non-manifold edge (0, 1)") && Contains("3 faces"));
  }
  SECTION("pinched vertex") {
    REQUIRE_THROWS_WITH(HalfedgeMesh::fromFaces({{0, 1, 2}, {0, 3, 4}}, 5, "bowtie.ply"),
                        Contains("bowtie.ply") && Contains("pinched vertex 0"));
  }
  SECTION("repeated vertex") {
    REQUIRE_THROWS_WITH(HalfedgeMesh::fromFaces({{0, 1, 1}}, 2, "rep.off"),
                        Contains("face 0 (0, 1, 1) repeats a vertex"));
  }
  SECTION("index out of range") {
    REQUIRE_THROWS_WITH(HalfedgeMesh::fromFaces({{0, 1, 7}}, 3, "oor.off"), Contains("vertex index 7 out of range"));
  }
  SECTION("unreferenced vertex") {
    REQUIRE_THROWS_WITH(HalfedgeMesh::fromFaces({{0, 1, 2}}, 4), Contains("vertex 3 belongs to no face"));
  }
  SECTION("no faces") { REQUIRE_THROWS_AS(HalfedgeMesh::fromFaces({}, 3), InputError); }
}

TEST_CASE("one-vertex torus Δ-complex with self-loops") {
  const HalfedgeMesh m = build(testing::oneVertexTorus());
  m.checkInvariants();
  CHECK(m.nVertices() == 1);
  CHECK(m.nEdges() == 3);
  CHECK(m.nFaces() == 2);
  CHECK(m.vertexDegree(0) == 6);
  CHECK(m.components()[0].genus == 1);
}

TEST_CASE("random flips, face splits and edge splits keep every invariant and the topology") {
  std::mt19937 rng(7);
  for (const auto& data : {testing::torusGrid(6, 5), testing::squareGrid(5), testing::icosahedron()}) {
    HalfedgeMesh m = build(data);
    const auto before = m.components()[0];
    int flips = 0;
    for (int step = 0; step < 400; ++step) {
      const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
      if (kind < 7) {
        flips += m.flip(std::uniform_int_distribution<int>(0, m.nEdges() - 1)(rng));
      } else if (kind < 9) {
        const int f = std::uniform_int_distribution<int>(0, m.nFaces() - 1)(rng);
        const int v = m.splitFace(f);
        CHECK(m.vertexDegree(v) == 3);
      } else {
        const int e = std::uniform_int_distribution<int>(0, m.nEdges() - 1)(rng);
        const bool boundary = m.isBoundaryEdge(e);
        const int v = m.splitEdge(e);
        if (v == kInvalid) continue;  // e folded inside one face: refused, nothing changed
        CHECK(m.vertexDegree(v) == (boundary ? 2 : 4));
        CHECK(m.isBoundaryVertex(v) == boundary);
      }
      m.checkInvariants();
    }
    CHECK(flips > 100);
    const auto after = m.components();
    REQUIRE(after.size() == 1);
    CHECK(after[0].eulerCharacteristic == before.eulerCharacteristic);
    CHECK(after[0].boundaryLoops == before.boundaryLoops);
  }
}

TEST_CASE("flip rotates the edge inside its quad") {
  HalfedgeMesh m = HalfedgeMesh::fromFaces({{0, 1, 2}, {0, 2, 3}}, 4);
  int diag = -1;
  for (int e = 0; e < m.nEdges(); ++e)
    if (!m.isBoundaryEdge(e)) diag = e;
  REQUIRE(diag >= 0);
  REQUIRE(m.flip(diag));
  const int h = m.edgeHalfedge(diag);
  const int a = std::min(m.tail(h), m.tip(h)), b = std::max(m.tail(h), m.tip(h));
  CHECK(a == 1);
  CHECK(b == 3);
  m.checkInvariants();
  int boundaryEdge = 0;
  while (!m.isBoundaryEdge(boundaryEdge)) ++boundaryEdge;
  CHECK_FALSE(m.flip(boundaryEdge));
}
