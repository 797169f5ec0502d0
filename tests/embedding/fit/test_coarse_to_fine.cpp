// test_coarse_to_fine.cpp — carrying positions from a coarse mesh to a fine one through their common chart: a field
// linear in a plane chart is carried exactly (also at vertices, on edges and just outside by round-off); on the sphere
// chart the carried reference points are the central projections onto the coarse faces and coarse vertices keep their
// positions exactly (poles included); the ellipsoid's true coarse positions carried to a fine mesh lie within O(h²) of
// the surface (order fitted over three coarse resolutions); the fit from a carried-over start reaches the convex
// realization, the one the true positions lead to (Cauchy's rigidity theorem); bad input is refused by name.
#include <cmath>

#include <catch2/catch.hpp>

#include "conformesh/embedding/fit/coarse_to_fine.h"
#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/embedding/extrinsic/mean_curvature_measure.h"
#include "conformesh/embedding/fit/procrustes.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh;
using namespace conformesh::embedding;
using Catch::Matchers::Contains;

namespace {

// A 4 × 3 grid of the rectangle [0, 4] × [0, 3] with its interior vertices moved off the grid, two triangles per cell.
ChartTriangulation jitteredGrid() {
  ChartTriangulation t;
  const int nu = 4, nv = 3;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const bool interior = i > 0 && i < nu && j > 0 && j < nv;
      t.points.emplace_back(i + (interior ? 0.21 * std::sin(3.0 * i + j) : 0),
                            j + (interior ? 0.17 * std::cos(i - 2.0 * j) : 0), 0);
    }
  auto id = [&](int i, int j) { return j * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return t;
}

Eigen::Vector3d linearField(const Eigen::Vector3d& x) {
  return {2 * x.x() - 3 * x.y() + 1, x.x() + 0.5 * x.y(), -x.y() + 0.25};
}

std::vector<Eigen::Vector3d> referencePointsOf(const intrinsic::SmoothMetric& m, int resolution) {
  intrinsic::DiscretizationOptions o;
  o.resolution = resolution;
  return chartTriangulation(intrinsic::discretizeMetric(m, o), m.domain()).points;
}

// Distance of p from the ellipsoid (ρ/a)² + (z/b)² = 1 to first order, |F|/|∇F| (exact up to O(d²), far below the
// O(h²) distances measured).
double ellipsoidDistance(const Eigen::Vector3d& p, double a, double b) {
  const double F = (p.x() * p.x() + p.y() * p.y()) / (a * a) + p.z() * p.z() / (b * b) - 1;
  const Eigen::Vector3d grad(2 * p.x() / (a * a), 2 * p.y() / (a * a), 2 * p.z() / (b * b));
  return std::abs(F) / grad.norm();
}

int minoritySignEdges(const intrinsic::IntrinsicTriangulation& tri, const std::vector<Eigen::Vector3d>& x) {
  int neg = 0, pos = 0;
  for (int e = 0; e < tri.mesh.nEdges(); ++e) {
    const double beta = signedDihedralAngle(tri.mesh, x, e);
    neg += beta<0, pos += beta> 0;
  }
  return std::min(neg, pos);
}

}  // namespace

TEST_CASE("a field linear in a plane chart is carried exactly, at vertices, on edges and outside by round-off") {
  const ChartTriangulation coarse = jitteredGrid();
  std::vector<Eigen::Vector3d> values;
  for (const auto& x : coarse.points) values.push_back(linearField(x));
  std::vector<Eigen::Vector3d> fine;
  for (int k = 0; k < 200; ++k)
    fine.emplace_back(4 * (0.5 + 0.5 * std::sin(1.7 * k)), 3 * (0.5 + 0.5 * std::cos(2.3 * k)), 0);
  for (const auto& x : coarse.points) fine.push_back(x);  // at coarse vertices (up to 6 faces meet)
  for (const auto& f : coarse.faces) fine.push_back(0.3 * coarse.points[f[0]] + 0.7 * coarse.points[f[1]]);  // on edges
  const size_t inside = fine.size();
  fine.emplace_back(-1e-14, 1.5, 0);           // outside the left side by round-off
  fine.emplace_back(4 + 1e-13, 3 + 1e-13, 0);  // outside the far corner by round-off
  const auto carried = carryPositions(coarse, values, fine);
  REQUIRE(carried.size() == fine.size());
  double worst = 0;
  for (size_t i = 0; i < inside; ++i) worst = std::max(worst, (carried[i] - linearField(fine[i])).norm());
  CHECK(worst < 1e-14 * 16);  // values up to ~10: a few ulps
  // Outside by δ, the clamped coordinates describe a point of the face within ~δ of x: the error is at most the
  // field's Lipschitz constant (the matrix norm, < 4.2) times a few δ.
  for (size_t i = inside; i < fine.size(); ++i) CHECK((carried[i] - linearField(fine[i])).norm() < 4.2 * 3e-13);
  // Every location is a convex combination.
  for (const auto& l : locateInChart(coarse, fine)) {
    CHECK(l.barycentric.minCoeff() >= 0);
    CHECK(std::abs(l.barycentric.sum() - 1) < 1e-15);
  }
}

TEST_CASE("on the sphere chart: central projection onto the coarse faces, coarse vertices (and poles) kept exactly") {
  const auto m = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  intrinsic::DiscretizationOptions o;
  o.resolution = 4;
  const ChartTriangulation coarse = chartTriangulation(intrinsic::discretizeMetric(*m, o), m->domain());
  REQUIRE(coarse.surface == ChartSurface::UnitSphere);
  // Frequency 8 subdivides every frequency-4 face: its vertices include the 162 coarse ones.
  const auto fine = referencePointsOf(*m, 8);
  const auto carried = carryPositions(coarse, coarse.points, fine);
  const auto located = locateInChart(coarse, fine);
  double worstDirection = 0, worstPlane = 0;
  for (size_t i = 0; i < fine.size(); ++i) {
    worstDirection = std::max(worstDirection, (carried[i].normalized() - fine[i]).norm());
    const auto& f = coarse.faces[located[i].face];
    const Eigen::Vector3d &a = coarse.points[f[0]], &b = coarse.points[f[1]], &c = coarse.points[f[2]];
    worstPlane = std::max(worstPlane, std::abs((carried[i] - a).dot((b - a).cross(c - a).normalized())));
  }
  CHECK(worstDirection < 1e-14);
  CHECK(worstPlane < 1e-15);
  // Fine vertices at coarse vertices: the coarse position itself, with any positions (here the true surface points).
  const auto coarsePositions = [&] {
    std::vector<Eigen::Vector3d> p;
    for (const auto& x : coarse.points) {
      const Eigen::Vector2d uv = intrinsic::chartPoint(m->domain(), x);
      p.push_back(m->position(uv.x(), uv.y()));
    }
    return p;
  }();
  const auto carriedTrue = carryPositions(coarse, coarsePositions, fine);
  int coincident = 0;
  for (size_t i = 0; i < fine.size(); ++i)
    for (size_t k = 0; k < coarse.points.size(); ++k)
      if ((fine[i] - coarse.points[k]).norm() < 1e-12) {
        ++coincident;
        CHECK((carriedTrue[i] - coarsePositions[k]).norm() < 1e-14);
      }
  CHECK(coincident == 162);
}

TEST_CASE("true coarse positions carried to a fine ellipsoid mesh lie within O(h²) of the surface") {
  const double a = 1, f = 0.3, b = a * (1 - f);
  const auto m = intrinsic::makeMetric("ellipsoid", {{"a", a}, {"f", f}});
  const auto fine = referencePointsOf(*m, 61);  // not a multiple of the coarse frequencies: points fall inside faces
  std::vector<double> h, err;
  for (int N : {6, 12, 24}) {
    intrinsic::DiscretizationOptions o;
    o.resolution = N;
    const auto mesh = intrinsic::discretizeMetric(*m, o);
    const auto carried = carryPositions(chartTriangulation(mesh, m->domain()), mesh.positions, fine);
    double worst = 0;
    for (const auto& p : carried) worst = std::max(worst, ellipsoidDistance(p, a, b));
    h.push_back(1.0 / N);
    err.push_back(worst);
  }
  // Linear interpolation of a smooth surface over triangles of size h: the deviation is ≤ κ_max h²/8 per unit of
  // squared edge, i.e. order 2.
  const double order = intrinsic::fitLogLogSlope(h, err);
  CHECK(order > 1.9);
  CHECK(order < 2.1);
}

TEST_CASE("the fit from a carried-over start reaches the convex realization of the fine lengths") {
  const auto m = intrinsic::makeMetric("ellipsoid", {{"f", 0.3}});
  intrinsic::DiscretizationOptions o;
  o.resolution = 6;
  const auto coarseMesh = intrinsic::discretizeMetric(*m, o);
  const auto coarseFit = fitIsometricEmbedding(intrinsic::toTriangulation(coarseMesh));  // from the MDS start
  REQUIRE(coarseFit.isometric);
  o.resolution = 14;
  const auto fineMesh = intrinsic::discretizeMetric(*m, o);
  const auto fineTri = intrinsic::toTriangulation(fineMesh);
  EmbeddingOptions carried;
  carried.initialPositions = carryPositions(chartTriangulation(coarseMesh, m->domain()), coarseFit.positions,
                                            chartTriangulation(fineMesh, m->domain()).points);
  carried.regularizerWeight = 0.01;  // one step per stage, as bench_embedding runs it
  carried.maxIterationsRegularized = 1;
  const auto fit = fitIsometricEmbedding(fineTri, carried);
  REQUIRE(fit.isometric);
  CHECK(minoritySignEdges(fineTri, fit.positions) == 0);
  // The same lengths fitted from the true surface points: two convex polyhedra with the same combinatorics and
  // congruent faces are congruent (Cauchy 1813), so the two fits agree up to a rigid motion.
  EmbeddingOptions fromTrue;
  fromTrue.initialPositions = fineMesh.positions;
  fromTrue.regularizerWeight = 0;
  const auto reference = fitIsometricEmbedding(fineTri, fromTrue);
  REQUIRE(reference.isometric);
  REQUIRE(minoritySignEdges(fineTri, reference.positions) == 0);
  CHECK(alignRigid(fit.positions, reference.positions).maxError < 1e-10);
}

TEST_CASE("bad input to the carry-over is refused by name") {
  const ChartTriangulation coarse = jitteredGrid();
  std::vector<Eigen::Vector3d> values(coarse.points.size(), Eigen::Vector3d::Zero());
  SECTION("a fine point outside every coarse face") {
    const std::vector<Eigen::Vector3d> fine{{1, 1, 0}, {2, 2, 0}, {5, 1, 0}};
    CHECK_THROWS_WITH(carryPositions(coarse, values, fine),
                      Contains("fine chart point 2") && Contains("lies in no coarse face"));
  }
  SECTION("a fine point just outside by more than round-off") {
    const std::vector<Eigen::Vector3d> fine{{-1e-6, 1.5, 0}};
    CHECK_THROWS_WITH(carryPositions(coarse, values, fine), Contains("fine chart point 0"));
  }
  SECTION("a fine point that is not finite") {
    const std::vector<Eigen::Vector3d> fine{{1, 1, 0}, {NAN, 1, 0}};
    CHECK_THROWS_WITH(carryPositions(coarse, values, fine), Contains("fine chart point 1") && Contains("not finite"));
  }
  SECTION("positions of the wrong count") {
    values.pop_back();
    CHECK_THROWS_WITH(carryPositions(coarse, values, {{1, 1, 0}}), Contains("19 coarse positions for 20"));
  }
  SECTION("a degenerate coarse face") {
    ChartTriangulation bad = coarse;
    bad.faces[3] = {0, 1, 2};  // three collinear points of the bottom row
    CHECK_THROWS_WITH(locateInChart(bad, {{1, 1, 0}}), Contains("coarse face 3") && Contains("degenerate"));
  }
  SECTION("a face naming a vertex that does not exist") {
    ChartTriangulation bad = coarse;
    bad.faces[5][1] = 99;
    CHECK_THROWS_WITH(locateInChart(bad, {{1, 1, 0}}), Contains("coarse face 5 refers to vertex 99"));
  }
  SECTION("a periodic chart") {
    const auto torus = intrinsic::makeMetric("torus", {});
    intrinsic::DiscretizationOptions o;
    o.resolution = 6;
    CHECK_THROWS_WITH(chartTriangulation(intrinsic::discretizeMetric(*torus, o), torus->domain()),
                      Contains("torus") && Contains("periodic"));
  }
}
