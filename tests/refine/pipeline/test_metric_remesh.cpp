// Tests for remesh.h: the whole pipeline on smooth metrics of each topology — the output is a homeomorphic image of
// the surface (no inverted triangle), its lengths come from the original metric (Gauss–Bonnet exact, area close to
// the smooth area), its circumradii respect ε, and its angles, measured with its own lengths, respect the shape bound.
#include <catch2/catch.hpp>

#include "support/gauss_bonnet_bound.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using namespace conformesh::refine;

namespace {
// ∫|K| dA over the Kerr horizon (Q = 0, Smarr 1973): K = (r₊² + a²)(r₊² − 3a² cos²θ)/(r₊² + a² cos²θ)³ with
// dA = (r₊² + a²) sin θ dθ dφ, by the midpoint rule in x = cos θ on 20000 cells (error ~1e-8 relative, the kinks of
// |K| included).
double kerrAbsCurvature(double M, double a) {
  const double rp = M + std::sqrt(M * M - a * a), s = rp * rp + a * a;
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -1 + (i + 0.5) * 2.0 / n, q = rp * rp + a * a * x * x;
    sum += std::abs(s * (rp * rp - 3 * a * a * x * x) / (q * q * q)) * s;
  }
  return 2 * M_PI * sum * 2.0 / n;
}

RemeshResult run(const SmoothMetric& m, double eps, int t0 = 10) {
  RemeshOptions o;
  o.epsilon = eps;
  o.t0Resolution = t0;
  return remeshMetric(m, o);
}
}  // namespace

TEST_CASE("remesh: closed surfaces of genus 0 and 1, and disks") {
  struct Case {
    std::unique_ptr<SmoothMetric> metric;
    double eps;
    double absCurvature;  // ∫|K| dA, closed form
    double absBoundary;   // ∫|k_g| ds, closed form
  };
  std::vector<Case> cases;
  // Ellipsoid: K > 0, so ∫|K| = ∫K = 4π. Torus (1, 0.4): ∫K = +4π on the outer half and −4π on the inner one.
  // Spherical cap R = 1, α = 1: K = 1 on area 2π(1 − cos α); boundary circle of length 2π sin α, k_g = cot α.
  cases.push_back({makeMetric("ellipsoid", {{"f", 0.3}}), 0.04, 4 * M_PI, 0});
  cases.push_back({makeMetric("kerr-newman", {{"a", 0.99}}), 0.08, kerrAbsCurvature(1.0, 0.99), 0});
  cases.push_back({makeMetric("torus", {{"R", 1.0}, {"r", 0.4}}), 0.04, 8 * M_PI, 0});
  cases.push_back({makeMetric("spherical-cap", {}), 0.05, 2 * M_PI * (1 - std::cos(1.0)), 2 * M_PI * std::cos(1.0)});
  for (const Case& c : cases) {
    const SmoothMetric& m = *c.metric;
    INFO(m.description());
    const RemeshResult r = run(m, c.eps);
    const int chi = m.domain().eulerCharacteristic();
    CHECK(r.mesh.mesh.eulerCharacteristic() == chi);
    CHECK(r.invertedTriangles == 0);
    // Gauss–Bonnet with the output's own lengths: Σ deficits + Σ turning = 2πχ.
    CHECK(std::abs(curvatureTotals(r.mesh).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(r.mesh.mesh.nFaces()));
    // Lengths are the metric's, so each flat face is the comparison triangle of a geodesic one: their areas differ by
    // K·A_f·(a² + b² + c²)/24 + O(ε⁴) (the spherical/hyperbolic excess expansion), and a² + b² + c² ≤ 9R² ≤ 9ε² for
    // circumradius R ≤ ε. Boundary chords cut off circular segments of area k_g ℓ³/12 ≤ k_g ε² ℓ/3 (ℓ ≤ 2ε). So
    // |A_mesh − A| ≤ ε² (3/8 ∫|K| dA + 1/3 ∫|k_g| ds), held with a factor 1.2 for the O(ε⁴) terms and R ≤ 1.05ε.
    // (The written lengths are of chart-straight curves, longer than geodesics by a further O(ℓ³) each; measured
    // errors are 0.05–0.55 of this bound, so it holds that term too on these charts: a measured margin, not derived.)
    const double area = metricArea(m).value;
    const double areaBound = 1.2 * c.eps * c.eps * (0.375 * c.absCurvature + c.absBoundary / 3);
    INFO("area error " << totalArea(r.mesh) - area << ", bound " << areaBound << " (former 2 %: " << 0.02 * area << ")");
    CHECK(std::abs(totalArea(r.mesh) - area) <= areaBound);
    // Quality in the original metric: the refinement's 20.7° bound survives the pull-back.
    CHECK(r.quality.minAngleDeg >= 20.7);
    CHECK(r.quality.meanMinAngleDeg >= 40);
    CHECK(r.mesh.mesh.nVertices() > r.t0Vertices);
  }
}

TEST_CASE("remesh: the conformal factor grades the mesh so that circumradii are at most ε in the original metric") {
  // Kerr with a = 0 is the round sphere of radius r₊ = 2M: the smooth λ ≡ log 2, so the uniformized bound ε·e^(−λ)
  // pulls back to ε. T0's lengths are arcs 2θ of that sphere while the flow compares chords (Penner lengths), so the
  // discrete λ is log 2 + log((θ/2)/sin(θ/2)) ≈ log 2 + θ²/24: below 1.7e-3 for T0's edges (θ ≤ 0.2 at resolution 10).
  const auto m = makeMetric("kerr-newman", {{"a", 0.0}});
  const double eps = 0.1;
  const RemeshResult r = run(*m, eps);
  for (double l : r.lambda) CHECK(l == Approx(std::log(2.0)).margin(1.7e-3));
  // The pull-back of ε·e^(−λ): λ varies by at most 1.7e-3 over a face (above), and circumradii from arc lengths exceed
  // those from chords by the arcs' θ²/24 ≤ (ε/r₊)²/6 = 4.2e-4 relative (edges ≤ 2ε on the sphere of radius 2): the
  // bound ε·(1 + 1.7e-3 + 4.2e-4), held at 1 + 2.5e-3 (the former 5 % was twenty times looser).
  INFO("max circumradius / eps " << r.quality.maxCircumradius / eps);
  CHECK(r.quality.maxCircumradius <= (1 + 2.5e-3) * eps);
  CHECK(r.quality.meanCircumradius > 0.5 * eps);
}

TEST_CASE(
    "remesh: the size threshold is eps itself — a flat torus of equilateral T0 refines at R0/1.005, not at R0/0.995") {
  // The bounds above hold with room (the Kerr sphere's largest circumradius is 0.88 ε), so a size test that is 1 %
  // too lax passes them. Pinned here: the hexagonal flat torus (τ = e^(iπ/3)) has K ≡ 0, its T0 is a lattice of
  // equilateral triangles of side 1/n in the original metric (circumradius R₀ = 1/(n√3)), the flow's λ is constant
  // (uniform lattice: every vertex alike; the flat target only rescales to its normalized area), so the grading
  // ε·e^(−λ) pulls back to exactly ε and the output lengths (straight chart segments of a flat metric) are exact.
  // Hence the pipeline must insert nothing at ε = R₀/(1 − δ) and refine every triangle below ε at ε = R₀/(1 + δ);
  // δ = 0.5 % catches the size threshold (ε, or the grading's scale e^(−λ)) or the output's length scale off by 1 % in
  // either direction. (Only the per-face test made 1 % stricter is masked here, by the quick pre-test at max λ = λ;
  // test_delaunay_refinement's λ bump catches that one.)
  const auto m = makeMetric("flat-torus", {{"tau_re", 0.5}, {"tau_im", std::sqrt(3.0) / 2}});
  const int n = 6;
  const double R0 = 1 / (n * std::sqrt(3.0)), delta = 5e-3;
  for (int sign : {-1, +1}) {
    INFO("eps = R0 / (1 " << (sign > 0 ? "+" : "-") << " delta)");
    const double eps = R0 / (1 + sign * delta);
    const RemeshResult r = run(*m, eps, n);
    REQUIRE(r.t0Vertices == n * n);
    INFO("max R / R0 " << r.quality.maxCircumradius / R0 << ", vertices " << r.mesh.mesh.nVertices());
    if (sign < 0) {
      CHECK(r.mesh.mesh.nVertices() == n * n);
      CHECK(r.quality.maxCircumradius == Approx(R0).epsilon(1e-12));
    } else {
      CHECK(r.mesh.mesh.nVertices() > n * n);
      CHECK(r.quality.maxCircumradius <= eps * (1 + 1e-9));
    }
  }
}

TEST_CASE("remesh: a Bezier patch with corners keeps its boundary and meets the 20.7 degree bound") {
  // The teapot body patch's chart is a rectangle: Auto flattens it keeping the boundary (boundary_flattening.h), so
  // λ = 0 on the boundary and the four corners stay corners of the domain, refined with straight (chord) sides.
  const auto m = makeMetric("teapot-patch", {{"patch", 4.0}});
  const double eps = 0.02;
  const RemeshResult r = run(*m, eps);
  REQUIRE(r.diskTarget == DiskTarget::KeepBoundary);
  CHECK(r.uniformization.target == UniformizationTarget::FlatKeepBoundary);
  CHECK(r.invertedTriangles == 0);
  CHECK(std::abs(curvatureTotals(r.mesh).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(r.mesh.mesh.nFaces()));
  // Ruppert's bound arcsin(1/(2√2)) = 20.7° with B = √2, in the ORIGINAL metric (the output's own lengths).
  CHECK(r.quality.minAngleDeg >= 20.7);
  CHECK(r.quality.meanMinAngleDeg >= 40);
  // The size bound in the flat domain, derived: the refinement leaves every T1* triangle with R* ≤ ε·e^(−λ(c)), λ(c)
  // the piecewise-linear interpolant of T0's λ at its circumcentre, whose minimum is attained at a T0 vertex (every one
  // is an output vertex): R* ≤ ε·e^(−min λ). Here min λ = 0, on the boundary (λ ≥ 0 inside, measured max 0.039), and
  // the largest R* is 0.9996 ε: a size test off by 1 % shows.
  const double lambdaMin = *std::min_element(r.lambda.begin(), r.lambda.end());
  INFO("min lambda " << lambdaMin << ", max R*/eps " << r.uniformQuality.maxCircumradius / eps << ", max R/eps "
                     << r.quality.maxCircumradius / eps);
  CHECK(r.uniformQuality.maxCircumradius <= eps * std::exp(-lambdaMin) * (1 + 1e-9));
  // In the original metric the bound is CALIBRATED, not derived. The Kerr case's error model (λ's variation over a
  // triangle, arcs against chords) predicts ε·(1 + max Δλ) = ε·(1 + 4.7e-3) here (the largest spread of λ over an
  // output triangle's corners is 4.7e-3), but the largest circumradius, 1.0269 ε, sits on a triangle at the boundary
  // where λ spreads by 1.6e-3 only: the excess comes from the pull-back's correspondence, which maps each T0* face
  // affinely onto its chart triangle, so that the Bézier metric's variation over one coarse T0 face (T0 of 209 vertices
  // for 7727 output ones, ~18 per T0 face; along the sides, the variation of the speed √g over a T0 boundary edge)
  // distorts the lengths of the small T1 triangles inside it. That term has no closed form for the teapot's metric; it
  // is held at the measurement + 0.3 % (the former 5 % let a 1 % length-scale error of the output through: 1.037 ε; a
  // size test 1 % too lax shows in R* above, not here: the largest R stays at 1.027 ε).
  constexpr double kTeapotMaxCircumradiusCalibratedMeasured1027 = 1.03;
  CHECK(r.quality.maxCircumradius <= kTeapotMaxCircumradiusCalibratedMeasured1027 * eps);
  // Chords against arcs: the area is the smooth area up to O(ε²) = 4e-4 relative.
  const double area = metricArea(*m).value;
  CHECK(std::abs(totalArea(r.mesh) - area) < 1e-3 * area);
  // Boundary vertices are on the chart's boundary (the refinement split the chords of T0's boundary edges, which the
  // correspondence keeps on T0's boundary edges), where λ = 0.
  int onBoundary = 0;
  for (int v = 0; v < r.mesh.mesh.nVertices(); ++v) {
    if (!r.mesh.mesh.isBoundaryVertex(v)) continue;
    ++onBoundary;
    const Eigen::Vector2d& c = r.chart[v];
    CHECK(std::min({c.x(), 1 - c.x(), c.y(), 1 - c.y()}) < 1e-12);
    CHECK(std::abs(r.lambda[v]) < 1e-12);
  }
  CHECK(onBoundary > 4 * 20);  // the sides were refined, not only T0's boundary kept
}

TEST_CASE("remesh: on the teapot patch the Gaussian curvature measure converges at order >= 1 in the mesh size") {
  // Theorem 3.4: e_G = mean |φ_T(B_v) − φ_M(B_v)| = O(ε). The smooth side integrates the metric's own K, independent
  // of the mesh's angles. Four sizes a factor √2 apart (≈ 1.1k to 8k vertices); the fitted slope must reach 0.9, the
  // issue's threshold (the full sweep measures 1.31, docs/studies.md).
  const auto m = makeMetric("teapot-patch", {{"patch", 4.0}});
  std::vector<double> meanR, eG;
  for (double eps : {0.056, 0.04, 0.028, 0.02}) {
    const RemeshResult r = run(*m, eps);
    REQUIRE(r.invertedTriangles == 0);
    CHECK(r.quality.minAngleDeg >= 20.7);
    const CurvatureMeasureResult g = gaussianCurvatureMeasure(r.mesh, r.reference, *m);
    meanR.push_back(r.quality.meanCircumradius);
    eG.push_back(g.meanAbsoluteError);
  }
  INFO("e_G " << eG[0] << " " << eG[1] << " " << eG[2] << " " << eG[3] << " slope " << fitLogLogSlope(meanR, eG));
  CHECK(fitLogLogSlope(meanR, eG) >= 0.9);
}

TEST_CASE("remesh: disk targets") {
  CHECK(parseDiskTarget("auto") == DiskTarget::Auto);
  CHECK(parseDiskTarget("circle") == DiskTarget::Circle);
  CHECK(parseDiskTarget("keep-boundary") == DiskTarget::KeepBoundary);
  CHECK_THROWS_WITH(parseDiskTarget("square"), Catch::Contains("'square'"));
  // A polar disk chart goes to the circle by default; a closed surface cannot keep a boundary it does not have.
  const auto cap = makeMetric("spherical-cap", {});
  CHECK(run(*cap, 0.1).diskTarget == DiskTarget::Circle);
  const auto sphere = makeMetric("sphere", {});
  RemeshOptions o;
  o.epsilon = 0.2;
  o.diskTarget = DiskTarget::KeepBoundary;
  CHECK_THROWS_WITH(remeshMetric(*sphere, o), Catch::Contains("topological disk"));
}

TEST_CASE("remesh: bad parameters are named") {
  const auto m = makeMetric("sphere", {});
  RemeshOptions o;
  o.epsilon = 0;
  REQUIRE_THROWS_WITH(remeshMetric(*m, o), Catch::Contains("--eps"));
  o.epsilon = NAN;
  REQUIRE_THROWS_WITH(remeshMetric(*m, o), Catch::Contains("--eps"));
}

TEST_CASE("RemeshOptions::validate names a bad eps, and is empty for valid options") {
  RemeshOptions o;
  CHECK_THAT(o.validate(), Catch::Contains("--eps") && Catch::Contains("found 0"));
  o.epsilon = INFINITY;
  CHECK_THAT(o.validate(), Catch::Contains("--eps"));
  o.epsilon = 0.05;
  CHECK(o.validate().empty());
}
