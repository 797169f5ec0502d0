// Tests for vertex_smoothing.h, one pass called directly on refined triangulations: it moves vertices, never lowers
// the smallest angle (each move keeps its star's), keeps every triangle within the size and shape bounds it was asked
// to keep, leaves no boundary edge encroached, raises the mean smallest angle, and keeps the input locations and
// signposts right (sphere: great-circle distances between the located points; disk: plane distances). Bad rule names
// and a negative pass count are rejected with messages naming the value.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/delaunay/vertex_smoothing.h"
#include "support/refine_test_surfaces.h"
#include "support/gauss_bonnet_bound.h"

using namespace conformesh;
using namespace conformesh::refine;
using namespace conformesh::refine::testing;
using intrinsic::IntrinsicTriangulation;

namespace {}  // namespace

TEST_CASE("one pass on the sphere: bounds kept, smallest angle kept, mean raised, locations right") {
  const SphereSurface s = sphere(1);
  RefineOptions o;
  o.epsilon = 0.06;
  RefineResult r = refineDelaunay(s.tri, o);
  const InputSurface input(s.tri);
  const QualityReport before = measureQuality(r.triangulation);
  SmoothingOptions so;
  so.epsilon = o.epsilon;
  so.ratioBound = o.ratioBound;
  for (SmoothingRule rule : {SmoothingRule::OptimalDelaunay, SmoothingRule::Centroid}) {
    so.rule = rule;
    INFO(toString(rule));
    const QualityReport q0 = measureQuality(r.triangulation);
    const SmoothingStatistics st =
        smoothFreeVertices(r.triangulation, r.signposts, r.locations, r.lambda, s.tri.mesh.nVertices(), input, {}, so);
    const QualityReport q = measureQuality(r.triangulation);
    INFO("moved " << st.moved << " of " << st.candidates << "; mean smallest angle " << q0.meanMinAngleDeg << " -> "
                  << q.meanMinAngleDeg << ", smallest " << q0.minAngleDeg << " -> " << q.minAngleDeg);
    CHECK(st.candidates == r.triangulation.mesh.nVertices() - s.tri.mesh.nVertices());
    CHECK(st.moved > st.candidates / 4);
    CHECK(st.moved + st.invalid + st.rejected == st.candidates);
    // 1e-12 rad of round-off in the angles from lengths.
    CHECK(q.minAngleDeg >= q0.minAngleDeg - 1e-10);
    CHECK(q.meanMinAngleDeg > q0.meanMinAngleDeg);
    // λ ≡ 0: the size test of the pass is the exact bound.
    CHECK(q.maxCircumradius <= o.epsilon * (1 + 1e-9));
    CHECK(q.maxRadiusEdgeRatio <= o.ratioBound * (1 + 1e-9));
    CHECK(std::abs(q.gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(q.triangles));
    CHECK(signpostDefect(r.triangulation, r.signposts) < 1e-9);
    CHECK(worstLocatedLengthError(s, r.triangulation, r.locations) < 1e-10);
  }
  CHECK(measureQuality(r.triangulation).meanMinAngleDeg > before.meanMinAngleDeg + 1);
}

TEST_CASE("one pass on a graded disk: no boundary edge becomes encroached, λ follows the moved vertices") {
  const DiskSurface d = disk(3);
  RefineOptions o;
  o.epsilon = 0.1;
  for (const auto& p : d.positions) o.lambda.push_back(0.8 * p.x());
  RefineResult r = refineDelaunay(d.tri, o);
  const InputSurface input(d.tri);
  SmoothingOptions so;
  so.epsilon = o.epsilon;
  const SmoothingStatistics st = smoothFreeVertices(r.triangulation, r.signposts, r.locations, r.lambda,
                                                    d.tri.mesh.nVertices(), input, o.lambda, so);
  CHECK(st.moved > 20);
  const auto& m = r.triangulation.mesh;
  double worstApex = 0, worstLambda = 0, worstLength = 0;
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    if (m.twin(h) == intrinsic::kInvalid)
      worstApex = std::max(worstApex, intrinsic::cornerAngle(r.triangulation, intrinsic::HalfedgeMesh::prev(h)));
    worstLength =
        std::max(worstLength, std::abs((d.locate(r.locations[m.tail(h)]) - d.locate(r.locations[m.tip(h)])).norm() -
                                       r.triangulation.edgeLengths[e]));
  }
  for (int v = 0; v < m.nVertices(); ++v)
    worstLambda = std::max(worstLambda, std::abs(r.lambda[v] - 0.8 * d.locate(r.locations[v]).x()));
  CHECK(worstApex <= M_PI / 2 + 1e-10);
  CHECK(worstLambda < 1e-12);  // λ is linear, so its interpolant at the new locations is exact
  CHECK(worstLength < 1e-10);
  CHECK(signpostDefect(r.triangulation, r.signposts) < 1e-9);
}

TEST_CASE("bad smoothing parameters are rejected with messages naming the value") {
  CHECK(parseSmoothingRule("odt") == SmoothingRule::OptimalDelaunay);
  CHECK(parseSmoothingRule(toString(SmoothingRule::Centroid)) == SmoothingRule::Centroid);
  CHECK_THROWS_WITH(parseSmoothingRule("laplace"), Catch::Contains("'laplace'") && Catch::Contains("odt, centroid"));
  const SphereSurface s = sphere(0);
  RefineOptions o;
  o.epsilon = 0.5;
  o.smoothingPasses = -2;
  CHECK_THROWS_AS(refineDelaunay(s.tri, o), InputError);
  CHECK_THROWS_WITH(refineDelaunay(s.tri, o), Catch::Contains("smoothingPasses") && Catch::Contains("-2"));
}
