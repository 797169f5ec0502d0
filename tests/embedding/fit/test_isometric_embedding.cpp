// test_isometric_embedding.cpp — Ceres fits of vertex positions to edge lengths: chord lengths of a known convex
// polyhedron are realized to round-off and the polyhedron recovered up to a rigid motion; the ellipsoid's intrinsic
// meshes (remeshMetric, lengths = geodesic lengths) are fitted WITHOUT their true positions, isometric to round-off,
// the Procrustes error against the true surface shrinking with ε; the Kerr horizon embeds at a/M = 0.5 and does not at
// a/M = 0.99 (K < 0 at the poles, Smarr 1973); bad input is refused by name.
#include <cmath>

#include <catch2/catch.hpp>

#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/embedding/fit/procrustes.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "support/embedding_test_meshes.h"

using namespace conformesh;
using namespace conformesh::embedding;
using intrinsic::makeMetric;

namespace {

// The same connectivity with chord lengths |x_i − x_j| of the given positions: exactly realizable.
intrinsic::IntrinsicTriangulation withChordLengths(intrinsic::IntrinsicTriangulation tri,
                                                   const std::vector<Eigen::Vector3d>& x) {
  for (int e = 0; e < tri.mesh.nEdges(); ++e) {
    const int h = tri.mesh.edgeHalfedge(e);
    tri.edgeLengths[e] = (x[tri.mesh.tail(h)] - x[tri.mesh.tip(h)]).norm();
  }
  return tri;
}

}  // namespace

TEST_CASE("chord lengths of a convex polyhedron: recovered up to a rigid motion from the MDS start") {
  const auto m = makeMetric("ellipsoid", {{"f", 0.25}});
  const auto p = testing::discretizedMesh(*m, 6);
  const auto tri = withChordLengths(p.tri, p.positions);
  const auto fit = fitIsometricEmbedding(tri);
  INFO(fit.verdict);
  CHECK(fit.isometric);
  CHECK(fit.start.find("landmark MDS") != std::string::npos);
  CHECK(fit.maxRelativeResidual < 1e-12);
  CHECK(fit.verdict.find("isometric to tolerance") == 0);
  // Cauchy rigidity: the convex polyhedron is determined by its edge lengths, up to a rigid motion and a mirror.
  const auto aligned = alignRigid(fit.positions, p.positions);
  CHECK(aligned.maxError < 1e-9);
}

TEST_CASE("given the true positions as a start, a realizable mesh stays where it is") {
  const auto m = makeMetric("sphere", {});
  const auto p = testing::discretizedMesh(*m, 5);
  const auto tri = withChordLengths(p.tri, p.positions);
  EmbeddingOptions o;
  o.initialPositions = p.positions;
  o.regularizerWeight = 0;
  const auto fit = fitIsometricEmbedding(tri, o);
  CHECK(fit.isometric);
  CHECK(fit.start == "initial positions");
  CHECK(fit.regularizedIterations == 0);
  // No rigid drift either: the start is already a zero of every residual.
  double drift = 0;
  for (std::size_t v = 0; v < p.positions.size(); ++v)
    drift = std::max(drift, (fit.positions[v] - p.positions[v]).norm());
  CHECK(drift < 1e-12);
}

TEST_CASE("ellipsoid meshes fitted without their positions: isometric, Procrustes error shrinking with ε") {
  const auto m = makeMetric("ellipsoid", {{"f", 0.3}});
  std::vector<double> h, procrustes;
  for (double eps : {0.2, 0.13, 0.09, 0.06, 0.045}) {
    refine::RemeshOptions ro;
    ro.epsilon = eps;
    ro.t0Resolution = 4;
    const auto t1 = refine::remeshMetric(*m, ro);
    const auto fit = fitIsometricEmbedding(t1.mesh);
    INFO(fit.verdict);
    CHECK(fit.isometric);
    CHECK(fit.maxRelativeResidual < 1e-12);
    const auto aligned = alignRigid(fit.positions, t1.positions);
    h.push_back(t1.quality.meanCircumradius);
    procrustes.push_back(aligned.rmsError);
    WARN("ellipsoid V = " << t1.mesh.mesh.nVertices() << ", mean circumradius " << h.back() << ": " << fit.verdict
                          << "; " << fit.regularizedIterations << " + " << fit.iterations << " LM iterations, "
                          << fit.fitSeconds << " s; Procrustes RMS " << aligned.rmsError << ", max "
                          << aligned.maxError);
  }
  // The fitted polyhedron has the curve lengths of the surface as straight edges, so it bulges out of the surface by
  // O(ε²) — the Procrustes error is that gap, not a fitting error.
  for (std::size_t i = 1; i < procrustes.size(); ++i) CHECK(procrustes[i] < procrustes[i - 1]);
  const double order = intrinsic::fitLogLogSlope(h, procrustes);
  WARN("order of the Procrustes RMS error against the mean circumradius: " << order);
  CHECK(order >= 1.8);
}

TEST_CASE("Kerr horizon: a/M = 0.5 embeds to round-off, a/M = 0.99 leaves a residual no fit removes") {
  refine::RemeshOptions ro;
  ro.epsilon = 0.3;
  ro.t0Resolution = 6;
  {
    const auto m = makeMetric("kerr-newman", {{"a", 0.5}});
    const auto t1 = refine::remeshMetric(*m, ro);
    const auto fit = fitIsometricEmbedding(t1.mesh);
    INFO(fit.verdict);
    CHECK(fit.isometric);
    CHECK(fit.maxRelativeResidual < 1e-12);
  }
  {
    const auto m = makeMetric("kerr-newman", {{"a", 0.99}});
    const auto t1 = refine::remeshMetric(*m, ro);
    EmbeddingOptions o;
    o.maxIterations = 80;
    const auto fit = fitIsometricEmbedding(t1.mesh, o);
    WARN("Kerr a/M = 0.99, V = " << t1.mesh.mesh.nVertices() << ": " << fit.verdict);
    CHECK_FALSE(fit.isometric);
    CHECK(fit.maxRelativeResidual > 1e-3);
    CHECK(fit.verdict.find("not isometric: residual") == 0);
    CHECK(fit.positions.size() == static_cast<std::size_t>(t1.mesh.mesh.nVertices()));  // the best fit is kept
  }
}

TEST_CASE("bad input is refused by name") {
  const auto m = makeMetric("sphere", {});
  const auto p = testing::discretizedMesh(*m, 2);

  auto nan = p.tri;
  nan.edgeLengths[3] = NAN;
  CHECK_THROWS_AS(fitIsometricEmbedding(nan), InputError);
  CHECK_THROWS_WITH(fitIsometricEmbedding(nan), Catch::Contains("edge 3") && Catch::Contains("nan"));

  intrinsic::IntrinsicTriangulation empty;
  CHECK_THROWS_WITH(fitIsometricEmbedding(empty), Catch::Contains("at least one triangle"));

  intrinsic::IntrinsicTriangulation two;
  two.mesh = intrinsic::HalfedgeMesh::fromFaces({{0, 1, 2}, {3, 4, 5}}, 6);
  two.edgeLengths.assign(two.mesh.nEdges(), 1.0);
  CHECK_THROWS_WITH(fitIsometricEmbedding(two), Catch::Contains("2 connected components"));

  auto spherical = p.tri;
  spherical.background = intrinsic::Background::Spherical;
  CHECK_THROWS_WITH(fitIsometricEmbedding(spherical), Catch::Contains("spherical"));

  EmbeddingOptions o;
  o.initialPositions.assign(3, Eigen::Vector3d::Zero());
  CHECK_THROWS_WITH(fitIsometricEmbedding(p.tri, o), Catch::Contains("3 initial positions"));
  o.initialPositions = p.positions;
  o.initialPositions[2].x() = NAN;
  CHECK_THROWS_WITH(fitIsometricEmbedding(p.tri, o), Catch::Contains("vertex 2"));
  o.initialPositions = p.positions;
  o.tolerance = -1;
  CHECK_THROWS_WITH(fitIsometricEmbedding(p.tri, o), Catch::Contains("tolerance"));
}
