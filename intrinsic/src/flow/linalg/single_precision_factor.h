// single_precision_factor.h — the conjugate gradients' preconditioner of the Ricci flow's Newton systems: a CHOLMOD
// supernodal Cholesky factor rounded to single precision, applied by triangular solves on two cores (internal to the
// flow, ricci_flow.cpp; tested in tests/intrinsic/test_single_precision_factor.cpp).
#pragma once

#include <Eigen/Core>

#include <cholmod.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace conformesh::intrinsic {

// The preconditioner of the conjugate gradients: CHOLMOD's supernodal factor P H Pᵀ = L Lᵀ with L rounded to single
// precision, applied by our own triangular solves on two cores. A solve reads every entry of L twice and does two
// flops with it, so it is bound by memory traffic: at 10⁶ vertices L has ≈ 8·10⁷ stored entries, and CHOLMOD's solve
// took 0.28 s (one core, ATLAS's dgemv/dtrsv per supernode). Single precision halves the traffic; the arithmetic stays
// in double. M = L̃ L̃ᵀ is still symmetric positive definite (L̃ has a positive diagonal), so the conjugate gradients
// keep their theory, and M⁻¹H differs from the exactly factored one by O(√κ(H) · 2⁻²⁴) — far less than the change of
// H between Newton steps, which the iterations absorb anyway. The Newton step right after a factorization still uses
// CHOLMOD's double-precision solve.
//
// Storage and kernels: CHOLMOD stores each supernode as a full nsrow × nscol column-major block, the unused upper
// triangle of its diagonal block included; the single-precision copy keeps column j from row j down only (at 10⁶
// vertices 6.8·10⁷ instead of 8.1·10⁷ entries). Both solves take the columns four at a time, so that every pass over
// a supernode's rows does four columns' work (the forward solve updates the rows below with four columns at once, the
// backward solve forms four dot products sharing the loads of the solution), and are compiled twice, for x86-64-v3
// (AVX2, FMA) and the baseline, the better one chosen at load time (measured on the 10⁶-vertex box, one solve: 95–105
// ms column by column, 70–75 ms with the four-column kernels on x86-64-v3).
//
// Two cores: in the postordered supernodal elimination tree, subtrees are contiguous ranges of supernodes and
// independent of each other in both triangular solves. The heaviest nodes are moved from the top of the tree into a
// serial "top" part until the remaining subtrees split into two bins of nearly equal work (within 55 : 45). The
// forward solve runs the bins as two chunks of runChunks (two_threads.h); their updates of rows of the top part are
// added into one buffer per bin, which are subtracted in bin order before the top part is solved, and the backward
// solve runs the top part first, then the bins in parallel (they only read the top part's values). Every row is
// computed by one bin in a fixed order, so the result does not depend on the number or timing of the threads.
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
