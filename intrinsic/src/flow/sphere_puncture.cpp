// sphere_puncture.cpp — the genus-0 target: SpherePuncture's steps (sphere_puncture.h) and the choice of punctures.
// docs/ricci_flow.md §3.1 derives the boundary condition, the star repairs, the layout check, the stereographic map,
// the Möbius centring and the choice of spherical lengths.
#include "flow/sphere_puncture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/planar_layout.h"
#include "flow/linalg/two_threads.h"
#include "flow/uniformization_support.h"

namespace conformesh::intrinsic::detail {

namespace {

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

}  // namespace

// === the attempt

SpherePuncture::SpherePuncture(const IntrinsicTriangulation& input, const UniformizationOptions& options, int puncture,
                               UniformizationReport& report)
    : input_(input),
      options_(options),
      inf_(puncture),
      report_(report),
      metric_(referencePenner(input), Background::Euclidean),
      m_(metric_.mesh()),
      log_(m_.nFaces()),
      nV_(m_.nVertices()) {}

SphereAttempt SpherePuncture::run(Uniformization& out) {
  target_.angleSum.assign(nV_, 2 * M_PI);
  target_.fixed.assign(nV_, 0);
  target_.fixed[inf_] = 1;
  frozen_.assign(m_.nFaces(), 0);
  setInitialGuess();
  if (!updateStar()) return {false, "the star of the puncture is not simple"};
  configureFlow();
  SphereAttempt step = solveAndRepairStar();
  if (!step.ok) return step;
  flow_.solverCache.reset();  // the factor (≈ 1 GB at 10⁶ vertices) is not needed for the layout
  if (!(step = checkDiskFaces()).ok) return step;
  int h = m_.vertexHalfedge(inf_);
  for (std::size_t s = 0; s < link_.size(); ++s, h = m_.nextOutgoing(h))
    spoke_.push_back(metric_.referencePenner(m_.edge(h)));
  if (!(step = layOutDisk()).ok) return step;
  projectToSphere();
  centreByMobius();
  setSphericalLengths();
  if (!(step = checkSphere()).ok) return step;
  out.uniform = std::move(sphere_);
  out.positions = x_;
  attachScale(out, w_, log_);
  return {true, ""};
}

// === the flat Dirichlet problem and the star of ∞

// The star of ∞ frozen; link vertices Dirichlet: u_a = −2 log c_a∞ (then e^{u_a/2} c_a∞ = 1 for all a: the limit of
// vertex scaling that sends ∞ to infinity). ∞ itself is in no active face.
bool SpherePuncture::updateStar() {
  std::fill(frozen_.begin(), frozen_.end(), 0);
  std::fill(target_.fixed.begin(), target_.fixed.end(), 0);
  target_.fixed[inf_] = 1;
  link_.clear();
  const int h0 = m_.vertexHalfedge(inf_);
  int h = h0;
  do {
    frozen_[HalfedgeMesh::face(h)] = 1;
    const int a = m_.tip(h);
    if (a == inf_ || target_.fixed[a]) return false;
    link_.push_back(a);
    target_.fixed[a] = 1;
    metric_.u()[a] = -2 * std::log(metric_.referencePenner(m_.edge(h)));
    h = m_.nextOutgoing(h);
  } while (h != h0);
  metric_.setFrozenFaces(frozen_);
  return true;
}

void SpherePuncture::setInitialGuess() {
  const std::vector<double> dist = edgeDistances(referencePenner(input_), inf_);
  for (int v = 0; v < nV_; ++v) metric_.u()[v] = v == inf_ ? 0.0 : -2 * std::log(dist[v]);
}

// Degenerate faces may occur; the first solves return at a degenerate stall (the energy is only C¹ there) so the star
// is repaired early; all solves of the puncture share one factor; with earlyReflexFactor > 0 a solve stops once a
// link vertex is clearly reflex.
void SpherePuncture::configureFlow() {
  flow_ = withProgress(options_, "sphere (punctured plane)");
  flow_.allowDegenerateFaces = true;
  flow_.returnAtDegenerateStall = true;
  flow_.solverCache = makeFlowSolverCache(flow_.maxReuseIterations, flow_.nestedDissectionMin);
  judgedEarly_.assign(nV_, 0);
  if (options_.earlyReflexFactor > 0)
    flow_.stopAfterStep = [this](const std::vector<double>& sums, double maxResidual) {
      return std::any_of(link_.begin(), link_.end(), [&](int a) { return clearlyReflex(a, sums, maxResidual); });
    };
}

// A vertex judged early at most once: one misjudged and put back on the link later is released only at a solution.
bool SpherePuncture::clearlyReflex(int a, const std::vector<double>& sums, double maxResidual) const {
  return !judgedEarly_[a] && sums[a] > M_PI + options_.earlyReflexFactor * maxResidual;
}

SphereAttempt SpherePuncture::solveAndRepairStar() {
  for (int round = 0;; ++round) {
    RicciFlowReport solved;
    try {
      solved = solveConformalFlow(metric_, target_, flow_, &log_);
    } catch (const ConvergenceError& e) {
      // A flow that fails for this puncture (a stall, the step cap) rejects the puncture like a failed layout or
      // sphere check: another star gives another Dirichlet problem (docs/ricci_flow.md §3.1).
      return {false, e.what()};
    }
    accumulate(report_, solved);
    // Early returns at a stall only until the first solve gets past its degenerate faces: afterwards reflex repairs
    // take vertices out of the link, and stopping the next solve at a degenerate face would put them straight back.
    if (!solved.stoppedAtDegenerate) flow_.returnAtDegenerateStall = false;
    bool changed = flipDegenerateFacesIntoStar();
    if (!changed && solved.stoppedAtDegenerate) {
      // Nothing to repair: finish this solve on the C¹ extension (reflex vertices are only judged at a solution).
      flow_.returnAtDegenerateStall = false;
      continue;
    }
    if (!changed) {
      changed = releaseReflexLinkVertices(solved);
      if (!changed && solved.stoppedByCaller) continue;  // none could go now: solve on, judged at the solution
    }
    if (!changed) return {true, ""};
    reportRepairRound(round, solved);
    if (round > 10 * nV_) return {false, "the star of the puncture did not stabilize"};
    if (!updateStar()) return {false, "a star flip made the link of the puncture non-simple"};
    // A released vertex keeps its Dirichlet value, far from its own equation's solution, where its angle sum responds
    // weakly to u: solving Θ_a(u_a) = 2π alone first leaves Newton a smooth, nearly solved problem.
    for (int a : released_) solveVertexLocally(a);
    released_.clear();
  }
}

// A disk face degenerate against a link edge ab flips ab to i∞ (Ptolemy gives exactly the Dirichlet value of i at
// the moment of degeneration), and i joins the link. All such flips are batched (each touches only its own quad; the
// faces it creates around ∞ are frozen at once). Validity is tested for all faces first, on two threads.
bool SpherePuncture::flipDegenerateFacesIntoStar() {
  std::vector<char> valid(m_.nFaces());
  onTwoCores(m_.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f) {
      double L[3];
      for (int k = 0; k < 3; ++k) L[k] = metric_.length(m_.edge(3 * f + k));
      valid[f] = frozen_[f] || isValidTriangle(Background::Euclidean, L[0], L[1], L[2]);
    }
  });
  bool changed = false;
  for (int f = 0; f < m_.nFaces(); ++f) {
    if (frozen_[f] || valid[f]) continue;
    double L[3];
    for (int k = 0; k < 3; ++k) L[k] = metric_.length(m_.edge(3 * f + k));
    if (isValidTriangle(Background::Euclidean, L[0], L[1], L[2])) continue;
    const int k = L[0] >= L[1] ? (L[0] >= L[2] ? 0 : 2) : (L[1] >= L[2] ? 1 : 2);
    const int h = 3 * f + k, t = m_.twin(h);
    const int i = m_.tail(HalfedgeMesh::prev(h));
    if (t == kInvalid || !frozen_[HalfedgeMesh::face(t)] || target_.fixed[i]) continue;
    const int g = HalfedgeMesh::face(t);
    if (metric_.flipPtolemy(m_.edge(h), &log_)) {
      changed = true;
      frozen_[f] = frozen_[g] = 1;  // both new faces contain ∞
      target_.fixed[i] = 1;         // i is on the link now (its Dirichlet value is set by updateStar)
    }
  }
  return changed;
}

// A link vertex with disk angle sum Θ_a > π (reflex link polygon: the stereographic image would fold) leaves the link
// by flipping its spoke a∞ to the link edge of its neighbours: at a solution when Θ_a exceeds π by more than the
// round-off of the angle sums (10⁻⁹ rad), after an early stop when it is clearly reflex.
bool SpherePuncture::releaseReflexLinkVertices(const RicciFlowReport& solved) {
  const std::vector<double>& sums = solved.angleSums;
  std::vector<int> reflex;
  for (int a : link_)
    if (solved.stoppedByCaller ? clearlyReflex(a, sums, solved.maxResidual) : sums[a] > M_PI + 1e-9)
      reflex.push_back(a);
  if (solved.stoppedByCaller)
    for (int a : reflex) judgedEarly_[a] = 1;
  bool changed = false;
  for (int a : releasableLinkVertices(link_, reflex)) {
    int h = m_.vertexHalfedge(inf_);
    while (m_.tip(h) != a) h = m_.nextOutgoing(h);
    if (metric_.flipPtolemy(m_.edge(h), &log_)) {
      changed = true;
      released_.push_back(a);
    }
  }
  return changed;
}

void SpherePuncture::reportRepairRound(int round, const RicciFlowReport& solved) const {
  if (options_.progress)
    options_.progress("sphere: star repair round " + std::to_string(round + 1) + ", link of " +
                      std::to_string(link_.size()) + " vertices, last solve " + std::to_string(solved.newtonSteps) +
                      " Newton steps" +
                      (solved.stoppedAtDegenerate ? " (stopped at a degenerate face)"
                       : solved.stoppedByCaller   ? " (stopped at a clearly reflex vertex)"
                                                  : ""));
}

// Θ_a over the non-frozen faces at a, with the flow's extension (π, 0, 0) of faces violating the triangle inequality:
// monotonically decreasing in u_a, from π·(#faces) at u_a → −∞ to 0 at u_a → +∞.
double SpherePuncture::diskAngleSumAt(int a) const {
  double sum = 0;
  const int h0 = m_.vertexHalfedge(a);
  int h = h0;
  do {
    if (!frozen_[HalfedgeMesh::face(h)]) {
      // Corner a of the face is opposite the edge of next(h); the edges of h and prev(h) meet at a.
      const double opposite = metric_.length(m_.edge(HalfedgeMesh::next(h))), b = metric_.length(m_.edge(h)),
                   c = metric_.length(m_.edge(HalfedgeMesh::prev(h)));
      if (isValidTriangle(Background::Euclidean, opposite, b, c))
        sum += angleOpposite(Background::Euclidean, opposite, b, c);
      else if (opposite >= b && opposite >= c)
        sum += M_PI;
    }
    h = m_.nextOutgoing(h);
  } while (h != h0);
  return sum;
}

// Bisection for Θ_a(u_a) = 2π, bracketed by doubling steps from the current value; the bracket shrinks to round-off.
// Without a bracket within 10³ (not expected: the limits straddle 2π for ≥ 3 faces) u_a is left alone and the global
// solve does the work.
void SpherePuncture::solveVertexLocally(int a) {
  double& ua = metric_.u()[a];
  const double start = ua;
  const bool increase = diskAngleSumAt(a) > 2 * M_PI;
  double lo = start, hi = start, step = 1;
  for (; step <= 1024; step *= 2) {
    ua = increase ? start + step : start - step;
    if ((diskAngleSumAt(a) > 2 * M_PI) != increase) break;
    (increase ? lo : hi) = ua;
  }
  if (step > 1024) {
    ua = start;
    return;
  }
  (increase ? hi : lo) = ua;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
    ua = 0.5 * (lo + hi);
    (diskAngleSumAt(a) > 2 * M_PI ? lo : hi) = ua;
  }
  ua = 0.5 * (lo + hi);
}

SphereAttempt SpherePuncture::checkDiskFaces() const {
  for (int f = 0; f < m_.nFaces(); ++f)
    if (!frozen_[f]) {
      double L[3];
      for (int k = 0; k < 3; ++k) L[k] = metric_.length(m_.edge(3 * f + k));
      if (!isValidTriangle(Background::Euclidean, L[0], L[1], L[2]))
        return {false, "face " + std::to_string(f) + " stays degenerate next to the puncture's star"};
    }
  return {true, ""};
}

// === map back

// layoutFlat's own closing test (relative to the mean edge length) is off; instead every edge must have its flow
// length to 10⁻⁶ relative or to allowance_ = max(10⁻¹⁰, 10 ε √#V) of its endpoints' coordinates, ε the flow's
// stopping tolerance. Tested on two threads; the first failing edge in face order is reported.
SphereAttempt SpherePuncture::layOutDisk() {
  planarTri_ = metric_.triangulation();
  try {
    z_ = layoutFlat(planarTri_, std::numeric_limits<double>::infinity(), frozen_);
  } catch (const ConvergenceError& e) {
    return {false, e.what()};
  }
  allowance_ = std::max(1e-10, 10 * report_.effectiveTolerance * std::sqrt(double(nV_)));
  std::vector<char> faceLaidOut(m_.nFaces(), 1);
  onTwoCores(m_.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f)
      if (!frozen_[f]) faceLaidOut[f] = edgeLaidOut(3 * f) && edgeLaidOut(3 * f + 1) && edgeLaidOut(3 * f + 2);
  });
  for (int f = 0; f < m_.nFaces(); ++f) {
    if (frozen_[f] || faceLaidOut[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + k;
      const double length = planarTri_.length(h), laid = (z_[m_.tip(h)] - z_[m_.tail(h)]).norm();
      if (!edgeLaidOut(h)) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "the planar layout gives edge " << m_.edge(h) << " the length " << laid << " instead of " << length
            << " (error " << std::abs(laid - length) << " at coordinates of size " << z_[m_.tip(h)].norm()
            << ", allowed 1e-6 of the length plus " << allowance_ << " of the coordinates)";
        return {false, msg.str()};
      }
    }
  }
  return {true, ""};
}

bool SpherePuncture::edgeLaidOut(int h) const {
  const double length = planarTri_.length(h), laid = (z_[m_.tip(h)] - z_[m_.tail(h)]).norm();
  return std::abs(laid - length) <= 1e-6 * length + allowance_ * (z_[m_.tip(h)].norm() + z_[m_.tail(h)].norm());
}

// Translates the layout to its centroid and scales it so the median |z| is 1 (a Möbius map fixing ∞: lengths × ρ ⇔
// u + log ρ), then maps it by inverse stereographic projection; w of ∞ is the mean over its spokes.
void SpherePuncture::projectToSphere() {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int v = 0; v < nV_; ++v)
    if (v != inf_) centroid += z_[v];
  centroid /= (nV_ - 1);
  std::vector<double> radii;
  for (int v = 0; v < nV_; ++v)
    if (v != inf_) radii.push_back((z_[v] - centroid).norm());
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double rho = 1.0 / std::max(radii[radii.size() / 2], 1e-300);
  w_.assign(nV_, 0.0);
  x_ = std::vector<Eigen::Vector3d>(nV_);
  onTwoCores(nV_, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto v = static_cast<int>(begin); v < end; ++v) {
      if (v == inf_) continue;
      const Eigen::Vector2d p = rho * (z_[v] - centroid);
      const double r2 = p.squaredNorm();
      // The y-reflection makes the map orientation preserving for the outward normal (stereographic projection from
      // the north pole reverses it); reflections do not change the conformal factor.
      x_[v] = Eigen::Vector3d(2 * p.x(), -2 * p.y(), r2 - 1) / (r2 + 1);
      // Inverse stereographic projection scales chords by e^{(s_a+s_b)/2}, e^{s} = 2/(1+|p|²).
      w_[v] = metric_.u()[v] + std::log(rho) + std::log(2 / (1 + r2));
    }
  });
  x_[inf_] = Eigen::Vector3d(0, 0, 1);
  double sum = 0;
  for (std::size_t i = 0; i < link_.size(); ++i)
    sum += 2 * std::log((x_[inf_] - x_[link_[i]]).norm() / spoke_[i]) - w_[link_[i]];
  w_[inf_] = sum / link_.size();
}

// Moves the centroid c of the input's area measure (fixed vertex weights: a third of each incident face's input area)
// to the origin by ball automorphisms φ_c(x) = (1−|c|²)(x−c)/|x−c|² − c, w gaining log |φ_c'|: Newton's method on
// the centroid, step a = ½ (I − M)⁻¹ C capped at |a| ≤ 0.5, (3/4) C where I − M is nearly singular.
void SpherePuncture::centreByMobius() {
  std::vector<double> weight(nV_, 0.0);
  {
    const IntrinsicTriangulation flat = referencePenner(input_);
    for (int f = 0; f < input_.mesh.nFaces(); ++f)
      for (int k = 0; k < 3; ++k) weight[input_.mesh.faceVertex(f, k)] += faceArea(flat, f) / 3;
  }
  for (int it = 0; it < 100; ++it) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    double total = 0;
    for (int v = 0; v < nV_; ++v) {
      c += weight[v] * x_[v];
      moment += weight[v] * x_[v] * x_[v].transpose();
      total += weight[v];
    }
    c /= total;
    moment /= total;
    if (c.norm() <= options_.centringTolerance) break;
    const Eigen::Matrix3d jacobian = 2 * (Eigen::Matrix3d::Identity() - moment);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> spectrum(jacobian, Eigen::EigenvaluesOnly);
    // Its eigenvalues are 4/3 for a uniform measure and tend to 0 as the measure concentrates on two antipodal points;
    // below 0.2 the linearization is not trusted.
    c = spectrum.eigenvalues().minCoeff() > 0.2 ? Eigen::Vector3d(jacobian.ldlt().solve(c)) : Eigen::Vector3d(0.75 * c);
    if (c.norm() > 0.5) c *= 0.5 / c.norm();
    const double k = 1 - c.squaredNorm();
    onTwoCores(nV_, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
      for (auto v = begin; v < end; ++v) {
        const double d2 = (x_[v] - c).squaredNorm();
        w_[v] += std::log(k / d2);
        x_[v] = (k * (x_[v] - c) / d2 - c).normalized();
      }
    });
    report_.centringIterations = it + 1;
  }
}

// Geodesic triangles on the points: the spherical distances of the chords when every chord is at least 10⁻⁴, else
// every edge from the Penner form e^{(w_i+w_j)/2} c⁰_ij (never a mix; report.pennerLengths).
void SpherePuncture::setSphericalLengths() {
  sphere_.mesh = m_;
  sphere_.background = Background::Spherical;
  sphere_.edgeLengths.resize(m_.nEdges());
  fromPoints_.assign(m_.nEdges(), 1);
  bool allResolved = true;
  for (int e = 0; e < m_.nEdges(); ++e) {
    const int h = m_.edgeHalfedge(e);
    fromPoints_[e] = (x_[m_.tail(h)] - x_[m_.tip(h)]).norm() >= 1e-4;
    allResolved = allResolved && fromPoints_[e];
  }
  onTwoCores(m_.nEdges(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto e = static_cast<int>(begin); e < end; ++e) {
      const int h = m_.edgeHalfedge(e), a = m_.tail(h), b = m_.tip(h);
      sphere_.edgeLengths[e] =
          allResolved
              ? sphericalDistance(x_[a], x_[b])
              : lengthFromPenner(Background::Spherical, metric_.referencePenner(e) * std::exp(0.5 * (w_[a] + w_[b])));
    }
  });
  report_.pennerLengths = !allResolved;
}

// Every face a valid spherical triangle, positively oriented where its points resolve it, and every angle sum 2π to
// 10⁻⁸: this certifies an embedded geodesic triangulation of the round sphere. The first failure is reported.
SphereAttempt SpherePuncture::checkSphere() const {
  std::vector<char> faceGood(m_.nFaces());
  onTwoCores(m_.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f) {
      const Eigen::Vector3d &a = x_[m_.faceVertex(f, 0)], &b = x_[m_.faceVertex(f, 1)], &c = x_[m_.faceVertex(f, 2)];
      const bool resolved =
          fromPoints_[m_.edge(3 * f)] && fromPoints_[m_.edge(3 * f + 1)] && fromPoints_[m_.edge(3 * f + 2)];
      faceGood[f] = !(resolved && !((b - a).cross(c - a).dot(a + b + c) > 0)) &&
                    isValidTriangle(Background::Spherical, sphere_.length(3 * f), sphere_.length(3 * f + 1),
                                    sphere_.length(3 * f + 2));
    }
  });
  for (int f = 0; f < m_.nFaces(); ++f) {
    if (!faceGood[f]) {
      std::ostringstream msg;
      msg.precision(3);
      msg << "face " << f << " is not positively oriented on the sphere (side lengths " << sphere_.length(3 * f) << ", "
          << sphere_.length(3 * f + 1) << ", " << sphere_.length(3 * f + 2) << ")";
      return {false, msg.str()};
    }
  }
  const std::vector<double> sums = sphericalAngleSums();
  for (int v = 0; v < nV_; ++v)
    if (std::abs(sums[v] - 2 * M_PI) > 1e-8)
      return {false, "vertex " + std::to_string(v) + " has spherical angle sum " + std::to_string(sums[v])};
  return {true, ""};
}

// Corner angles on two threads, added in halfedge order.
std::vector<double> SpherePuncture::sphericalAngleSums() const {
  std::vector<double> corner(m_.nHalfedges()), s(nV_, 0.0);
  onTwoCores(m_.nHalfedges(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto h = static_cast<int>(begin); h < end; ++h) corner[h] = cornerAngle(sphere_, h);
  });
  for (int h = 0; h < m_.nHalfedges(); ++h) s[m_.tail(h)] += corner[h];
  return s;
}

// === the target

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
    const SphereAttempt result = SpherePuncture(input, options, candidates[attempt], r).run(out);
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

}  // namespace conformesh::intrinsic::detail
