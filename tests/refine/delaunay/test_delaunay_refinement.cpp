// Tests for delaunay_refinement.h in the three background geometries: every output triangle meets the size and shape
// bounds, the output is Delaunay, Gauss–Bonnet holds and the area is unchanged (refinement is an isometry), the
// smallest angle is ≥ arcsin(1/(2B)); every vertex's input location reproduces the lengths of its edges; the mean
// circumradius scales like 1/√V (paper Fig. 10b); boundary splits land on the circle; bad input and caps are named.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <iomanip>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "support/refine_test_surfaces.h"
#include "support/gauss_bonnet_bound.h"

using namespace conformesh;
using namespace conformesh::refine;
using namespace conformesh::refine::testing;
using intrinsic::IntrinsicTriangulation;

namespace {

constexpr double kDeg = 180 / M_PI;

// The located-points check of a surface with closed-form distances, as a function of the refinement's result.
template <class Surface>
std::function<double(const RefineResult&)> locatedError(const Surface& s) {
  return [&s](const RefineResult& r) { return worstLocatedLengthError(s, r.triangulation, r.locations); };
}

// One input of each geometry for the tests of refinement options (frontal placement, smoothing): the planar disk
// (uniform or graded), the sphere, the hyperbolic genus-2 octagon and a skewed flat torus. A case's `located` checks
// the recorded input locations against the surface's closed-form distances (none for the octagon).
struct GeometryCase {
  const IntrinsicTriangulation* in;
  double eps;
  bool graded;
  std::function<double(const RefineResult&)> located;
};
struct EveryGeometry {
  DiskSurface d = disk(3);
  SphereSurface sph = sphere(1);
  OctagonSurface oct = genus2Octagon();
  FlatTorus torus = flatTorus({1, 0}, {0.37, 0.61}, 5);
  GeometryCase diskCase(double eps, bool graded) const { return {&d.tri, eps, graded, locatedError(d)}; }
  GeometryCase sphereCase(double eps) const { return {&sph.tri, eps, false, locatedError(sph)}; }
  GeometryCase octagonCase(double eps) const { return {&oct.tri, eps, false, nullptr}; }
  GeometryCase torusCase(double eps) const { return {&torus.tri, eps, false, locatedError(torus)}; }
};

// The graded disk of the tests: λ = 1.5·x at the input vertices (linear, so its interpolant is exact). Returns min λ.
double gradeLinearly(const DiskSurface& d, RefineOptions& o) {
  double lambdaMin = 0;
  for (const auto& p : d.positions) {
    o.lambda.push_back(1.5 * p.x());
    lambdaMin = std::min(lambdaMin, 1.5 * p.x());
  }
  return lambdaMin;
}

// The properties every refinement output must have, whatever the geometry (λ ≡ 0).
void checkBounds(const IntrinsicTriangulation& in, const RefineResult& r, double eps, double B) {
  const IntrinsicTriangulation& t = r.triangulation;
  REQUIRE_NOTHROW(t.mesh.checkInvariants());
  REQUIRE_NOTHROW(intrinsic::validateLengths(t, "refined"));
  const QualityReport q = measureQuality(t);
  INFO("vertices " << q.vertices << " min angle " << q.minAngleDeg << " max R " << q.maxCircumradius);
  // Size and shape, with a relative slack of 1e-9 for the round-off of circumradii computed from lengths.
  CHECK(q.maxCircumradius <= eps * (1 + 1e-9));
  CHECK(q.maxRadiusEdgeRatio <= B * (1 + 1e-9));
  // R / shortest ≤ B gives a smallest angle ≥ arcsin(1/(2B)) by the inscribed-angle theorem of the plane; spherical
  // triangles only gain angle over their Euclidean comparison triangles. Hyperbolic ones lose angle (their defect is
  // the total loss), so there the guarantee is the ratio bound above; the angle check against the defect-reduced
  // bound is a consistency check, not a theorem.
  const double angleBound = std::asin(1 / (2 * B)) * kDeg;
  if (t.background != intrinsic::Background::Hyperbolic) {
    CHECK(q.minAngleDeg >= angleBound - 1e-7);
  } else {
    double maxDefect = 0;
    for (int f = 0; f < t.mesh.nFaces(); ++f) maxDefect = std::max(maxDefect, intrinsic::faceArea(t, f));
    CHECK(q.minAngleDeg >= angleBound - maxDefect * kDeg);
  }
  CHECK(q.nonDelaunayEdges == 0);
  CHECK(std::abs(q.gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(q.triangles));  // support/gauss_bonnet_bound.h
  CHECK(t.mesh.eulerCharacteristic() == in.mesh.eulerCharacteristic());
  CHECK(static_cast<int>(r.locations.size()) == t.mesh.nVertices());
  // Signposts: consecutive outgoing halfedges differ by the corner angle between them (mod the vertex's period).
  double worst = 0;
  for (int h = 0; h < t.mesh.nHalfedges(); ++h) {
    const int g = t.mesh.nextOutgoing(h);
    if (g == intrinsic::kInvalid) continue;
    const int v = t.mesh.tail(h);
    const double d = std::remainder(r.signposts.angle[g] - r.signposts.angle[h] - intrinsic::cornerAngle(t, h),
                                    r.signposts.period[v]);
    worst = std::max(worst, std::abs(d));
  }
  CHECK(worst < 1e-9);
}

// The unit square [0,1]² as an n×n grid of right triangles: corners of 90°, and collinear boundary vertices (180°).
IntrinsicTriangulation unitSquare(int n, std::vector<Eigen::Vector2d>* positions) {
  intrinsic::MeshData d;
  d.nVertices = (n + 1) * (n + 1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      d.positions.emplace_back(double(i) / n, double(j) / n, 0.0);
      positions->emplace_back(double(i) / n, double(j) / n);
    }
  auto id = [n](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      d.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      d.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return intrinsic::toTriangulation(d);
}

Eigen::Vector2d locateIn(const IntrinsicTriangulation& in, const std::vector<Eigen::Vector2d>& pos,
                         const InputLocation& loc) {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (int k = 0; k < 3; ++k) p += loc.bary[k] * pos[in.mesh.faceVertex(loc.face, k)];
  return p;
}

// A regular hexagon of the given background fanned from its centre (vertex 6): radial edges `radius`, sides `side`.
IntrinsicTriangulation regularHexagonFan(intrinsic::Background g, double radius, double side) {
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < 6; ++i) faces.push_back({6, i, (i + 1) % 6});
  IntrinsicTriangulation t;
  t.mesh = intrinsic::HalfedgeMesh::fromFaces(faces, 7);
  t.background = g;
  t.edgeLengths.assign(t.mesh.nEdges(), side);
  for (int e = 0; e < t.mesh.nEdges(); ++e) {
    const int h = t.mesh.edgeHalfedge(e);
    if (t.mesh.tail(h) == 6 || t.mesh.tip(h) == 6) t.edgeLengths[e] = radius;
  }
  return t;
}

// The number of vertices on each boundary circle of the input annulus.
int annulusRingVertexCountFor(const DiskSurface& s) {
  int n = 0;
  for (size_t v = 0; v < s.positions.size(); ++v)
    if (s.tri.mesh.isBoundaryVertex(static_cast<int>(v)) && s.positions[v].norm() < 0.75) ++n;
  return n;
}

}  // namespace

TEST_CASE("flat tori of skewed lattices refine to the bounds, isometrically, with correct input locations") {
  struct Lattice {
    std::complex<double> w1, w2;
    int n;
  };
  const Lattice lattices[] = {{{1, 0}, {0, 1}, 3},                   // square: every grid quad cocircular
                              {{1, 0}, {0.5, std::sqrt(3) / 2}, 4},  // hexagonal
                              {{1, 0}, {0.37, 0.61}, 5},             // generic skew
                              {{1, 0}, {3.3, 0.25}, 4}};             // very skewed: input angles of a few degrees
  for (const Lattice& L : lattices) {
    const FlatTorus torus = flatTorus(L.w1, L.w2, L.n);
    const double eps = 0.06;
    RefineOptions o;
    o.epsilon = eps;
    const RefineResult r = refineDelaunay(torus.tri, o);
    INFO("lattice " << L.w1 << " " << L.w2);
    checkBounds(torus.tri, r, eps, std::sqrt(2.0));
    CHECK(intrinsic::totalArea(r.triangulation) == Approx(intrinsic::totalArea(torus.tri)).epsilon(1e-12));
    // Every edge's length equals the torus distance between its endpoints' input locations.
    CHECK(worstLocatedLengthError(torus, r.triangulation, r.locations) < 1e-10);
  }
}

TEST_CASE("the sphere refines with great-circle lengths; locations lie at the right great-circle distances") {
  const SphereSurface s = sphere(1);
  for (double B : {std::sqrt(2.0), 1.0}) {
    const double eps = 0.12;
    RefineOptions o;
    o.epsilon = eps;
    o.ratioBound = B;
    const RefineResult r = refineDelaunay(s.tri, o);
    checkBounds(s.tri, r, eps, B);
    CHECK(intrinsic::totalArea(r.triangulation) == Approx(intrinsic::totalArea(s.tri)).epsilon(1e-11));
    CHECK(worstLocatedLengthError(s, r.triangulation, r.locations) < 1e-10);
  }
}

TEST_CASE("a hyperbolic genus-2 surface refines without any layout; area stays 4π and Gauss–Bonnet holds") {
  const OctagonSurface s = genus2Octagon();
  REQUIRE(intrinsic::totalArea(s.tri) == Approx(4 * M_PI).epsilon(1e-12));
  const double eps = 0.35;
  RefineOptions o;
  o.epsilon = eps;
  const RefineResult r = refineDelaunay(s.tri, o);
  checkBounds(s.tri, r, eps, std::sqrt(2.0));
  CHECK(intrinsic::totalArea(r.triangulation) == Approx(4 * M_PI).epsilon(1e-11));
  // Every input face has the octagon's centre (vertex 0) as corner 0, at the origin of its canonical layout: a vertex
  // joined to the centre by an edge shorter than the inradius lies at exactly that distance from the origin.
  const BackgroundModel model(intrinsic::Background::Hyperbolic);
  const auto& m = r.triangulation.mesh;
  int checked = 0;
  double worst = 0;
  for (int h = 0; h < m.nHalfedges(); ++h) {
    if (m.tail(h) != 0 || r.triangulation.length(h) >= s.inradius) continue;
    const InputLocation& loc = r.locations[m.tip(h)];
    const auto C = layoutFace(s.tri, model, loc.face);
    REQUIRE(s.tri.mesh.faceVertex(loc.face, 0) == 0);
    const Vec3 p = model.fromBarycentric(C[0], C[1], C[2], loc.bary);
    worst = std::max(worst, std::abs(model.distance(BackgroundModel::origin(), p) - r.triangulation.length(h)));
    ++checked;
  }
  CHECK(checked >= 6);
  CHECK(worst < 1e-10);
}

TEST_CASE("the unit disk refines with new boundary vertices on the circle, not on the chords") {
  const DiskSurface s = disk(3);
  for (double eps : {0.2, 0.07}) {
    RefineOptions o;
    o.epsilon = eps;
    const RefineResult r = refineDelaunay(s.tri, o);
    checkBounds(s.tri, r, eps, std::sqrt(2.0));
    CHECK(r.statistics.circleLoops == 1);
    CHECK(r.statistics.boundarySplits > 0);
    const auto& m = r.triangulation.mesh;
    double worstCircle = 0, worstEdge = 0;
    for (int v = 0; v < m.nVertices(); ++v)
      if (m.isBoundaryVertex(v)) worstCircle = std::max(worstCircle, std::abs(s.locate(r.locations[v]).norm() - 1));
    for (int e = 0; e < m.nEdges(); ++e) {
      const int h = m.edgeHalfedge(e);
      const double d = (s.locate(r.locations[m.tail(h)]) - s.locate(r.locations[m.tip(h)])).norm();
      worstEdge = std::max(worstEdge, std::abs(d - r.triangulation.edgeLengths[e]));
    }
    CHECK(worstCircle < 1e-12);
    CHECK(worstEdge < 1e-10);
    // The area is that of the polygon of the refined boundary vertices, inscribed in the unit circle.
    double polygon = 0;
    for (const auto& loop : m.boundaryLoops())
      for (int h : loop) {
        const Eigen::Vector2d a = s.locate(r.locations[m.tail(h)]), b = s.locate(r.locations[m.tip(h)]);
        polygon += (a.x() * b.y() - a.y() * b.x()) / 2;
      }
    CHECK(intrinsic::totalArea(r.triangulation) == Approx(polygon).epsilon(1e-11));
  }
}

TEST_CASE("shape bound B = 1 (Chew's 30°) on closed surfaces of every geometry") {
  const FlatTorus torus = flatTorus({1, 0}, {0.37, 0.61}, 5);
  const OctagonSurface oct = genus2Octagon();
  const IntrinsicTriangulation* inputs[] = {&torus.tri, &oct.tri};
  for (const IntrinsicTriangulation* in : inputs) {
    RefineOptions o;
    o.epsilon = in->background == intrinsic::Background::Hyperbolic ? 0.4 : 0.08;
    o.ratioBound = 1.0;
    const RefineResult r = refineDelaunay(*in, o);
    checkBounds(*in, r, o.epsilon, 1.0);
  }
}

TEST_CASE("mean circumradius scales like 1/sqrt(V) over a sweep of epsilon (paper Fig. 10b)") {
  // A generic skewed lattice: on the hexagonal one circumcentre insertion produces a regular lattice and the law
  // would hold trivially. Measured: slope −0.503 (torus), −0.4999 (sphere), −0.497 (genus 2), −0.510 (disk).
  const FlatTorus torus = flatTorus({1, 0}, {0.37, 0.61}, 5);
  std::vector<double> x, y;
  for (double eps : {0.1, 0.07, 0.05, 0.035, 0.025, 0.018}) {
    RefineOptions o;
    o.epsilon = eps;
    const RefineResult r = refineDelaunay(torus.tri, o);
    const QualityReport q = measureQuality(r.triangulation);
    x.push_back(std::log(q.vertices));
    y.push_back(std::log(q.meanCircumradius));
  }
  // Least-squares slope of log(mean R) against log(V).
  const double n = x.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  INFO("slope " << std::setprecision(6) << slope);
  CHECK(slope == Approx(-0.5).margin(0.03));
}

TEST_CASE(
    "the size test's threshold is eps * exp(-lambda(c)) itself: inputs 0.5 % above it refine, 0.5 % below do not") {
  // The bound R ≤ ε·e^(−λ) cannot catch a size test that is too strict, and catches a too lax one only where the
  // output's largest circumradius sits within the error of ε (in the remesh pipeline it sits at 0.88ε), so the
  // threshold itself is pinned: the hexagonal flat torus is tiled by equilateral triangles of side s = 1/n, all of
  // circumradius R₀ = s/√3 and ratio R/ℓ = 1/√3 < B (shape-good, strictly Delaunay). The refinement inserts a point iff
  // some face has R > ε·e^(−λ(c)), λ(c) the input's piecewise-linear λ at the circumcentre c — the centroid of an
  // equilateral face, so λ(c) is the mean of its corners' λ. With ε·e^(−λ(c)) = R₀/(1 + δ) at every face, every face
  // is too large and all output circumradii must fall below it; with R₀/(1 − δ) at the faces of least threshold, none
  // is and the output is the input. δ = 0.5 %: a threshold off by 1 % in either direction flips one outcome.
  // Three gradings: λ ≡ 0; λ ≡ 0.4; λ = 0.4 with a bump β = 0.03 at vertex 0, whose six faces have λ(c) = 0.4 + β/3.
  // The bump puts the quick pre-test (R > ε·e^(−max λ), which admits every face here) below the faces' own thresholds,
  // so that only the per-face test at λ(c) decides — a test too strict by 1 % there refines the bump's faces.
  const int n = 5;
  const FlatTorus torus = flatTorus({1, 0}, {0.5, std::sqrt(3.0) / 2}, n);
  for (double l : torus.tri.edgeLengths) REQUIRE(l == Approx(1.0 / n).epsilon(1e-14));  // equilateral
  const double R0 = 1.0 / (n * std::sqrt(3.0)), delta = 5e-3;
  struct Grading {
    double lambda, bump;
  };
  for (const Grading g : {Grading{0, 0}, Grading{0.4, 0}, Grading{0.4, 0.03}}) {
    for (int sign : {+1, -1}) {
      INFO("lambda " << g.lambda << " bump " << g.bump << ", threshold R0 / (1 " << (sign > 0 ? "+" : "-")
                     << " delta)");
      RefineOptions o;
      // The least threshold, at the bump's faces: ε·e^(−λ − β/3); the others' is e^(β/3) larger.
      const double least = sign > 0 ? R0 / (1 + delta) * std::exp(-g.bump / 3) : R0 / (1 - delta);
      o.epsilon = least * std::exp(g.lambda + g.bump / 3);
      if (g.lambda != 0) {
        o.lambda.assign(torus.tri.mesh.nVertices(), g.lambda);
        o.lambda[0] += g.bump;
      }
      const RefineResult r = refineDelaunay(torus.tri, o);
      const QualityReport q = measureQuality(r.triangulation);
      if (sign > 0) {
        CHECK(r.statistics.circumcenterInsertions > 0);
        CHECK(q.maxCircumradius <= o.epsilon * std::exp(-g.lambda - g.bump) * (1 + 1e-9));  // below the least bound
      } else {
        CHECK(r.statistics.circumcenterInsertions + r.statistics.centroidInsertions +
                  r.statistics.offCenterInsertions ==
              0);
        CHECK(q.vertices == torus.tri.mesh.nVertices());
        CHECK(q.maxCircumradius == Approx(R0).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("grading by the conformal factor: every circumradius is below eps * exp(-lambda(circumcentre))") {
  const DiskSurface s = disk(3);
  // λ = 0.8·x is linear, so its piecewise-linear interpolant on the input is exact everywhere (also in boundary caps).
  std::vector<double> lambda;
  for (const auto& p : s.positions) lambda.push_back(0.8 * p.x());
  RefineOptions o;
  o.epsilon = 0.1;
  o.lambda = lambda;
  const RefineResult r = refineDelaunay(s.tri, o);
  const IntrinsicTriangulation& t = r.triangulation;
  const auto& m = t.mesh;
  double worstLambda = 0, worstRatio = 0;
  for (int v = 0; v < m.nVertices(); ++v)
    worstLambda = std::max(worstLambda, std::abs(r.lambda[v] - 0.8 * s.locate(r.locations[v]).x()));
  int dense = 0, sparse = 0;
  for (int f = 0; f < m.nFaces(); ++f) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = s.locate(r.locations[m.faceVertex(f, k)]);
    const Eigen::Vector2d u = p[1] - p[0], v = p[2] - p[0];
    const double d = 2 * (u.x() * v.y() - u.y() * v.x());
    const Eigen::Vector2d c = p[0] + Eigen::Vector2d(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(),
                                                     u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) /
                                         d;
    const double R = intrinsic::faceCircumradius(t, f);
    worstRatio = std::max(worstRatio, R / (o.epsilon * std::exp(-0.8 * c.x())));
    (c.x() > 0.5 ? dense : sparse) += c.x() > 0.5 || c.x() < -0.5;
  }
  CHECK(worstLambda < 1e-12);
  CHECK(worstRatio <= 1 + 1e-9);
  CHECK(dense > 2 * sparse);  // e^(0.8·2·0.75) ≈ 3.3 times the density on the right strip x > 0.5 vs the left one
  checkBounds(s.tri, r, o.epsilon * std::exp(0.8), std::sqrt(2.0));
}

TEST_CASE("a square with collinear boundary vertices refines with geodesic boundary splits") {
  std::vector<Eigen::Vector2d> pos;
  const IntrinsicTriangulation in = unitSquare(3, &pos);
  RefineOptions o;
  o.epsilon = 0.05;
  const RefineResult r = refineDelaunay(in, o);
  checkBounds(in, r, o.epsilon, std::sqrt(2.0));
  CHECK(r.statistics.circleLoops == 0);
  CHECK(intrinsic::totalArea(r.triangulation) == Approx(1.0).epsilon(1e-12));
  const auto& m = r.triangulation.mesh;
  double worst = 0;
  for (int v = 0; v < m.nVertices(); ++v)
    if (m.isBoundaryVertex(v)) {
      const Eigen::Vector2d p = locateIn(in, pos, r.locations[v]);
      worst = std::max(worst, std::min({std::abs(p.x()), std::abs(p.y()), std::abs(1 - p.x()), std::abs(1 - p.y())}));
    }
  CHECK(worst < 1e-12);

  o.boundarySplit = BoundarySplit::Circle;
  CHECK_THROWS_WITH(refineDelaunay(in, o),
                    Catch::Contains("boundary loop 0") && Catch::Contains("is not inscribed in a circle"));
}

TEST_CASE("bad parameters are rejected with messages naming the element; caps stop runaway runs") {
  const FlatTorus torus = flatTorus({1, 0}, {0, 1}, 3);
  RefineOptions o;
  o.epsilon = 0;
  CHECK_THROWS_AS(refineDelaunay(torus.tri, o), InputError);
  CHECK_THROWS_WITH(refineDelaunay(torus.tri, o), Catch::Contains("epsilon"));
  o.epsilon = 0.1;
  o.ratioBound = 0.9;
  CHECK_THROWS_WITH(refineDelaunay(torus.tri, o), Catch::Contains("at least 1"));
  o.ratioBound = std::sqrt(2.0);
  o.lambda = {0, 0};
  CHECK_THROWS_WITH(refineDelaunay(torus.tri, o), Catch::Contains("expected one per input vertex (9)"));
  o.lambda.assign(9, 0.0);
  o.lambda[4] = NAN;
  CHECK_THROWS_WITH(refineDelaunay(torus.tri, o), Catch::Contains("vertex 4"));
  o.lambda.clear();
  IntrinsicTriangulation broken = torus.tri;
  broken.edgeLengths[5] = 10;
  CHECK_THROWS_AS(refineDelaunay(broken, o), InputError);

  o.epsilon = 0.01;
  o.maxInsertions = 5;
  CHECK_THROWS_AS(refineDelaunay(torus.tri, o), ConvergenceError);
  CHECK_THROWS_WITH(refineDelaunay(torus.tri, o), Catch::Contains("maxInsertions"));
  o.maxInsertions = 1000000;
  o.minCircumradius = 0.2;
  CHECK_THROWS_WITH(refineDelaunay(torus.tri, o), Catch::Contains("below the smallest size"));
}

TEST_CASE("off-centres meet the same bounds as circumcentres, with no more vertices, around a small feature") {
  // The unit square with two interior vertices 0.01 apart: the Delaunay triangles at that pair have radius-edge ratios
  // ≈ 35, far above B, so the shape bound drives the refinement (ε is large) and off-centres (placed only when nearer
  // than the circumcentre, i.e. for ratios above ≈ 2B) come into play.
  intrinsic::MeshData d;
  d.nVertices = 6;
  d.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0.51, 0.5, 0}};
  d.faces = {{0, 1, 5}, {1, 2, 5}, {2, 3, 4}, {3, 0, 4}, {0, 5, 4}, {2, 4, 5}};
  const IntrinsicTriangulation in = intrinsic::toTriangulation(d);
  RefineOptions o;
  o.epsilon = 1.0;
  o.ratioBound = 1.2;
  const RefineResult circ = refineDelaunay(in, o);
  o.offCenters = true;
  const RefineResult off = refineDelaunay(in, o);
  CHECK(off.statistics.offCenterInsertions > 0);
  checkBounds(in, circ, o.epsilon, 1.2);
  checkBounds(in, off, o.epsilon, 1.2);
  INFO("vertices: circumcentres " << circ.triangulation.mesh.nVertices() << ", off-centres "
                                  << off.triangulation.mesh.nVertices());
  CHECK(off.triangulation.mesh.nVertices() <= circ.triangulation.mesh.nVertices());
}

TEST_CASE("sharp boundary corners (7.5° hyperbolic, 11.5° Euclidean) terminate: concentric shells and a terminator") {
  // Single triangles: hyperbolic with sides 5, 3, 3 (angles 74.3°, 7.47°, 7.47°; no circumcircle, since
  // sinh(5/2) > 2 sinh(3/2)) and Euclidean with sides 1, 1, 0.2 (apex 11.5°). Below 60° Ruppert's rules alone need not
  // terminate; with concentric-shell segment splits and the shape test waived at the sharp corners they do, with
  // Ruppert's and with Chew's segment rule (measured: 39 / 69 deletions). Every triangle meets the size bound; every
  // triangle away from the sharp corners meets the shape bound too.
  struct Case {
    intrinsic::Background g;
    double a, b, eps;
  };
  for (SegmentRule rule : {SegmentRule::Ruppert, SegmentRule::Chew})
    for (const Case& c :
         {Case{intrinsic::Background::Hyperbolic, 5, 3, 0.2}, Case{intrinsic::Background::Euclidean, 0.2, 1, 0.03}}) {
      IntrinsicTriangulation in;
      in.mesh = intrinsic::HalfedgeMesh::fromFaces({{0, 1, 2}}, 3);
      in.background = c.g;
      in.edgeLengths.assign(3, c.b);
      for (int e = 0; e < 3; ++e) {
        const int h = in.mesh.edgeHalfedge(e);
        if (std::min(in.mesh.tail(h), in.mesh.tip(h)) == 1) in.edgeLengths[e] = c.a;  // the edge 1-2, opposite vertex 0
      }
      if (c.g == intrinsic::Background::Hyperbolic) REQUIRE(std::isinf(intrinsic::faceCircumradius(in, 0)));
      const std::vector<double> sums = intrinsic::angleSums(in);
      RefineOptions o;
      o.epsilon = c.eps;
      o.segmentRule = rule;
      const RefineResult r = refineDelaunay(in, o);
      const IntrinsicTriangulation& t = r.triangulation;
      const auto& m = t.mesh;
      double worstRatio = 0, maxR = 0;
      for (int f = 0; f < m.nFaces(); ++f) {
        const double R = intrinsic::faceCircumradius(t, f);
        maxR = std::max(maxR, R);
        bool sharp = false;
        for (int k = 0; k < 3; ++k) {
          const int v = m.faceVertex(f, k);
          sharp = sharp || (v < 3 && sums[v] < M_PI / 3);
        }
        if (sharp) continue;
        const double shortest = std::min({t.length(3 * f), t.length(3 * f + 1), t.length(3 * f + 2)});
        worstRatio = std::max(worstRatio, R / shortest);
      }
      INFO("background " << intrinsic::toString(c.g) << (rule == SegmentRule::Chew ? ", Chew" : ", Ruppert")
                         << ", vertices " << m.nVertices());
      CHECK(maxR <= c.eps * (1 + 1e-9));
      CHECK(worstRatio <= std::sqrt(2.0) * (1 + 1e-9));
      CHECK(intrinsic::countNonDelaunayEdges(t) == 0);
      CHECK(std::abs(intrinsic::curvatureTotals(t).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(t.mesh.nFaces()));
      CHECK(intrinsic::totalArea(t) == Approx(intrinsic::totalArea(in)).epsilon(1e-11));
    }
}

TEST_CASE("a circle domain (annulus): boundary vertices land on both circles, the hole's split into the domain") {
  const DiskSurface s = annulus(3);
  RefineOptions o;
  o.epsilon = 0.05;
  const RefineResult r = refineDelaunay(s.tri, o);
  checkBounds(s.tri, r, o.epsilon, std::sqrt(2.0));
  CHECK(r.statistics.circleLoops == 2);
  const auto& m = r.triangulation.mesh;
  double worst = 0;
  int inner = 0, outer = 0;
  for (int v = 0; v < m.nVertices(); ++v) {
    if (!m.isBoundaryVertex(v)) continue;
    const double rad = s.locate(r.locations[v]).norm();
    const bool isInner = rad < 0.75;
    (isInner ? inner : outer)++;
    worst = std::max(worst, std::abs(rad - (isInner ? 0.5 : 1.0)));
  }
  CHECK(worst < 1e-12);
  CHECK(inner >= 2 * annulusRingVertexCountFor(s));  // input edges (0.116) exceed 2ε: each is split
  CHECK(outer >= 2 * annulusRingVertexCountFor(s));
}

// The planar domains of the tests below √2: the hard cases for boundary rules. Interior vertex pairs 0.002–0.003
// apart, vertices 0.002 and 0.0055 from a boundary edge (shape-driven refinement down to that scale, ε is large), 60°
// and 90° corners, a 270° reflex corner, circle boundaries, grading by λ = 3x.
struct PlanarCase {
  const char* name;
  DiskSurface surface;
  double eps;
  bool graded;
};
std::vector<PlanarCase> planarBelowSqrt2Cases() {
  std::vector<PlanarCase> cases;
  cases.push_back({"disk (circle)", disk(3), 0.2, true});
  cases.push_back({"annulus (circle domain)", annulus(3), 0.2, true});
  cases.push_back({"rectangle with a close pair and a vertex near the boundary",
                   planarDelaunay({{0, 0}, {1, 0}, {1, 0.8}, {0, 0.8}, {0.5, 0.4}, {0.503, 0.4}, {0.3, 0.002}}), 10,
                   false});
  cases.push_back({"equilateral triangle (60° corners) with a close pair",
                   planarDelaunay({{0, 0}, {1, 0}, {0.5, std::sqrt(0.75)}, {0.5, 0.3}, {0.502, 0.3}}), 10, false});
  cases.push_back({"regular 12-gon (read as a circle) with a vertex 0.0055 inside an edge",
                   planarDelaunay({{1, 0},
                                   {std::cos(M_PI / 6), std::sin(M_PI / 6)},
                                   {std::cos(M_PI / 3), std::sin(M_PI / 3)},
                                   {0, 1},
                                   {-std::cos(M_PI / 3), std::sin(M_PI / 3)},
                                   {-std::cos(M_PI / 6), std::sin(M_PI / 6)},
                                   {-1, 0},
                                   {-std::cos(M_PI / 6), -std::sin(M_PI / 6)},
                                   {-std::cos(M_PI / 3), -std::sin(M_PI / 3)},
                                   {0, -1},
                                   {std::cos(M_PI / 3), -std::sin(M_PI / 3)},
                                   {std::cos(M_PI / 6), -std::sin(M_PI / 6)},
                                   {0.05, 0.02},
                                   {0.93, 0.24}}),
                   10, false});
  {
    // L-shape [0,2]² minus [1,2]×[1,2]: a reflex corner of 270° at (1, 1), right angles elsewhere.
    intrinsic::MeshData d;
    d.nVertices = 8;
    d.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}};
    d.faces = {{0, 1, 4}, {0, 4, 7}, {1, 2, 3}, {1, 3, 4}, {7, 4, 5}, {7, 5, 6}};
    DiskSurface s{intrinsic::toTriangulation(d), {}};
    for (const auto& p : d.positions) s.positions.emplace_back(p.x(), p.y());
    cases.push_back({"L-shape (270° reflex corner)", s, 4.0, true});
  }
  return cases;
}

// Refines a planar case at shape bound B under `rule` and checks every bound (λ = 3x where graded; the size bound that
// holds everywhere is ε·e^(−min λ)) and the input locations against the plane positions.
RefineResult refinePlanarCase(const PlanarCase& c, double B, SegmentRule rule) {
  RefineOptions o;
  o.epsilon = c.eps;
  o.ratioBound = B;
  o.segmentRule = rule;
  // Regression cap, calibrated on earlier runs (20–1 210 insertions with Ruppert's rules, 20–1 500 with Chew's, at
  // b32757c), not derived: no size bound is proved below B = √2. A cascade would exceed it by orders of magnitude.
  o.maxInsertions = 20000;
  if (c.graded)
    for (const auto& p : c.surface.positions) o.lambda.push_back(3 * p.x());
  INFO(c.name << ", B = " << B);
  RefineResult r;
  REQUIRE_NOTHROW(r = refineDelaunay(c.surface.tri, o));
  double lambdaMin = 0;
  for (double l : o.lambda) lambdaMin = std::min(lambdaMin, l);
  checkBounds(c.surface.tri, r, c.eps * std::exp(-lambdaMin), B);
  CHECK(r.statistics.boundarySplits > 0);
  CHECK(worstLocatedLengthError(c.surface, r.triangulation, r.locations) < 1e-10);
  return r;
}

// Curved backgrounds with a boundary (split at geodesic midpoints): regular hexagons fanned from their centre, with
// right-angled corners in H² (triangle angles 60°, 45°, 45°: cosh(side) = 2, cosh(radius) = √3) and 150° corners on
// S² (angles 60°, 75°, 75°: cos(side) = (cos 60° + cos² 75°)/sin² 75°, cos(radius) = cos 75°·(1 + cos 60°)/(sin 60°
// sin 75°)), both by the (hyperbolic / spherical) law of cosines for angles.
std::vector<IntrinsicTriangulation> curvedHexagons() {
  const double c75 = std::cos(75 * M_PI / 180), s75 = std::sin(75 * M_PI / 180);
  std::vector<IntrinsicTriangulation> hexagons{
      regularHexagonFan(intrinsic::Background::Hyperbolic, std::acosh(std::sqrt(3.0)), std::acosh(2.0)),
      regularHexagonFan(intrinsic::Background::Spherical, std::acos(c75 * 1.5 / (std::sqrt(0.75) * s75)),
                        std::acos((0.5 + c75 * c75) / (s75 * s75)))};
  for (const IntrinsicTriangulation& in : hexagons) {
    const std::vector<double> sums = intrinsic::angleSums(in);
    REQUIRE(sums[0] == Approx(in.background == intrinsic::Background::Hyperbolic ? M_PI / 2 : 5 * M_PI / 6));
    REQUIRE(sums[6] == Approx(2 * M_PI));
  }
  return hexagons;
}

RefineResult refineHexagon(const IntrinsicTriangulation& in, double B, SegmentRule rule) {
  RefineOptions o;
  o.epsilon = in.background == intrinsic::Background::Hyperbolic ? 0.05 : 0.03;
  o.ratioBound = B;
  o.segmentRule = rule;
  // Regression cap, calibrated on earlier runs (900–2 460 insertions at b32757c), not derived (see refinePlanarCase).
  o.maxInsertions = 20000;
  INFO(intrinsic::toString(in.background) << " hexagon, B = " << B);
  RefineResult r;
  REQUIRE_NOTHROW(r = refineDelaunay(in, o));
  checkBounds(in, r, o.epsilon, B);
  return r;
}

TEST_CASE("shape bounds below sqrt(2) with boundaries (B = 1.12, 1.07): circles, polygons, small features terminate") {
  // Ruppert's theorem covers B ≥ √2 only (docs/refinement.md §6); below it termination with Ruppert's rules is
  // measured, not proved. Every run must stop by its bounds well inside a regression insertion cap calibrated on
  // earlier runs (8× the largest count measured; a cascade toward a
  // corner or a feature would hit it), with every triangle meeting the bounds, Delaunay, and the smallest angle
  // ≥ arcsin(1/(2B)) (26.5° at 1.12, 27.9° at 1.07).
  for (const PlanarCase& c : planarBelowSqrt2Cases())
    for (double B : {1.12, 1.07}) refinePlanarCase(c, B, SegmentRule::Ruppert);
  for (const IntrinsicTriangulation& in : curvedHexagons())
    for (double B : {1.12, 1.07}) refineHexagon(in, B, SegmentRule::Ruppert);
}

TEST_CASE(
    "Chew's second algorithm at B = sqrt(5)/2 and 1.12: free vertices deleted, every bound met, locations right") {
  // Shewchuk's bound √5/2 ≈ 1.1180 (26.57°) and 1.12 (26.5°) on the same domains. The output is constrained Delaunay
  // (a vertex may sit inside a segment's diametral circle), which is what checkBounds' test of the interior edges
  // asks. Deletions must happen in each geometry (planar disks, H², S²): the rule is not inert on these domains
  // (measured: 5–128 per planar domain, 107 on the hyperbolic and 140 on the spherical hexagon, none refused).
  std::int64_t planar = 0;
  for (const PlanarCase& c : planarBelowSqrt2Cases())
    for (double B : {std::sqrt(5.0) / 2, 1.12}) {
      const RefineResult r = refinePlanarCase(c, B, SegmentRule::Chew);
      planar += r.statistics.deletedVertices;
      CHECK(r.statistics.refusedDeletions == 0);
    }
  CHECK(planar > 0);
  for (const IntrinsicTriangulation& in : curvedHexagons())
    for (double B : {std::sqrt(5.0) / 2, 1.12}) {
      INFO(intrinsic::toString(in.background) << " hexagon, B = " << B);
      const RefineResult r = refineHexagon(in, B, SegmentRule::Chew);
      CHECK(r.statistics.deletedVertices > 0);
    }
}

TEST_CASE("frontal placement (Rebay) meets the same bounds in every geometry, with correct input locations") {
  // Frontal points are not circumcentres: they lie on the bisector of a front edge, inside the bad triangle's empty
  // circumdisk. The bounds, Delaunay, Gauss–Bonnet and signposts must hold as for circumcentres, and every vertex's
  // recorded input location must reproduce the lengths of its edges (disk: plane positions; sphere: great circles).
  const EveryGeometry g;
  // The ε are chosen so that proper frontal points occur (measured: 3 to a few hundred per run); on a coarse input
  // refined only a little none may (no triangle is far enough above its target next to a good one), and then the
  // option only changes the order in which bad triangles are served.
  for (const GeometryCase& c :
       {g.diskCase(0.05, false), g.diskCase(0.15, true), g.sphereCase(0.05), g.octagonCase(0.15), g.torusCase(0.04)}) {
    RefineOptions o;
    o.epsilon = c.eps;
    o.frontal = true;
    const double lambdaMin = c.graded ? gradeLinearly(g.d, o) : 0;
    INFO(intrinsic::toString(c.in->background) << (c.graded ? " graded" : " uniform") << ", eps " << c.eps);
    const RefineResult r = refineDelaunay(*c.in, o);
    checkBounds(*c.in, r, c.eps * std::exp(-lambdaMin), std::sqrt(2.0));
    CHECK(r.statistics.frontalInsertions > 0);
    if (c.located) CHECK(c.located(r) < 1e-10);
  }
}

TEST_CASE("smoothing passes keep the bounds, Delaunay and the input locations, and raise the mean smallest angle") {
  // RefineOptions::smoothingPasses moves free vertices (vertex_smoothing.h), restores Delaunay and re-runs the
  // refinement loop, so every bound must hold as without smoothing; the located points must still reproduce every
  // edge length (disk: plane positions, sphere: great circles), and on the graded disk (λ = 1.5x, linear, so its
  // interpolant is exact) every circumradius must stay below ε·e^(−λ) at the circumcentre, computed from the
  // located points.
  const EveryGeometry g;
  for (const GeometryCase& c : {g.diskCase(0.08, true), g.sphereCase(0.05), g.octagonCase(0.15), g.torusCase(0.03)}) {
    RefineOptions o;
    o.epsilon = c.eps;
    const double lambdaMin = c.graded ? gradeLinearly(g.d, o) : 0;
    INFO(intrinsic::toString(c.in->background) << (c.graded ? " graded" : " uniform") << ", eps " << c.eps);
    const RefineResult plain = refineDelaunay(*c.in, o);
    o.smoothingPasses = 3;
    const RefineResult r = refineDelaunay(*c.in, o);
    checkBounds(*c.in, r, c.eps * std::exp(-lambdaMin), std::sqrt(2.0));
    CHECK(r.statistics.smoothingMoves > 0);
    const double before = measureQuality(plain.triangulation).meanMinAngleDeg;
    const double after = measureQuality(r.triangulation).meanMinAngleDeg;
    INFO("mean smallest angle " << before << "° -> " << after << "°, moves " << r.statistics.smoothingMoves
                                << ", insertions after smoothing " << r.statistics.insertionsAfterSmoothing);
    CHECK(after > before + 0.5);
    if (c.located) CHECK(c.located(r) < 1e-10);
    if (c.graded) {
      const auto& m = r.triangulation.mesh;
      double worstRatio = 0;
      for (int f = 0; f < m.nFaces(); ++f) {
        Eigen::Vector2d p[3];
        for (int k = 0; k < 3; ++k) p[k] = g.d.locate(r.locations[m.faceVertex(f, k)]);
        const Eigen::Vector2d u = p[1] - p[0], v = p[2] - p[0];
        const double det = 2 * (u.x() * v.y() - u.y() * v.x());
        const Eigen::Vector2d cc = p[0] + Eigen::Vector2d(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(),
                                                          u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) /
                                              det;
        worstRatio =
            std::max(worstRatio, intrinsic::faceCircumradius(r.triangulation, f) / (c.eps * std::exp(-1.5 * cc.x())));
      }
      CHECK(worstRatio <= 1 + 1e-9);
    }
  }
}
