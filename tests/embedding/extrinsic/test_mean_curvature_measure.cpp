// test_mean_curvature_measure.cpp — paper eq. 2 against ∫(κ₁ + κ₂) dA: the pieces in closed form (chord of a ball,
// signed dihedral angle), the smooth side on the sphere (ball ∩ sphere is a cap of area πr², so ∫ = 2πr²/R; total
// 8πR), and the convergence of e_H on remeshMetric's ellipsoid meshes (Theorem 3.4: order ≥ 1 in the mesh size).
#include <cmath>

#include <catch2/catch.hpp>

#include "conformesh/embedding/extrinsic/mean_curvature_measure.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "support/embedding_test_meshes.h"

using namespace conformesh;
using namespace conformesh::embedding;
using intrinsic::makeMetric;

TEST_CASE("segment inside a ball: closed forms") {
  const Eigen::Vector3d c(1, 2, 3);
  const double r = 0.5;
  // Through the centre, sticking out on both sides: the diameter.
  CHECK(segmentLengthInBall(c - Eigen::Vector3d(2, 0, 0), c + Eigen::Vector3d(1, 0, 0), c, r) ==
        Approx(1.0).epsilon(1e-15));
  // Entirely inside.
  CHECK(segmentLengthInBall(c, c + Eigen::Vector3d(0, 0.3, 0), c, r) == Approx(0.3).epsilon(1e-15));
  // Starting at the centre, leaving: the radius.
  CHECK(segmentLengthInBall(c, c + Eigen::Vector3d(0, 0, 4), c, r) == Approx(0.5).epsilon(1e-15));
  // A chord at distance d from the centre: 2√(r² − d²).
  const double d = 0.3;
  CHECK(segmentLengthInBall(c + Eigen::Vector3d(-1, d, 0), c + Eigen::Vector3d(1, d, 0), c, r) ==
        Approx(2 * std::sqrt(r * r - d * d)).epsilon(1e-14));
  // Missing the ball.
  CHECK(segmentLengthInBall(c + Eigen::Vector3d(-1, 0.6, 0), c + Eigen::Vector3d(1, 0.6, 0), c, r) == 0);
}

TEST_CASE("signed dihedral angle: positive on a convex hinge, negative on a concave one, 0 on the boundary") {
  // Faces (a, b, c) and (b, a, d) with a = 0, b = x̂, c in the xy-plane: n₁ = +z. d below the plane beyond the edge
  // folds the second face down — convex for the +z side — by the angle atan(h).
  const double h = 0.7;
  const auto mesh = intrinsic::HalfedgeMesh::fromFaces({{0, 1, 2}, {1, 0, 3}}, 4);
  std::vector<Eigen::Vector3d> x = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, -h}};
  int interior = -1, boundary = -1;
  for (int e = 0; e < mesh.nEdges(); ++e) (mesh.isBoundaryEdge(e) ? boundary : interior) = e;
  CHECK(signedDihedralAngle(mesh, x, interior) == Approx(std::atan(h)).epsilon(1e-14));
  x[3].z() = h;
  CHECK(signedDihedralAngle(mesh, x, interior) == Approx(-std::atan(h)).epsilon(1e-14));
  CHECK(signedDihedralAngle(mesh, x, boundary) == 0);
}

TEST_CASE("sphere: the smooth ball measures are 2πr²/R and the totals 8πR") {
  const double R = 1.5;
  const auto m = makeMetric("sphere", {{"R", R}});
  const EmbeddedSurface s(*m);
  const auto p = testing::discretizedMesh(*m, 8);
  const auto r = meanCurvatureMeasure(p.tri, p.positions, p.reference, s);
  CHECK(r.radius == Approx(0.08 * std::sqrt([&] {
                             double a = 0;
                             for (int f = 0; f < p.tri.mesh.nFaces(); ++f) {
                               const auto& x0 = p.positions[p.tri.mesh.faceVertex(f, 0)];
                               a += 0.5 * (p.positions[p.tri.mesh.faceVertex(f, 1)] - x0)
                                              .cross(p.positions[p.tri.mesh.faceVertex(f, 2)] - x0)
                                              .norm();
                             }
                             return a;
                           }())));
  // The smooth total is the image of the whole mesh: ∫ 2/R dA over the sphere, to the degree-2 rule's accuracy.
  CHECK(r.smoothTotal == Approx(8 * M_PI * R).epsilon(1e-6));
  // The discrete total Σ|e|β tends to it at O(ε²) (here ε ≈ 0.13 R).
  CHECK(r.discreteTotal == Approx(8 * M_PI * R).epsilon(0.01));
  const double cap = 2 * M_PI * r.radius * r.radius / R;
  double worst = 0;
  for (int v = 0; v < p.tri.mesh.nVertices(); ++v) {
    worst = std::max(worst, std::abs(r.smooth[v] / cap - 1));
    CHECK(r.absoluteScale[v] == Approx(r.smooth[v]).epsilon(1e-12));  // H > 0 everywhere
  }
  INFO("worst relative error of the smooth ball measure: " << worst);
  CHECK(worst < 1e-3);  // the rim's linear clipping: O((ε/2)²/r²)
  // Eq. 2 against the smooth measure: a few percent at this resolution.
  CHECK(r.meanRelativeError < 0.05);
  int total = 0;
  for (int c : r.histogram) total += c;
  CHECK(total == p.tri.mesh.nVertices());
}

TEST_CASE("ellipsoid, remeshMetric at five sizes: e_H falls at least linearly in the mesh size") {
  const auto m = makeMetric("ellipsoid", {{"f", 0.3}});
  const EmbeddedSurface s(*m);
  std::vector<double> h, eH, rel, totalError;
  // ∫(κ₁ + κ₂) dA over the oblate spheroid with semi-axes a, c: 4π (c + a² arccos(c/a)/√(a² − c²)) (4π × the mean
  // width; for a = c it is 8πa).
  const double a = 1, c = 0.7;
  const double total = 4 * M_PI * (c + a * a * std::acos(c / a) / std::sqrt(a * a - c * c));
  for (double eps : {0.16, 0.12, 0.09, 0.07, 0.055}) {
    refine::RemeshOptions o;
    o.epsilon = eps;
    o.t0Resolution = 4;
    const auto t1 = refine::remeshMetric(*m, o);
    const auto r = meanCurvatureMeasure(t1.mesh, t1.positions, t1.reference, s);
    h.push_back(t1.quality.meanCircumradius);
    eH.push_back(r.meanAbsoluteError);
    rel.push_back(r.meanRelativeError);
    // The triangles' images tile the ellipsoid, so the smooth total is the closed form up to the degree-2 rule's
    // O(h⁴) error (checked by its order below).
    totalError.push_back(std::abs(r.smoothTotal / total - 1));
    CHECK(totalError.back() < 1e-5);
    WARN("ellipsoid V = " << t1.mesh.mesh.nVertices() << ", mean circumradius " << h.back() << ": e_H " << eH.back()
                          << ", mean relative " << rel.back() << ", within ±5%: " << r.fractionWithinBand << ", totals "
                          << r.discreteTotal << " / " << r.smoothTotal);
  }
  const double order = intrinsic::fitLogLogSlope(h, eH);
  WARN("order of e_H against the mean circumradius: " << order);
  CHECK(order >= 0.9);
  CHECK(intrinsic::fitLogLogSlope(h, rel) >= 0.9);
  const double quadratureOrder = intrinsic::fitLogLogSlope(h, totalError);
  WARN("order of the smooth total's quadrature error: " << quadratureOrder);
  CHECK(quadratureOrder > 3);
}

TEST_CASE("bad input is reported") {
  const auto m = makeMetric("sphere", {});
  const EmbeddedSurface s(*m);
  auto p = testing::discretizedMesh(*m, 2);
  auto fewer = p.positions;
  fewer.pop_back();
  CHECK_THROWS_WITH(meanCurvatureMeasure(p.tri, fewer, p.reference, s),
                    Catch::Contains("positions") && Catch::Contains("vertices"));
  auto bad = p.positions;
  bad[5].x() = NAN;
  CHECK_THROWS_WITH(meanCurvatureMeasure(p.tri, bad, p.reference, s), Catch::Contains("vertex 5"));
  MeanCurvatureMeasureOptions o;
  o.subdivision = 9;
  CHECK_THROWS_WITH(meanCurvatureMeasure(p.tri, p.positions, p.reference, s, o), Catch::Contains("subdivision"));
}
