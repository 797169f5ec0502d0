// test_homology_basis.cpp — tree–cotree decomposition on closed surfaces of genus 0–3 (the genus-g slabs of
// mesh_generators.h and a one-vertex flat torus with self-loops): the edge classes partition the edges with
// |T| = V − 1, |C| = F − 1, |G| = 2g; the tree is a shortest-path tree; every generator loop is closed through the
// root; the relation has length 4g with each generator once with each sign; inputs with boundary or several components
// named.
#include <catch2/catch.hpp>

#include <map>

#include "conformesh/embedding/layout/homology_basis.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

using namespace conformesh::embedding;
using namespace conformesh::intrinsic;

namespace {

void checkBasis(const IntrinsicTriangulation& tri, int genus) {
  const HomologyBasis b = treeCotree(tri);
  const HalfedgeMesh& m = tri.mesh;
  CHECK(b.genus == genus);
  std::map<EdgeClass, int> count;
  for (EdgeClass c : b.edgeClass) ++count[c];
  CHECK(count[EdgeClass::Tree] == m.nVertices() - 1);
  CHECK(count[EdgeClass::Cotree] == m.nFaces() - 1);
  CHECK(count[EdgeClass::Generator] == 2 * genus);
  REQUIRE(static_cast<int>(b.generatorEdges.size()) == 2 * genus);
  // Shortest-path tree: d(v) = d(parent) + ℓ, and no edge offers a shorter path (Bellman's condition).
  for (int v = 0; v < m.nVertices(); ++v) {
    if (v == b.rootVertex) continue;
    const int h = b.parentHalfedge[v];
    CHECK(b.rootDistance[v] == Approx(b.rootDistance[m.tail(h)] + tri.length(h)).epsilon(1e-12));
  }
  for (int h = 0; h < m.nHalfedges(); ++h)
    CHECK(b.rootDistance[m.tip(h)] <= b.rootDistance[m.tail(h)] + tri.length(h) + 1e-12);
  for (int i = 0; i < 2 * genus; ++i) {
    const std::vector<int> loop = generatorLoop(tri, b, i);
    CHECK(m.tail(loop.front()) == b.rootVertex);
    CHECK(m.tip(loop.back()) == b.rootVertex);
    for (std::size_t k = 0; k + 1 < loop.size(); ++k) CHECK(m.tip(loop[k]) == m.tail(loop[k + 1]));
  }
  CHECK(static_cast<int>(b.relation.size()) == 4 * genus);
  std::map<int, int> letters;
  for (int l : b.relation) ++letters[l];
  for (int i = 1; i <= 2 * genus; ++i) CHECK((letters[i] == 1 && letters[-i] == 1));
  // Crossing words: a halfedge and its twin carry inverse words; cotree halfedges the empty word.
  for (int h = 0; h < m.nHalfedges(); ++h) {
    CHECK(freeReduce(inverse(b.crossingWord[h])) == b.crossingWord[m.twin(h)]);
    if (b.edgeClass[m.edge(h)] == EdgeClass::Cotree) CHECK(b.crossingWord[h].empty());
  }
}

}  // namespace

TEST_CASE("tree-cotree gives 2g generators and a relation of length 4g") {
  for (int g = 0; g <= 3; ++g) {
    INFO("genus " << g);
    GenusSurfaceOptions o;
    o.genus = g;
    o.resolution = 2;
    checkBasis(toTriangulation(makeGenusSurface(o)), g);
  }
  // A one-vertex torus (self-loops, a Δ-complex: n = 1): T is empty, C has one edge (2 faces), G the other two.
  FlatTorusOptions t;
  t.n = 1;
  checkBasis(toTriangulation(makeFlatTorus(t)), 1);
}

TEST_CASE("word helpers") {
  CHECK(freeReduce({1, 2, -2, -1, 3}) == GroupWord{3});
  CHECK(inverse({1, -2}) == GroupWord{2, -1});
  CHECK(toString(GroupWord{1, -2}) == "g1 g2^-1");
  CHECK(toString(GroupWord{}) == "1");
}

TEST_CASE("treeCotree names what it cannot handle") {
  CHECK_THROWS_WITH(treeCotree(toTriangulation(makeDisk({2, 1.0}))), Catch::Contains("1 boundary loop"));
  IntrinsicTriangulation two;
  two.mesh = HalfedgeMesh::fromFaces({{0, 1, 2}, {0, 2, 1}, {3, 4, 5}, {3, 5, 4}}, 6);
  two.edgeLengths.assign(two.mesh.nEdges(), 1.0);
  CHECK_THROWS_WITH(treeCotree(two), Catch::Contains("found 2"));
  const IntrinsicTriangulation ico = toTriangulation(makeIcosphere({0, 1.0}));
  CHECK_THROWS_WITH(treeCotree(ico, 12), Catch::Contains("root vertex 12 out of range"));
  CHECK_THROWS_WITH(generatorLoop(ico, treeCotree(ico), 0), Catch::Contains("generator 0 out of range"));
}
