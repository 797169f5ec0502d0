// newton_flow.cpp — the steps of the Newton solver for vertex-scaling conformal metrics (newton_flow.h): target checks,
// unknowns, the symmetric Hessian (CHOLMOD through FlowSolverCache) or the circle-domain Jacobian (sparse LU plus
// Sherman–Morrison–Woodbury), the Armijo line search with Ptolemy flips, and the stopping tests.
#include "flow/newton_flow.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "flow/extended_angles.h"

namespace conformesh::intrinsic {

using detail::angleJacobian;
using detail::evaluateFaces;
using detail::extendedAngleSums;

NewtonFlowSolver::NewtonFlowSolver(DiscreteConformalMetric& metric, const ConformalTarget& target,
                                   const RicciFlowOptions& options, FlowCorrespondence* log)
    : metric_(metric),
      target_(target),
      options_(options),
      log_(log),
      m_(metric.mesh()),
      nV_(metric.mesh().nVertices()),
      bg_(metric.geometry()),
      circles_(!target.circleLoops.empty()),
      start_(std::chrono::steady_clock::now()),
      local_(options.maxReuseIterations, options.nestedDissectionMin) {}

RicciFlowReport NewtonFlowSolver::run() {
  checkTargetShape();
  markCircleVertices();
  markActiveFaces();
  checkGaussBonnet(checkConeAngles());
  buildUnknowns();
  prepareCircleLoops();
  start();
  while (maxAbs_ > report_.effectiveTolerance) {
    checkStepCap();
    if (gaugeLoop_ >= 0 && !gaugeOn_ && maxAbs_ < gaugeSwitch_) switchOnGauge();
    const Eigen::VectorXd delta = circles_ ? circleDomainNewtonStep() : symmetricNewtonStep();
    NewtonStepInfo info;
    info.step = report_.newtonSteps + 1;
    info.maxResidual = maxAbs_;
    const double t = lineSearch(delta, info);
    if (report_.stoppedAtDegenerate) {
      ++report_.newtonSteps;
      break;
    }
    if (finishStep(info, t)) break;
  }
  return finish();
}

// === validate the target

void NewtonFlowSolver::checkTargetShape() const {
  if (static_cast<int>(target_.angleSum.size()) != nV_)
    throw InputError("conformal target: expected " + std::to_string(nV_) + " target angle sums, found " +
                     std::to_string(target_.angleSum.size()));
  if (!target_.fixed.empty() && static_cast<int>(target_.fixed.size()) != nV_)
    throw InputError("conformal target: expected " + std::to_string(nV_) + " fixed flags, found " +
                     std::to_string(target_.fixed.size()));
  if (bg_ == Background::Spherical)
    throw InputError(
        "conformal target: the spherical vertex-scaling energy is not convex; genus-0 surfaces are "
        "uniformized through a punctured Euclidean problem (uniformization.h)");
  if (circles_ && bg_ != Background::Euclidean)
    throw InputError("conformal target: circle boundary loops are implemented for the Euclidean background only");
}

void NewtonFlowSolver::markCircleVertices() {
  targetSum_ = target_.angleSum;  // circle-loop entries follow the metric
  onCircle_.assign(nV_, 0);
  for (const auto& loop : target_.circleLoops)
    for (int v : loop.vertices) {
      onCircle_[v] = 1;
      targetSum_[v] = M_PI;  // placeholder, only for the admissibility checks below (the turning angles sum correctly)
    }
}

// Which vertices carry an angle-sum equation: free, and in at least one non-frozen face.
void NewtonFlowSolver::markActiveFaces() {
  inActiveFace_.assign(nV_, 0);
  for (int f = 0; f < m_.nFaces(); ++f) {
    if (metric_.isFrozen(f)) {
      anyFrozen_ = true;
      continue;
    }
    for (int k = 0; k < 3; ++k) inActiveFace_[m_.faceVertex(f, k)] = 1;
  }
}

double NewtonFlowSolver::checkConeAngles() {
  double targetCurvature = 0;  // Σ (2π or π) − Θ̂ over free vertices
  for (int v = 0; v < nV_; ++v) {
    if (!target_.fixed.empty() && target_.fixed[v]) {
      anyFixed_ = true;
      continue;
    }
    if (!inActiveFace_[v] || onCircle_[v]) continue;
    const double t = target_.angleSum[v];
    if (!std::isfinite(t) || !(t > 0)) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "conformal target: vertex " << v << " has target angle sum " << t
          << "; a cone angle must be finite and positive";
      throw InputError(msg.str());
    }
    targetCurvature += (m_.isBoundaryVertex(v) ? M_PI : 2 * M_PI) - t;
  }
  return targetCurvature;
}

// Gauss–Bonnet (docs/ricci_flow.md §2): Σ K̂ = 2πχ − K_bg · Area. Euclidean: equality; hyperbolic: Area = Σ K̂ − 2πχ
// must be positive. 1e-9 rad absorbs the round-off of summing 10⁶ targets of size 2π.
void NewtonFlowSolver::checkGaussBonnet(double targetCurvature) const {
  const double twoPiChi = 2 * M_PI * m_.eulerCharacteristic();
  if (anyFixed_ || anyFrozen_ || circles_) return;
  if (bg_ == Background::Euclidean && std::abs(targetCurvature - twoPiChi) > 1e-9 * std::max(1.0, std::sqrt(nV_))) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "conformal target is inadmissible: a flat metric needs total curvature 2πχ = " << twoPiChi
        << " (Gauss–Bonnet), the targets sum to " << targetCurvature;
    throw InputError(msg.str());
  }
  if (bg_ == Background::Hyperbolic && !(targetCurvature - twoPiChi > 0)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "conformal target is inadmissible: a hyperbolic metric has area Σ K̂ − 2πχ = " << targetCurvature - twoPiChi
        << ", which must be positive";
    throw InputError(msg.str());
  }
}

// === build the unknowns

// Free vertices in an active face. With a shared solver cache the Dirichlet vertices of active faces stay unknowns
// with the equation δ_v = 0 (an identity row), so that the dimension — and with it the cached factor — survives
// changes of the Dirichlet set.
void NewtonFlowSolver::buildUnknowns() {
  auto isFixed = [&](int v) { return !target_.fixed.empty() && target_.fixed[v]; };
  index_.assign(nV_, -1);
  shared_ = options_.solverCache != nullptr && !circles_;
  for (int v = 0; v < nV_; ++v)
    if (inActiveFace_[v] && (!isFixed(v) || shared_)) {
      index_[v] = static_cast<int>(unknowns_.size());
      unknowns_.push_back(v);
      identityRow_.push_back(isFixed(v));
      if (!isFixed(v)) equations_.push_back(v);
    }
  if (bg_ == Background::Euclidean && !anyFixed_ && !unknowns_.empty()) pinGaugeVertex();
  n_ = static_cast<int>(unknowns_.size());
  report_.effectiveTolerance = std::max(options_.tolerance, options_.relativeFloor * std::sqrt(double(nV_)));
}

// The Euclidean scale invariance is removed by pinning the first unknown when nothing else fixes it (its equation then
// holds automatically by Gauss–Bonnet). An interior vertex is preferred: circle vertices may carry the Möbius gauge
// rows.
void NewtonFlowSolver::pinGaugeVertex() {
  auto pin = std::find_if(unknowns_.begin(), unknowns_.end(), [&](int v) { return !onCircle_[v]; });
  if (pin == unknowns_.end()) pin = unknowns_.begin();
  index_[*pin] = -1;
  identityRow_.erase(identityRow_.begin() + (pin - unknowns_.begin()));
  unknowns_.erase(pin);
  for (std::size_t i = 0; i < unknowns_.size(); ++i) index_[unknowns_[i]] = static_cast<int>(i);
  report_.gaugeFixed = true;
}

void NewtonFlowSolver::prepareCircleLoops() {
  r_ = Eigen::VectorXd::Zero(n_);
  loopSides_.resize(target_.circleLoops.size());
  loopPolygons_.resize(target_.circleLoops.size());
  report_.circleRadii.assign(target_.circleLoops.size(), 0.0);
  chooseMoebiusGauge();
  // The kernel only matters once the residual is small: for a disk the gauge rows are switched on below gaugeSwitch_;
  // with holes only when the line search stalls (docs/ricci_flow.md §3.3).
  gaugeSwitch_ = target_.circleLoops.size() == 1 ? 1e-6 : 0.0;
}

// The Möbius gauge of circle domains (docs/ricci_flow.md §3.3): the equations of the outer-loop vertices q1, q2 are
// replaced by "the arcs q0→q1 and q1→q2 subtend the central angles they have at the start", q_i = vertices[k_i],
// k_i = 0, n/3, 2n/3. Arc k: edges j with gaugeK_[k] < j ≤ gaugeK_[k+1].
void NewtonFlowSolver::chooseMoebiusGauge() {
  for (std::size_t i = 0; i < target_.circleLoops.size() && gaugeLoop_ < 0; ++i)
    if (target_.circleLoops[i].sign > 0 && target_.circleLoops[i].vertices.size() >= 3)
      gaugeLoop_ = static_cast<int>(i);
  if (gaugeLoop_ < 0) return;
  const auto& loop = target_.circleLoops[gaugeLoop_];
  const int len = static_cast<int>(loop.vertices.size());
  gaugeK_[1] = len / 3;
  gaugeK_[2] = (2 * len) / 3;
  gaugeRow_[0] = index_[loop.vertices[gaugeK_[1]]];
  gaugeRow_[1] = index_[loop.vertices[gaugeK_[2]]];
  if (gaugeRow_[0] < 0 || gaugeRow_[1] < 0) gaugeLoop_ = -1;  // a Dirichlet vertex already fixes the gauge
}

// === the residual

void NewtonFlowSolver::updateCircleTargets() {
  for (std::size_t i = 0; i < target_.circleLoops.size(); ++i) {
    const auto& loop = target_.circleLoops[i];
    const int len = static_cast<int>(loop.edges.size());
    loopSides_[i].resize(len);
    for (int j = 0; j < len; ++j) loopSides_[i][j] = metric_.length(loop.edges[j]);
    loopPolygons_[i] = inscribedPolygon(loopSides_[i], static_cast<int>(i));
    report_.circleRadii[i] = loopPolygons_[i].radius;
    const std::vector<double>& phi = loopPolygons_[i].halfAngle;
    for (int j = 0; j < len; ++j) targetSum_[loop.vertices[j]] = M_PI - loop.sign * (phi[j] + phi[(j + 1) % len]);
  }
}

double NewtonFlowSolver::gaugeAngle(int k) const {
  double angle = 0;
  for (int j = gaugeK_[k] + 1; j <= gaugeK_[k + 1]; ++j) angle += 2 * loopPolygons_[gaugeLoop_].halfAngle[j];
  return angle;
}

// r_v = Θ̂_v − Θ_v on the equations (and the gauge rows when on): max |r| and |r|², infinite when not finite.
void NewtonFlowSolver::evaluateResidual(double& maxAbs, double& norm2) {
  if (circles_) {
    // A trial step can make a short loop uninscribable (one side longer than the rest): an infinite merit rejects
    // the step; at the starting point it is reported.
    try {
      updateCircleTargets();
    } catch (const ConvergenceError& e) {
      circleFailure_ = e.what();
      maxAbs = norm2 = std::numeric_limits<double>::infinity();
      return;
    }
  }
  evaluateFaces(metric_, work_->lengths, work_->sums, work_->faces);
  const std::vector<double>& sums = work_->sums;
  maxAbs = 0;
  norm2 = 0;
  for (int v : equations_) {
    const double rv = targetSum_[v] - sums[v];
    if (!std::isfinite(rv)) {
      maxAbs = norm2 = std::numeric_limits<double>::infinity();
      return;
    }
    maxAbs = std::max(maxAbs, std::abs(rv));
    if (index_[v] >= 0) r_[index_[v]] = rv;
  }
  if (gaugeOn_)
    for (int k = 0; k < 2; ++k) {
      r_[gaugeRow_[k]] = gaugeAngle(k) - gaugeTarget_[k];
      maxAbs = std::max(maxAbs, std::abs(r_[gaugeRow_[k]]));
    }
  norm2 = r_.squaredNorm();
}

bool NewtonFlowSolver::anyDegenerateFace() const {
  for (int f = 0; f < m_.nFaces(); ++f)
    if (!metric_.isFrozen(f) && work_->faces[f].degenerate) return true;
  return false;
}

void NewtonFlowSolver::activateGaugeRows() {
  gaugeOn_ = true;
  row0_ = gaugeRow_[0];
  row1_ = gaugeRow_[1];
}

// The gauge rows on at the current u, their targets the current arcs (docs/ricci_flow.md §3.3, "Möbius gauge").
void NewtonFlowSolver::switchOnGauge() {
  activateGaugeRows();
  for (int k = 0; k < 2; ++k) gaugeTarget_[k] = gaugeAngle(k);
  evaluateResidual(maxAbs_, norm2_);
  patternValid_ = false;
}

// === first evaluation and solver set-up

void NewtonFlowSolver::start() {
  solver_ = shared_ ? options_.solverCache.get() : &local_;
  work_ = &solver_->workspace();
  report_.flips += metric_.makeDelaunay(options_.delaunayTolerance, log_);
  evaluateResidual(maxAbs_, norm2_);
  if (!std::isfinite(maxAbs_))
    throw ConvergenceError(
        "discrete Ricci flow cannot start: " +
        (circleFailure_.empty() ? std::string("the initial angle sums are not finite") : circleFailure_));
  report_.maxResidual = maxAbs_;

  solver_->setDimension(n_);
  factorizationsBefore_ = solver_->factorizations();
  cgBefore_ = solver_->cgIterations();
  faceIndex_.assign(nV_, -1);
  if (!circles_) {
    for (int v = 0; v < nV_; ++v)
      if (index_[v] >= 0 && !identityRow_[index_[v]]) faceIndex_[v] = index_[v];
    work_->assembly.setIdentityRows(identityRow_);
  }
  work_->H.resize(n_, n_);
}

// === assemble and solve the Newton system

// δ = −H⁻¹ r for the symmetric problems, H = −∂Θ/∂u, by inexact Newton (docs/ricci_flow.md §2, "Inexact Newton").
Eigen::VectorXd NewtonFlowSolver::symmetricNewtonStep() {
  Eigen::SparseMatrix<double>& H = work_->H;
  if (!patternValid_) {
    work_->assembly.rebuild(metric_, faceIndex_, n_, H);
    solver_->patternChanged();
    patternValid_ = true;
  }
  work_->assembly.assemble(metric_, work_->faces, H);
  // Forcing term η = max(10⁻¹³, 10⁻² min(1, max|r|), min(10⁻², ε/(4|r|₂))).
  const double eta = std::max(
      {1e-13, 1e-2 * std::min(1.0, maxAbs_), std::min(1e-2, 0.25 * report_.effectiveTolerance / std::sqrt(norm2_))});
  Eigen::VectorXd delta;
  if (!solver_->solve(H, r_, eta, delta)) {
    std::ostringstream msg;
    msg.precision(3);
    msg << "discrete Ricci flow: the Hessian is not positive definite at Newton step " << report_.newtonSteps
        << " (max |Θ̂ − Θ| = " << maxAbs_ << " rad); a triangle has probably degenerated";
    throw ConvergenceError(msg.str());
  }
  delta = -delta;
  for (int i = 0; i < n_; ++i)
    if (identityRow_[i]) delta[i] = 0;  // exactly: the conjugate gradients leave round-off there
  return delta;
}

// δ = −J⁻¹ r for circle domains, J = S + U Vᵀ with S sparse (docs/ricci_flow.md §3.3).
Eigen::VectorXd NewtonFlowSolver::circleDomainNewtonStep() {
  Eigen::MatrixXd U, V;
  assembleCircleJacobian(U, V);
  return solveCircleDomain(U, V);
}

// The sparse part S of J = ∂(Θ̂ − Θ)/∂u into H (the face terms, then the loops' local terms and the gauge rows), and
// the loops' rank-one terms U Vᵀ through their radii.
void NewtonFlowSolver::assembleCircleJacobian(Eigen::MatrixXd& U, Eigen::MatrixXd& V) {
  triplets_.clear();
  triplets_.reserve(9 * static_cast<std::size_t>(m_.nFaces()));
  for (int f = 0; f < m_.nFaces(); ++f) {
    if (metric_.isFrozen(f)) continue;
    double J[3][3];
    angleJacobian(bg_, work_->faces[f], J);
    int idx[3];
    for (int k = 0; k < 3; ++k) idx[k] = index_[m_.faceVertex(f, k)];
    for (int k = 0; k < 3; ++k) {
      if (idx[k] < 0) continue;
      for (int j = 0; j < 3; ++j)
        if (idx[j] >= 0 && idx[j] != row0_ && idx[j] != row1_) triplets_.emplace_back(idx[j], idx[k], -J[j][k]);
    }
  }
  const int nLoops = static_cast<int>(target_.circleLoops.size());
  U = Eigen::MatrixXd::Zero(n_, nLoops);
  V = Eigen::MatrixXd::Zero(n_, nLoops);
  for (int i = 0; i < nLoops; ++i) addCircleLoopTerms(i, U, V);
  Eigen::SparseMatrix<double>& H = work_->H;
  H.setFromTriplets(triplets_.begin(), triplets_.end());
  H.makeCompressed();
}

// Loop i's terms of J: dℓ_e = (ℓ_e/2)(du_a + du_b), c_e = dφ_e/dx_e = ±1/sqrt(1 − x_e²) (x_e = ℓ_e/2R),
// dR = R Σ c_e dℓ_e / Σ c_e ℓ_e and dΘ̂_v = −σ/(2R) (c_p dℓ_p + c_n dℓ_n) + σ (c_p ℓ_p + c_n ℓ_n)/(2R²) dR; on the gauge
// loop the gauge rows d(Σ_arc 2 φ_j) = Σ_arc (c_j/R) dℓ_j − (Σ_arc c_j ℓ_j / R²) dR.
void NewtonFlowSolver::addCircleLoopTerms(int i, Eigen::MatrixXd& U, Eigen::MatrixXd& V) {
  const auto& loop = target_.circleLoops[i];
  const std::vector<double>& sides = loopSides_[i];
  const int len = static_cast<int>(loop.edges.size());
  const double R = report_.circleRadii[i], sigma = loop.sign;
  std::vector<double> c(len);
  double sumCl = 0;
  for (int j = 0; j < len; ++j) {
    const double x = std::min(1.0 - 1e-16, sides[j] / (2 * R));
    c[j] = loopPolygons_[i].side[j] / std::sqrt((1 - x) * (1 + x));  // dφ_j/dx_j
    sumCl += c[j] * sides[j];
  }
  for (int j = 0; j < len; ++j) {
    const int e = loop.edges[j], h = m_.edgeHalfedge(e);
    const int ends[2] = {index_[m_.tail(h)], index_[m_.tip(h)]};
    const double dl = 0.5 * sides[j];  // ∂ℓ_e/∂u at either end
    // Rows of the two loop vertices that edge j borders: vertices[j−1] (edge j is its "next") and vertices[j].
    const int rows[2] = {index_[loop.vertices[(j + len - 1) % len]], index_[loop.vertices[j]]};
    for (int row : rows)
      if (row >= 0 && row != row0_ && row != row1_)
        for (int col : ends)
          if (col >= 0) triplets_.emplace_back(row, col, -sigma / (2 * R) * c[j] * dl);
    for (int col : ends)
      if (col >= 0) V(col, i) += R / sumCl * c[j] * dl;
  }
  for (int j = 0; j < len; ++j) {
    const int row = index_[loop.vertices[j]];
    if (row >= 0 && row != row0_ && row != row1_)
      U(row, i) = sigma * (c[j] * sides[j] + c[(j + 1) % len] * sides[(j + 1) % len]) / (2 * R * R);
  }
  if (!(gaugeOn_ && i == gaugeLoop_)) return;
  for (int k = 0; k < 2; ++k) {
    double sumArc = 0;
    for (int j = gaugeK_[k] + 1; j <= gaugeK_[k + 1]; ++j) {
      const int h = m_.edgeHalfedge(loop.edges[j]);
      for (int col : {index_[m_.tail(h)], index_[m_.tip(h)]})
        if (col >= 0) triplets_.emplace_back(gaugeRow_[k], col, c[j] / R * 0.5 * sides[j]);
      sumArc += c[j] * sides[j];
    }
    U(gaugeRow_[k], i) = -sumArc / (R * R);
  }
}

// Sherman–Morrison–Woodbury: (S + U Vᵀ)⁻¹ r = y − Z (I + Vᵀ Z)⁻¹ Vᵀ y with S y = r, S Z = U (S by sparse LU).
Eigen::VectorXd NewtonFlowSolver::solveCircleDomain(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V) {
  const Eigen::SparseMatrix<double>& H = work_->H;
  if (!patternValid_) {
    lu_.analyzePattern(H);
    patternValid_ = true;
  }
  lu_.factorize(H);
  if (lu_.info() != Eigen::Success) {
    std::ostringstream msg;
    msg.precision(3);
    msg << "discrete Ricci flow: the circle-domain Jacobian is singular at Newton step " << report_.newtonSteps
        << " (max |Θ̂ − Θ| = " << maxAbs_ << " rad)";
    throw ConvergenceError(msg.str());
  }
  const int nLoops = static_cast<int>(U.cols());
  const Eigen::VectorXd y = lu_.solve(r_);
  Eigen::MatrixXd Z(n_, nLoops);
  for (int i = 0; i < nLoops; ++i) Z.col(i) = lu_.solve(Eigen::VectorXd(U.col(i)));
  const Eigen::MatrixXd small = Eigen::MatrixXd::Identity(nLoops, nLoops) + V.transpose() * Z;
  return -(y - Z * small.fullPivLu().solve(V.transpose() * y));
}

// === line search

// Armijo backtracking from u0 along δ, halving t: on ½|r|² (the Newton direction has slope −|r|²), and for Euclidean
// problems without circle loops also on the convex energy (acceptByEnergy). Special exits: with
// returnAtDegenerateStall, a return to a start with degenerate faces (report_.stoppedAtDegenerate); for circle domains
// with the gauge still off, switching it on at the start; otherwise a stall below minStep throws.
double NewtonFlowSolver::lineSearch(const Eigen::VectorXd& delta, NewtonStepInfo& info) {
  const std::vector<double> u0 = metric_.u();
  if (usesEnergy()) {
    double magnitude = 0;
    energy0_ = energyHere(magnitude);
    slope0_ = r_.dot(delta);
  }
  double t = 1.0;
  const double longest = delta.lpNorm<Eigen::Infinity>();
  while (t * longest > options_.maxTrialStep && t > options_.minStep) t *= 0.5;  // trials that far only flip
  const double norm2Old = norm2_;
  bool startChecked = false;
  while (!tryStep(u0, delta, t, norm2Old, info)) {
    t *= 0.5;
    if (options_.allowDegenerateFaces && options_.returnAtDegenerateStall && t <= 0.5 && !startChecked) {
      startChecked = true;  // once per step
      if (stopAtDegenerateStart(u0)) break;
    }
    if (t < options_.minStep && gaugeLoop_ >= 0 && !gaugeOn_) {
      switchOnGaugeAtStall(u0);
      break;
    }
    if (t < options_.minStep) {
      if (polishInExtendedPrecision(u0)) {
        t = 1;  // full refinement steps
        break;
      }
      throwStalled(u0, info);
    }
  }
  return t;
}

// u = u0 + t δ on the unknowns, flips, and the residual there; accepted (maxAbs_, norm2_ updated) when Armijo holds.
bool NewtonFlowSolver::tryStep(const std::vector<double>& u0, const Eigen::VectorXd& delta, double t, double norm2Old,
                               NewtonStepInfo& info) {
  for (int i = 0; i < n_; ++i) metric_.u()[unknowns_[i]] = u0[unknowns_[i]] + t * delta[i];
  const std::int64_t flips = metric_.makeDelaunay(options_.delaunayTolerance, log_);
  info.flips += flips;
  report_.flips += flips;
  if (flips > 0) patternValid_ = false;
  double newMax = 0, newNorm2 = 0;
  evaluateResidual(newMax, newNorm2);
  const bool accept = usesEnergy() ? acceptByEnergy(t, newNorm2, norm2Old)
                                   : std::isfinite(newNorm2) && newNorm2 <= (1 - 2 * options_.armijo * t) * norm2Old;
  if (accept) {
    maxAbs_ = newMax;
    norm2_ = newNorm2;
    return true;
  }
  return false;
}

// E(u) − (terms constant in the unknowns) from the faces of the last evaluateResidual (conformal_energy.h).
double NewtonFlowSolver::energyHere(double& magnitude) const {
  magnitude = 0;
  double energy = detail::faceEnergy(metric_, work_->faces, magnitude);
  for (int v : equations_) {
    energy += targetSum_[v] * metric_.u()[v];
    magnitude += std::abs(targetSum_[v] * metric_.u()[v]);
  }
  return energy;
}

// A step is accepted when ½|r|² decreases by Armijo (as without the energy) or when the convex energy does,
// E(u0 + tδ) ≤ E(u0) + c t rᵀδ (docs/ricci_flow.md §2 "The energy and the line search"); the energy test only counts
// while the expected decrease ½ t |rᵀδ| is above E's round-off (64 ε Σ|terms|). The energy descends along every
// Newton direction (rᵀδ = −rᵀH⁻¹r < 0), so steps that the residual test rejects far from the solution — where the
// residual may grow on the way to the minimum — are still taken.
bool NewtonFlowSolver::acceptByEnergy(double t, double newNorm2, double norm2Old) {
  if (!std::isfinite(newNorm2)) return false;
  if (newNorm2 <= (1 - 2 * options_.armijo * t) * norm2Old) return true;
  double magnitude = 0;
  const double dE = energyHere(magnitude) - energy0_;
  const double roundOff = 64 * std::numeric_limits<double>::epsilon() * magnitude;
  return std::isfinite(dE) && 0.5 * t * std::abs(slope0_) > roundOff && dE <= options_.armijo * t * slope0_;
}

std::pair<int, double> NewtonFlowSolver::worstResidual() const {
  int worst = -1;
  double err = 0;
  for (int v : equations_) {
    const double rv = targetSum_[v] - work_->sums[v];
    if (worst < 0 || std::abs(rv) > std::abs(err)) {
      worst = v;
      err = rv;
    }
  }
  return {worst, err};
}

std::string NewtonFlowSolver::worstVertex() const {
  const auto [worst, err] = worstResidual();
  std::ostringstream msg;
  msg.precision(3);
  msg << "worst at vertex " << worst << " (Θ̂ − Θ = " << err << " rad)";
  return msg.str();
}

void NewtonFlowSolver::restoreStart(const std::vector<double>& u0) {
  for (int i = 0; i < n_; ++i) metric_.u()[unknowns_[i]] = u0[unknowns_[i]];
}

// Back to the step's start, where the degenerate faces that the caller can repair are: true (and the flow stops) when
// some face there has the extended angles (π, 0, 0).
bool NewtonFlowSolver::stopAtDegenerateStart(const std::vector<double>& u0) {
  restoreStart(u0);
  report_.flips += metric_.makeDelaunay(options_.delaunayTolerance, log_);
  double startMax = 0, startNorm2 = 0;
  evaluateResidual(startMax, startNorm2);
  if (!anyDegenerateFace()) return false;
  maxAbs_ = startMax;
  norm2_ = startNorm2;
  report_.maxResidual = maxAbs_;
  report_.stoppedAtDegenerate = true;
  return true;
}

// With holes the gauge is only a fallback: switched on at the step's start when no step decreases the merit.
void NewtonFlowSolver::switchOnGaugeAtStall(const std::vector<double>& u0) {
  restoreStart(u0);
  metric_.makeDelaunay(options_.delaunayTolerance, log_);
  activateGaugeRows();
  evaluateResidual(maxAbs_, norm2_);
  for (int k = 0; k < 2; ++k) gaugeTarget_[k] = gaugeAngle(k);
  evaluateResidual(maxAbs_, norm2_);
  patternValid_ = false;
}

// The precision fallback (docs/ricci_flow.md §2 "Where double precision runs out"): at a stall with max |r| below
// kPolishBelow, Newton by iterative refinement — the residual in long double at u + du (extendedAngleSums), the
// correction from the double Hessian of the stall point (symmetricNewtonStep, no flips: the corrections are at
// round-off size), du accumulated in long double. Accepted when max |r| reaches the tolerance within kPolishSteps
// steps, each reducing it at least by half; then u is rounded to double and the residual reported is the extended one.
// Otherwise u is restored and the stall is reported as before. Euclidean problems without circle loops only.
bool NewtonFlowSolver::polishInExtendedPrecision(const std::vector<double>& u0) {
  constexpr double kPolishBelow = 1e-5;
  constexpr int kPolishSteps = 8;
  if (bg_ != Background::Euclidean || circles_) return false;
  restoreStart(u0);
  report_.flips += metric_.makeDelaunay(options_.delaunayTolerance, log_);
  evaluateResidual(maxAbs_, norm2_);
  if (!(maxAbs_ <= kPolishBelow)) return false;
  std::vector<long double> du(nV_, 0.0L), sums;
  long double previous = std::numeric_limits<long double>::infinity();
  for (int step = 0; step <= kPolishSteps; ++step) {
    extendedAngleSums(metric_, du, sums);
    long double maxAbs = 0;
    for (int v : equations_) {
      const long double rv = static_cast<long double>(targetSum_[v]) - sums[v];
      maxAbs = std::max(maxAbs, std::abs(rv));
      if (index_[v] >= 0) r_[index_[v]] = static_cast<double>(rv);
    }
    if (!(maxAbs < 0.5L * previous)) break;
    previous = maxAbs;
    maxAbs_ = static_cast<double>(maxAbs);
    norm2_ = r_.squaredNorm();
    if (maxAbs_ <= report_.effectiveTolerance) {
      for (int v = 0; v < nV_; ++v) {
        metric_.u()[v] = static_cast<double>(static_cast<long double>(metric_.u()[v]) + du[v]);
        work_->sums[v] = static_cast<double>(sums[v]);
      }
      report_.extendedPolishSteps = step;
      return true;
    }
    const Eigen::VectorXd delta = symmetricNewtonStep();
    for (int i = 0; i < n_; ++i) du[unknowns_[i]] += delta[i];
  }
  restoreStart(u0);
  evaluateResidual(maxAbs_, norm2_);
  return false;
}

void NewtonFlowSolver::throwStalled(const std::vector<double>& u0, const NewtonStepInfo& info) {
  // Restore a consistent residual vector before reporting.
  restoreStart(u0);
  metric_.makeDelaunay(options_.delaunayTolerance, log_);
  evaluateResidual(maxAbs_, norm2_);
  std::ostringstream msg;
  msg.precision(3);
  msg << "discrete Ricci flow stalled at Newton step " << info.step
      << (usesEnergy() ? ": no step decreases the energy, max |Θ̂ − Θ| = "
                       : ": no step decreases |Θ̂ − Θ|, max |Θ̂ − Θ| = ")
      << maxAbs_ << " rad, tolerance " << report_.effectiveTolerance << "; " << worstVertex();
  throw ConvergenceError(msg.str(), worstResidual().first);
}

// === stopping tests

// A flow whose line search accepts only tiny steps without progress is stalled in all but name: each trial step still
// flips (cylinder_locally_refined.off: 22 Newton steps of t from 2⁻¹⁰ down to 1.5·10⁻⁸ at max |r| ≈ 5.2·10⁻³, their
// trials flipping 4·10⁶ edges in 20 s before a Ptolemy length overflowed). Eight consecutive steps of t < 2⁻⁸ that
// together reduce max |r| by less than 1 % end it: first by switching on a circle domain's Möbius gauge if it is off
// (the kernel is one cause of crawling), then as a stall, so that the caller's fallbacks (the double) start at once.
// Newton in its quadratic region takes t = 1; a run of tiny steps that makes progress is left alone.
//
// Close to the solution (max |r| < 10⁻⁶) a circle domain's gauge goes on at the first step halved below 2⁻⁷: Newton is
// in its quadratic region there and takes t = 1 unless the direction runs along the Möbius kernel (lion.off, 5 loops:
// 85 steps of t ≈ 2⁻¹² from 8.5·10⁻¹⁰ to the step cap at 8.25·10⁻¹⁰; with the gauge on, converged in one more step).
void NewtonFlowSolver::checkCrawl(double t, double before) {
  constexpr double kCrawlStep = 1.0 / 256, kProgress = 0.99, kNearStep = 1.0 / 128, kNear = 1e-6;
  constexpr int kCrawlRun = 8;
  const bool gaugeAvailable = gaugeLoop_ >= 0 && !gaugeOn_;
  if (gaugeAvailable && t < kNearStep && maxAbs_ < kNear) {
    crawlSteps_ = 0;
    switchOnGauge();
    return;
  }
  if (!(t < kCrawlStep)) {
    crawlSteps_ = 0;
    return;
  }
  if (crawlSteps_++ == 0) crawlFrom_ = before;
  if (crawlSteps_ < kCrawlRun) return;
  if (!(maxAbs_ > kProgress * crawlFrom_)) {
    crawlSteps_ = 0;
    return;
  }
  crawlSteps_ = 0;
  if (gaugeAvailable) {
    switchOnGauge();
    return;
  }
  std::ostringstream msg;
  msg.precision(3);
  msg << "discrete Ricci flow stalled at Newton step " << report_.newtonSteps << ": " << kCrawlRun
      << " steps of length below 2^-8 reduced max |Θ̂ − Θ| only from " << crawlFrom_ << " to " << maxAbs_
      << " rad, tolerance " << report_.effectiveTolerance << "; " << worstVertex();
  throw ConvergenceError(msg.str(), worstResidual().first);
}

void NewtonFlowSolver::checkStepCap() const {
  if (report_.newtonSteps < options_.maxNewtonSteps) return;
  std::ostringstream msg;
  msg.precision(3);
  msg << "discrete Ricci flow did not converge in " << options_.maxNewtonSteps
      << " Newton steps: max |Θ̂ − Θ| = " << maxAbs_ << " rad, tolerance " << report_.effectiveTolerance << "; "
      << worstVertex();
  throw ConvergenceError(msg.str(), worstResidual().first);
}

bool NewtonFlowSolver::finishStep(const NewtonStepInfo& info, double t) {
  NewtonStepInfo done = info;
  done.stepLength = t;
  ++report_.newtonSteps;
  report_.maxResidual = maxAbs_;
  if (options_.onStep) options_.onStep(done);
  checkCrawl(t, info.maxResidual);
  if (options_.stopAfterStep && maxAbs_ > report_.effectiveTolerance && options_.stopAfterStep(work_->sums, maxAbs_)) {
    report_.stoppedByCaller = true;
    return true;
  }
  return false;
}

RicciFlowReport NewtonFlowSolver::finish() {
  report_.maxResidual = maxAbs_;
  report_.factorizations = solver_->factorizations() - factorizationsBefore_;
  report_.cgIterations = solver_->cgIterations() - cgBefore_;
  report_.nestedDissection = solver_->nestedDissection();
  if (!report_.stoppedAtDegenerate && !report_.stoppedByCaller) {
    // The extended angles (π, 0, 0) make the energy convex everywhere, but a solution with such a face is not a
    // metric: it happens only next to edges that may not flip (boundary, frozen), when the conformal class has no
    // triangulation of this boundary with valid triangles.
    for (int f = 0; f < m_.nFaces() && !options_.allowDegenerateFaces; ++f)
      if (!metric_.isFrozen(f) && work_->faces[f].degenerate)
        throw ConvergenceError("discrete Ricci flow converged to a degenerate face " + std::to_string(f) + " (" +
                               std::to_string(m_.faceVertex(f, 0)) + ", " + std::to_string(m_.faceVertex(f, 1)) + ", " +
                               std::to_string(m_.faceVertex(f, 2)) +
                               "): the target needs a flip of an edge that may not flip (a boundary edge)");
  }
  report_.angleSums = work_->sums;
  report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return report_;
}

}  // namespace conformesh::intrinsic
