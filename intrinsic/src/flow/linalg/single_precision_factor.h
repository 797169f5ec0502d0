// single_precision_factor.h — the conjugate gradients' preconditioner of the Ricci flow's Newton systems: a CHOLMOD
// supernodal Cholesky factor rounded to single precision, applied by triangular solves on two cores. Private to the
// flow (flow_solver_cache.cpp); reads the CHOLMOD factor it is given, owns its copy. Tested in
// tests/intrinsic/flow/linalg/test_single_precision_factor.cpp; storage, kernels and threading: docs/ricci_flow.md §2.
#pragma once

#include <Eigen/Core>

#include <cholmod.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace conformesh::intrinsic {

// M = L̃ L̃ᵀ with L̃ CHOLMOD's supernodal factor of P H Pᵀ rounded to single precision (arithmetic in double): symmetric
// positive definite, so conjugate gradients keep their theory. Each supernode keeps its columns from the diagonal down;
// both solves take four columns at a time (compiled for x86-64-v3 and the baseline, chosen at load time). The
// postordered elimination tree is split into a serial top part and two bins of independent subtrees run on two
// threads (two_threads.h), each row computed by one bin in a fixed order: the result does not depend on the threads.
class SinglePrecisionFactor {
 public:
  // After an analysis: the structure and the bins. Returns false when CHOLMOD's factor is not supernodal.
  bool analyse(const cholmod_factor* L);
  // After a factorization with that analysis, before the first solve with it: the values in single precision, the
  // columns of each supernode from their diagonal down.
  void setValues(const cholmod_factor* L);
  bool valid() const { return valid_; }
  void invalidate() { valid_ = false; }
  // x = Pᵀ L̃⁻ᵀ L̃⁻¹ P b.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

 private:
  // Index in value_ of row 0 of column j of supernode t, whose rows i ≥ j only are stored (the column holds nsrow − j
  // of them, after those of columns 0 … j − 1): the entry (i, j) is at column(t, j, nsrow) + i for i ≥ j.
  std::ptrdiff_t column(std::ptrdiff_t t, std::ptrdiff_t j, std::ptrdiff_t nsrow) const {
    return start_[t] + j * nsrow - j * (j - 1) / 2 - j;
  }

  // One supernode of the forward and of the backward solve (single_precision_factor.cpp).
  void forward(int t, double* y, double* buffer, double* w) const;
  void backward(int t, double* y, double* w) const;

  bool valid_ = false;
  int n_ = 0, nsuper_ = 0, maxRows_ = 0;
  bool parallel_ = false;  // the two bins on two threads
  const int *perm_ = nullptr, *super_ = nullptr, *pi_ = nullptr, *px_ = nullptr, *rows_ = nullptr;
  std::vector<std::ptrdiff_t> start_;  // per supernode, the index of its first entry in value_
  std::vector<float> value_;
  std::vector<char> inTop_, topRow_;
  std::vector<int> topRows_;
  std::vector<std::pair<int, int>> bins_[2];  // supernode ranges [first, end) of the subtrees of each bin
  std::vector<double> buffer_[2], scratch_[2];
  Eigen::VectorXd y_;
};

}  // namespace conformesh::intrinsic
