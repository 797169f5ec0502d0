// circle_packing.cpp — the circle-packing Ricci flow (Jin–Kim–Luo–Gu 2008): circle packing metrics from radii and
// inversive distances, Newton's method on the convex energy with the Hessian −∂Θ/∂u assembled per face from ∂θ/∂ℓ and
// ∂ℓ/∂u and factored by CHOLMOD, Armijo backtracking that also keeps every triangle in existence, and the flat-torus /
// hyperbolic targets. No flips: when Newton leaves the region where all triangles exist, or the Hessian is not
// positive definite, the flow reports it (naming the face) instead of continuing. See circle_packing.h and
// docs/ricci_flow.md ("Circle packing").
#include "conformesh/intrinsic/flow/circle_packing.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "flow/linalg/supernodal_cholesky.h"

namespace conformesh::intrinsic {

std::string toString(CirclePackingScheme scheme) {
  return scheme == CirclePackingScheme::Tangential ? "circle-packing" : "inversive-distance";
}

namespace {

// === radii in the flow variable u

// Per vertex: the radius r and, for the hyperbolic plane, sinh r and cosh r − 1 (kept separately so that small
// circles keep full relative accuracy). Euclidean: r = e^u. Hyperbolic: u = log tanh(r/2) (Chow–Luo 2003, the
// variable in which the Jacobian ∂Θ/∂u is symmetric), t = e^u < 1, sinh r = 2t/(1 − t²), cosh r − 1 = 2t²/(1 − t²).
struct Radius {
  double r = 0, sinhR = 0, coshM1 = 0;
};

bool radiusFromU(Background g, double u, Radius& out) {
  if (!std::isfinite(u)) return false;
  if (g == Background::Euclidean) {
    out.r = std::exp(u);
    out.sinhR = out.r;
    out.coshM1 = 0;
    return out.r > 0 && std::isfinite(out.r);
  }
  if (u >= 0) return false;  // tanh(r/2) < 1: u ≥ 0 is an infinite radius
  const double t = std::exp(u), oneMinusT2 = -std::expm1(2 * u);
  out.r = 2 * std::atanh(t);
  out.sinhR = 2 * t / oneMinusT2;
  out.coshM1 = 2 * t * t / oneMinusT2;
  return out.r > 0 && std::isfinite(out.sinhR);
}

double uFromRadius(Background g, double r) {
  return g == Background::Euclidean ? std::log(r) : std::log(std::tanh(0.5 * r));
}

Radius radiusOf(Background g, double r) {
  Radius out;
  out.r = r;
  out.sinhR = g == Background::Euclidean ? r : std::sinh(r);
  out.coshM1 = g == Background::Euclidean ? 0 : 2 * std::sinh(0.5 * r) * std::sinh(0.5 * r);
  return out;
}

// ℓ from two radii and I. Hyperbolic: cosh ℓ − 1 = (cosh r_i − 1) cosh r_j + (cosh r_j − 1) + I sinh r_i sinh r_j, and
// ℓ = acosh(1 + X) = log1p(X + sqrt(X(X + 2))), accurate for small ℓ.
double lengthOf(Background g, const Radius& a, const Radius& b, double I) {
  if (g == Background::Euclidean) return std::sqrt(a.r * a.r + b.r * b.r + 2 * a.r * b.r * I);
  const double X = a.coshM1 * (1 + b.coshM1) + b.coshM1 + I * a.sinhR * b.sinhR;
  return std::log1p(X + std::sqrt(X * (X + 2)));
}

// ∂ℓ/∂u at endpoint a. Euclidean: ℓ dℓ = (r_a² + I r_a r_b) du_a. Hyperbolic: sinh ℓ dℓ = (sinh r_a cosh r_b +
// I cosh r_a sinh r_b) dr_a with dr_a = sinh r_a du_a.
double lengthDerivative(Background g, const Radius& a, const Radius& b, double I, double length) {
  if (g == Background::Euclidean) return a.r * (a.r + I * b.r) / length;
  return a.sinhR * (a.sinhR * (1 + b.coshM1) + I * (1 + a.coshM1) * b.sinhR) / std::sinh(length);
}

// === the packing at one u

struct Problem {
  const HalfedgeMesh* mesh = nullptr;
  Background geometry = Background::Euclidean;
  std::vector<double> I;  // per edge
};

struct State {
  std::vector<Radius> radius;  // per vertex
  std::vector<double> length;  // per edge
  std::vector<double> angle;   // per halfedge: the corner angle at tail(h)
  std::vector<double> sum;     // per vertex
  std::string failure;         // why this u is not admissible (empty when it is)
};

std::string faceName(const HalfedgeMesh& m, int f) {
  std::ostringstream s;
  s << "face " << f << " (vertices " << m.faceVertex(f, 0) << ", " << m.faceVertex(f, 1) << ", " << m.faceVertex(f, 2)
    << ")";
  return s.str();
}

// Fills `s` for radii u; returns false (with s.failure naming the vertex or face) when a radius is not admissible or a
// triangle does not exist (the triangle inequality fails — possible only for I > 1, Guo 2011).
bool evaluate(const Problem& p, const std::vector<double>& u, State& s) {
  const HalfedgeMesh& m = *p.mesh;
  s.radius.resize(m.nVertices());
  s.failure.clear();
  for (int v = 0; v < m.nVertices(); ++v)
    if (!radiusFromU(p.geometry, u[v], s.radius[v])) {
      std::ostringstream msg;
      msg << "vertex " << v << " has no admissible radius (u = " << u[v] << ")";
      s.failure = msg.str();
      return false;
    }
  s.length.resize(m.nEdges());
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    s.length[e] = lengthOf(p.geometry, s.radius[m.tail(h)], s.radius[m.tip(h)], p.I[e]);
  }
  s.angle.resize(m.nHalfedges());
  s.sum.assign(m.nVertices(), 0.0);
  for (int f = 0; f < m.nFaces(); ++f) {
    double L[3];
    for (int k = 0; k < 3; ++k) L[k] = s.length[m.edge(3 * f + (k + 1) % 3)];  // opposite corner k
    if (!isValidTriangle(p.geometry, L[0], L[1], L[2])) {
      std::ostringstream msg;
      msg.precision(17);
      msg << faceName(m, f) << " violates the triangle inequality: opposite lengths " << L[0] << ", " << L[1] << ", "
          << L[2];
      s.failure = msg.str();
      return false;
    }
    for (int k = 0; k < 3; ++k) {
      const double theta = angleOpposite(p.geometry, L[k], L[(k + 1) % 3], L[(k + 2) % 3]);
      s.angle[3 * f + k] = theta;
      s.sum[m.faceVertex(f, k)] += theta;
    }
  }
  return true;
}

// J[k][n] = ∂θ_k/∂u_{v_n} in face f: dθ_k = A_k (dL_k − cos θ_{k+2} dL_{k+1} − cos θ_{k+1} dL_{k+2}) with L_k opposite
// corner k and A_k = L_k/(L_{k+1} L_{k+2} sin θ_k) (Euclidean) resp. sinh L_k/(sinh L_{k+1} sinh L_{k+2} sin θ_k)
// (hyperbolic); dL_k = Σ_n ∂L_k/∂u_{v_n} du_{v_n} over the two endpoints of the edge opposite k. The matrix is
// symmetric (the energy exists: Chow–Luo 2003 for I ∈ [0, 1], Guo 2011 for inversive distances).
void triangleJacobian(Background g, const Radius* radius, const double* I, const double* L, const double* theta,
                      double J[3][3]) {
  double D[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    D[k][a] = lengthDerivative(g, radius[a], radius[b], I[k], L[k]);
    D[k][b] = lengthDerivative(g, radius[b], radius[a], I[k], L[k]);
  }
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    const double A = g == Background::Euclidean
                         ? L[k] / (L[k1] * L[k2] * std::sin(theta[k]))
                         : std::sinh(L[k]) / (std::sinh(L[k1]) * std::sinh(L[k2]) * std::sin(theta[k]));
    for (int n = 0; n < 3; ++n)
      J[k][n] = A * (D[k][n] - std::cos(theta[k2]) * D[k1][n] - std::cos(theta[k1]) * D[k2][n]);
  }
}

void faceJacobian(const Problem& p, const State& s, int f, double J[3][3]) {
  const HalfedgeMesh& m = *p.mesh;
  Radius radius[3];
  double I[3], L[3], theta[3];
  for (int k = 0; k < 3; ++k) {
    const int e = m.edge(3 * f + (k + 1) % 3);
    radius[k] = s.radius[m.faceVertex(f, k)];
    I[k] = p.I[e];
    L[k] = s.length[e];
    theta[k] = s.angle[3 * f + k];
  }
  triangleJacobian(p.geometry, radius, I, L, theta, J);
}

// The face whose local Hessian −½(J + Jᵀ) has the most negative eigenvalue (relative to its largest), or −1 when none
// is below −1e-10 of it: the round-off of a 3×3 eigenvalue of an O(1) matrix is ~1e-15, so 1e-10 flags only genuine
// indefiniteness.
int mostIndefiniteFace(const Problem& p, const State& s, double& eigenvalue) {
  int worst = -1;
  eigenvalue = 0;
  for (int f = 0; f < p.mesh->nFaces(); ++f) {
    double J[3][3];
    faceJacobian(p, s, f, J);
    Eigen::Matrix3d M;
    for (int k = 0; k < 3; ++k)
      for (int n = 0; n < 3; ++n) M(k, n) = -0.5 * (J[k][n] + J[n][k]);
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M, Eigen::EigenvaluesOnly).eigenvalues();
    const double relative = ev[0] / std::max(std::abs(ev[2]), 1e-300);
    if (relative < -1e-10 && relative < eigenvalue) {
      eigenvalue = relative;
      worst = f;
    }
  }
  return worst;
}

struct Topology {
  int genus = 0, chi = 0;
};

Topology checkInput(const IntrinsicTriangulation& input) {
  validateLengths(input, "circle packing input");
  const std::vector<ComponentTopology> comps = input.mesh.components();
  if (comps.size() != 1) {
    throw InputError("circle packing: the surface has " + std::to_string(comps.size()) +
                     " connected components; uniformize one component at a time");
  }
  const ComponentTopology& c = comps[0];
  if (c.boundaryLoops > 0 || c.genus < 1) {
    throw InputError("circle packing: the surface has genus " + std::to_string(c.genus) + " and " +
                     std::to_string(c.boundaryLoops) +
                     " boundary loops; the circle-packing flows support closed surfaces of genus >= 1 only (use "
                     "the yamabe method for spheres and surfaces with boundary)");
  }
  if (input.background == Background::Spherical)
    throw InputError("circle packing: spherical input lengths are not supported (Euclidean or hyperbolic only)");
  return {c.genus, c.eulerCharacteristic};
}

}  // namespace

// =====================================================================================================================
// Public helpers
// =====================================================================================================================

double circlePackingLength(Background g, double ri, double rj, double I) {
  if (g == Background::Spherical) throw InputError("circlePackingLength: the spherical background is not supported");
  return lengthOf(g, radiusOf(g, ri), radiusOf(g, rj), I);
}

double inversiveDistanceOf(Background g, double ri, double rj, double length) {
  if (g == Background::Spherical) throw InputError("inversiveDistanceOf: the spherical background is not supported");
  if (g == Background::Euclidean) return (length * length - ri * ri - rj * rj) / (2 * ri * rj);
  // I = (cosh ℓ − cosh r_i cosh r_j)/(sinh r_i sinh r_j), differences of cosh − 1 for small radii.
  const Radius a = radiusOf(g, ri), b = radiusOf(g, rj);
  const double coshLM1 = 2 * std::sinh(0.5 * length) * std::sinh(0.5 * length);
  return (coshLM1 - a.coshM1 * (1 + b.coshM1) - b.coshM1) / (a.sinhR * b.sinhR);
}

std::vector<double> initialCircleRadii(const IntrinsicTriangulation& tri, InitialRadii rule) {
  const HalfedgeMesh& m = tri.mesh;
  std::vector<double> shortest(m.nVertices(), std::numeric_limits<double>::infinity()), total(m.nVertices(), 0.0);
  std::vector<int> count(m.nVertices(), 0);
  for (int h = 0; h < m.nHalfedges(); ++h) {
    // Each halfedge counts for both its endpoints, so an interior edge is counted twice at each end; the mean is the
    // same as over edges (a self-loop counts twice, as it meets its vertex twice).
    for (int v : {m.tail(h), m.tip(h)}) {
      shortest[v] = std::min(shortest[v], tri.length(h));
      total[v] += tri.length(h);
      ++count[v];
    }
  }
  std::vector<double> r(m.nVertices());
  for (int v = 0; v < m.nVertices(); ++v)
    r[v] = (rule == InitialRadii::ThirdOfShortestEdge ? shortest[v] : total[v] / count[v]) / 3;
  return r;
}

std::array<std::array<double, 3>, 3> circlePackingAngleJacobian(Background g, const std::array<double, 3>& radii,
                                                                const std::array<double, 3>& I) {
  if (g == Background::Spherical)
    throw InputError("circlePackingAngleJacobian: the spherical background is not supported");
  Radius radius[3];
  double L[3], theta[3], J[3][3];
  for (int k = 0; k < 3; ++k) radius[k] = radiusOf(g, radii[k]);
  for (int k = 0; k < 3; ++k) L[k] = lengthOf(g, radius[(k + 1) % 3], radius[(k + 2) % 3], I[k]);
  if (!isValidTriangle(g, L[0], L[1], L[2]))
    throw InputError(
        "circlePackingAngleJacobian: the triangle with these radii and inversive distances does not exist");
  for (int k = 0; k < 3; ++k) theta[k] = angleOpposite(g, L[k], L[(k + 1) % 3], L[(k + 2) % 3]);
  triangleJacobian(g, radius, I.data(), L, theta, J);
  std::array<std::array<double, 3>, 3> out;
  for (int k = 0; k < 3; ++k)
    for (int n = 0; n < 3; ++n) out[k][n] = J[k][n];
  return out;
}

// =====================================================================================================================
// The flow
// =====================================================================================================================

namespace {

// The steps of uniformizeByCirclePacking: inversive distances → starting radii → Newton (assemble and factor the
// Hessian, Armijo line search inside the admissible region, stopping tests) → area normalisation → outputs.
class CirclePackingFlow {
 public:
  CirclePackingFlow(const IntrinsicTriangulation& input, const CirclePackingOptions& options)
      : start_(std::chrono::steady_clock::now()),
        input_(input),
        options_(options),
        topo_(checkInput(input)),
        m_(input.mesh),
        nV_(input.mesh.nVertices()) {}

  CirclePacking run() {
    if (!options_.startPerturbation.empty() && static_cast<int>(options_.startPerturbation.size()) != nV_)
      throw InputError("circle packing: startPerturbation has " + std::to_string(options_.startPerturbation.size()) +
                       " entries for " + std::to_string(nV_) + " vertices");
    out_.scheme = options_.scheme;
    p_.mesh = &m_;
    p_.geometry = topo_.genus == 1 ? Background::Euclidean : Background::Hyperbolic;
    setInversiveDistances();
    findStart();
    chooseUnknowns();
    newton();
    if (p_.geometry == Background::Euclidean) scaleToUnitArea();
    return outputs();
  }

 private:
  // Inversive distances in the input's own background, from its lengths and initial radii.
  void setInversiveDistances() {
    r0_ = initialCircleRadii(input_, options_.initialRadii);
    p_.I.assign(m_.nEdges(), 1.0);
    if (options_.scheme != CirclePackingScheme::InversiveDistance) return;
    for (int e = 0; e < m_.nEdges(); ++e) {
      const int h = m_.edgeHalfedge(e);
      p_.I[e] = inversiveDistanceOf(input_.background, r0_[m_.tail(h)], r0_[m_.tip(h)], input_.edgeLengths[e]);
      if (!(p_.I[e] >= 0)) {
        std::ostringstream msg;
        msg << "circle packing: edge " << e << " (vertices " << m_.tail(h) << ", " << m_.tip(h)
            << ") has inversive distance " << p_.I[e]
            << " < 0 with the chosen initial radii; the energy is convex only for I >= 0 (use initial radii of a "
               "third of the shortest edge)";
        throw InputError(msg.str());
      }
    }
  }

  // Initial u. Same background: the initial radii (for inversive distances they reproduce the input lengths). A
  // Euclidean input in the hyperbolic class keeps its inversive distances; its radii are scaled by s so that the
  // small triangles have roughly the target area −2πχ (s² A_E ≈ −2πχ), halved while a triangle does not exist.
  void findStart() {
    u_.resize(nV_);
    double scale = 1;
    if (p_.geometry == Background::Hyperbolic && input_.background == Background::Euclidean)
      scale = std::sqrt(-2 * M_PI * topo_.chi / totalArea(input_));
    for (int attempt = 0;; ++attempt) {
      for (int v = 0; v < nV_; ++v)
        u_[v] = uFromRadius(p_.geometry, scale * r0_[v]) +
                (options_.startPerturbation.empty() ? 0.0 : options_.startPerturbation[v]);
      if (evaluate(p_, u_, state_)) break;
      if (p_.geometry == Background::Euclidean || attempt >= 60)
        throw ConvergenceError("circle packing cannot start: " + state_.failure);
      scale *= 0.5;
    }
  }

  // Newton on the free vertices. Euclidean closed surfaces are invariant under u → u + const: vertex 0 is pinned and
  // its equation holds by Gauss–Bonnet (Σ (2π − Θ_v) = 2πχ = 0 for genus 1).
  void chooseUnknowns() {
    const bool pin = p_.geometry == Background::Euclidean;
    index_.resize(nV_);
    n_ = 0;
    for (int v = 0; v < nV_; ++v) index_[v] = (pin && v == 0) ? -1 : n_++;
    tolerance_ = std::max(options_.tolerance, options_.relativeFloor * std::sqrt(double(nV_)));
  }

  // r = 2π − Θ on the unknowns of state s; returns |r|², sets max |2π − Θ| over all vertices.
  double residual(const State& s, Eigen::VectorXd& r, double& maxAbs) const {
    r.resize(n_);
    maxAbs = 0;
    for (int v = 0; v < nV_; ++v) {
      const double rv = 2 * M_PI - s.sum[v];
      maxAbs = std::max(maxAbs, std::abs(rv));
      if (index_[v] >= 0) r[index_[v]] = rv;
    }
    return r.squaredNorm();
  }

  [[noreturn]] void failWith(const std::string& what, double maxAbs) const {
    std::ostringstream msg;
    msg.precision(3);
    msg << toString(options_.scheme) << " flow did not converge: " << what << "; max |Θ̂ − Θ| = " << maxAbs
        << " rad after " << out_.result.report.newtonSteps << " Newton steps (tolerance " << tolerance_
        << "). The classical circle-packing flow does no flips, so a solution need not exist for this "
           "triangulation";
    throw ConvergenceError(msg.str());
  }

  void newton() {
    norm2_ = residual(state_, r_, maxAbs_);
    H_.resize(n_, n_);
    uTrial_.resize(nV_);
    int& steps = out_.result.report.newtonSteps;
    while (true) {
      out_.residualHistory.push_back(maxAbs_);
      if (maxAbs_ <= tolerance_) break;
      if (steps >= options_.maxNewtonSteps) failWith("the Newton step cap was reached", maxAbs_);
      const Eigen::VectorXd delta = newtonDirection();
      std::string lastFailure;
      const double t = lineSearch(delta, lastFailure);
      ++steps;
      checkBlocked(t, lastFailure);
      reportProgress(t, lastFailure);
    }
  }

  // δ = −H⁻¹ r with H = −∂Θ/∂u on the free vertices (lower triangle, symmetrized against round-off), by CHOLMOD.
  Eigen::VectorXd newtonDirection() {
    triplets_.clear();
    triplets_.reserve(9 * static_cast<std::size_t>(m_.nFaces()));
    for (int f = 0; f < m_.nFaces(); ++f) {
      double J[3][3];
      faceJacobian(p_, state_, f, J);
      int idx[3];
      for (int k = 0; k < 3; ++k) idx[k] = index_[m_.faceVertex(f, k)];
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          if (idx[k] >= 0 && idx[j] >= idx[k]) triplets_.emplace_back(idx[j], idx[k], -0.5 * (J[k][j] + J[j][k]));
    }
    H_.setFromTriplets(triplets_.begin(), triplets_.end());
    if (!analyzed_) {
      solver_.analyzePattern(H_);  // the connectivity never changes: one symbolic analysis for the whole flow
      analyzed_ = true;
    }
    solver_.factorize(H_);
    if (solver_.info() != Eigen::Success) {
      double ev = 0;
      const int f = mostIndefiniteFace(p_, state_, ev);
      std::ostringstream what;
      what << "the Hessian is not positive definite at Newton step " << out_.result.report.newtonSteps;
      if (f >= 0) what << " (" << faceName(m_, f) << " has a local Hessian with λ_min/λ_max = " << ev << ")";
      failWith(what.str(), maxAbs_);
    }
    return -solver_.solve(r_);
  }

  // Armijo on ½|r|², and every trial must stay in the admissible region: every radius finite (hyperbolic u < 0),
  // every triangle existing. Returns the accepted step length; lastFailure tells why the last rejected trial was
  // inadmissible (empty when none was).
  double lineSearch(const Eigen::VectorXd& delta, std::string& lastFailure) {
    double t = 1;
    while (true) {
      for (int v = 0; v < nV_; ++v) uTrial_[v] = u_[v] + (index_[v] >= 0 ? t * delta[index_[v]] : 0.0);
      if (evaluate(p_, uTrial_, trial_)) {
        Eigen::VectorXd rTrial;
        double maxTrial = 0;
        const double normTrial = residual(trial_, rTrial, maxTrial);
        if (normTrial <= (1 - 2 * options_.armijo * t) * norm2_) {
          u_.swap(uTrial_);
          std::swap(state_, trial_);
          r_ = rTrial;
          maxAbs_ = maxTrial;
          norm2_ = normTrial;
          return t;
        }
      } else {
        lastFailure = trial_.failure;
      }
      t *= 0.5;
      if (t < options_.minStep) {
        failWith(lastFailure.empty() ? std::string("the line search stalled")
                                     : "every step leaves the admissible region: " + lastFailure,
                 maxAbs_);
      }
    }
  }

  // Stopping test: too many consecutive steps cut below 1/16 by the boundary of the admissible region.
  void checkBlocked(double t, const std::string& lastFailure) {
    blocked_ = (!lastFailure.empty() && t < 1.0 / 16) ? blocked_ + 1 : 0;
    if (blocked_ < options_.maxBlockedSteps) return;
    std::ostringstream what;
    what << "Newton is blocked by the boundary of the admissible region (every radius finite, every triangle "
            "existing): "
         << blocked_ << " consecutive steps cut short, the last to length " << t << "; at the next longer trial "
         << lastFailure;
    failWith(what.str(), maxAbs_);
  }

  void reportProgress(double t, const std::string& lastFailure) const {
    if (!options_.progress) return;
    std::ostringstream line;
    line.precision(3);
    line << toString(options_.scheme) << ": Newton step " << out_.result.report.newtonSteps
         << ", max |K - K^| = " << maxAbs_ << " rad, step length " << t;
    if (!lastFailure.empty()) line << " (shortened: a longer step leaves the admissible region)";
    options_.progress(line.str());
  }

  // Flat tori: scale to area 1 (u → u − ½ log A multiplies every radius, hence every length, by A^{−1/2}).
  void scaleToUnitArea() {
    double area = 0;
    for (int f = 0; f < m_.nFaces(); ++f)
      area += triangleArea(p_.geometry, state_.length[m_.edge(3 * f)], state_.length[m_.edge(3 * f + 1)],
                           state_.length[m_.edge(3 * f + 2)]);
    for (double& x : u_) x -= 0.5 * std::log(area);
    if (!evaluate(p_, u_, state_)) failWith("rescaling to area 1 failed: " + state_.failure, maxAbs_);
    residual(state_, r_, maxAbs_);  // angles are scale-invariant: this changes maxAbs by round-off only
  }

  CirclePacking outputs() {
    Uniformization& res = out_.result;
    res.uniform.mesh = m_;
    res.uniform.background = p_.geometry;
    res.uniform.edgeLengths = state_.length;
    // λ_i = log(Σ ℓ⁰ / Σ ℓ*) over the edges at i: a circle packing moves the vertices relative to each other, so there
    // is no exact per-vertex factor; this is the ratio of the local length scales, O(h)-accurate for smooth conformal
    // maps.
    std::vector<double> before(nV_, 0.0), after(nV_, 0.0);
    for (int h = 0; h < m_.nHalfedges(); ++h) {
      before[m_.tail(h)] += input_.length(h);
      after[m_.tail(h)] += state_.length[m_.edge(h)];
    }
    res.lambda.resize(nV_);
    for (int v = 0; v < nV_; ++v) res.lambda[v] = std::log(before[v] / after[v]);
    res.correspondence = FlowCorrespondence(m_.nFaces());
    res.correspondence.logScale.assign(nV_, 0.0);
    out_.radii.resize(nV_);
    for (int v = 0; v < nV_; ++v) out_.radii[v] = state_.radius[v].r;
    out_.inversiveDistance = p_.I;
    UniformizationReport& rep = res.report;
    rep.target =
        p_.geometry == Background::Euclidean ? UniformizationTarget::FlatTorus : UniformizationTarget::Hyperbolic;
    rep.genus = topo_.genus;
    rep.boundaryLoops = 0;
    rep.flips = 0;
    rep.maxResidual = maxAbs_;
    rep.effectiveTolerance = tolerance_;
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return out_;
  }

  using SparseMatrix = Eigen::SparseMatrix<double>;

  const std::chrono::steady_clock::time_point start_;
  const IntrinsicTriangulation& input_;
  const CirclePackingOptions& options_;
  const Topology topo_;
  const HalfedgeMesh& m_;
  const int nV_;
  CirclePacking out_;
  Problem p_;
  std::vector<double> r0_;  // initial radii in the input's background
  std::vector<double> u_;   // the flow variable per vertex
  State state_, trial_;     // at u_, and at the line search's trial point
  std::vector<double> uTrial_;
  std::vector<int> index_;  // unknown of each vertex (−1: pinned)
  int n_ = 0;
  double tolerance_ = 0;
  Eigen::VectorXd r_;
  double maxAbs_ = 0, norm2_ = 0;
  SupernodalCholesky solver_;
  bool analyzed_ = false;
  std::vector<Eigen::Triplet<double>> triplets_;
  SparseMatrix H_;
  int blocked_ = 0;  // consecutive steps cut below 1/16 by the boundary of the admissible region
};

}  // namespace

std::string CirclePackingOptions::validate() const {
  std::ostringstream msg;
  msg.precision(17);
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    msg << "CirclePackingOptions::tolerance: expected a finite value >= 0, found " << tolerance;
  else if (!(relativeFloor >= 0) || !std::isfinite(relativeFloor))
    msg << "CirclePackingOptions::relativeFloor: expected a finite value >= 0, found " << relativeFloor;
  else if (maxNewtonSteps < 0)
    msg << "CirclePackingOptions::maxNewtonSteps: expected >= 0, found " << maxNewtonSteps;
  else if (!(armijo > 0 && armijo < 0.5))
    msg << "CirclePackingOptions::armijo: expected 0 < armijo < 0.5, found " << armijo;
  else if (!(minStep > 0 && minStep <= 1))
    msg << "CirclePackingOptions::minStep: expected 0 < minStep <= 1, found " << minStep;
  else if (maxBlockedSteps < 1)
    msg << "CirclePackingOptions::maxBlockedSteps: expected >= 1, found " << maxBlockedSteps;
  return msg.str();
}

CirclePacking uniformizeByCirclePacking(const IntrinsicTriangulation& input, const CirclePackingOptions& options) {
  const std::string invalid = options.validate();
  if (!invalid.empty()) throw InputError(invalid);
  return CirclePackingFlow(input, options).run();
}

}  // namespace conformesh::intrinsic
