// flow_solver_cache.h — the linear algebra of the symmetric Newton systems H δ = b, shared by consecutive flow solves
// on one metric (RicciFlowOptions::solverCache): the last CHOLMOD factor, which preconditions conjugate gradients in
// the next steps, its single-precision copy, and the arrays of the solve. Private to the flow (newton_flow.cpp,
// ricci_flow.cpp); owns its CHOLMOD state, touches nothing else. Derivation: docs/ricci_flow.md §2 ("Linear
// algebra").
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "flow/face_angles.h"
#include "flow/linalg/single_precision_factor.h"
#include "flow/linalg/supernodal_cholesky.h"
#include "flow/symmetric_assembly.h"

namespace conformesh::intrinsic {

// The arrays of one flow solve — the last evaluation (edge lengths, angle sums, face geometry) and the Newton system;
// kept in the cache so that repeated solves on one mesh reuse their memory.
struct FlowWorkspace {
  std::vector<double> lengths, sums;
  std::vector<detail::FaceGeometry> faces;
  detail::SymmetricAssembly assembly;
  Eigen::SparseMatrix<double> H;
};

// Solves H δ = b for the symmetric positive definite Hessian (lower triangle stored): conjugate gradients
// preconditioned by the last factor (applied in single precision) while they converge within `maxIterations`,
// otherwise a new supernodal Cholesky factorization and a direct solve. The symbolic analysis (CHOLMOD's order, or
// SCOTCH nested dissection from `nestedDissectionMin` unknowns on) is redone only after patternChanged().
class FlowSolverCache {
 public:
  FlowSolverCache(int maxIterations, int nestedDissectionMin)
      : maxIterations_(maxIterations), nestedDissectionMin_(nestedDissectionMin) {}
  void patternChanged() { patternValid_ = false; }
  // A factor of another dimension cannot precondition: forget it.
  void setDimension(int n) {
    if (n != dimension_) haveFactor_ = patternValid_ = false;
    dimension_ = n;
  }
  int factorizations() const { return factorizations_; }
  int cgIterations() const { return cgIterations_; }
  FlowWorkspace& workspace() { return workspace_; }
  bool nestedDissection() const { return nestedDissection_; }

  // x = H⁻¹ b to the relative residual `relativeTolerance` (exactly, up to round-off, after a factorization). Returns
  // false when the factorization fails (H not positive definite); throws ConvergenceError when CHOLMOD's symbolic
  // analysis fails.
  bool solve(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& b, double relativeTolerance,
             Eigen::VectorXd& x);

 private:
  // The symbolic analysis of H's pattern, in the order chosen by its size.
  void analyse(const Eigen::SparseMatrix<double>& H);
  // Conjugate gradients preconditioned by the last factor; false when they do not converge within maxIterations_.
  bool preconditionedCG(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& b, double relativeTolerance,
                        Eigen::VectorXd& x);
  // out = M⁻¹ residual with M the last factor: its single-precision copy when rounded, else CHOLMOD's solve.
  void precondition(const Eigen::VectorXd& residual, Eigen::VectorXd& out);

  SupernodalCholesky solver_;
  SinglePrecisionFactor single_;
  FlowWorkspace workspace_;
  int maxIterations_, nestedDissectionMin_;
  int dimension_ = -1;
  bool patternValid_ = false, haveFactor_ = false, analysed_ = false, nestedDissection_ = false;
  int factorizations_ = 0, cgIterations_ = 0;
};

}  // namespace conformesh::intrinsic
