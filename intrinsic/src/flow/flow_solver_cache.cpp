// flow_solver_cache.cpp — factor reuse, single-precision preconditioning and conjugate gradients for the symmetric
// Newton systems (flow_solver_cache.h).
#include "flow/flow_solver_cache.h"

#include <string>

#include "conformesh/intrinsic/errors.h"
#include "flow/linalg/fill_reducing_order.h"

namespace conformesh::intrinsic {

using SparseMatrix = Eigen::SparseMatrix<double>;

bool FlowSolverCache::solve(const SparseMatrix& H, const Eigen::VectorXd& b, double relativeTolerance,
                            Eigen::VectorXd& x) {
  if (haveFactor_ && maxIterations_ > 0 && preconditionedCG(H, b, relativeTolerance, x)) return true;
  if (!patternValid_) analyse(H);
  solver_.factorize(H);
  ++factorizations_;
  haveFactor_ = solver_.info() == Eigen::Success;
  if (!haveFactor_) return false;
  if (!analysed_) analysed_ = single_.analyse(solver_.factor());
  single_.invalidate();  // rounded when the conjugate gradients first need it (a torus at 10⁶ never does)
  x = solver_.solve(b);
  return true;
}

void FlowSolverCache::analyse(const SparseMatrix& H) {
  nestedDissection_ = H.rows() >= nestedDissectionMin_;
  if (nestedDissection_)
    solver_.analyzePattern(H, nestedDissectionOrder(H));
  else
    solver_.analyzePattern(H);
  if (solver_.factor() == nullptr)
    throw ConvergenceError("discrete Ricci flow: CHOLMOD's symbolic analysis of the " + std::to_string(H.rows()) +
                           "-unknown Newton system failed (CHOLMOD status " + std::to_string(solver_.cholmod().status) +
                           "; −2 is out of memory)");
  patternValid_ = true;
  analysed_ = false;
}

void FlowSolverCache::precondition(const Eigen::VectorXd& residual, Eigen::VectorXd& out) {
  if (single_.valid())
    single_.solve(residual, out);
  else
    out = solver_.solve(residual);
}

bool FlowSolverCache::preconditionedCG(const SparseMatrix& H, const Eigen::VectorXd& b, double relativeTolerance,
                                       Eigen::VectorXd& x) {
  const double bound = relativeTolerance * b.norm();
  x.setZero(b.size());
  if (analysed_ && !single_.valid()) single_.setValues(solver_.factor());
  Eigen::VectorXd r = b, z, p, q;
  precondition(r, z);
  p = z;
  double rz = r.dot(z);
  for (int it = 1; it <= maxIterations_; ++it) {
    q = H.selfadjointView<Eigen::Lower>() * p;
    const double pq = p.dot(q);
    if (!(pq > 0)) return false;
    const double alpha = rz / pq;
    x += alpha * p;
    r -= alpha * q;
    ++cgIterations_;
    if (r.norm() <= bound) return true;
    precondition(r, z);
    const double rzNew = r.dot(z);
    p = z + (rzNew / rz) * p;
    rz = rzNew;
  }
  return false;
}

}  // namespace conformesh::intrinsic
