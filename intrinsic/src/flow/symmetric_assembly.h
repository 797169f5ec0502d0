// symmetric_assembly.h — the Hessian H = −∂Θ/∂u of the symmetric Newton systems, assembled straight into the
// compressed lower triangle of a sparse matrix with a pattern kept between steps. Private to the flow
// (newton_flow.cpp); reads the metric and the face geometry of face_angles.h.
#pragma once

#include <vector>

#include <Eigen/SparseCore>

#include "flow/face_angles.h"

namespace conformesh::intrinsic::detail {

// H = −∂Θ/∂u of the symmetric problems, assembled straight into its compressed lower triangle. Face f contributes
// −½(J[k][j] + J[j][k]) at (row, column) = (i_j, i_k) for its corners' unknowns i_j ≥ i_k (J = angleJacobian), and an
// identity row gets 1. The pattern, and for every face the position of each of its entries in it, depend only on the
// connectivity and change only with flips, so they are rebuilt only then. The faces' Jacobians (transcendental
// functions in the hyperbolic case) are evaluated in parallel; they are then added into their slots on one thread in
// face order, starting from −0 — which is what summing the triplets in that order gives (Eigen's setFromTriplets, used
// before: the first value, then the rest added in order), so H is the same to the bit, whatever the number of threads.
class SymmetricAssembly {
 public:
  // The pattern of H (n × n, lower triangle) for the unknown index of every vertex (−1: not an unknown, or an identity
  // row), and the slot of every face's entries in it; call after every change of connectivity.
  void rebuild(const DiscreteConformalMetric& metric, const std::vector<int>& unknownIndex, int n,
               Eigen::SparseMatrix<double>& H);

  // Which unknowns have identity rows (Dirichlet vertices kept as unknowns); their faces' entries are left out.
  void setIdentityRows(const std::vector<char>& identity) { identity_ = identity; }

  // The values of H at the geometry `faces` (evaluateFaces), into the pattern of the last rebuild.
  void assemble(const DiscreteConformalMetric& metric, const std::vector<FaceGeometry>& faces,
                Eigen::SparseMatrix<double>& H);

 private:
  std::vector<char> identity_;
  std::vector<int> slot_;  // 9 per face, pair (k, j) at 3k + j: the position of its entry in H, −1 when not stored
  std::vector<int> identitySlot_;
  std::vector<double> value_;  // 6 per face (kPair)
};

}  // namespace conformesh::intrinsic::detail
