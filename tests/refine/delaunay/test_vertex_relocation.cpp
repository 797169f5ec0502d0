// Tests for vertex_relocation.h in the three background geometries: after every free vertex of a refined triangulation
// has been moved (twice over), the signpost invariant holds, Gauss–Bonnet and the area are unchanged, and each moved
// vertex's re-traced input location is where an independent computation puts it — on the flat torus and the sphere
// the known embedding (the located point reproduces the distances to all its neighbours and the length of the move),
// on the hyperbolic surface the move and its inverse (the location comes back). Refused moves change nothing; input
// and boundary vertices are never offered for relocation.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/vertex_relocation.h"
#include "support/refine_test_surfaces.h"
#include "support/gauss_bonnet_bound.h"

using namespace conformesh;
using namespace conformesh::refine;
using namespace conformesh::refine::testing;
using intrinsic::IntrinsicTriangulation;

namespace {

// The move used throughout: 40% of the way from v toward the centroid of star triangle (v mod degree). It lies in that
// triangle; it is a valid position only when it is also in the kernel of the star polygon, so some moves are refused.
Vec3 trialPoint(const BackgroundModel& model, const VertexStar& star) {
  const int d = static_cast<int>(star.ring.size()), i = star.vertex % d;
  const Vec3 O = BackgroundModel::origin();
  const Vec3 c = model.normalize(O + star.ring[i] + star.ring[(i + 1) % d]);
  return model.normalize(O + 0.4 * (c - O));
}

struct MoveLog {
  int moved = 0, refused = 0;
  std::vector<int> vertex;
  std::vector<double> distance;  // length of each move (background distance)
};

// The largest |distance between a moved vertex's old and new located points − the move's length| over the moves of
// `log`, by the surface's closed-form distance (one move per vertex per round; neighbours moved later do not change
// v's location).
template <class Surface>
double worstMoveLengthError(const Surface& surface, const std::vector<InputLocation>& before,
                            const std::vector<InputLocation>& after, const MoveLog& log) {
  double worst = 0;
  for (size_t k = 0; k < log.vertex.size(); ++k) {
    const int v = log.vertex[k];
    worst = std::max(worst, std::abs(surface.distance(before[v], after[v]) - log.distance[k]));
  }
  return worst;
}

// Moves every free vertex once by trialPoint, checking that a refused move changes nothing.
MoveLog moveAll(RefineResult& r, const InputSurface& input) {
  const int n0 = input.triangulation().mesh.nVertices();
  const BackgroundModel model(r.triangulation.background);
  MoveLog log;
  for (int v = n0; v < r.triangulation.mesh.nVertices(); ++v) {
    const std::optional<VertexStar> star = layoutStar(r.triangulation, r.signposts, v, n0);
    if (!star) continue;
    const Vec3 p = trialPoint(model, *star);
    const std::vector<double> lengths = r.triangulation.edgeLengths, angles = r.signposts.angle;
    const InputLocation loc = r.locations[v];
    if (relocateVertex(r.triangulation, r.signposts, r.locations, input, *star, p)) {
      ++log.moved;
      log.vertex.push_back(v);
      log.distance.push_back(model.distance(BackgroundModel::origin(), p));
    } else {
      ++log.refused;
      CHECK(r.triangulation.edgeLengths == lengths);
      CHECK(r.signposts.angle == angles);
      CHECK(r.locations[v].face == loc.face);
      CHECK(r.locations[v].bary == loc.bary);
    }
  }
  return log;
}

// `sums`: the angle sums before the moves. A move inside the star's kernel keeps every vertex's angle sum (the moved
// vertex stays a regular point, its neighbours' corners re-partition the same wedges), hence every angle deficit —
// the curvature measure — and Gauss–Bonnet.
void checkIntrinsic(const IntrinsicTriangulation& in, const RefineResult& r, const std::vector<double>& sums) {
  const IntrinsicTriangulation& t = r.triangulation;
  REQUIRE_NOTHROW(intrinsic::validateLengths(t, "relocated"));
  CHECK(signpostDefect(t, r.signposts) < 1e-9);
  const std::vector<double> now = intrinsic::angleSums(t);
  double worst = 0;
  for (size_t v = 0; v < sums.size(); ++v) worst = std::max(worst, std::abs(now[v] - sums[v]));
  CHECK(worst < 1e-9);
  CHECK(std::abs(intrinsic::curvatureTotals(t).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(t.mesh.nFaces()));
  // Closed surfaces: moving a vertex inside its star keeps the star's union, so the area is unchanged.
  CHECK(intrinsic::totalArea(t) == Approx(intrinsic::totalArea(in)).epsilon(1e-11));
}

RefineResult refined(const IntrinsicTriangulation& in, double eps) {
  RefineOptions o;
  o.epsilon = eps;
  return refineDelaunay(in, o);
}

}  // namespace

TEST_CASE("flat torus: relocated vertices land where the embedding puts them") {
  const FlatTorus torus = flatTorus({1, 0}, {0.37, 0.61}, 5);
  RefineResult r = refined(torus.tri, 0.03);
  const InputSurface input(torus.tri);
  const int n0 = torus.tri.mesh.nVertices();
  REQUIRE(r.triangulation.mesh.nVertices() > n0 + 200);
  for (int round = 0; round < 2; ++round) {
    const std::vector<InputLocation> before = r.locations;
    const std::vector<double> sums = intrinsic::angleSums(r.triangulation);
    const MoveLog log = moveAll(r, input);
    INFO("round " << round << ": moved " << log.moved << ", refused " << log.refused);
    CHECK(log.moved > 2 * log.refused);
    checkIntrinsic(torus.tri, r, sums);
    // The length of each move, measured between the old and the new located points.
    CHECK(worstMoveLengthError(torus, before, r.locations, log) < 1e-10);
    // Every edge's length equals the torus distance between the located endpoints: each moved vertex is at the
    // distances its new lengths say from all its neighbours (which fixes the point) — the embedding's answer.
    CHECK(worstLocatedLengthError(torus, r.triangulation, r.locations) < 1e-10);
  }
}

TEST_CASE("sphere: relocated vertices lie at the great-circle distances of their new edges") {
  const SphereSurface s = sphere(1);
  RefineResult r = refined(s.tri, 0.1);
  const InputSurface input(s.tri);
  for (int round = 0; round < 2; ++round) {
    const std::vector<InputLocation> before = r.locations;
    const std::vector<double> sums = intrinsic::angleSums(r.triangulation);
    const MoveLog log = moveAll(r, input);
    INFO("round " << round << ": moved " << log.moved << ", refused " << log.refused);
    CHECK(log.moved > 2 * log.refused);
    checkIntrinsic(s.tri, r, sums);
    CHECK(worstMoveLengthError(s, before, r.locations, log) < 1e-10);
    CHECK(worstLocatedLengthError(s, r.triangulation, r.locations) < 1e-10);
  }
}

TEST_CASE("hyperbolic genus-2 surface: a move and its inverse restore location, lengths and signposts") {
  const OctagonSurface s = genus2Octagon();
  RefineResult r = refined(s.tri, 0.3);
  const InputSurface input(s.tri);
  const int n0 = s.tri.mesh.nVertices();
  const BackgroundModel model(intrinsic::Background::Hyperbolic);
  int roundTrips = 0, interior = 0;
  double worstBary = 0, worstLength = 0, worstAngle = 0;
  for (int v = n0; v < r.triangulation.mesh.nVertices(); ++v) {
    const std::optional<VertexStar> star = layoutStar(r.triangulation, r.signposts, v, n0);
    if (!star) continue;
    const std::vector<double> lengths = r.triangulation.edgeLengths, angles = r.signposts.angle;
    const InputLocation loc = r.locations[v];
    const Vec3 p = trialPoint(model, *star);
    if (!relocateVertex(r.triangulation, r.signposts, r.locations, input, *star, p)) continue;
    CHECK(signpostDefect(r.triangulation, r.signposts) < 1e-9);
    // The old position, in the moved star's layout: the point at distance |Op| back along the arrival direction.
    const std::optional<VertexStar> moved = layoutStar(r.triangulation, r.signposts, v, n0);
    REQUIRE(moved);
    std::vector<double> d;
    for (const Vec3& u : star->ring) d.push_back(model.distance(BackgroundModel::origin(), u));
    // The old point is the one at the old lengths from the (fixed) neighbours: X and Xalt are the two points at the
    // old lengths from the first two in the new layout, the old length to the third picks one.
    const Vec3 &A = moved->ring[0], &B = moved->ring[1];
    const double ab = model.distance(A, B);
    const double angleAtA = intrinsic::angleOpposite(intrinsic::Background::Hyperbolic, d[1], ab, d[0]);
    const Vec3 X = model.thirdVertex(A, B, -angleAtA, d[0]);
    const Vec3 Xalt = model.thirdVertex(A, B, angleAtA, d[0]);
    const Vec3& back =
        std::abs(model.distance(X, moved->ring[2]) - d[2]) < std::abs(model.distance(Xalt, moved->ring[2]) - d[2])
            ? X
            : Xalt;
    REQUIRE(relocateVertex(r.triangulation, r.signposts, r.locations, input, *moved, back));
    ++roundTrips;
    for (size_t e = 0; e < lengths.size(); ++e)
      worstLength = std::max(worstLength, std::abs(r.triangulation.edgeLengths[e] - lengths[e]));
    // A vertex inserted on an input edge (a zero coordinate) may come back in the face across it, whose frame
    // differs; location and signposts are compared for vertices strictly inside an input face.
    if (!(loc.bary.minCoeff() > 1e-9)) continue;
    ++interior;
    worstBary =
        r.locations[v].face == loc.face ? std::max(worstBary, (r.locations[v].bary - loc.bary).norm()) : INFINITY;
    for (size_t h = 0; h < angles.size(); ++h)
      worstAngle = std::max(worstAngle, std::abs(std::remainder(r.signposts.angle[h] - angles[h], 2 * M_PI)));
  }
  INFO("round trips " << roundTrips << ", from inside an input face " << interior);
  CHECK(roundTrips > 20);
  CHECK(interior > 20);
  CHECK(worstBary < 1e-10);
  CHECK(worstLength < 1e-10);
  CHECK(worstAngle < 1e-9);
  // And a full round of moves keeps the invariants.
  const std::vector<double> sums = intrinsic::angleSums(r.triangulation);
  const MoveLog log = moveAll(r, input);
  CHECK(log.moved > 2 * log.refused);
  checkIntrinsic(s.tri, r, sums);
}

TEST_CASE("input and boundary vertices are not offered; positions outside the star's kernel are refused") {
  const DiskSurface s = disk(3);
  RefineResult r = refined(s.tri, 0.1);
  const int n0 = s.tri.mesh.nVertices();
  const auto& m = r.triangulation.mesh;
  for (int v = 0; v < n0; ++v) CHECK_FALSE(layoutStar(r.triangulation, r.signposts, v, n0));
  int boundary = 0, free = 0;
  const InputSurface input(s.tri);
  for (int v = n0; v < m.nVertices(); ++v) {
    if (m.isBoundaryVertex(v)) {
      ++boundary;
      CHECK_FALSE(layoutStar(r.triangulation, r.signposts, v, n0));
      continue;
    }
    const std::optional<VertexStar> star = layoutStar(r.triangulation, r.signposts, v, n0);
    REQUIRE(star);
    ++free;
    // The neighbour itself, and a point beyond it, fold the star.
    const Vec3 far = BackgroundModel::origin() + 1.5 * (star->ring[0] - BackgroundModel::origin());
    CHECK_FALSE(isValidStarPosition(r.triangulation, *star, star->ring[0]));
    CHECK_FALSE(isValidStarPosition(r.triangulation, *star, far));
    const std::vector<double> lengths = r.triangulation.edgeLengths;
    CHECK_FALSE(relocateVertex(r.triangulation, r.signposts, r.locations, input, *star, far));
    CHECK(r.triangulation.edgeLengths == lengths);
    // Staying in place is not a move.
    CHECK_FALSE(relocateVertex(r.triangulation, r.signposts, r.locations, input, *star, BackgroundModel::origin()));
  }
  CHECK(boundary > 10);
  CHECK(free > 50);
  // Disk: moves keep the located points at their edges' lengths (plane positions of the input).
  const MoveLog log = moveAll(r, input);
  CHECK(log.moved > 2 * log.refused);
  CHECK(worstLocatedLengthError(s, r.triangulation, r.locations) < 1e-10);
  CHECK(signpostDefect(r.triangulation, r.signposts) < 1e-9);
}
