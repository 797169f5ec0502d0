// Tests for gaussian_curvature_measure.h: the smooth side against closed forms (spherical excess, 2πχ), and the
// convergence of the discrete Gaussian curvature measure to the smooth one on discretized metrics, with its order
// measured by a log–log fit (paper Theorem 3.4, eq. 5).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "conformesh/intrinsic/convergence_order.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric_discretization.h"
#include "conformesh/intrinsic/metric_families.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {

struct Discretized {
  IntrinsicTriangulation tri;
  std::vector<Eigen::Vector3d> reference;
  double meanEdge = 0;
};

Discretized discretize(const SmoothMetric& m, int resolution) {
  DiscretizationOptions o;
  o.resolution = resolution;
  MeshData d = discretizeMetric(m, o);
  Discretized out;
  out.tri = toTriangulation(d);
  for (int v = 0; v < d.nVertices; ++v)
    out.reference.push_back(referencePoint(m.domain(), d.vertexProperties.at("u")[v], d.vertexProperties.at("v")[v]));
  for (double l : out.tri.edgeLengths) out.meanEdge += l / out.tri.edgeLengths.size();
  return out;
}

// Least-squares slope of log y against log x.

}  // namespace

TEST_CASE("reference triangles on the round sphere: ∫K dA is the spherical excess") {
  const double R = 2.5;
  const RoundSphereMetric sphere(R);
  // A geodesic triangle of the reference (unit) sphere; on the sphere of radius R, K = 1/R² and dA = R² dA_ref, so
  // ∫K dA = its spherical excess, l'Huilier's formula on its arc lengths.
  const Eigen::Vector3d a = Eigen::Vector3d(1, 0.2, 0.1).normalized(), b = Eigen::Vector3d(0.7, 0.7, 0.3).normalized(),
                        c = Eigen::Vector3d(0.6, 0.1, 0.8).normalized();
  const double excess = triangleArea(Background::Spherical, std::acos(b.dot(c)), std::acos(c.dot(a)), std::acos(a.dot(b)));
  const QuadratureResult q = integrateOverReferenceTriangle(sphere, curvatureDensity(sphere), a, b, c);
  CHECK(q.value == Approx(excess).epsilon(1e-11));
}

TEST_CASE("the triangles' images tile the surface: Σ ∫K dA = 2πχ") {
  const RoundSphereMetric sphere(1.0);
  const EllipsoidMetric ellipsoid(1.0, 0.3);
  const KerrNewmanMetric kerr(1.0, 0.99, 0.0);
  const TorusMetric torus(1.0, 0.4);
  for (const SmoothMetric* m : std::initializer_list<const SmoothMetric*>{&sphere, &ellipsoid, &kerr, &torus}) {
    INFO(m->description());
    const Discretized d = discretize(*m, 12);
    const CurvatureMeasureResult r = gaussianCurvatureMeasure(d.tri, d.reference, *m);
    CHECK(r.smoothTotalCurvature == Approx(2 * M_PI * m->domain().eulerCharacteristic()).margin(1e-9));
  }
}

TEST_CASE("the Gaussian curvature measure converges at first order, with the order fitted") {
  // Discretized metrics (T0) are meshes whose vertices lie on the surface and whose lengths are the metric's. The
  // ellipsoid's chart is conformal, so its T0 is a uniformly well-shaped icosphere: a κ-light ε-sample, the setting of
  // Theorem 3.4, which bounds the error by O(ε). (T0 of a non-conformal chart, e.g. Kerr's θ–φ chart, is not; the
  // refined meshes of such metrics are tested in tests/refine/test_convergence_study.cpp.) Below ~5000 vertices a ball
  // of radius 0.05·√area holds too few vertices for the asymptotics (e_G is not yet monotone), so the fit starts there.
  const EllipsoidMetric ellipsoid(1.0, 0.3);
  const EllipsoidMetric prolate(1.0, -0.5);
  for (const SmoothMetric* m : std::initializer_list<const SmoothMetric*>{&ellipsoid, &prolate}) {
    std::vector<double> h, ball, triangles;
    for (int n : {24, 32, 40, 48}) {
      const Discretized d = discretize(*m, n);
      h.push_back(d.meanEdge);
      ball.push_back(gaussianCurvatureMeasure(d.tri, d.reference, *m).meanAbsoluteError);
      CurvatureMeasureOptions o;
      o.region = MeasureRegion::TriangleUnion;
      triangles.push_back(gaussianCurvatureMeasure(d.tri, d.reference, *m, o).meanAbsoluteError);
    }
    const double slope = fitLogLogSlope(h, ball);
    INFO(m->description() << ": geodesic balls, fitted order " << slope << ", e_G " << ball.front() << " .. "
                          << ball.back() << "; triangle unions, order " << fitLogLogSlope(h, triangles));
    CHECK(slope >= 0.9);
    // Triangle unions carry the one-sided rim term of Theorem 3.4: still decreasing, at a lower pre-asymptotic order.
    for (size_t i = 1; i < triangles.size(); ++i) CHECK(triangles[i] < triangles[i - 1]);
  }
}

TEST_CASE("curvature measure: bad input is named") {
  const RoundSphereMetric sphere(1.0);
  Discretized d = discretize(sphere, 4);
  d.reference.pop_back();
  REQUIRE_THROWS_WITH(gaussianCurvatureMeasure(d.tri, d.reference, sphere),
                      Catch::Contains("one reference point per vertex"));
  Discretized s = discretize(sphere, 4);
  s.tri.background = Background::Spherical;
  REQUIRE_THROWS_WITH(gaussianCurvatureMeasure(s.tri, s.reference, sphere), Catch::Contains("Euclidean"));
  Discretized z = discretize(sphere, 4);
  CurvatureMeasureOptions o;
  o.radiusFraction = 0;
  REQUIRE_THROWS_WITH(gaussianCurvatureMeasure(z.tri, z.reference, sphere, o), Catch::Contains("radius"));
}
