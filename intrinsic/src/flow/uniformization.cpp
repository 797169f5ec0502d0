// uniformization.cpp — T0 → T0*: the discrete Ricci flow set up for each topology (sphere by puncture and stereographic
// projection, flat torus, hyperbolic, circle domains), the conformal factor and the correspondence. See
// uniformization.h and docs/ricci_flow.md.
#include "conformesh/intrinsic/flow/uniformization.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <sstream>

#include <Eigen/Cholesky>
#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/errors.h"
#include "flow/linalg/two_threads.h"

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

// === helpers shared by the targets

IntrinsicTriangulation referencePenner(const IntrinsicTriangulation& input) {
  IntrinsicTriangulation ref;
  ref.mesh = input.mesh;
  ref.background = Background::Euclidean;
  ref.edgeLengths.resize(input.edgeLengths.size());
  for (std::size_t e = 0; e < input.edgeLengths.size(); ++e)
    ref.edgeLengths[e] = pennerFromLength(input.background, input.edgeLengths[e]);
  return ref;
}

RicciFlowOptions withProgress(const UniformizationOptions& options, const std::string& stage) {
  RicciFlowOptions flow = options.flow;
  if (options.progress) {
    auto user = options.flow.onStep;
    auto progress = options.progress;
    flow.onStep = [user, progress, stage](const NewtonStepInfo& info) {
      std::ostringstream line;
      line.precision(3);
      line << stage << ": Newton step " << info.step << ", max |K - K^| = " << info.maxResidual << " rad, step length "
           << info.stepLength << ", flips " << info.flips;
      progress(line.str());
      if (user) user(info);
    };
  }
  return flow;
}

void accumulate(UniformizationReport& report, const RicciFlowReport& flow) {
  report.newtonSteps += flow.newtonSteps;
  report.flips += flow.flips;
  report.factorizations += flow.factorizations;
  report.cgIterations += flow.cgIterations;
  report.maxResidual = flow.maxResidual;
  report.effectiveTolerance = flow.effectiveTolerance;
}

// Records the total vertex scaling w of the flow in `out`: the correspondence's log scale, and λ. Vertex scaling
// multiplies lengths by e^{(w_i+w_j)/2}, i.e. by e^{w} where w is constant: the uniform metric is e^{2w} × the
// original, so the original is e^{2λ} × the uniform one with λ = −w.
void attachScale(Uniformization& out, const std::vector<double>& w, FlowCorrespondence& log) {
  out.lambda.resize(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) out.lambda[i] = -w[i];
  log.logScale = w;
  out.correspondence = std::move(log);
}

Uniformization uniformizeConstant(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                  UniformizationReport report, Background geometry);

// === circle domains (genus 0 with boundary)

// An annulus is conformal to {e^{−Λ} < |z| < 1}, Λ = 2π × its modulus. Its inner circle's points, in coordinates of
// the outer circle's frame, are resolved only to ε/e^{−Λ} relative (ε the double epsilon); beyond Λ = log(10⁻⁸/ε)
// ≈ 17.6 they cannot be circles to 10⁻⁸, the accuracy the tests ask of every loop.
const double kMaxAnnulusLogRadiusRatio = std::log(1e-8 / std::numeric_limits<double>::epsilon());
// Largest relative radius deviation of a laid-out loop from its circle accepted from the layout: the 10⁻⁸ that the
// pre-check above is derived from and that the tests ask of every loop, so that a circle domain is either circles to
// 10⁻⁸ or an error. Measured: 4·10⁻¹¹ / 1.3·10⁻¹⁰ on the real annulus (blobby_3cc), below 10⁻⁸ on cylinder grids up
// to Λ = 8; with the rotated layout (layoutFlat) a cylinder grid with Λ = 12 still comes out 2.7·10⁻⁶ off (refused).
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
    // One sparse Cholesky factorization, as in one Newton step of the flow (measured: 1.6·10⁹ instructions on a
    // 65 824-vertex annulus, of 2.8·10⁹ for the whole `conformesh uniformize` of it, which needs no Newton step).
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> solver(L);
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

// Centre of the circle through A, B, C.
Eigen::Vector2d circumcentre(const Eigen::Vector2d& A, const Eigen::Vector2d& B, const Eigen::Vector2d& C) {
  const double d = 2 * (A.x() * (B.y() - C.y()) + B.x() * (C.y() - A.y()) + C.x() * (A.y() - B.y()));
  return {
      (A.squaredNorm() * (B.y() - C.y()) + B.squaredNorm() * (C.y() - A.y()) + C.squaredNorm() * (A.y() - B.y())) / d,
      (A.squaredNorm() * (C.x() - B.x()) + B.squaredNorm() * (A.x() - C.x()) + C.squaredNorm() * (B.x() - A.x())) / d};
}

Uniformization uniformizeCircleDomain(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                      UniformizationReport report) {
  report.target = UniformizationTarget::CircleDomain;
  DiscreteConformalMetric metric(referencePenner(input), Background::Euclidean);
  const HalfedgeMesh& m = metric.mesh();  // boundary edges are never flipped, so loops keep their halfedge edges
  FlowCorrespondence log(m.nFaces());
  // Boundary loops as edge lists (halfedge indices move with flips; edge indices and their endpoints on the boundary
  // do not). The longest loop (in the input metric) becomes the outer circle.
  const std::vector<std::vector<int>> loopsH = input.mesh.boundaryLoops();
  std::vector<std::vector<int>> loopEdges(loopsH.size()), loopTips(loopsH.size());
  int outer = 0;
  double longest = -1;
  for (std::size_t i = 0; i < loopsH.size(); ++i) {
    double total = 0;
    for (int h : loopsH[i]) {
      loopEdges[i].push_back(input.mesh.edge(h));
      loopTips[i].push_back(input.mesh.tip(h));
      total += input.length(h);
    }
    if (total > longest) {
      longest = total;
      outer = static_cast<int>(i);
    }
  }
  if (loopsH.size() == 2) {
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
      return uniformizeConstant(input, options, report, Background::Euclidean);
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
  const RicciFlowReport flow = solveConformalFlow(metric, target, withProgress(options, "circle domain"), &log);
  accumulate(report, flow);
  std::vector<double> radius = flow.circleRadii;
  // Scale so that the outer circle is the unit circle: lengths scale by e^{Δu}.
  const double shift = -std::log(radius[outer]);
  for (double& x : metric.u()) x += shift;

  Uniformization out;
  out.uniform = metric.triangulation();
  attachScale(out, metric.u(), log);
  const std::vector<Eigen::Vector2d> planar = layoutFlat(out.uniform);
  // Centre the outer circle at the origin: circumcentre of three well-spread outer vertices.
  const std::vector<int>& tips = loopTips[outer];
  const int n = static_cast<int>(tips.size());
  const Eigen::Vector2d centre = circumcentre(planar[tips[0]], planar[tips[n / 3]], planar[tips[(2 * n) / 3]]);
  // The flow makes every loop concyclic in its lengths; the layout must reproduce that, which it cannot once a loop is
  // too small for the outer circle's coordinates (a silent wrong domain otherwise: measured on cylinder grids).
  for (std::size_t i = 0; i < loopTips.size(); ++i) {
    const std::vector<int>& t = loopTips[i];
    const int k = static_cast<int>(t.size());
    const Eigen::Vector2d c = circumcentre(planar[t[0]], planar[t[k / 3]], planar[t[(2 * k) / 3]]);
    const double r = (planar[t[0]] - c).norm();
    double deviation = 0;
    for (int v : t) deviation = std::max(deviation, std::abs((planar[v] - c).norm() - r) / r);
    if (!(deviation <= kMaxLoopCircleDeviation) && loopTips.size() == 2) {
      // The pre-check's bound was below the limit but the modulus is not: the flat cylinder (see above).
      if (options.progress)
        options.progress(
            "annulus: the circle domain's layout does not resolve the inner circle to 1e-8; target the "
            "flat cylinder");
      report.target = UniformizationTarget::FlatCylinder;
      return uniformizeConstant(input, options, report, Background::Euclidean);
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

// === flat tori and hyperbolic surfaces (no boundary condition beyond the cone angles)

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
    // Every boundary vertex has angle sum π: both loops are closed geodesics of a flat annulus, i.e. the two ends of a
    // cylinder (circumference C, height H), which have one length. Check that, then scale to C = 2π, so that H is
    // Λ = log(R/r) of the circle domain e^{−H} < |z| < 1 that z = e^{i(x + iy)} would give.
    const IntrinsicTriangulation current = metric.triangulation();
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
    const double shift = std::log(2 * M_PI / (0.5 * (loopLength[0] + loopLength[1])));
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

// === the sphere (closed genus 0)

// Vertices usable as the puncture: a simple star (distinct link vertices, none equal to the vertex), sorted so that the
// roundest links (smallest max/min ratio of the spoke lengths, i.e. the most uniform Dirichlet data) come first.
std::vector<int> punctureCandidates(const IntrinsicTriangulation& tri) {
  const HalfedgeMesh& m = tri.mesh;
  std::vector<std::pair<double, int>> scored;
  std::vector<int> seen(m.nVertices(), -1);
  for (int v = 0; v < m.nVertices(); ++v) {
    bool simple = true;
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    const int h0 = m.vertexHalfedge(v);
    int h = h0;
    do {
      const int a = m.tip(h);
      if (a == v || seen[a] == v) simple = false;
      seen[a] = v;
      lo = std::min(lo, tri.length(h));
      hi = std::max(hi, tri.length(h));
      h = m.nextOutgoing(h);
    } while (h != h0 && h != kInvalid);
    if (simple && m.vertexDegree(v) >= 3) scored.emplace_back(hi / lo, v);
  }
  std::sort(scored.begin(), scored.end());
  std::vector<int> out;
  for (const auto& s : scored) out.push_back(s.second);
  return out;
}

// Dijkstra distances from `source` along edges (initial guess of the conformal factor only).
std::vector<double> edgeDistances(const IntrinsicTriangulation& tri, int source) {
  const HalfedgeMesh& m = tri.mesh;
  std::vector<double> dist(m.nVertices(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  dist[source] = 0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    const int h0 = m.vertexHalfedge(v);
    int h = h0;
    do {
      const int a = m.tip(h);
      if (d + tri.length(h) < dist[a]) {
        dist[a] = d + tri.length(h);
        queue.emplace(dist[a], a);
      }
      h = m.nextOutgoing(h);
    } while (h != h0 && h != kInvalid);
  }
  return dist;
}

// Spherical geodesic length of the chord between two unit vectors, accurate for short chords.
double sphericalDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return 2 * std::asin(std::min(1.0, 0.5 * (a - b).norm()));
}

// Which of the reflex link vertices (in link order) leave the link in one round: no two consecutive on the link (their
// spokes share a face, one flip would destroy the other's quad), and the link keeps at least 3 vertices.
std::vector<int> releasableLinkVertices(const std::vector<int>& link, const std::vector<int>& reflex) {
  const std::size_t degree = link.size();
  std::vector<int> chosen;
  for (std::size_t s = 0; s < degree; ++s) {
    const bool prevChosen = !chosen.empty() && chosen.back() == link[(s + degree - 1) % degree];
    const bool wrapsToFirst = s + 1 == degree && !chosen.empty() && chosen.front() == link[0];
    if (std::find(reflex.begin(), reflex.end(), link[s]) != reflex.end() && !prevChosen && !wrapsToFirst &&
        degree - chosen.size() > 3)
      chosen.push_back(link[s]);
  }
  return chosen;
}

struct SphereAttempt {
  bool ok = false;
  std::string why;
};

SphereAttempt trySphere(const IntrinsicTriangulation& input, const UniformizationOptions& options, int inf,
                        Uniformization& out, UniformizationReport& report) {
  DiscreteConformalMetric metric(referencePenner(input), Background::Euclidean);
  const HalfedgeMesh& m = metric.mesh();
  FlowCorrespondence log(m.nFaces());
  const int nV = m.nVertices();

  // Star of ∞ frozen; link vertices Dirichlet: u_a = −2 log c_a∞ (then e^{u_a/2} c_a∞ = 1 for all a: the limit of
  // vertex scaling that sends ∞ to infinity, where all spokes become equally long). ∞ itself is in no active face.
  ConformalTarget target;
  target.angleSum.assign(nV, 2 * M_PI);
  target.fixed.assign(nV, 0);
  target.fixed[inf] = 1;
  std::vector<char> frozen(m.nFaces(), 0);
  std::vector<int> link;
  // Recomputes the star of ∞ after flips; returns false when the link is not simple (a vertex twice).
  auto updateStar = [&]() {
    std::fill(frozen.begin(), frozen.end(), 0);
    std::fill(target.fixed.begin(), target.fixed.end(), 0);
    target.fixed[inf] = 1;
    link.clear();
    const int h0 = m.vertexHalfedge(inf);
    int h = h0;
    do {
      frozen[HalfedgeMesh::face(h)] = 1;
      const int a = m.tip(h);
      if (a == inf || target.fixed[a]) return false;
      link.push_back(a);
      target.fixed[a] = 1;
      metric.u()[a] = -2 * std::log(metric.referencePenner(m.edge(h)));
      h = m.nextOutgoing(h);
    } while (h != h0);
    metric.setFrozenFaces(frozen);
    return true;
  };
  // Θ_a over the non-frozen faces at a, with the flow's extension (π, 0, 0) of faces violating the triangle inequality;
  // it decreases monotonically in u_a (∂θ_a/∂u_a = −½(cot θ_b + cot θ_c) < 0 in a valid face, the extension is locally
  // constant), from π·(#faces) at u_a → −∞ (a's edges short: θ_a = π in every face) to 0 at u_a → +∞.
  auto angleSumAt = [&](int a) {
    double sum = 0;
    const int h0 = m.vertexHalfedge(a);
    int h = h0;
    do {
      if (!frozen[HalfedgeMesh::face(h)]) {
        // Corner a of the face is opposite the edge of next(h); the edges of h and prev(h) meet at a.
        const double opposite = metric.length(m.edge(HalfedgeMesh::next(h))), b = metric.length(m.edge(h)),
                     c = metric.length(m.edge(HalfedgeMesh::prev(h)));
        if (isValidTriangle(Background::Euclidean, opposite, b, c))
          sum += angleOpposite(Background::Euclidean, opposite, b, c);
        else if (opposite >= b && opposite >= c)
          sum += M_PI;
      }
      h = m.nextOutgoing(h);
    } while (h != h0);
    return sum;
  };
  // Bisection for Θ_a(u_a) = 2π, bracketed by doubling steps from the current value (Θ_a is monotone); the bracket
  // shrinks to round-off. Without a bracket within 10³ (not expected: the limits above straddle 2π for ≥ 3 faces),
  // u_a is left alone and the global solve does the work.
  std::vector<int> released;
  auto solveVertexLocally = [&](int a) {
    double& ua = metric.u()[a];
    const double start = ua;
    const bool increase = angleSumAt(a) > 2 * M_PI;
    double lo = start, hi = start, step = 1;
    for (; step <= 1024; step *= 2) {
      ua = increase ? start + step : start - step;
      if ((angleSumAt(a) > 2 * M_PI) != increase) break;
      (increase ? lo : hi) = ua;
    }
    if (step > 1024) {
      ua = start;
      return;
    }
    (increase ? hi : lo) = ua;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
      ua = 0.5 * (lo + hi);
      (angleSumAt(a) > 2 * M_PI ? lo : hi) = ua;
    }
    ua = 0.5 * (lo + hi);
  };
  const std::vector<double> dist = edgeDistances(referencePenner(input), inf);
  for (int v = 0; v < nV; ++v) metric.u()[v] = v == inf ? 0.0 : -2 * std::log(dist[v]);
  if (!updateStar()) return {false, "the star of the puncture is not simple"};
  std::vector<double> spoke;

  // Solve the Dirichlet problem, then repair the star: a disk face that degenerated against a link edge ab (its
  // angle at i reached π) means ab must flip to i∞, i joining the link — Ptolemy gives e^{u_i/2} c_i∞ =
  // (ℓ_ai + ℓ_bi)/ℓ_ab, i.e. exactly the Dirichlet value at the moment of degeneration; a link vertex a with disk angle
  // sum Θ_a > π (reflex link polygon, so the stereographic image would fold) leaves the link by flipping its spoke a∞
  // to the link edge bc. Both are exact Penner flips; repeat until the star is stable.
  RicciFlowOptions flow = withProgress(options, "sphere (punctured plane)");
  flow.allowDegenerateFaces = true;
  // "Solve, repair, solve again": the first solves return as soon as a degenerate face stalls the line search (the
  // energy is only C¹ there), so the star is repaired early instead of after several short Newton steps.
  flow.returnAtDegenerateStall = true;
  flow.solverCache = makeFlowSolverCache(flow.maxReuseIterations, flow.nestedDissectionMin);
  // A reflex link vertex need not wait for a converged solve: once Newton converges quadratically, the angle sums move
  // by about the residual per step, and a disk angle sum above π + 10·(residual) does not come back below π
  // (UniformizationOptions::earlyReflexFactor). The solve stops there (stopAfterStep), and the round repairs as after a
  // solve: degenerate faces first, else it releases those vertices (measured on the 10⁶-vertex box: the two vertices
  // that the first repair adds are reflex by 0.097 rad after one Newton step at residual 10⁻³, and by 0.097 rad at the
  // solution; converging first cost two Newton steps). Each vertex is judged early at most once, so one misjudged and
  // put back on the link by a later repair is only released again at a solution: the rounds cannot cycle through early
  // judgements.
  std::vector<char> judgedEarly(nV, 0);
  auto clearlyReflex = [&](int a, const std::vector<double>& sums, double maxResidual) {
    return !judgedEarly[a] && sums[a] > M_PI + options.earlyReflexFactor * maxResidual;
  };
  if (options.earlyReflexFactor > 0)
    flow.stopAfterStep = [&](const std::vector<double>& sums, double maxResidual) {
      return std::any_of(link.begin(), link.end(), [&](int a) { return clearlyReflex(a, sums, maxResidual); });
    };
  for (int round = 0;; ++round) {
    const RicciFlowReport solved = solveConformalFlow(metric, target, flow, &log);
    accumulate(report, solved);
    // Early returns at a stall only until the first solve gets past its degenerate faces: afterwards reflex repairs
    // take vertices out of the link, and stopping the next solve at a degenerate face would put them straight back
    // (measured: a 2-cycle of rounds).
    if (!solved.stoppedAtDegenerate) flow.returnAtDegenerateStall = false;
    // All repairs of one kind are batched per round (each flip only touches its own quad; the faces it creates
    // around ∞ are marked frozen at once so that later candidates see the current star). A face's validity depends
    // only on its own lengths, which only the flips below change — and they freeze the faces they touch — so it is
    // tested for all faces first, on two threads.
    std::vector<char> valid(m.nFaces());
    onTwoCores(m.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
      for (auto f = static_cast<int>(begin); f < end; ++f) {
        double L[3];
        for (int k = 0; k < 3; ++k) L[k] = metric.length(m.edge(3 * f + k));
        valid[f] = frozen[f] || isValidTriangle(Background::Euclidean, L[0], L[1], L[2]);
      }
    });
    bool changed = false;
    for (int f = 0; f < m.nFaces(); ++f) {
      if (frozen[f] || valid[f]) continue;
      double L[3];
      for (int k = 0; k < 3; ++k) L[k] = metric.length(m.edge(3 * f + k));
      if (isValidTriangle(Background::Euclidean, L[0], L[1], L[2])) continue;
      const int k = L[0] >= L[1] ? (L[0] >= L[2] ? 0 : 2) : (L[1] >= L[2] ? 1 : 2);
      const int h = 3 * f + k, t = m.twin(h);
      const int i = m.tail(HalfedgeMesh::prev(h));
      if (t == kInvalid || !frozen[HalfedgeMesh::face(t)] || target.fixed[i]) continue;
      const int g = HalfedgeMesh::face(t);
      if (metric.flipPtolemy(m.edge(h), &log)) {
        changed = true;
        frozen[f] = frozen[g] = 1;  // both new faces contain ∞
        target.fixed[i] = 1;        // i is on the link now (its Dirichlet value is set by updateStar)
      }
    }
    if (!changed && solved.stoppedAtDegenerate) {
      // Nothing to repair: finish this solve on the C¹ extension (reflex vertices are only judged at a solution).
      flow.returnAtDegenerateStall = false;
      continue;
    }
    if (!changed) {
      // Reflex link vertices: at a solution, by more than the round-off of the angle sums (1e-9 rad); after an early
      // stop, the clearly reflex ones.
      const std::vector<double>& sums = solved.angleSums;
      std::vector<int> reflex;
      for (int a : link)
        if (solved.stoppedByCaller ? clearlyReflex(a, sums, solved.maxResidual) : sums[a] > M_PI + 1e-9)
          reflex.push_back(a);
      if (solved.stoppedByCaller)
        for (int a : reflex) judgedEarly[a] = 1;
      for (int a : releasableLinkVertices(link, reflex)) {
        int h = m.vertexHalfedge(inf);
        while (m.tip(h) != a) h = m.nextOutgoing(h);
        if (metric.flipPtolemy(m.edge(h), &log)) {
          changed = true;
          released.push_back(a);
        }
      }
      if (!changed && solved.stoppedByCaller) continue;  // none could go now: solve on, they are judged at the solution
    }
    if (!changed) break;
    if (options.progress)
      options.progress("sphere: star repair round " + std::to_string(round + 1) + ", link of " +
                       std::to_string(link.size()) + " vertices, last solve " + std::to_string(solved.newtonSteps) +
                       " Newton steps" +
                       (solved.stoppedAtDegenerate ? " (stopped at a degenerate face)"
                        : solved.stoppedByCaller   ? " (stopped at a clearly reflex vertex)"
                                                   : ""));
    if (round > 10 * nV) return {false, "the star of the puncture did not stabilize"};
    if (!updateStar()) return {false, "a star flip made the link of the puncture non-simple"};
    // A vertex released from the link keeps its Dirichlet value, which is far from its own equation's solution: the
    // angle sum responds weakly to u there (measured at 10⁵ vertices: the next solve took 7 Newton steps with full
    // steps, the residual stuck at that vertex, 1.3·10⁻³ → 1.1·10⁻³ in the first three). Solving its own equation
    // Θ_a(u_a) = 2π with its neighbours fixed first leaves Newton a smooth, nearly solved problem.
    for (int a : released) solveVertexLocally(a);
    released.clear();
  }
  flow.solverCache.reset();  // the factor (≈ 1 GB at 10⁶ vertices) is not needed for the layout
  for (int f = 0; f < m.nFaces(); ++f)
    if (!frozen[f]) {
      double L[3];
      for (int k = 0; k < 3; ++k) L[k] = metric.length(m.edge(3 * f + k));
      if (!isValidTriangle(Background::Euclidean, L[0], L[1], L[2]))
        return {false, "face " + std::to_string(f) + " stays degenerate next to the puncture's star"};
    }
  {
    int h = m.vertexHalfedge(inf);
    for (std::size_t s = 0; s < link.size(); ++s, h = m.nextOutgoing(h))
      spoke.push_back(metric.referencePenner(m.edge(h)));
  }

  // Lay out the plane, translate to the centroid and scale so the median |z| is 1 (a Möbius map of the sphere fixing
  // ∞, absorbed in the scale bookkeeping: lengths × ρ ⇔ u + log ρ, since ℓ = e^{(u_i+u_j)/2} c).
  // The closing test of layoutFlat is relative to the mean edge length, but the punctured plane spans many orders of
  // magnitude (spokes ~1/h near the link, ~h far from it) and the unfolding's round-off is relative to the coordinates.
  // The test below replaces it: every edge of the layout must have its flow length to 10⁻⁶ relative, or to
  // a = max(10⁻¹⁰, 10 ε sqrt(#V)) of its endpoints' coordinates, ε the flow's stopping tolerance (edges of 10⁻¹² on
  // CGAL's cow cannot be resolved at coordinates of order 1 and need not be: below, the lengths are taken from the
  // Penner form and the coordinates only enter through smooth conformal factors). The flow certifies the metric flat
  // to ε; this test catches a layout gone wrong (layoutFlat: the unfolding is built so that round-off does not grow
  // across short edges). The embedding is verified on the sphere below.
  IntrinsicTriangulation planarTri = metric.triangulation();
  std::vector<Eigen::Vector2d> z;
  try {
    z = layoutFlat(planarTri, std::numeric_limits<double>::infinity(), frozen);
  } catch (const ConvergenceError& e) {
    return {false, e.what()};
  }
  const double allowance = std::max(1e-10, 10 * report.effectiveTolerance * std::sqrt(double(nV)));
  auto laidOut = [&](int h) {
    const double length = planarTri.length(h), laid = (z[m.tip(h)] - z[m.tail(h)]).norm();
    return std::abs(laid - length) <= 1e-6 * length + allowance * (z[m.tip(h)].norm() + z[m.tail(h)].norm());
  };
  // Tested on two threads; the first failing edge in face order is reported.
  std::vector<char> faceLaidOut(m.nFaces(), 1);
  onTwoCores(m.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f)
      if (!frozen[f]) faceLaidOut[f] = laidOut(3 * f) && laidOut(3 * f + 1) && laidOut(3 * f + 2);
  });
  for (int f = 0; f < m.nFaces(); ++f) {
    if (frozen[f] || faceLaidOut[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + k;
      const double length = planarTri.length(h), laid = (z[m.tip(h)] - z[m.tail(h)]).norm();
      if (!laidOut(h)) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "the planar layout gives edge " << m.edge(h) << " the length " << laid << " instead of " << length
            << " (error " << std::abs(laid - length) << " at coordinates of size " << z[m.tip(h)].norm()
            << ", allowed 1e-6 of the length plus " << allowance << " of the coordinates)";
        return {false, msg.str()};
      }
    }
  }
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int v = 0; v < nV; ++v)
    if (v != inf) centroid += z[v];
  centroid /= (nV - 1);
  std::vector<double> radii;
  for (int v = 0; v < nV; ++v)
    if (v != inf) radii.push_back((z[v] - centroid).norm());
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double rho = 1.0 / std::max(radii[radii.size() / 2], 1e-300);
  std::vector<double> w(nV);
  std::vector<Eigen::Vector3d> x(nV);
  onTwoCores(nV, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto v = static_cast<int>(begin); v < end; ++v) {
      if (v == inf) continue;
      const Eigen::Vector2d p = rho * (z[v] - centroid);
      const double r2 = p.squaredNorm();
      // The y-reflection makes the map orientation preserving for the outward normal (stereographic projection from
      // the north pole reverses it); reflections do not change the conformal factor.
      x[v] = Eigen::Vector3d(2 * p.x(), -2 * p.y(), r2 - 1) / (r2 + 1);
      // Inverse stereographic projection scales chords by e^{(s_a+s_b)/2}, e^{s} = 2/(1+|p|²).
      w[v] = metric.u()[v] + std::log(rho) + std::log(2 / (1 + r2));
    }
  });
  x[inf] = Eigen::Vector3d(0, 0, 1);
  {
    double sum = 0;
    for (std::size_t i = 0; i < link.size(); ++i)
      sum += 2 * std::log((x[inf] - x[link[i]]).norm() / spoke[i]) - w[link[i]];
    w[inf] = sum / link.size();
  }

  // Möbius centring: move the centroid c of the input's area measure (vertex weights: a third of the input area of
  // each incident face, fixed — the sphere's own area measure would have centroid ≈ 0 for every configuration) to
  // the origin with the ball automorphism φ_c(x) = (1−|c|²)(x−c)/|x−c|² − c, whose conformal factor on the sphere is
  // |φ_c'(x)| = (1−|c|²)/|x−c|²; chords scale by sqrt(|φ'(x)||φ'(y)|), so w gains log |φ'|. Newton's method on the
  // centroid C(a) of the measure moved by φ_a: dφ_a(x)/da = 2(x xᵀ − I) at a = 0 for |x| = 1, so dC/da = −2(I − M)
  // with M = Σ ω x xᵀ / Σ ω (trace 1), and the step is a = ½ (I − M)⁻¹ C — (3/4) C for a uniform measure (M = I/3),
  // the fixed step used before, which converged linearly (28 iterations to 10⁻¹² on the 10⁵-vertex box). Steps are
  // capped at |a| ≤ 0.5; where I − M is nearly singular (the measure close to a pair of antipodal points) the step
  // falls back to (3/4) C.
  std::vector<double> weight(nV, 0.0);
  {
    const IntrinsicTriangulation flat = referencePenner(input);
    for (int f = 0; f < input.mesh.nFaces(); ++f)
      for (int k = 0; k < 3; ++k) weight[input.mesh.faceVertex(f, k)] += faceArea(flat, f) / 3;
  }
  for (int it = 0; it < 100; ++it) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    double total = 0;
    for (int v = 0; v < nV; ++v) {
      c += weight[v] * x[v];
      moment += weight[v] * x[v] * x[v].transpose();
      total += weight[v];
    }
    c /= total;
    moment /= total;
    if (c.norm() <= options.centringTolerance) break;
    const Eigen::Matrix3d jacobian = 2 * (Eigen::Matrix3d::Identity() - moment);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> spectrum(jacobian, Eigen::EigenvaluesOnly);
    // Its eigenvalues are 4/3 for a uniform measure and tend to 0 as the measure concentrates on two antipodal points;
    // below 0.2 the linearization is not trusted.
    c = spectrum.eigenvalues().minCoeff() > 0.2 ? Eigen::Vector3d(jacobian.ldlt().solve(c)) : Eigen::Vector3d(0.75 * c);
    if (c.norm() > 0.5) c *= 0.5 / c.norm();
    const double k = 1 - c.squaredNorm();
    onTwoCores(nV, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
      for (auto v = begin; v < end; ++v) {
        const double d2 = (x[v] - c).squaredNorm();
        w[v] += std::log(k / d2);
        x[v] = (k * (x[v] - c) / d2 - c).normalized();
      }
    });
    report.centringIterations = it + 1;
  }

  // The spherical triangulation: geodesic triangles on the points. Inverse stereographic projection and the Möbius
  // maps scale chords by vertex factors exactly (|φ(x) − φ(y)| = sqrt(|φ'(x)||φ'(y)|) |x − y|), so every chord is also
  // e^{(w_i+w_j)/2} c⁰_ij, the Penner form of the flow's metric. Lengths from the points give angle sums 2π to
  // round-off whatever the flow residual, but chords of unit vectors carry an absolute round-off of ~10⁻¹⁶: on thin
  // appendages whose conformal factor reaches 10⁻¹⁵ (CGAL's cow: its tail collapses to one double-precision point) they
  // are meaningless. So the points are used when every chord is at least 10⁻⁴ (relative round-off below ~10⁻¹²), and
  // otherwise every edge takes the Penner form, exact to round-off at any scale, whose angle sums are 2π to the flow
  // residual (mixing both would not be: the two differ by the layout's accumulated error). Faces are checked for
  // positive orientation of their points where these resolve them; every face must be a valid spherical triangle and
  // every angle sum 2π (to 10⁻⁸): a spherical metric without cone points on a genus-0 surface is the round sphere, so
  // this certifies an embedded geodesic triangulation (a non-convex flattened link shows up here).
  IntrinsicTriangulation sphere;
  sphere.mesh = m;
  sphere.background = Background::Spherical;
  sphere.edgeLengths.resize(m.nEdges());
  std::vector<char> fromPoints(m.nEdges(), 1);
  bool allResolved = true;
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    fromPoints[e] = (x[m.tail(h)] - x[m.tip(h)]).norm() >= 1e-4;
    allResolved = allResolved && fromPoints[e];
  }
  onTwoCores(m.nEdges(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto e = static_cast<int>(begin); e < end; ++e) {
      const int h = m.edgeHalfedge(e), a = m.tail(h), b = m.tip(h);
      sphere.edgeLengths[e] = allResolved ? sphericalDistance(x[a], x[b])
                                          : lengthFromPenner(Background::Spherical,
                                                             metric.referencePenner(e) * std::exp(0.5 * (w[a] + w[b])));
    }
  });
  report.pennerLengths = !allResolved;
  // Faces and corner angles on two threads; the first failing face is reported, the angle sums are added in
  // halfedge order.
  std::vector<char> faceGood(m.nFaces());
  onTwoCores(m.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f) {
      const Eigen::Vector3d &a = x[m.faceVertex(f, 0)], &b = x[m.faceVertex(f, 1)], &c = x[m.faceVertex(f, 2)];
      const bool resolved = fromPoints[m.edge(3 * f)] && fromPoints[m.edge(3 * f + 1)] && fromPoints[m.edge(3 * f + 2)];
      faceGood[f] = !(resolved && !((b - a).cross(c - a).dot(a + b + c) > 0)) &&
                    isValidTriangle(Background::Spherical, sphere.length(3 * f), sphere.length(3 * f + 1),
                                    sphere.length(3 * f + 2));
    }
  });
  for (int f = 0; f < m.nFaces(); ++f) {
    if (!faceGood[f]) {
      std::ostringstream msg;
      msg.precision(3);
      msg << "face " << f << " is not positively oriented on the sphere (side lengths " << sphere.length(3 * f) << ", "
          << sphere.length(3 * f + 1) << ", " << sphere.length(3 * f + 2) << ")";
      return {false, msg.str()};
    }
  }
  const std::vector<double> sums = [&] {
    std::vector<double> corner(m.nHalfedges()), s(nV, 0.0);
    onTwoCores(m.nHalfedges(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
      for (auto h = static_cast<int>(begin); h < end; ++h) corner[h] = cornerAngle(sphere, h);
    });
    for (int h = 0; h < m.nHalfedges(); ++h) s[m.tail(h)] += corner[h];
    return s;
  }();
  for (int v = 0; v < nV; ++v)
    if (std::abs(sums[v] - 2 * M_PI) > 1e-8)
      return {false, "vertex " + std::to_string(v) + " has spherical angle sum " + std::to_string(sums[v])};

  out.uniform = std::move(sphere);
  out.positions = x;
  attachScale(out, w, log);
  return {true, ""};
}

Uniformization uniformizeSphere(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                UniformizationReport report) {
  report.target = UniformizationTarget::Sphere;
  const std::vector<int> candidates = punctureCandidates(input);
  if (candidates.empty())
    throw InputError(
        "genus-0 uniformization needs a vertex with a simple star (distinct neighbours) to puncture; "
        "this triangulation has none");
  std::string reasons;
  for (int attempt = 0; attempt < std::min<int>(options.maxPunctureAttempts, candidates.size()); ++attempt) {
    Uniformization out;
    UniformizationReport r = report;
    r.punctureVertex = candidates[attempt];
    r.punctureAttempts = attempt + 1;
    if (options.progress) options.progress("sphere: puncturing vertex " + std::to_string(candidates[attempt]));
    const SphereAttempt result = trySphere(input, options, candidates[attempt], out, r);
    if (result.ok) {
      out.report = r;
      return out;
    }
    reasons += (reasons.empty() ? "" : "; ") + ("vertex " + std::to_string(candidates[attempt]) + ": " + result.why);
    if (options.progress)
      options.progress("sphere: puncture at vertex " + std::to_string(candidates[attempt]) +
                       " rejected: " + result.why);
    report.newtonSteps = r.newtonSteps;
    report.flips = r.flips;
  }
  throw ConvergenceError("genus-0 uniformization failed for every puncture tried (" + reasons + ")");
}

}  // namespace

// === layout

std::vector<Eigen::Vector2d> layoutFlat(const IntrinsicTriangulation& tri, double mismatch,
                                        const std::vector<char>& skipFaces) {
  if (tri.background != Background::Euclidean)
    throw InputError("layoutFlat: the triangulation is " + toString(tri.background) +
                     ", a flat layout needs Euclidean");
  const HalfedgeMesh& m = tri.mesh;
  auto skip = [&](int f) { return !skipFaces.empty() && skipFaces[f]; };
  std::vector<Eigen::Vector2d> p(m.nVertices(), Eigen::Vector2d::Zero());
  std::vector<char> placed(m.nVertices(), 0), done(m.nFaces(), 0);
  double meanLength = 0;
  for (double l : tri.edgeLengths) meanLength += l;
  meanLength /= std::max<std::size_t>(1, tri.edgeLengths.size());
  auto place = [&](int v, const Eigen::Vector2d& q) {
    if (placed[v]) {
      if ((p[v] - q).norm() > mismatch * meanLength) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "layoutFlat: vertex " << v << " is reached at two places " << (p[v] - q).norm()
            << " apart; the metric is not flat or not simply developable";
        throw ConvergenceError(msg.str());
      }
      return;
    }
    p[v] = q;
    placed[v] = 1;
  };
  // Every halfedge of a laid-out face gets its direction by rotating the direction of the edge the face was reached
  // across by the face's angles — never from the difference of its endpoints' coordinates. That difference carries
  // the coordinates' absolute round-off, which on a short edge is a large direction error, and the unfolding carries
  // it to everything beyond. The punctured plane of the sphere has edges of 10⁻⁵ and of 10² (box, 10⁶ vertices):
  // unfolded from coordinate differences it closed edges only to 2·10⁻⁴ of the coordinates although every angle sum
  // was 2π to 3·10⁻¹⁴; long double coordinates gave 2·10⁻⁵ from face 0 and 0.56 from the face with the shortest edges.
  // With rotated directions the direction errors are sums of the angles' round-off along the path, independent of
  // the edge lengths: 1.2·10⁻⁹ from face 0, 9·10⁻¹⁰ from that face (measured; the 10⁵-vertex box: 10⁻¹¹ instead of
  // 1–3·10⁻¹⁰).
  std::vector<Eigen::Vector2d> dir(m.nHalfedges(), Eigen::Vector2d::Zero());
  // (cos, sin) of every corner angle, computed up front on two cores: the arctangents, cosines and sines are most of
  // the work, and only the breadth-first unfolding below is sequential.
  std::vector<Eigen::Vector2d> turn(m.nHalfedges());
  onTwoCores(m.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f)
      if (!skip(f))
        for (int h = 3 * f; h < 3 * f + 3; ++h) {
          const double angle = cornerAngle(tri, h);
          turn[h] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
        }
  });
  // d rotated counter-clockwise (sign +1) or clockwise (−1) by the corner angle at the tail of h.
  auto rotate = [&](const Eigen::Vector2d& d, int h, double sign) {
    const double c = turn[h].x(), s = sign * turn[h].y();
    return Eigen::Vector2d(c * d.x() - s * d.y(), s * d.x() + c * d.y());
  };
  // Face of halfedge h (a → b, direction known), third vertex c to the left of a → b: place c from a and set the
  // directions of the other two halfedges (c → a and b → c), rotating a → b by the angle at a (counter-clockwise) and
  // b → a by the angle at b (clockwise).
  auto layFace = [&](int h) {
    const int pv = HalfedgeMesh::prev(h), nx = HalfedgeMesh::next(h);
    const Eigen::Vector2d ac = rotate(dir[h], h, 1);
    place(m.tail(pv), p[m.tail(h)] + tri.length(pv) * ac);
    dir[pv] = -ac;
    dir[nx] = rotate(-dir[h], nx, -1);
  };
  std::vector<int> queue;
  for (int seed = 0; seed < m.nFaces(); ++seed) {
    if (done[seed] || skip(seed)) continue;
    // Place the seed face with its first edge on the x-axis.
    const int h = 3 * seed;
    const int a = m.tail(h), b = m.tip(h);
    if (!placed[a] && !placed[b]) {
      place(a, Eigen::Vector2d(0, 0));
      place(b, Eigen::Vector2d(tri.length(h), 0));
    }
    dir[h] = (p[b] - p[a]).normalized();
    layFace(h);
    done[seed] = 1;
    queue.assign(1, seed);
    for (std::size_t qi = 0; qi < queue.size(); ++qi) {
      const int f = queue[qi];
      for (int k = 0; k < 3; ++k) {
        const int t = m.twin(3 * f + k);
        if (t == kInvalid) continue;
        const int g = HalfedgeMesh::face(t);
        if (done[g] || skip(g)) continue;
        // In g, t runs from a to b (both placed: they are f's vertices), opposite to f's halfedge.
        dir[t] = -dir[3 * f + k];
        layFace(t);
        done[g] = 1;
        queue.push_back(g);
      }
    }
  }
  return p;
}

// === entry point

Uniformization uniformize(const IntrinsicTriangulation& input, const UniformizationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validateLengths(input, "uniformize");
  const std::vector<ComponentTopology> components = input.mesh.components();
  if (components.size() != 1)
    throw InputError("uniformize: the surface has " + std::to_string(components.size()) +
                     " connected components; uniformize each separately");
  UniformizationReport report;
  report.genus = components[0].genus;
  report.boundaryLoops = components[0].boundaryLoops;
  Uniformization out;
  if (report.boundaryLoops == 0 && report.genus == 0) {
    out = uniformizeSphere(input, options, report);
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
    out = uniformizeConstant(input, options, report, Background::Hyperbolic);
  }
  out.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace conformesh::intrinsic
