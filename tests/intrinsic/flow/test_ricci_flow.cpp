// test_ricci_flow.cpp — the Newton solver of the vertex-scaling flow: inadmissible targets are reported (not looped
// on), non-convergence names the residual reached, inputs with obtuse and near-degenerate triangles converge through
// Ptolemy flips (counted), cone targets are met, the inscribed-polygon radius is exact, and Newton is quadratic.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/conformal_energy.h"
#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/flow/ricci_flow.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

using namespace conformesh::intrinsic;

namespace {

ConformalTarget flatTarget(const HalfedgeMesh& m) {
  ConformalTarget t;
  t.angleSum.assign(m.nVertices(), 2 * M_PI);
  return t;
}

// A 960-vertex torus of revolution (120 × 8) with long thin triangles (n ≫ m·R/r) and random length perturbations of
// up to 30 %, which leave needles and caps with angles near π (the perturbation stays within the triangle inequality).
IntrinsicTriangulation perturbedTorus() {
  TorusOptions options;
  options.n = 120;
  options.m = 8;
  MeshData data = makeTorus(options);
  perturbLengths(data, 0.3, 11);
  return toTriangulation(data);
}

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST_CASE("inadmissible targets are reported, naming the vertex or the imbalance") {
  const IntrinsicTriangulation torus = toTriangulation(makeTorus({}));
  DiscreteConformalMetric metric(torus, Background::Euclidean);
  ConformalTarget t = flatTarget(torus.mesh);
  // Gauss–Bonnet: a flat torus with one cone of angle π has total curvature π ≠ 0 = 2πχ.
  t.angleSum[17] = M_PI;
  CHECK_THROWS_WITH(solveConformalFlow(metric, t), Catch::Contains("inadmissible") && Catch::Contains("Gauss"));
  // A balanced but non-positive cone angle.
  t.angleSum[17] = 0;
  t.angleSum[18] = 4 * M_PI;
  CHECK_THROWS_WITH(solveConformalFlow(metric, t), Catch::Contains("vertex 17"));
  // Hyperbolic metrics need positive area: Σ K̂ − 2πχ > 0, false for the flat targets on a torus.
  DiscreteConformalMetric hyperbolic(torus, Background::Hyperbolic);
  CHECK_THROWS_WITH(solveConformalFlow(hyperbolic, flatTarget(torus.mesh)), Catch::Contains("area"));
  // Spherical backgrounds are not solved by this (non-convex) energy.
  DiscreteConformalMetric sphere(torus, Background::Spherical);
  CHECK_THROWS_AS(solveConformalFlow(sphere, flatTarget(torus.mesh)), conformesh::InputError);
}

TEST_CASE("a flow stopped early reports the residual it reached") {
  const IntrinsicTriangulation torus = toTriangulation(makeTorus({}));
  DiscreteConformalMetric metric(torus, Background::Euclidean);
  RicciFlowOptions options;
  options.maxNewtonSteps = 1;
  CHECK_THROWS_WITH(solveConformalFlow(metric, flatTarget(torus.mesh), options),
                    Catch::Contains("1 Newton steps") && Catch::Contains("max |"));
}

TEST_CASE("stopAfterStep sees the angle sums of each accepted step and can end the flow there") {
  const IntrinsicTriangulation input = perturbedTorus();
  // Reference: the unstopped flow's residual after each step.
  std::vector<double> before;
  {
    DiscreteConformalMetric metric(input, Background::Euclidean);
    RicciFlowOptions flow;
    flow.onStep = [&](const NewtonStepInfo& s) { before.push_back(s.maxResidual); };
    solveConformalFlow(metric, flatTarget(input.mesh), flow);
  }
  REQUIRE(before.size() >= 4);
  DiscreteConformalMetric metric(input, Background::Euclidean);
  RicciFlowOptions flow;
  int calls = 0;
  double lastSeen = 0, sumsError = 0;
  flow.stopAfterStep = [&](const std::vector<double>& sums, double maxResidual) {
    ++calls;
    lastSeen = maxResidual;
    // The sums are those of the metric as it stands, and maxResidual is their largest deviation from 2π.
    const std::vector<double> now = flowAngleSums(metric);
    sumsError = std::max(sumsError, maxAbsDifference(sums, now));
    double worst = 0;
    for (double s : sums) worst = std::max(worst, std::abs(s - 2 * M_PI));
    CHECK(worst == maxResidual);
    return calls == 2;
  };
  const RicciFlowReport report = solveConformalFlow(metric, flatTarget(input.mesh), flow);
  CHECK(report.stoppedByCaller);
  CHECK(report.newtonSteps == 2);
  CHECK(calls == 2);
  CHECK(sumsError == 0);
  // Stopped where the unstopped flow stood after two steps: the residual entering step 3. Compared bit for bit across
  // two runs: this relies on the flow's parallel loops splitting their work into fixed ranges that write disjoint data
  // (two_threads.h, onTwoCores), so that the bits do not depend on which of the two threads ran which range.
  CHECK(report.maxResidual == lastSeen);
  CHECK(report.maxResidual == before[2]);
  CHECK(report.maxResidual > report.effectiveTolerance);
  // The report carries the angle sums at exit.
  CHECK(maxAbsDifference(report.angleSums, flowAngleSums(metric)) == 0);
}

TEST_CASE("obtuse and near-degenerate inputs converge through Ptolemy flips, quadratically") {
  const IntrinsicTriangulation input = perturbedTorus();
  double maxAngle = 0;
  for (int h = 0; h < input.mesh.nHalfedges(); ++h) maxAngle = std::max(maxAngle, cornerAngle(input, h));
  INFO("largest input angle " << maxAngle);
  CHECK(maxAngle > 2.8);
  DiscreteConformalMetric metric(input, Background::Euclidean);
  std::vector<double> residuals;
  RicciFlowOptions flow;
  flow.onStep = [&](const NewtonStepInfo& s) { residuals.push_back(s.maxResidual); };
  const RicciFlowReport report = solveConformalFlow(metric, flatTarget(input.mesh), flow);
  CHECK(report.flips > 0);
  CHECK(report.maxResidual < 1e-10);
  const IntrinsicTriangulation out = metric.triangulation();
  validateLengths(out);
  const std::vector<double> sums = angleSums(out);
  for (double s : sums) CHECK(std::abs(s - 2 * M_PI) < 1e-10);
  CHECK(countNonDelaunayEdges(out) == 0);
  // Quadratic convergence in the last full steps: r_{k+1} ≤ C r_k² with a moderate C, for every step that ends in
  // (1e-9, 1e-3) — below 1e-3 Newton is in its quadratic basin, above 1e-9 the residual is not yet round-off. onStep
  // sees the residual before each step, so the residual after the last step (report.maxResidual) closes the history.
  // At least one step must land in the window, or the loop would check nothing.
  residuals.push_back(report.maxResidual);
  int checked = 0;
  for (std::size_t k = 1; k < residuals.size(); ++k)
    if (residuals[k] < 1e-3 && residuals[k] > 1e-9) {
      INFO("step " << k - 1 << ": " << residuals[k - 1] << " -> " << residuals[k]);
      CHECK(residuals[k] < 100 * residuals[k - 1] * residuals[k - 1]);
      ++checked;
    }
  INFO(residuals.size() - 1 << " Newton steps");
  REQUIRE(checked >= 1);
}

TEST_CASE("a flat torus with two cones of angle π and 3π is met exactly") {
  const IntrinsicTriangulation torus = toTriangulation(makeTorus({}));
  DiscreteConformalMetric metric(torus, Background::Euclidean);
  ConformalTarget t = flatTarget(torus.mesh);
  t.angleSum[0] = M_PI;
  t.angleSum[700] = 3 * M_PI;
  const RicciFlowReport report = solveConformalFlow(metric, t);
  const std::vector<double> sums = angleSums(metric.triangulation());
  for (int v = 0; v < torus.mesh.nVertices(); ++v) CHECK(std::abs(sums[v] - t.angleSum[v]) < 1e-10);
  CHECK(report.gaugeFixed);
}

TEST_CASE("hyperbolic flow on a genus-2 surface reaches curvature −1 and area 4π") {
  const IntrinsicTriangulation surface = toTriangulation(makeGenusSurface({2, 3, 1.0}));
  DiscreteConformalMetric metric(surface, Background::Hyperbolic);
  std::fill(metric.u().begin(), metric.u().end(), -1.0);
  const RicciFlowReport report = solveConformalFlow(metric, flatTarget(surface.mesh));
  const IntrinsicTriangulation out = metric.triangulation();
  CHECK(report.maxResidual < 1e-10);
  CHECK(totalArea(out) == Approx(4 * M_PI).epsilon(1e-9));
  CHECK(std::abs(curvatureTotals(out).gaussBonnetResidual) < 1e-9);
  CHECK(countNonDelaunayEdges(out) == 0);  // Penner–Delaunay in chords is Delaunay in the hyperbolic metric
}

TEST_CASE("inscribed polygons: regular, and with the centre outside") {
  // Regular n-gon of side s: R = s / (2 sin(π/n)).
  const InscribedPolygon regular = inscribedPolygon(std::vector<double>(7, 0.3), 0);
  CHECK(regular.radius == Approx(0.3 / (2 * std::sin(M_PI / 7))).epsilon(1e-15));
  // Obtuse triangle 3-4-6: R = abc / (4 area) (Heron), centre outside: the long side's half angle exceeds π/2.
  const InscribedPolygon obtuse = inscribedPolygon({3, 4, 6}, 1);
  const double s = 6.5, area = std::sqrt(s * (s - 3) * (s - 4) * (s - 6));
  CHECK(obtuse.radius == Approx(3.0 * 4 * 6 / (4 * area)).epsilon(1e-14));
  CHECK(obtuse.side[2] == -1);
  CHECK(obtuse.halfAngle[0] + obtuse.halfAngle[1] + obtuse.halfAngle[2] == Approx(M_PI).epsilon(1e-15));
  CHECK_THROWS_WITH(inscribedPolygon({1, 1, 2.5}, 4), Catch::Contains("boundary loop 4"));
}

TEST_CASE("inscribed polygons with a side on the diameter: rectangles and right triangles") {
  // Rectangle a × b: its circle has the diagonal as diameter, R = √(a² + b²)/2, and φ = atan(a/b), atan(b/a) (Σ = π).
  // Here perimeter/2π < ℓ_max/2, so Newton from ℓ_max/2 (infinite dφ/dR) overshot: R came out too large.
  const InscribedPolygon rectangle = inscribedPolygon({1, 4, 1, 4}, 0);
  CHECK(rectangle.radius == Approx(std::sqrt(17.0) / 2).epsilon(1e-15));
  CHECK(rectangle.halfAngle[0] == Approx(std::atan(0.25)).epsilon(1e-15));
  CHECK(rectangle.halfAngle[1] == Approx(std::atan(4.0)).epsilon(1e-15));
  // Right triangle (CGAL's tetra_intersected_by_triangle.off, component 1): legs √0.5 and 0.1, hypotenuse √0.51 the
  // diameter. Its half-angles are the opposite angles; the hypotenuse's is π/2, which asin near 1 resolves only to
  // √ε ≈ 1.5·10⁻⁸ (the flow stalled there), so it is the complement of the others.
  const InscribedPolygon right = inscribedPolygon({std::sqrt(0.5), 0.1, std::sqrt(0.51)}, 0);
  CHECK(right.radius == Approx(std::sqrt(0.51) / 2).epsilon(1e-15));
  CHECK(std::abs(right.halfAngle[2] - M_PI / 2) < 1e-15);
  CHECK(std::abs(right.halfAngle[0] - std::atan(std::sqrt(0.5) / 0.1)) < 1e-15);
  CHECK(std::abs(right.halfAngle[0] + right.halfAngle[1] + right.halfAngle[2] - M_PI) < 1e-15);
}

TEST_CASE("the Penner Delaunay margin agrees with the angle test on valid triangles") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.2, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const double ab = U(rng), bc = U(rng), ca = U(rng), ad = U(rng), db = U(rng);
    if (!isValidTriangle(Background::Euclidean, ab, bc, ca) || !isValidTriangle(Background::Euclidean, ab, ad, db))
      continue;
    const double gc = angleOpposite(Background::Euclidean, ab, bc, ca),
                 gd = angleOpposite(Background::Euclidean, ab, ad, db);
    CHECK(pennerDelaunayMargin(ab, bc, ca, ad, db) == Approx(2 * (std::cos(gc) + std::cos(gd))).margin(1e-12));
  }
}

TEST_CASE("a reused Cholesky factor preconditioning conjugate gradients keeps the solution, saves factorizations") {
  const IntrinsicTriangulation input = perturbedTorus();
  DiscreteConformalMetric reused(input, Background::Euclidean), direct(input, Background::Euclidean);
  const RicciFlowReport a = solveConformalFlow(reused, flatTarget(input.mesh));
  RicciFlowOptions everyStep;
  everyStep.maxReuseIterations = 0;  // factor at every Newton step
  const RicciFlowReport b = solveConformalFlow(direct, flatTarget(input.mesh), everyStep);
  INFO("Newton steps " << a.newtonSteps << " / " << b.newtonSteps << ", factorizations " << a.factorizations << " / "
                       << b.factorizations << ", CG iterations " << a.cgIterations);
  CHECK(b.factorizations == b.newtonSteps);
  CHECK(a.factorizations < a.newtonSteps);
  CHECK(a.cgIterations > 0);
  CHECK(a.maxResidual < 1e-10);
  // Both stop within 1e-10 rad of the unique solution (same gauge vertex); the inverse cotangent Laplacian of this
  // 960-vertex torus amplifies angle residuals by at most ~10³ (its smallest non-zero eigenvalue is ~(2π/L)² with L the
  // torus length 2π(R + r)), so the conformal factors agree to 1e-7.
  CHECK(maxAbsDifference(reused.u(), direct.u()) < 1e-7);
}

TEST_CASE("SCOTCH nested dissection (RicciFlowOptions::nestedDissectionMin) keeps the solution of CHOLMOD's ordering") {
  // The perturbed torus, once ordered by CHOLMOD's default choice (AMD at this size) and once by the
  // SCOTCH call that large systems use; both also precondition conjugate gradients with the factor in single
  // precision, whose supernode tree is then the one of the given (postordered) order.
  const IntrinsicTriangulation input = perturbedTorus();
  DiscreteConformalMetric byCholmod(input, Background::Euclidean), byScotch(input, Background::Euclidean);
  const RicciFlowReport a = solveConformalFlow(byCholmod, flatTarget(input.mesh));
  RicciFlowOptions scotch;
  scotch.nestedDissectionMin = 0;
  const RicciFlowReport b = solveConformalFlow(byScotch, flatTarget(input.mesh), scotch);
  INFO("Newton steps " << a.newtonSteps << " / " << b.newtonSteps << ", CG iterations " << a.cgIterations << " / "
                       << b.cgIterations);
  CHECK_FALSE(a.nestedDissection);
  CHECK(b.nestedDissection);
  CHECK(b.cgIterations > 0);
  CHECK(b.maxResidual < 1e-10);
  const std::vector<double> sums = angleSums(byScotch.triangulation());
  for (int v = 0; v < input.mesh.nVertices(); ++v) CHECK(std::abs(sums[v] - 2 * M_PI) < 1e-10);
  // Within 1e-10 rad of the unique solution both: the conformal factors agree to 1e-7 (the bound of the test above).
  CHECK(maxAbsDifference(byCholmod.u(), byScotch.u()) < 1e-7);
}

TEST_CASE("a solver cache shared by Dirichlet problems with different fixed sets gives the uncached solutions") {
  const IntrinsicTriangulation torus = toTriangulation(makeTorus({}));
  const int nV = torus.mesh.nVertices();
  ConformalTarget first = flatTarget(torus.mesh), second = flatTarget(torus.mesh);
  first.fixed.assign(nV, 0);
  second.fixed.assign(nV, 0);
  for (int v = 0; v < 10; ++v) first.fixed[v] = 1;
  for (int v = 5; v < 12; ++v) second.fixed[v] = 1;  // a different Dirichlet set of another size
  DiscreteConformalMetric shared(torus, Background::Euclidean), alone(torus, Background::Euclidean);
  for (int v = 0; v < nV; ++v) shared.u()[v] = alone.u()[v] = 0.05 * std::sin(0.1 * v);  // fixed values ≠ 0
  RicciFlowOptions withCache;
  withCache.solverCache = makeFlowSolverCache();
  solveConformalFlow(shared, first, withCache);
  // The second solve starts from the first one's solution in both runs; only the cache differs.
  alone.u() = shared.u();
  const RicciFlowReport cached = solveConformalFlow(shared, second, withCache);
  const RicciFlowReport plain = solveConformalFlow(alone, second);
  CHECK(cached.factorizations == 0);  // the first solve's factor preconditions the second one
  CHECK(plain.factorizations >= 1);
  const std::vector<double> sums = angleSums(shared.triangulation());
  for (int v = 0; v < nV; ++v) {
    if (second.fixed[v]) {
      CHECK(shared.u()[v] == alone.u()[v]);  // Dirichlet values untouched (identity rows are not updated)
      continue;
    }
    CHECK(std::abs(sums[v] - 2 * M_PI) < 1e-10);
    CHECK(std::abs(shared.u()[v] - alone.u()[v]) < 1e-7);  // both within 1e-10 rad of the unique solution
  }
}

// --- the convex energy behind the line search (conformal_energy.h)

TEST_CASE("Milnor's Lobachevsky function: closed values, π-periodic, odd, Л' = −log|2 sin x|") {
  // Л(π/4) = G/2 (Catalan's constant), Л(π/6) = (3/2) Л(π/3), Л(π/2) = 0; to 1e-15 (a few ulps of the series).
  const double catalan = 0.915965594177219015054603514932;
  CHECK(std::abs(lobachevsky(M_PI / 4) - catalan / 2) < 1e-15);
  CHECK(std::abs(lobachevsky(M_PI / 6) - 1.5 * lobachevsky(M_PI / 3)) < 1e-15);
  CHECK(std::abs(lobachevsky(M_PI / 2)) < 1e-15);
  CHECK(std::abs(lobachevsky(0.3 + M_PI) - lobachevsky(0.3)) < 1e-15);
  CHECK(std::abs(lobachevsky(-0.7) + lobachevsky(0.7)) < 1e-15);
  // Central differences have error h² Л'''(x)/6 + O(h⁴): it falls by ≈ 4 when h halves (h = 1e-2, 5e-3).
  for (double x : {0.1, 0.5, 1.0, 1.4, 2.5, 3.0}) {
    auto fd = [&](double h) { return (lobachevsky(x + h) - lobachevsky(x - h)) / (2 * h); };
    const double exact = -std::log(2 * std::sin(x));
    const double e1 = std::abs(fd(1e-2) - exact), e2 = std::abs(fd(5e-3) - exact);
    INFO("x = " << x << ": errors " << e1 << ", " << e2);
    CHECK(e1 < 1.05 * 1e-4 / (6 * std::sin(x) * std::sin(x)));  // the leading term h² Л'''/6, Л''' = 1/sin²x
    CHECK(std::log2(e1 / e2) > 1.9);
    CHECK(std::log2(e1 / e2) < 2.1);
  }
}

TEST_CASE("the conformal energy's gradient is Θ̂ − Θ (central differences of order 2, across Ptolemy flips)") {
  DiscreteConformalMetric metric(perturbedTorus(), Background::Euclidean);
  const int nV = metric.nVertices();
  std::vector<double> target(nV, 2 * M_PI);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (double& u : metric.u()) u = 0.5 * uniform(rng);
  metric.makeDelaunay(1e-12, nullptr);
  const std::vector<double> u0 = metric.u();
  std::vector<double> d(nV);
  for (double& x : d) x = uniform(rng);
  auto energyAt = [&](double t, std::int64_t* flips) {
    for (int v = 0; v < nV; ++v) metric.u()[v] = u0[v] + t * d[v];
    const std::int64_t n = metric.makeDelaunay(1e-12, nullptr);
    if (flips) *flips += n;
    return conformalEnergy(metric, target);
  };
  energyAt(0, nullptr);
  const std::vector<double> sums = flowAngleSums(metric);
  double slope = 0;  // (Θ̂ − Θ)·d
  for (int v = 0; v < nV; ++v) slope += (target[v] - sums[v]) * d[v];
  std::int64_t flips = 0;
  auto fd = [&](double h) { return (energyAt(h, &flips) - energyAt(-h, &flips)) / (2 * h); };
  const double e1 = std::abs(fd(0.02) - slope), e2 = std::abs(fd(0.01) - slope), e3 = std::abs(fd(0.005) - slope);
  INFO("slope " << slope << ", FD errors " << e1 << ", " << e2 << ", " << e3 << ", flips " << flips);
  CHECK(flips > 0);  // the differences cross Delaunay cells: E is C¹ across the flips
  // Observed order log2(e1/e2), log2(e2/e3) ≈ 2 (± 0.3: the third derivative jumps at flips).
  CHECK(std::log2(e1 / e2) > 1.7);
  CHECK(std::log2(e2 / e3) > 1.7);
  CHECK(e3 < 1e-4 * std::abs(slope));
  // Convex along the line: second differences over 200 points of t ∈ [−1, 1] are ≥ −1e-9 (round-off of E ~ 1e-12).
  std::vector<double> E;
  for (int i = 0; i <= 200; ++i) E.push_back(energyAt(-1 + 0.01 * i, &flips));
  double worst = 0;
  for (int i = 1; i < 200; ++i) worst = std::min(worst, E[i - 1] - 2 * E[i] + E[i + 1]);
  CHECK(worst > -1e-9);
}

TEST_CASE("the flat-torus flow descends the convex energy at every Newton step and converges") {
  DiscreteConformalMetric metric(perturbedTorus(), Background::Euclidean);
  const ConformalTarget target = flatTarget(metric.mesh());
  std::vector<double> energies;
  double magnitude = 0;
  energies.push_back(conformalEnergy(metric, target.angleSum, &magnitude));
  RicciFlowOptions options;
  options.onStep = [&](const NewtonStepInfo&) { energies.push_back(conformalEnergy(metric, target.angleSum)); };
  const RicciFlowReport report = solveConformalFlow(metric, target, options);
  CHECK(report.maxResidual <= report.effectiveTolerance);
  // Each accepted step lowers E or (near the solution, where the residual test decides) changes it by at most its
  // round-off, 64 ε Σ|terms| (conformal_energy.h, docs/ricci_flow.md §2).
  const double roundOff = 64 * std::numeric_limits<double>::epsilon() * magnitude;
  for (std::size_t i = 1; i < energies.size(); ++i) {
    INFO("step " << i << ": E " << energies[i - 1] << " -> " << energies[i]);
    CHECK(energies[i] <= energies[i - 1] + roundOff);
  }
  CHECK(energies.size() >= 3);
}
