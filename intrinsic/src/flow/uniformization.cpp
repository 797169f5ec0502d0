// uniformization.cpp — T0 → T0*: uniformize's dispatch by topology, the options' validation, the flat-torus,
// hyperbolic and flat-cylinder targets and the circle domains. The sphere is in sphere_puncture.cpp, the planar layout
// in planar_layout.cpp. See uniformization.h and docs/ricci_flow.md §3.
#include "conformesh/intrinsic/flow/uniformization.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include <Eigen/CholmodSupport>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"
#include "flow/boundary_split.h"
#include "flow/disk_double.h"
#include "flow/geodesic_half.h"
#include "flow/inscribed_disk.h"
#include "flow/linalg/supernodal_cholesky.h"
#include "flow/sphere_puncture.h"
#include "flow/uniformization_support.h"

namespace conformesh::intrinsic {

std::string toString(UniformizationTarget target) {
  switch (target) {
    case UniformizationTarget::Sphere:
      return "sphere";
    case UniformizationTarget::FlatTorus:
      return "flat-torus";
    case UniformizationTarget::Hyperbolic:
      return "hyperbolic";
    case UniformizationTarget::CircleDomain:
      return "circle-domain";
    case UniformizationTarget::FlatCylinder:
      return "flat-cylinder";
    case UniformizationTarget::HyperbolicGeodesicBoundary:
      return "hyperbolic-geodesic-boundary";
    case UniformizationTarget::FlatKeepBoundary:
      return "flat-keep-boundary";
  }
  return "unknown";
}

namespace {

// "UniformizationOptions::<name>: expected <what>, found <value>" in the manner of Ceres' IsValid.
std::string uniformizationExpected(const char* name, const char* what, double found) {
  std::ostringstream msg;
  msg.precision(17);
  msg << "UniformizationOptions::" << name << ": expected " << what << ", found " << found;
  return msg.str();
}

}  // namespace

std::string UniformizationOptions::validate() const {
  if (maxPunctureAttempts < 1) return uniformizationExpected("maxPunctureAttempts", ">= 1", maxPunctureAttempts);
  if (!(earlyReflexFactor >= 0) || !std::isfinite(earlyReflexFactor))
    return uniformizationExpected("earlyReflexFactor", "a finite value >= 0 (0: off)", earlyReflexFactor);
  if (!(centringTolerance >= 0) || !std::isfinite(centringTolerance))
    return uniformizationExpected("centringTolerance", "a finite value >= 0", centringTolerance);
  return flow.validate();  // the flow options every target's solve uses
}

double maxInteriorAngleSumError(const IntrinsicTriangulation& tri) {
  const std::vector<double> sums = angleSums(tri);
  double worst = 0;
  for (int v = 0; v < tri.mesh.nVertices(); ++v)
    if (!tri.mesh.isBoundaryVertex(v)) worst = std::max(worst, std::abs(sums[v] - 2 * M_PI));
  return worst;
}

double maxGeodesicBoundaryResidual(const IntrinsicTriangulation& tri, int* worstVertex) {
  const std::vector<double> sums = angleSums(tri);
  double worst = 0;
  for (int v = 0; v < tri.mesh.nVertices(); ++v) {
    const double e = std::abs(sums[v] - (tri.mesh.isBoundaryVertex(v) ? M_PI : 2 * M_PI));
    if (!(e <= worst)) {
      worst = e;
      if (worstVertex) *worstVertex = v;
    }
  }
  return worst;
}

double maxCircleDomainResidual(const IntrinsicTriangulation& tri, const ConformalTarget& target, int* worstVertex) {
  std::vector<double> sums = angleSums(tri), targets = target.angleSum;
  for (std::size_t i = 0; i < target.circleLoops.size(); ++i) {
    const ConformalTarget::CircleLoop& loop = target.circleLoops[i];
    const int len = static_cast<int>(loop.edges.size());
    std::vector<double> sides(len);
    for (int j = 0; j < len; ++j) sides[j] = tri.edgeLengths[loop.edges[j]];
    const std::vector<double> phi = inscribedPolygon(sides, static_cast<int>(i)).halfAngle;
    for (int j = 0; j < len; ++j) targets[loop.vertices[j]] = M_PI - loop.sign * (phi[j] + phi[(j + 1) % len]);
  }
  double worst = 0;
  for (int v = 0; v < tri.mesh.nVertices(); ++v) {
    const double e = std::abs(targets[v] - sums[v]);
    if (!(e <= worst)) {
      worst = e;
      if (worstVertex) *worstVertex = v;
    }
  }
  return worst;
}

namespace {

using detail::accumulate;
using detail::attachScale;
using detail::referencePenner;
using detail::withProgress;

Uniformization uniformizeConstant(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                  UniformizationReport report, Background geometry);
Uniformization uniformizeGeodesicBoundary(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                          const UniformizationReport& report, Background geometry);

// === circle domains (genus 0 with boundary)

// An annulus is conformal to {e^{−Λ} < |z| < 1}, Λ = 2π × its modulus. Its inner circle's points, in coordinates of
// the outer circle's frame, are resolved only to ε/e^{−Λ} relative (ε the double epsilon); beyond Λ = log(10⁻⁸/ε)
// ≈ 17.6 they cannot be circles to 10⁻⁸, the accuracy the tests ask of every loop.
const double kMaxAnnulusLogRadiusRatio = std::log(1e-8 / std::numeric_limits<double>::epsilon());
// Largest relative radius deviation of a laid-out loop from its circle accepted from the layout: the 10⁻⁸ that the
// pre-check above is derived from and that the tests ask of every loop, so that a circle domain is either circles to
// 10⁻⁸ or an error (docs/ricci_flow.md §3.3).
constexpr double kMaxLoopCircleDeviation = 1e-8;

// A lower bound on Λ = log(R/r) of the input's own (piecewise flat) annulus, by the Dirichlet principle: the harmonic
// measure of {r < |z| < R} (0 on one circle, 1 on the other) has energy 2π/Λ, the least among functions with these
// boundary values, and the piecewise-linear minimizer (cotan Laplacian) has at least that energy E, so Λ ≥ 2π/E.
// Scale-free (one sparse solve on the input lengths), unlike the circle domain itself. NaN if the solve fails.
double annulusLogRadiusRatioLowerBound(const IntrinsicTriangulation& tri, const std::vector<int>& loopA,
                                       const std::vector<int>& loopB) {
  const HalfedgeMesh& m = tri.mesh;
  const int nv = m.nVertices();
  std::vector<double> phi(nv, 0.0);
  std::vector<int> unknown(nv, 0);
  for (int v : loopA) unknown[v] = -1;
  for (int v : loopB) {
    unknown[v] = -1;
    phi[v] = 1;
  }
  int n = 0;
  for (int v = 0; v < nv; ++v) unknown[v] = unknown[v] == 0 ? n++ : -1;
  // E(φ) = Σ_h ½ cot θ_h (φ_tip − φ_tail)², θ_h the angle opposite halfedge h: the exact energy of the interpolant.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (int h = 0; h < m.nHalfedges(); ++h) {
    const double w = 0.5 * cotanOpposite(tri, h);
    const int a = unknown[m.tail(h)], b = unknown[m.tip(h)];
    if (a >= 0) entries.emplace_back(a, a, w);
    if (b >= 0) entries.emplace_back(b, b, w);
    if (a >= 0 && b >= 0) {
      entries.emplace_back(a, b, -w);
      entries.emplace_back(b, a, -w);
    }
    if (a >= 0 && b < 0) rhs[a] += w * phi[m.tip(h)];
    if (b >= 0 && a < 0) rhs[b] += w * phi[m.tail(h)];
  }
  if (n > 0) {  // else every vertex is on a loop and φ is already fixed
    Eigen::SparseMatrix<double> L(n, n);
    L.setFromTriplets(entries.begin(), entries.end());
    // One sparse Cholesky factorization, as in one Newton step of the flow.
    SupernodalCholesky solver;
    solver.compute(L);
    if (solver.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
    const Eigen::VectorXd x = solver.solve(rhs);
    if (!x.allFinite()) return std::numeric_limits<double>::quiet_NaN();
    for (int v = 0; v < nv; ++v)
      if (unknown[v] >= 0) phi[v] = x[unknown[v]];
  }
  double energy = 0;
  for (int h = 0; h < m.nHalfedges(); ++h) {
    const double d = phi[m.tip(h)] - phi[m.tail(h)];
    energy += 0.5 * cotanOpposite(tri, h) * d * d;
  }
  return energy > 0 ? 2 * M_PI / energy : std::numeric_limits<double>::quiet_NaN();
}

// Boundary loops as edge lists (halfedge indices move with flips; edge indices and their endpoints on the boundary
// do not), and which loop is the longest in the input metric (the outer circle).
struct BoundaryLoops {
  std::vector<std::vector<int>> edges, tips;  // per loop, in loop order
  int outer = 0;
};

BoundaryLoops boundaryLoopsOf(const IntrinsicTriangulation& input) {
  const std::vector<std::vector<int>> loopsH = input.mesh.boundaryLoops();
  BoundaryLoops loops;
  loops.edges.resize(loopsH.size());
  loops.tips.resize(loopsH.size());
  double longest = -1;
  for (std::size_t i = 0; i < loopsH.size(); ++i) {
    double total = 0;
    for (int h : loopsH[i]) {
      loops.edges[i].push_back(input.mesh.edge(h));
      loops.tips[i].push_back(input.mesh.tip(h));
      total += input.length(h);
    }
    if (total > longest) {
      longest = total;
      loops.outer = static_cast<int>(i);
    }
  }
  return loops;
}

// `options` with each progress line prefixed (the double's solves report as "double: …").
UniformizationOptions prefixedProgress(const UniformizationOptions& options, const std::string& prefix) {
  UniformizationOptions out = options;
  if (options.progress) out.progress = [&options, prefix](const std::string& line) { options.progress(prefix + line); };
  return out;
}

// The double's sphere (disk_double.h), kept for the half below when the restart fails too.
struct DoubleSphere {
  detail::DiskDouble twin;
  Uniformization sphere;
};

DoubleSphere solveDouble(const IntrinsicTriangulation& input, const UniformizationOptions& options) {
  DoubleSphere out{detail::doubleDisk(input), {}};
  const UniformizationOptions quiet = prefixedProgress(options, "double: ");
  UniformizationReport sphereReport;
  out.sphere = detail::uniformizeSphere(out.twin.surface, quiet, sphereReport);
  return out;
}

// u for a disk from the sphere of its double (disk_double.h): the double's total scaling w (λ = −w) plus the factor of
// the stereographic projection from the mirror pole p onto the equatorial plane, |σx − σy| = 2|x − y|/(|x − p||y − p|)
// (an inversion of radius √2 centred at p: vertex scaling is Möbius invariant, BPS 2015), so u = w + log 2 − 2 log|x −
// p|. The pole is −n, n the unit mean of x_v − x_v' over the disk's vertices (the solution is mirror-symmetric).
void startFromDouble(const IntrinsicTriangulation& input, const DoubleSphere& solved, DiscreteConformalMetric& metric) {
  const Uniformization& sphere = solved.sphere;
  const int n = input.mesh.nVertices();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int v = 0; v < n; ++v) normal += sphere.positions[v] - sphere.positions[solved.twin.mirror[v]];
  normal.normalize();
  for (int v = 0; v < n; ++v)
    metric.u()[v] = -sphere.lambda[v] + std::log(2.0) - 2 * std::log((sphere.positions[v] + normal).norm());
}

// The circle domain as the half of the double's sphere (detail::halveDoubleSphere): when boundary edges flipped away
// on the double, the disk's own flow (boundary edges kept) has no solution to reach; the half subdivides each crossing
// edge where it meets the mirror's great circle. Its residual is recomputed from its own lengths: interior |Θ − 2π|,
// boundary |Θ − (π − φ_prev − φ_next)| with φ = asin(ℓ/2) on the unit circle (§3.3), and held to the flow's tolerance;
// the boundary must lie on the unit circle to the layout check's 1e-8. Throws ConvergenceError otherwise.
Uniformization circleDomainFromHalf(const IntrinsicTriangulation& input, const DoubleSphere& solved,
                                    const UniformizationOptions& options, UniformizationReport report) {
  const detail::DiskHalf half = detail::halveDoubleSphere(input, solved.twin, solved.sphere);
  Uniformization out;
  out.uniform = half.plane;
  out.positions = half.positions;
  out.lambda = half.lambda;
  out.correspondence = FlowCorrespondence(0);
  for (const detail::HalfBoundaryVertex& q : half.inserted)
    out.insertedVertices.push_back({q.vertex, q.inputEdge, q.parameter});
  const std::vector<double> sums = angleSums(out.uniform);
  const HalfedgeMesh& m = out.uniform.mesh;
  double residual = 0;
  for (int v = 0; v < m.nVertices(); ++v)
    if (!m.isBoundaryVertex(v)) residual = std::max(residual, std::abs(sums[v] - 2 * M_PI));
  for (const std::vector<int>& loop : m.boundaryLoops())
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const double into = out.uniform.length(loop[(i + loop.size() - 1) % loop.size()]);
      const double theta = M_PI - std::asin(into / 2) - std::asin(out.uniform.length(loop[i]) / 2);
      residual = std::max(residual, std::abs(sums[m.tail(loop[i])] - theta));
    }
  double circle = 0;
  for (int v = 0; v < m.nVertices(); ++v)
    if (m.isBoundaryVertex(v)) circle = std::max(circle, std::abs(out.positions[v].norm() - 1));
  if (!(residual <= options.flow.tolerance) || !(circle <= 1e-8)) {
    std::ostringstream message;
    message.precision(3);
    message << "uniformize: half of the double: max |Θ̂ − Θ| = " << residual << " rad (tolerance "
            << options.flow.tolerance << "), boundary off the unit circle by " << circle << " (tolerance 1e-08)";
    throw ConvergenceError(message.str());
  }
  report.maxResidual = residual;
  report.effectiveTolerance = options.flow.tolerance;
  report.flips += solved.sphere.report.flips + half.delaunayFlips;
  report.newtonSteps += solved.sphere.report.newtonSteps;
  out.report = report;
  return out;
}

// The flow's report for a disk without interior vertices developed onto its circle (inscribed_disk.h), as if the flow
// had taken 0 Newton steps, but with the residual recomputed from the development's `lengths` (computed in quadruple
// precision and rounded once) instead of from the rounded u: at |u| ≈ 12 an ulp of u moves a length by ≈ 9·10⁻¹⁶
// relative, 8× the rounding of the length itself (ε/2), and a corner angle θ turns that into ≈ 9·10⁻¹⁶/θ in the angle
// sums (boeing.off's 32-vertex strip, θ = 2.9·10⁻⁶: 5.3·10⁻¹⁰ from the rounded u, where the flow stalled at
// 1.15·10⁻¹⁰; 4.0·10⁻¹¹ from the lengths rounded once; docs/ricci_flow.md §3.3). The tolerance is the flow's
// stopping rule (newton_flow.cpp).
RicciFlowReport developedDiskReport(const DiscreteConformalMetric& metric, const std::vector<double>& lengths,
                                    const ConformalTarget& target, const RicciFlowOptions& flowOptions) {
  IntrinsicTriangulation developed = metric.triangulation();
  developed.edgeLengths = lengths;
  RicciFlowReport report;
  report.effectiveTolerance =
      std::max(flowOptions.tolerance, flowOptions.relativeFloor * std::sqrt(double(metric.nVertices())));
  report.maxResidual = maxCircleDomainResidual(developed, target);
  std::vector<double> sides;
  for (int e : target.circleLoops[0].edges) sides.push_back(lengths[e]);
  report.circleRadii = {inscribedPolygon(sides, 0).radius};
  report.angleSums = angleSums(developed);
  return report;
}

// Which boundary edges a round of circleDomainWithSplitBoundary splits first (the other rule when that finds none).
enum class SplitRule { DegenerateFirst, WorstVertexFirst };
struct SplitRound {
  int round = 0;  // how many rounds of boundary splits the input has been through
  SplitRule rule = SplitRule::DegenerateFirst;
};

Uniformization circleDomainWithSplitBoundary(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                             const UniformizationReport& report, const IntrinsicTriangulation& stalled,
                                             const ConvergenceError& failed);
Uniformization splitBoundaryOnce(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                 const UniformizationReport& report, const IntrinsicTriangulation& stalled,
                                 const ConvergenceError& failed, SplitRound split);

// A disk with interior vertices for which every route failed: `what`, and the likely cause when it has a part without
// interior vertices whose own circle domain is beyond double precision (likely, not proven: the part's circle domain
// as a disk of its own is not the restriction of the whole disk's; boeing.off's component 117 was checked in 80 digits)
// (inscribed_disk.h; docs/ricci_flow.md §3.3, "Disks without interior vertices"). Only on this failure path, so that
// nothing that converges changes.
ConvergenceError diskFailure(const IntrinsicTriangulation& input, const std::string& what) {
  const std::string part = detail::unrepresentableBoundaryPart(referencePenner(input));
  return ConvergenceError(part.empty() ? what : what + "; the likely cause: " + part);
}

Uniformization uniformizeCircleDomain(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                      UniformizationReport report, SplitRound splitRound = {}) {
  report.target = UniformizationTarget::CircleDomain;
  DiscreteConformalMetric metric(referencePenner(input), Background::Euclidean);
  const HalfedgeMesh& m = metric.mesh();  // boundary edges are never flipped, so loops keep their halfedge edges
  FlowCorrespondence log(m.nFaces());
  const BoundaryLoops loops = boundaryLoopsOf(input);
  const std::vector<std::vector<int>>& loopEdges = loops.edges;
  const std::vector<std::vector<int>>& loopTips = loops.tips;
  const int outer = loops.outer;
  if (loopTips.size() == 2) {
    // On the reference chords: the Euclidean metric whose conformal class the flow works in (the input itself when
    // Euclidean).
    const double atLeast = annulusLogRadiusRatioLowerBound(referencePenner(input), loopTips[0], loopTips[1]);
    if (atLeast > kMaxAnnulusLogRadiusRatio) {
      // Its circle domain's inner circle would have radius at most e^{−Λ} of the outer one, below what planar double
      // coordinates resolve to 10⁻⁸: uniformize to the flat cylinder instead, the same conformal class by z = e^{w}.
      if (options.progress) {
        std::ostringstream line;
        line.precision(6);
        line << "annulus: log(R/r) >= " << atLeast << " (Dirichlet principle) > " << kMaxAnnulusLogRadiusRatio
             << ", beyond planar double precision: target the flat cylinder";
        options.progress(line.str());
      }
      report.target = UniformizationTarget::FlatCylinder;
      return uniformizeGeodesicBoundary(input, options, report, Background::Euclidean);
    }
  }
  ConformalTarget target;
  target.angleSum.assign(m.nVertices(), 2 * M_PI);
  for (std::size_t i = 0; i < loopEdges.size(); ++i) {
    ConformalTarget::CircleLoop loop;
    loop.edges = loopEdges[i];
    loop.vertices = loopTips[i];
    loop.sign = static_cast<int>(i) == outer ? 1.0 : -1.0;
    target.circleLoops.push_back(std::move(loop));
  }
  bool interior = false;
  for (int v = 0; v < m.nVertices(); ++v) interior = interior || !m.isBoundaryVertex(v);
  std::vector<double> developed;  // a disk without interior vertices: its lengths on the unit circle
  RicciFlowReport flow;
  bool onCircle = false;
  if (loopTips.size() == 1 && !interior) {
    // Developed onto its circle directly, its lengths computed in quadruple precision and rounded once; the flow
    // below runs only when those lengths miss the tolerance (it starts from the rounded u and polishes the round-off).
    developed = detail::inscribeDiskWithoutInterior(metric);
    flow = developedDiskReport(metric, developed, target, options.flow);
    onCircle = flow.maxResidual <= flow.effectiveTolerance;
    if (options.progress)
      options.progress(onCircle
                           ? "circle domain: no interior vertex, developed onto its circle"
                           : "circle domain: no interior vertex, developed onto its circle; polishing by the flow");
  }
  try {
    if (!onCircle) flow = solveConformalFlow(metric, target, withProgress(options, "circle domain"), &log);
  } catch (const ConvergenceError& failed) {
    if (loopTips.size() == 1 && !interior)
      throw detail::explainInscribedFailure(metric, options.flow.tolerance, failed);
    if (loopTips.size() == 2) {
      // An annulus: its flat cylinder, the same conformal class by z = e^{w}, with geodesic ends — through the double
      // where a boundary edge would have to flip (docs/ricci_flow.md §3.4).
      if (options.progress)
        options.progress(std::string("circle domain: ") + failed.what() + "; target the flat cylinder");
      report.target = UniformizationTarget::FlatCylinder;
      try {
        return uniformizeGeodesicBoundary(input, options, report, Background::Euclidean);
      } catch (const ConvergenceError& again) {
        throw ConvergenceError(std::string(failed.what()) + "; the flat cylinder: " + again.what());
      }
    }
    if (loopTips.size() != 1)
      return splitRound.round == 0
                 ? circleDomainWithSplitBoundary(input, options, report, metric.triangulation(), failed)
                 : splitBoundaryOnce(input, options, report, metric.triangulation(), failed, splitRound);
    // A disk: start again from its double's sphere, projected (docs/ricci_flow.md §3.3, "The double").
    if (options.progress)
      options.progress(std::string("circle domain: ") + failed.what() + "; restarting from the double");
    metric = DiscreteConformalMetric(referencePenner(input), Background::Euclidean);
    log = FlowCorrespondence(m.nFaces());
    std::unique_ptr<DoubleSphere> solved;
    try {
      solved = std::make_unique<DoubleSphere>(solveDouble(input, options));
      startFromDouble(input, *solved, metric);
      flow = solveConformalFlow(metric, target, withProgress(options, "circle domain from the double"), &log);
    } catch (const ConvergenceError& again) {
      if (!solved) throw diskFailure(input, std::string(failed.what()) + "; from the double's sphere: " + again.what());
      // The double converged but its boundary edges flipped: take its half, subdivided on the mirror (§3.3).
      if (options.progress)
        options.progress(std::string("circle domain from the double: ") + again.what() +
                         "; taking the half of the double's sphere");
      try {
        return circleDomainFromHalf(input, *solved, options, report);
      } catch (const ConvergenceError& half) {
        throw diskFailure(input, std::string(failed.what()) + "; from the double's sphere: " + again.what() +
                                     "; its half: " + half.what());
      }
    }
  }
  accumulate(report, flow);
  Uniformization out;
  if (onCircle) {
    // The development is on the unit circle to quadruple precision: rescaling by the radius measured in double
    // (1 to a few ulps) would round every length a second time.
    out.uniform = metric.triangulation();
    out.uniform.edgeLengths = developed;
  } else {
    // Scale so that the outer circle is the unit circle: lengths scale by e^{Δu}.
    const double shift = -std::log(flow.circleRadii[outer]);
    for (double& x : metric.u()) x += shift;
    out.uniform = metric.triangulation();
  }
  attachScale(out, metric.u(), log);
  const std::vector<Eigen::Vector2d> planar = layoutFlat(out.uniform);
  // Centre the outer circle at the origin: circumcentre of three well-spread outer vertices.
  const Eigen::Vector2d centre = fitLoopCircle(planar, loopTips[outer]).centre;
  // The flow makes every loop concyclic in its lengths; the layout must reproduce that, which it cannot once a loop is
  // too small for the outer circle's coordinates (a silent wrong domain otherwise).
  for (std::size_t i = 0; i < loopTips.size(); ++i) {
    const std::vector<int>& t = loopTips[i];
    const int k = static_cast<int>(t.size());
    const LoopCircle fit = fitLoopCircle(planar, t);
    const double deviation = fit.deviation, r = fit.radius;
    if (!(deviation <= kMaxLoopCircleDeviation) && loopTips.size() == 2) {
      // The pre-check's bound was below the limit but the modulus is not: the flat cylinder (see above).
      if (options.progress)
        options.progress(
            "annulus: the circle domain's layout does not resolve the inner circle to 1e-8; target the "
            "flat cylinder");
      report.target = UniformizationTarget::FlatCylinder;
      return uniformizeGeodesicBoundary(input, options, report, Background::Euclidean);
    }
    if (!(deviation <= kMaxLoopCircleDeviation)) {
      std::ostringstream message;
      message.precision(3);
      message << "uniformize: boundary loop " << i << " (" << k << " edges, through vertex " << t[0]
              << ") is laid out in the plane with relative radius deviation " << deviation << " > "
              << kMaxLoopCircleDeviation << " (radius " << r << " of the outer circle): the planar layout does not "
              << "resolve its circle";
      throw ConvergenceError(message.str());
    }
  }
  out.positions.resize(planar.size());
  for (std::size_t v = 0; v < planar.size(); ++v)
    out.positions[v] = Eigen::Vector3d(planar[v].x() - centre.x(), planar[v].y() - centre.y(), 0.0);
  out.report = report;
  return out;
}

// Boundary edges are split where the flow of a circle domain with several loops fails (docs/ricci_flow.md §3.3,
// "Boundary edges split"), on the input's own piecewise flat metric, and the flow starts again on the subdivision. Two
// ways a target is out of the flow's reach with boundary edges that never flip: a face degenerates against a boundary
// edge — an interior vertex crowds against the chord of its loop, the angle opposite that edge going to π
// (b9_mesh.off's component 2) — and a boundary vertex whose angle sum cannot come down to its circle's target (a small
// inner loop whose chords at that vertex are near a diameter: component 13). The rules: split the boundary edges whose
// opposite (extended) angle is at least kSplitOppositeAngle (far above the ≤ π/2 of a Delaunay boundary edge; the
// degenerate faces have π), or the two at the flow's worst vertex when it is on the boundary; a round takes one rule
// first and the other when the first finds nothing. Neither is a theorem: `uniformize` tries the degenerate-first
// chain, then the worst-vertex-first chain, each of at most kMaxBoundarySplitRounds rounds (each a whole flow), and
// every result is verified like any circle domain (angle sums, loops on their circles).
constexpr double kSplitOppositeAngle = 0.75 * M_PI;
constexpr int kMaxBoundarySplitRounds = 6;

std::vector<int> boundaryEdgesToSplit(const IntrinsicTriangulation& stalled, const ConvergenceError& failed,
                                      SplitRule rule) {
  std::vector<int> degenerate = detail::boundaryEdgesOpposite(stalled, kSplitOppositeAngle);
  std::vector<int> worst = detail::boundaryEdgesAt(stalled, failed.vertex());
  if (rule == SplitRule::WorstVertexFirst) std::swap(degenerate, worst);
  return degenerate.empty() ? worst : degenerate;
}

// The degenerate-first chain of rounds, then the worst-vertex-first chain, each from the input.
Uniformization circleDomainWithSplitBoundary(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                             const UniformizationReport& report, const IntrinsicTriangulation& stalled,
                                             const ConvergenceError& failed) {
  try {
    return splitBoundaryOnce(input, options, report, stalled, failed, {0, SplitRule::DegenerateFirst});
  } catch (const ConvergenceError& first) {
    try {
      return splitBoundaryOnce(input, options, report, stalled, failed, {0, SplitRule::WorstVertexFirst});
    } catch (const ConvergenceError& second) {
      throw ConvergenceError(std::string(failed.what()) + "; boundary edges split at degenerate faces first: " +
                             first.what() + "; at the worst vertex first: " + second.what());
    }
  }
}

// One round: the edges of the rule split on `input`, whose flow failed (`stalled`, `failed`), and the circle domain of
// the subdivision, its inserted vertices composed back onto `input`'s edges.
Uniformization splitBoundaryOnce(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                 const UniformizationReport& report, const IntrinsicTriangulation& stalled,
                                 const ConvergenceError& failed, SplitRound split) {
  const std::vector<int> edges = boundaryEdgesToSplit(stalled, failed, split.rule);
  if (split.round > 0 && (edges.empty() || split.round >= kMaxBoundarySplitRounds))
    throw ConvergenceError("after " + std::to_string(split.round) + " rounds, " + failed.what() +
                           (edges.empty() ? "; no boundary edge to split"
                                          : "; the cap of " + std::to_string(kMaxBoundarySplitRounds) + " rounds"));
  if (edges.empty()) throw ConvergenceError("no boundary edge to split");
  const detail::BoundarySplit subdivided = detail::splitBoundaryEdges(referencePenner(input), edges);
  if (options.progress) {
    std::ostringstream line;
    line << "circle domain: " << failed.what() << "; splitting " << edges.size() << " boundary edges ("
         << (split.rule == SplitRule::DegenerateFirst ? "degenerate faces" : "worst vertex") << " first, round "
         << split.round + 1 << ")";
    options.progress(line.str());
  }
  Uniformization out = uniformizeCircleDomain(subdivided.tri, options, report, {split.round + 1, split.rule});
  out.insertedVertices = detail::composeInserted(input, subdivided, out.insertedVertices);
  out.insertion = Uniformization::Insertion::BoundarySplits;
  out.correspondence = FlowCorrespondence(0);
  return out;
}

// === flat tori and hyperbolic surfaces (no boundary condition beyond the cone angles)

// Every boundary vertex of a flat annulus with angle sums π there lies on one of two closed geodesics, the two ends of
// a cylinder (circumference C, height H), which have one length. Checks that and returns log(2π/C), the shift of u
// (lengths × e^{shift}) that makes C = 2π, so that H is Λ = log(R/r) of the circle domain e^{−H} < |z| < 1 that
// z = e^{i(x + iy)} gives. Throws ConvergenceError when the two lengths differ by more than kMaxLoopCircleDeviation.
double cylinderLogScale(const IntrinsicTriangulation& current) {
  std::vector<double> loopLength;
  for (const std::vector<int>& loop : current.mesh.boundaryLoops()) {
    double length = 0;
    for (int h : loop) length += current.length(h);
    loopLength.push_back(length);
  }
  const double mismatch = std::abs(loopLength[0] - loopLength[1]) / std::max(loopLength[0], loopLength[1]);
  if (!(mismatch <= kMaxLoopCircleDeviation)) {
    std::ostringstream message;
    message.precision(3);
    message << "uniformize: flat cylinder: its two boundary geodesics have lengths " << loopLength[0] << " and "
            << loopLength[1] << " (relative difference " << mismatch << " > " << kMaxLoopCircleDeviation
            << "), which the two ends of a cylinder cannot have";
    throw ConvergenceError(message.str());
  }
  return std::log(2 * M_PI / (0.5 * (loopLength[0] + loopLength[1])));
}

Uniformization uniformizeConstant(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                  UniformizationReport report, Background geometry) {
  DiscreteConformalMetric metric(referencePenner(input), geometry);
  const HalfedgeMesh& m = metric.mesh();
  FlowCorrespondence log(m.nFaces());
  ConformalTarget target;
  target.angleSum.resize(m.nVertices());
  for (int v = 0; v < m.nVertices(); ++v) target.angleSum[v] = m.isBoundaryVertex(v) ? M_PI : 2 * M_PI;
  if (geometry == Background::Hyperbolic) {
    // Start at the scale whose small-triangle area matches the target area −2πχ (Gauss–Bonnet), so Newton starts in
    // its quadratic basin for fine meshes instead of walking there.
    double euclideanArea = 0;
    IntrinsicTriangulation flat = referencePenner(input);
    for (int f = 0; f < m.nFaces(); ++f) euclideanArea += faceArea(flat, f);
    const double u0 = 0.5 * std::log(-2 * M_PI * m.eulerCharacteristic() / euclideanArea);
    std::fill(metric.u().begin(), metric.u().end(), u0);
  }
  accumulate(report, solveConformalFlow(
                         metric, target,
                         withProgress(options, geometry == Background::Hyperbolic                    ? "hyperbolic"
                                               : report.target == UniformizationTarget::FlatCylinder ? "flat cylinder"
                                                                                                     : "flat torus"),
                         &log));
  if (report.target == UniformizationTarget::FlatCylinder) {
    const double shift = cylinderLogScale(metric.triangulation());
    for (double& x : metric.u()) x += shift;
    report.cylinderHeight = totalArea(metric.triangulation()) / (2 * M_PI);
  } else if (geometry == Background::Euclidean) {
    // Normalize the total area to 1: areas scale by e^{2Δu}.
    const IntrinsicTriangulation current = metric.triangulation();
    const double shift = -0.5 * std::log(totalArea(current));
    for (double& x : metric.u()) x += shift;
  }
  Uniformization out;
  out.uniform = metric.triangulation();
  attachScale(out, metric.u(), log);
  out.report = report;
  return out;
}

// === geodesic boundary through the double (docs/ricci_flow.md §3.4)

void addSolveCounts(UniformizationReport& report, const UniformizationReport& solve) {
  report.newtonSteps += solve.newtonSteps;
  report.flips += solve.flips;
  report.factorizations += solve.factorizations;
  report.cgIterations += solve.cgIterations;
  report.effectiveTolerance = std::max(report.effectiveTolerance, solve.effectiveTolerance);
}

// The target with geodesic boundary (hyperbolic, or the flat cylinder of an annulus) as the half of the double's
// closed uniformization: the double (disk_double.h, any topology: genus 2g + b − 1) has no boundary, so every edge may
// flip and the flow's existence theorem (Gu–Luo–Sun–Wu) covers it; its metric is mirror-symmetric, the input's boundary
// — the mirror's fixed set — is a union of closed geodesics, and the half is the target (geodesic_half.h). Edges that
// cross the mirror are halved there: boundary vertices inserted, located on the input's boundary through the double's
// flip log (insertedVertices), λ of the vertex whose edge they halve (its mirror image has the same by symmetry).
Uniformization geodesicBoundaryFromDouble(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                          UniformizationReport report, Background geometry) {
  const detail::DiskDouble twin = detail::doubleDisk(input);
  const UniformizationOptions quiet = prefixedProgress(options, "double: ");
  UniformizationReport closedReport;
  closedReport.target =
      geometry == Background::Hyperbolic ? UniformizationTarget::Hyperbolic : UniformizationTarget::FlatTorus;
  const Uniformization closed = uniformizeConstant(twin.surface, quiet, closedReport, geometry);
  const int n = input.mesh.nVertices();
  detail::GeodesicHalf half = detail::halveSymmetricDouble(closed.uniform, twin.mirror, n, closed.correspondence,
                                                           twin.surface.mesh, twin.diskFaces);
  // The inserted vertices are the split edges' midpoints.
  std::vector<FacePoint> midpoints;
  std::vector<detail::HalfBoundaryVertex> where(half.splitFrom.size());
  for (std::size_t i = 0; i < half.splitHalfedge.size(); ++i) {
    const int h = half.splitHalfedge[i];
    FacePoint p{HalfedgeMesh::face(h), {0, 0, 0}};
    p.bary[h % 3] = p.bary[HalfedgeMesh::next(h) % 3] = 0.5;
    midpoints.push_back(p);
    where[i].vertex = n + static_cast<int>(i);
  }
  detail::locateOnInputBoundary(input, twin, closed.uniform.mesh, closed.correspondence, midpoints, where);
  Uniformization out;
  out.uniform = std::move(half.half);
  out.lambda.assign(closed.lambda.begin(), closed.lambda.begin() + n);
  for (std::size_t i = 0; i < half.splitFrom.size(); ++i) {
    out.lambda.push_back(closed.lambda[half.splitFrom[i]]);
    out.insertedVertices.push_back({where[i].vertex, where[i].inputEdge, where[i].parameter});
  }
  if (report.target == UniformizationTarget::FlatCylinder) {
    const double shift = cylinderLogScale(out.uniform);
    for (double& l : out.uniform.edgeLengths) l *= std::exp(shift);
    for (double& l : out.lambda) l -= shift;
    report.cylinderHeight = totalArea(out.uniform) / (2 * M_PI);
  }
  out.correspondence = FlowCorrespondence(0);
  addSolveCounts(report, closed.report);
  report.maxResidual = maxGeodesicBoundaryResidual(out.uniform);
  if (!(report.maxResidual <= std::max(options.flow.tolerance, report.effectiveTolerance))) {
    std::ostringstream message;
    message.precision(3);
    message << "geodesic boundary from the double: the half's angle sums are off by " << report.maxResidual
            << " rad (tolerance " << options.flow.tolerance << "; the double's asymmetry " << half.asymmetry << ")";
    throw ConvergenceError(message.str());
  }
  if (options.progress)
    options.progress("double: halved, " + std::to_string(out.insertedVertices.size()) +
                     " boundary vertices inserted where its edges cross the mirror (faces split " +
                     std::to_string(half.splitFaces) + ", trapezoids " + std::to_string(half.trapezoids) + ", loops " +
                     std::to_string(half.splitLoops) + ")");
  out.report = report;
  return out;
}

// uniformizeConstant for a target with geodesic boundary, through the double when the flow that keeps the boundary
// edges fails (a boundary edge that would have to flip: a degenerate face or a Hessian that is not positive definite
// there).
Uniformization uniformizeGeodesicBoundary(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                          const UniformizationReport& report, Background geometry) {
  try {
    return uniformizeConstant(input, options, report, geometry);
  } catch (const ConvergenceError& failed) {
    if (options.progress) options.progress(std::string(failed.what()) + "; restarting from the double");
    try {
      return geodesicBoundaryFromDouble(input, options, report, geometry);
    } catch (const ConvergenceError& again) {
      throw ConvergenceError(std::string(failed.what()) + "; from the double: " + again.what());
    }
  }
}
}  // namespace

// === entry point

Uniformization uniformize(const IntrinsicTriangulation& input, const UniformizationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string problem = options.validate(); !problem.empty()) throw InputError("uniformize: " + problem);
  validateLengths(input, "uniformize");
  const std::vector<ComponentTopology> components = input.mesh.components();
  if (components.size() != 1)
    throw InputError("uniformize: the surface has " + std::to_string(components.size()) +
                     " connected components; uniformize each separately (uniformizeComponents)");
  UniformizationReport report;
  report.genus = components[0].genus;
  report.boundaryLoops = components[0].boundaryLoops;
  Uniformization out;
  if (report.boundaryLoops == 0 && report.genus == 0) {
    out = detail::uniformizeSphere(input, options, report);
  } else if (report.boundaryLoops == 0 && report.genus == 1) {
    report.target = UniformizationTarget::FlatTorus;
    out = uniformizeConstant(input, options, report, Background::Euclidean);
  } else if (report.boundaryLoops == 0) {
    report.target = UniformizationTarget::Hyperbolic;
    out = uniformizeConstant(input, options, report, Background::Hyperbolic);
  } else if (report.genus == 0) {
    out = uniformizeCircleDomain(input, options, report);
  } else {
    report.target = UniformizationTarget::HyperbolicGeodesicBoundary;
    out = uniformizeGeodesicBoundary(input, options, report, Background::Hyperbolic);
  }
  out.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

ComponentUniformization uniformizeComponents(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                             const ComponentFlow& flow) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string problem = options.validate(); !problem.empty()) throw InputError("uniformize: " + problem);
  validateLengths(input, "uniformize");
  ComponentUniformization out;
  out.components = splitComponents(input);
  const int n = static_cast<int>(out.components.size());
  for (int i = 0; i < n; ++i) {
    const MeshComponent& c = out.components[i];
    UniformizationOptions own = options;
    if (options.progress)
      own.progress = [&options, i, n](const std::string& line) {
        options.progress("component " + std::to_string(i) + "/" + std::to_string(n) + ": " + line);
      };
    // The component's own message keeps its own "uniformize: " prefix after the component's description.
    const std::string where = "uniformize: " + describeComponent(i, n, c.topology) + ": ";
    try {
      out.parts.push_back(flow ? flow(c.triangulation, own) : uniformize(c.triangulation, own));
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    } catch (const ConvergenceError& e) {
      throw ConvergenceError(where + e.what());
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string insertionReason(const Uniformization& u) {
  return u.insertion == Uniformization::Insertion::BoundarySplits ? "by splitting boundary edges"
                                                                  : "where the double's flipped edges cross its mirror";
}

std::string correspondenceUnavailable(const Uniformization& u) {
  if (u.insertedVertices.empty()) return "";
  const bool circles = u.report.target == UniformizationTarget::CircleDomain;
  return std::string(circles ? "the circle domain has " : "the surface with geodesic boundary has ") +
         std::to_string(u.insertedVertices.size()) + " boundary vertices inserted " + insertionReason(u);
}

}  // namespace conformesh::intrinsic
