// Tests for geodesic_trace.h, background_model.h and signposts.h: traced end points against closed forms — straight
// lines on flat tori (end = start + ℓ·e^{iθ} up to the lattice), great circles on the sphere (distance ℓ from the
// start, and the right direction), hyperbolic distances from the octagon's centre — and the model's own identities.
#include <catch2/catch.hpp>

#include <cmath>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/geodesic_trace.h"
#include "conformesh/refine/input_location.h"
#include "conformesh/refine/signposts.h"
#include "refine_test_surfaces.h"

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
