// Tests for vertex_removal.h (and HalfedgeMesh::removeDegree3Vertex) in the three background geometries, on closed and
// bounded surfaces: after deleting free vertices of a refined triangulation and Lawson-flipping (with signposts), the
// halfedge invariants hold, the lengths are valid, the triangulation is Delaunay, Gauss–Bonnet and the area are
// unchanged to round-off, the signpost invariant holds and every surviving vertex's input location still reproduces
// the lengths of its edges by the surface's closed-form distances; the counts of vertices, edges and faces drop by
// 1, 3 and 2 per removal; input and boundary vertices are refused.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/delaunay/vertex_removal.h"
#include "support/refine_test_surfaces.h"
#include "support/gauss_bonnet_bound.h"

using namespace conformesh;
using namespace conformesh::refine;
using namespace conformesh::refine::testing;
using intrinsic::IntrinsicTriangulation;

namespace {

// Lawson's flips with signposts (intrinsic::makeDelaunay does not carry them).
void lawson(IntrinsicTriangulation& t, Signposts& sp) {
  for (bool again = true; again;) {
    again = false;
    for (int e = 0; e < t.mesh.nEdges(); ++e)
      if (intrinsic::delaunayMargin(t, e) < -1e-12 && flipWithSignposts(t, sp, e)) again = true;
  }
}

struct RemovalLog {
  int removed = 0, refused = 0;
};

// Deletes every second inserted interior vertex (by index, counted from the top so that the swap-with-last compaction
// moves only vertices already passed over), applying the moves to the locations, then restores Delaunay.
RemovalLog removeEverySecond(RefineResult& r) {
  IntrinsicTriangulation& t = r.triangulation;
  const int n0 = r.statistics.inputVertices;
  RemovalLog log;
  for (int v = t.mesh.nVertices() - 1; v >= n0; v -= 2) {
    if (v >= t.mesh.nVertices() || t.mesh.isBoundaryVertex(v)) continue;
    const int V = t.mesh.nVertices(), E = t.mesh.nEdges(), F = t.mesh.nFaces();
    const VertexRemovalResult res = removeInsertedVertex(t, r.signposts, v, n0);
    if (!res.removed) {
      ++log.refused;
      continue;
    }
    ++log.removed;
    REQUIRE(t.mesh.nVertices() == V - 1);
    REQUIRE(t.mesh.nEdges() == E - 3);
    REQUIRE(t.mesh.nFaces() == F - 2);
    intrinsic::applyMoves(r.locations, res.moves.vertices, t.mesh.nVertices());
    intrinsic::applyMoves(r.lambda, res.moves.vertices, t.mesh.nVertices());
    REQUIRE_NOTHROW(t.mesh.checkInvariants());
  }
  lawson(t, r.signposts);
  return log;
}

struct Thinned {
  RefineResult r;
  int before = 0;  // vertices after refinement, before the removals
  RemovalLog log;
};
// Refines `tri` at ε with the default options, then removes every second free vertex.
Thinned refineThenRemoveEverySecond(const IntrinsicTriangulation& tri, double epsilon) {
  RefineOptions o;
  o.epsilon = epsilon;
  Thinned t{refineDelaunay(tri, o), 0, {}};
  t.before = t.r.triangulation.mesh.nVertices();
  t.log = removeEverySecond(t.r);
  return t;
}

// Every intrinsic property a triangulation keeps through removals (`areaBefore`: the area they must keep).
void checkIntrinsicAfterRemoval(const RefineResult& r, const RemovalLog& log, int verticesBefore, double areaBefore,
                                int eulerCharacteristic) {
  const IntrinsicTriangulation& t = r.triangulation;
  INFO("removed " << log.removed << ", refused " << log.refused << ", vertices " << verticesBefore << " -> "
                  << t.mesh.nVertices());
  CHECK(log.removed > 0);
  CHECK(t.mesh.nVertices() == verticesBefore - log.removed);
  REQUIRE_NOTHROW(t.mesh.checkInvariants());
  REQUIRE_NOTHROW(intrinsic::validateLengths(t, "after removal"));
  CHECK(t.mesh.eulerCharacteristic() == eulerCharacteristic);
  CHECK(intrinsic::countNonDelaunayEdges(t) == 0);
  CHECK(std::abs(measureQuality(t).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(t.mesh.nFaces()));
  CHECK(intrinsic::totalArea(t) == Approx(areaBefore).epsilon(1e-11));
  CHECK(signpostDefect(t, r.signposts) < 1e-9);
  // Every surviving inserted interior vertex is still flat.
  const std::vector<double> sums = intrinsic::angleSums(t);
  double worst = 0;
  for (int v = r.statistics.inputVertices; v < t.mesh.nVertices(); ++v)
    if (!t.mesh.isBoundaryVertex(v)) worst = std::max(worst, std::abs(sums[v] - 2 * M_PI));
  CHECK(worst < 1e-9);
}

// The above, and the input locations of the survivors against the surface's closed-form distances.
template <class Surface>
void checkAfterRemoval(const Surface& s, const RefineResult& r, const RemovalLog& log, int verticesBefore,
                       double areaBefore) {
  checkIntrinsicAfterRemoval(r, log, verticesBefore, areaBefore, s.tri.mesh.eulerCharacteristic());
  CHECK(static_cast<int>(r.locations.size()) == r.triangulation.mesh.nVertices());
  CHECK(worstLocatedLengthError(s, r.triangulation, r.locations) < 1e-10);
}

}  // namespace

TEST_CASE("removeDegree3Vertex undoes splitFace: counts, invariants and compaction moves") {
  const SphereSurface s = sphere(1);
  intrinsic::HalfedgeMesh m = s.tri.mesh;
  const int V0 = m.nVertices(), E0 = m.nEdges(), F0 = m.nFaces();
  std::vector<int> added;
  for (int f = 0; f < 12; ++f) added.push_back(m.splitFace(3 * f % m.nFaces()));
  // A per-vertex tag that must follow the compaction: the vertex's own index before removals.
  std::vector<int> tag(m.nVertices());
  for (int v = 0; v < m.nVertices(); ++v) tag[v] = v;
  // Input vertices are never removed here; remove the inserted ones in an order that makes the last vertex move.
  for (int k : {0, 5, 11, 3, 7, 1, 9, 2, 4, 6, 8, 10}) {
    int v = -1;
    for (int w = 0; w < m.nVertices(); ++w)
      if (tag[w] == added[k]) v = w;
    REQUIRE(v >= V0);
    intrinsic::ElementMoves moves;
    int merged = -1;
    REQUIRE(m.removeDegree3Vertex(v, moves, merged));
    REQUIRE_NOTHROW(m.checkInvariants());
    REQUIRE(merged >= 0);
    REQUIRE(merged < m.nFaces());
    intrinsic::applyMoves(tag, moves.vertices, m.nVertices());
  }
  CHECK(m.nVertices() == V0);
  CHECK(m.nEdges() == E0);
  CHECK(m.nFaces() == F0);
  for (int v = 0; v < V0; ++v) CHECK(tag[v] == v);
  // Input vertices have degree ≥ 5 and boundary vertices are refused.
  intrinsic::ElementMoves moves;
  int merged = -1;
  CHECK_FALSE(m.removeDegree3Vertex(0, moves, merged));
  const DiskSurface d = disk(2);
  intrinsic::HalfedgeMesh dm = d.tri.mesh;
  for (int v = 0; v < dm.nVertices(); ++v)
    if (dm.isBoundaryVertex(v)) CHECK_FALSE(dm.removeDegree3Vertex(v, moves, merged));
}

TEST_CASE("removing free vertices keeps lengths, signposts, locations, Delaunay and Gauss-Bonnet (closed surfaces)") {
  SECTION("flat torus") {
    const FlatTorus torus = flatTorus({1, 0}, {0.37, 0.61}, 5);
    auto [r, before, log] = refineThenRemoveEverySecond(torus.tri, 0.05);
    checkAfterRemoval(torus, r, log, before, intrinsic::totalArea(torus.tri));
  }
  SECTION("sphere") {
    const SphereSurface s = sphere(1);
    auto [r, before, log] = refineThenRemoveEverySecond(s.tri, 0.1);
    checkAfterRemoval(s, r, log, before, intrinsic::totalArea(s.tri));
  }
  SECTION("hyperbolic genus 2 (no closed-form locations: area 4π, Gauss–Bonnet, signposts)") {
    const OctagonSurface s = genus2Octagon();
    auto [r, before, log] = refineThenRemoveEverySecond(s.tri, 0.2);
    checkIntrinsicAfterRemoval(r, log, before, 4 * M_PI, -2);
  }
}

TEST_CASE("removing free vertices of a bounded surface (unit disk): boundary untouched, locations still right") {
  const DiskSurface d = disk(3);
  RefineOptions o;
  o.epsilon = 0.05;
  RefineResult r = refineDelaunay(d.tri, o);
  const int before = r.triangulation.mesh.nVertices();
  // Boundary vertices (input and inserted) are refused.
  for (int v = 0; v < before; ++v)
    if (r.triangulation.mesh.isBoundaryVertex(v)) {
      RefineResult copy = r;
      CHECK_FALSE(removeInsertedVertex(copy.triangulation, copy.signposts, v, r.statistics.inputVertices).removed);
    }
  const int boundaryBefore = static_cast<int>(r.triangulation.mesh.boundaryLoops()[0].size());
  // The refined disk's area is that of its refined boundary polygon (arc splits), not the input's.
  const double area = intrinsic::totalArea(r.triangulation);
  const RemovalLog log = removeEverySecond(r);
  checkAfterRemoval(d, r, log, before, area);
  CHECK(static_cast<int>(r.triangulation.mesh.boundaryLoops()[0].size()) == boundaryBefore);
}
TEST_CASE("removal on Delta-complex flat tori (n = 1, 2: self-loops and multi-edges among the neighbours)") {
  // A one- or four-vertex torus refined coarsely: inserted vertices have repeated neighbours and multi-edges, which the
  // merge and the compaction must keep straight. The located-length check does not apply here: edges up to 0.65 exceed
  // half the systole (|ω2| / 2 = 0.36), so an edge need not be the shortest path between its located ends (before any
  // removal the check already fails by 0.2); everything else is checked.
  for (int n : {1, 2}) {
    INFO("n = " << n);
    const FlatTorus torus = flatTorus({1, 0}, {0.37, 0.61}, n);
    auto [r, before, log] = refineThenRemoveEverySecond(torus.tri, 0.2);
    checkIntrinsicAfterRemoval(r, log, before, intrinsic::totalArea(torus.tri), 0);
    // The input vertices of a flat torus are flat too.
    const std::vector<double> sums = intrinsic::angleSums(r.triangulation);
    for (int v = 0; v < r.statistics.inputVertices; ++v) CHECK(std::abs(sums[v] - 2 * M_PI) < 1e-9);
  }
}
