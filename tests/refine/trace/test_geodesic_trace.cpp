// Tests for geodesic_trace.h, background_model.h and signposts.h: traced end points against closed forms — straight
// lines on flat tori (end = start + ℓ·e^{iθ} up to the lattice), great circles on the sphere (distance ℓ from the
// start, and the right direction), hyperbolic distances from the octagon's centre — and the model's own identities.
// Issue 5 (a hang on the uniformized cow): circumcentres of 10⁻¹³-sized curved triangles, traces and insertions that
// stop with a ConvergenceError on corrupt input instead of looping, and the cow itself refined to its bounds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "conformesh/refine/trace/input_location.h"
#include "conformesh/refine/trace/signposts.h"
#include "support/refine_test_surfaces.h"

using namespace conformesh;
using namespace conformesh::refine;
using namespace conformesh::refine::testing;

TEST_CASE("background models: distances, exponential map and circumcentres against closed forms") {
  using intrinsic::Background;
  for (Background g : {Background::Euclidean, Background::Spherical, Background::Hyperbolic}) {
    const BackgroundModel m(g);
    const Vec3 o = BackgroundModel::origin();
    for (double r : {1e-9, 1e-3, 0.4, 1.2}) {
      const Vec3 p = m.polar(r, 0.7);
      CHECK(m.distance(o, p) == Approx(r).epsilon(1e-13));
      CHECK(m.angleOf(o, m.tangentToward(o, p)) == Approx(0.7).epsilon(1e-13));
      // Walking back from p toward the origin for r lands on the origin.
      const Vec3 back = m.exp(p, m.tangentToward(p, o), r);
      CHECK((back - o).norm() < 1e-12);
    }
    // Equilateral triangle of side a: circumradius from triangle_geometry's closed form.
    const double a = 0.5;
    const Vec3 A = o, B = m.polar(a, 0), C = m.thirdVertex(A, B, intrinsic::angleOpposite(g, a, a, a), a);
    CHECK(m.distance(B, C) == Approx(a).epsilon(1e-13));
    const auto cc = m.circumcenter(A, B, C);
    REQUIRE(cc);
    CHECK(m.distance(*cc, A) == Approx(intrinsic::circumradius(g, a, a, a)).epsilon(1e-12));
    CHECK(m.distance(*cc, C) == Approx(intrinsic::circumradius(g, a, a, a)).epsilon(1e-12));
    const Eigen::Vector3d bary = m.barycentric(A, B, C, *cc);
    CHECK(bary.sum() == Approx(1.0));
    CHECK((m.fromBarycentric(A, B, C, bary) - *cc).norm() < 1e-13);
  }
  // Three points on a horocycle have no hyperbolic circumcircle.
  const BackgroundModel h(intrinsic::Background::Hyperbolic);
  // Horocycle through the origin of the hyperboloid: points (x, y, z) with z − y = 1 (a null plane section).
  auto horo = [](double x) { return Vec3(x, x * x / 2, 1 + x * x / 2); };
  CHECK_FALSE(h.circumcenter(horo(-1), horo(0), horo(1.5)).has_value());
}

TEST_CASE("on flat tori of skewed lattices a traced geodesic ends at start + length * direction") {
  const FlatTorus torus = flatTorus({1, 0}, {3.3, 0.25}, 4);  // input angles of a few degrees
  const Signposts sp = initialSignposts(torus.tri);
  const BackgroundModel model(torus.tri.background);
  const auto& m = torus.tri.mesh;
  double worst = 0;
  for (int v = 0; v < m.nVertices(); v += 3) {
    // The reference direction of v: its vertexHalfedge, toward the right lattice copy of its tip.
    const int h0 = m.vertexHalfedge(v);
    const std::complex<double> p = torus.position(v);
    const double ref = std::arg(torus.unfoldTip(h0, p) - p);
    for (double theta = 0.05; theta < 2 * M_PI; theta += 0.37)
      for (double len : {0.01, 0.3, 2.0}) {  // 2.0 wraps around the torus several times
        const TraceResult r = traceFromVertex(torus.tri, sp, model, v, theta, len);
        REQUIRE(r.reachedTarget());
        const std::complex<double> got = torus.locate({r.face, r.bary});
        const std::complex<double> want = p + std::polar(len, theta + ref);
        worst = std::max(worst, torus.torusDistance(got, want));
      }
  }
  CHECK(worst < 1e-12);
}

TEST_CASE("on the sphere a traced geodesic ends at the point exp_v(length * direction) of the great circle") {
  const SphereSurface s = sphere(2);
  const Signposts sp = initialSignposts(s.tri);
  const BackgroundModel model(s.tri.background);
  const auto& m = s.tri.mesh;
  double worst = 0;
  for (int v = 0; v < m.nVertices(); v += 7) {
    const Eigen::Vector3d p = s.positions[v];
    const Eigen::Vector3d q = s.positions[m.tip(m.vertexHalfedge(v))];
    const Eigen::Vector3d t0 = (q - p.dot(q) * p).normalized(), t1 = p.cross(t0);
    for (double theta = 0.1; theta < 2 * M_PI; theta += 0.5)
      for (double len : {0.02, 0.7, 2.5}) {
        const TraceResult r = traceFromVertex(s.tri, sp, model, v, theta, len);
        const Eigen::Vector3d got = s.locate({r.face, r.bary});
        const Eigen::Vector3d want = std::cos(len) * p + std::sin(len) * (std::cos(theta) * t0 + std::sin(theta) * t1);
        worst = std::max(worst, (got - want).norm());
      }
  }
  CHECK(worst < 1e-12);
}

TEST_CASE("on the genus-2 octagon surface, geodesics from the centre end at hyperbolic distance = length") {
  const OctagonSurface s = genus2Octagon();
  const InputSurface in(s.tri);
  const BackgroundModel& model = in.model();
  double worst = 0;
  for (double theta = 0.05; theta < 2 * M_PI; theta += 0.3)
    for (double len : {0.01, 0.5, 1.4}) {  // below the inradius 1.528: inside the octagon
      const InputSurface::Arrival a = in.follow(0, true, {}, theta, len);
      REQUIRE(s.tri.mesh.faceVertex(a.location.face, 0) == 0);
      const auto C = layoutFace(s.tri, model, a.location.face);
      const Vec3 p = model.fromBarycentric(C[0], C[1], C[2], a.location.bary);
      worst = std::max(worst, std::abs(model.distance(BackgroundModel::origin(), p) - len));
      // Radial geodesic: it arrives pointing away from the centre.
      const double away = model.angleOf(p, -model.tangentToward(p, BackgroundModel::origin()));
      worst = std::max(worst, std::abs(std::remainder(a.angle - away, 2 * M_PI)));
    }
  CHECK(worst < 1e-11);
}

TEST_CASE("signposts survive flips: consecutive directions differ by corner angles") {
  FlatTorus torus = flatTorus({1, 0}, {3.3, 0.25}, 4);
  Signposts sp = initialSignposts(torus.tri);
  int flips = 0;
  for (int e = 0; e < torus.tri.mesh.nEdges(); ++e) flips += flipWithSignposts(torus.tri, sp, e);
  REQUIRE(flips > 0);
  const auto& m = torus.tri.mesh;
  double worst = 0;
  for (int h = 0; h < m.nHalfedges(); ++h) {
    const int g = m.nextOutgoing(h);
    worst = std::max(worst, std::abs(std::remainder(sp.angle[g] - sp.angle[h] - intrinsic::cornerAngle(torus.tri, h),
                                                    sp.period[m.tail(h)])));
  }
  CHECK(worst < 1e-12);
}

// === issue 5: `conformesh remesh cow.off --eps 0.015` never finished. The uniformized cow has spherical edges down to
// 2·10⁻¹³; a spherical circumcentre computed as the normal of the plane through three unit vectors near the origin
// (0, 0, 1) — whose stored z = 1 − O(r²) carries no information at r ≲ 10⁻⁸ — landed on a corner, the insertion made a
// zero-length edge, the new vertex's signposts were NaN, findWedge matched no wedge and traceFromVertex took the
// interior vertex for a boundary one and walked its closed fan forever.

TEST_CASE("circumcentres, distances and tangents of tiny triangles in curved models keep full relative accuracy") {
  using intrinsic::Background;
  for (Background g : {Background::Spherical, Background::Hyperbolic}) {
    const BackgroundModel m(g);
    // An obtuse needle like the cow's (sides 1.86, 0.78, 1.08 in units s), laid out from a corner at the origin as
    // the refinement does, and the same triangle laid out 10⁻³ away from the origin (a trace away from its start).
    for (double s : {1e-4, 1e-8, 1e-10, 1e-13}) {
      const double a = 1.857 * s, b = 0.782 * s, c = 1.080 * s;  // |BC| = a, |CA| = b, |AB| = c
      const double R = intrinsic::circumradius(g, a, b, c);
      for (double offset : {0.0, 1e-3}) {
        const Vec3 A = offset == 0 ? BackgroundModel::origin() : m.polar(offset, 0.3);
        const Vec3 B = m.exp(A, m.direction(A, 0.1), c);
        const Vec3 C = m.thirdVertex(A, B, intrinsic::angleOpposite(g, a, b, c), b);
        // Round-off of the layout itself, relative to s: coordinates of size ~offset carry an absolute error of a few
        // ulps of offset, i.e. ~u·offset/s relative (measured ≤ 4·u·offset/s); at the origin, a few ulps (measured
        // ≤ 1e-14). The plain chord formulas were off by ~u/s² relative: 0.11 at s = 1e-8, 100% below.
        const double tol = 1e-12 + 32 * 2.2e-16 * offset / s;
        CHECK(std::abs(m.distance(B, C) - a) <= tol * a);
        const auto cc = m.circumcenter(A, B, C);
        REQUIRE(cc);
        INFO("background " << intrinsic::toString(g) << ", s = " << s << ", offset " << offset);
        for (const Vec3& X : {A, B, C}) CHECK(std::abs(m.distance(*cc, X) - R) <= tol * R);
        // The tangent toward a close point is a unit tangent (orthogonal to the point in the model's inner product).
        const Vec3 t = m.tangentToward(A, B);
        CHECK(std::abs(m.norm(t) - 1) < 1e-12);
        const double ortho = g == Background::Spherical ? t.dot(A) : -m.inner(t, A);
        CHECK(std::abs(ortho) < 1e-12);
      }
    }
  }
}

TEST_CASE("a trace from an interior vertex with a NaN direction or corrupt signposts stops with an error naming it") {
  const SphereSurface sph = sphere(1);
  const BackgroundModel model(sph.tri.background);
  Signposts sp = initialSignposts(sph.tri);
  const int v = 5;
  // Before the fix both calls walked v's closed fan looking for a boundary edge, forever.
  CHECK_THROWS_WITH(traceFromVertex(sph.tri, sp, model, v, std::nan(""), 0.1),
                    Catch::Contains("vertex 5") && Catch::Contains("not finite"));
  const auto& m = sph.tri.mesh;
  int h = m.vertexHalfedge(v);
  do {
    sp.angle[h] = std::nan("");
    h = m.nextOutgoing(h);
  } while (h != m.vertexHalfedge(v));
  CHECK_THROWS_AS(traceFromVertex(sph.tri, sp, model, v, 0.5, 0.1), ConvergenceError);
  CHECK_THROWS_WITH(traceFromVertex(sph.tri, sp, model, v, 0.5, 0.1),
                    Catch::Contains("interior vertex 5") && Catch::Contains("no corner"));
}

TEST_CASE("inserting a vertex with a zero-length edge is refused before the mesh changes") {
  const SphereSurface sph = sphere(1);
  intrinsic::IntrinsicTriangulation tri = sph.tri;
  Signposts sp = initialSignposts(tri);
  const int nV = tri.mesh.nVertices();
  const double l = tri.length(0);
  CHECK_THROWS_WITH(splitFaceWithSignposts(tri, sp, 3, {0.0, l, l}, 0.0),
                    Catch::Contains("face 3") && Catch::Contains("length 0"));
  CHECK(tri.mesh.nVertices() == nV);
  CHECK_THROWS_WITH(splitEdgeWithSignposts(tri, sp, 7, 0.0, l, l, l, 0.0, 0.0),
                    Catch::Contains("edge 7") && Catch::Contains("length 0"));
  CHECK(tri.mesh.nVertices() == nV);
}

TEST_CASE("uniformized cow, spherical edges down to 1e-13: refinement terminates within its bounds") {
  const intrinsic::IntrinsicTriangulation cow =
      intrinsic::toTriangulation(intrinsic::readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/cow.off"));
  const intrinsic::Uniformization u = intrinsic::uniformize(cow);
  REQUIRE(u.uniform.background == intrinsic::Background::Spherical);
  const double shortest = *std::min_element(u.uniform.edgeLengths.begin(), u.uniform.edgeLengths.end());
  CHECK(shortest < 1e-11);  // the regime of the fault
  const double B = std::sqrt(2.0);
  // ε = 5 (shape only, the smallest reproducer) and ε = 0.015, graded by the cow's conformal factor as `remesh` does.
  for (double eps : {5.0, 0.015}) {
    INFO("epsilon " << eps);
    RefineOptions opt;
    opt.epsilon = eps;
    opt.lambda = u.lambda;
    opt.maxInsertions = 100000;  // ~2 200 are needed; a runaway stops here instead of hanging the test
    const RefineResult r = refineDelaunay(u.uniform, opt);
    const auto& T = r.triangulation;
    CHECK(T.mesh.nVertices() > u.uniform.mesh.nVertices());
    CHECK(intrinsic::countNonDelaunayEdges(T, 1e-12) == 0);
    double worstRatio = 0, smallestAngle = INFINITY;
    for (int f = 0; f < T.mesh.nFaces(); ++f) {
      const double l0 = T.length(3 * f), l1 = T.length(3 * f + 1), l2 = T.length(3 * f + 2);
      REQUIRE(intrinsic::isValidTriangle(T.background, l0, l1, l2));
      worstRatio = std::max(worstRatio, intrinsic::faceCircumradius(T, f) / std::min({l0, l1, l2}));
      for (int k = 0; k < 3; ++k) smallestAngle = std::min(smallestAngle, intrinsic::cornerAngle(T, 3 * f + k));
    }
    CHECK(worstRatio <= B * (1 + 1e-9));
    CHECK(smallestAngle >= std::asin(1 / (2 * B)) - 1e-9);
    // Gauss–Bonnet on the unit sphere: total area 4π is kept by refinement.
    CHECK(intrinsic::totalArea(T) == Approx(4 * M_PI).epsilon(1e-10));
    for (double s : r.signposts.angle) REQUIRE(std::isfinite(s));
    // Input locations at every scale (edges from 0.3 down to 1e-12): an edge whose two ends lie in the same input face
    // has the length of the segment between the located points in that face's layout. Measured worst 1.8e-13 (ε = 5)
    // and 4.8e-13 (ε = 0.015) relative; 3.4e-11 at ε = 0.005 (39 000 such edges, not in the test).
    const BackgroundModel model(u.uniform.background);
    double worstLocation = 0, shortestChecked = INFINITY;
    for (int e = 0; e < T.mesh.nEdges(); ++e) {
      const int h = T.mesh.edgeHalfedge(e);
      const InputLocation &La = r.locations[T.mesh.tail(h)], &Lb = r.locations[T.mesh.tip(h)];
      if (La.face != Lb.face) continue;
      const std::array<Vec3, 3> C = layoutFace(u.uniform, model, La.face);
      const double d = model.distance(model.fromBarycentric(C[0], C[1], C[2], La.bary),
                                      model.fromBarycentric(C[0], C[1], C[2], Lb.bary));
      worstLocation = std::max(worstLocation, std::abs(d - T.edgeLengths[e]) / T.edgeLengths[e]);
      shortestChecked = std::min(shortestChecked, T.edgeLengths[e]);
    }
    CHECK(shortestChecked < 1e-11);
    CHECK(worstLocation < 1e-9);
  }
}

// The pull-back's walk (TraceOptions): crossings collected in order on the segment, the corner-angle unfolding giving
// the same end point, and a direction just outside a boundary vertex's fan followed along the nearer boundary edge.
TEST_CASE("trace options: edge crossings lie on the segment in order, and outward directions follow the boundary") {
  const DiskSurface s = disk(4);
  const InputSurface surface(s.tri);  // the disk's own signposts and model
  const Signposts& sp = surface.signposts();
  const BackgroundModel& model = surface.model();
  const intrinsic::HalfedgeMesh& m = s.tri.mesh;
  int interior = 0;
  while (m.isBoundaryVertex(interior)) ++interior;
  std::vector<EdgeCrossing> crossings;
  TraceOptions options;
  options.unfolding = Unfolding::CornerAngle;
  options.crossings = &crossings;
  for (double theta = 0.1; theta < 2 * M_PI; theta += 0.7) {
    crossings.clear();
    const TraceResult plain = traceFromVertex(s.tri, sp, model, interior, theta, 0.6);
    const TraceResult r = traceFromVertex(s.tri, sp, model, interior, theta, 0.6, intrinsic::kInvalid, options);
    REQUIRE(r.reachedTarget());
    CHECK((s.locate({r.face, r.bary}) - s.locate({plain.face, plain.bary})).norm() < 1e-12);
    REQUIRE(r.startHalfedge != intrinsic::kInvalid);
    CHECK(m.tail(r.startHalfedge) == interior);
    CHECK(static_cast<int>(crossings.size()) == r.steps - 1);
    const Eigen::Vector2d a = s.positions[interior], b = s.locate({r.face, r.bary});
    const Eigen::Vector2d u = (b - a).normalized();
    int face = intrinsic::HalfedgeMesh::face(r.startHalfedge);
    double along = 0;
    for (const EdgeCrossing& c : crossings) {
      CHECK(intrinsic::HalfedgeMesh::face(c.halfedge) == face);
      CHECK(c.bary[(c.halfedge % 3 + 2) % 3] == 0);
      CHECK(c.bary.sum() == Approx(1.0));
      const Eigen::Vector2d x = s.locate({face, c.bary}) - a;
      CHECK(std::abs(u.x() * x.y() - u.y() * x.x()) < 1e-12);  // on the line
      CHECK(x.dot(u) >= along);                                // in order
      along = x.dot(u);
      face = intrinsic::HalfedgeMesh::face(m.twin(c.halfedge));
    }
    CHECK(face == r.face);
  }
  // A boundary vertex of the ring disk: a direction 0.01 rad before its first outgoing (boundary) halfedge.
  int v = 0;
  while (!m.isBoundaryVertex(v)) ++v;
  const int hOut = m.vertexHalfedge(v);
  const double theta = sp.angle[hOut] - 0.01, len = 0.5 * s.tri.length(hOut);
  const TraceResult left = traceFromVertex(s.tri, sp, model, v, theta, len);
  CHECK_FALSE(left.reachedTarget());
  options.outward = OutwardDirection::FollowBoundary;
  options.crossings = nullptr;
  const TraceResult followed = traceFromVertex(s.tri, sp, model, v, theta, len, intrinsic::kInvalid, options);
  REQUIRE(followed.reachedTarget());
  CHECK(followed.startHalfedge == hOut);
  const Eigen::Vector2d want =
      s.positions[v] + len * (s.positions[m.tip(hOut)] - s.positions[v]).normalized();
  CHECK((s.locate({followed.face, followed.bary}) - want).norm() < 1e-12);
}

TEST_CASE("interpolatePositions: barycentric combinations of the corners, nothing without positions") {
  const DiskSurface s = disk(2);
  std::vector<Eigen::Vector3d> positions;
  for (const Eigen::Vector2d& p : s.positions) positions.emplace_back(p.x(), p.y(), 0.5 * p.x());
  const std::vector<InputLocation> at = {{0, {1, 0, 0}}, {3, {0.2, 0.3, 0.5}}, {5, {-0.1, 0.6, 0.5}}};
  CHECK(interpolatePositions(s.tri.mesh, {}, at).empty());
  const std::vector<Eigen::Vector3d> got = interpolatePositions(s.tri.mesh, positions, at);
  REQUIRE(got.size() == at.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    const Eigen::Vector2d p = s.locate(at[i]);
    CHECK((got[i] - Eigen::Vector3d(p.x(), p.y(), 0.5 * p.x())).norm() < 1e-14);
  }
  CHECK((got[0] - positions[s.tri.mesh.faceVertex(0, 0)]).norm() == 0);
}
