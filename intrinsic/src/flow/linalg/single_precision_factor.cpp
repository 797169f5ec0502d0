// single_precision_factor.cpp — the single-precision copy of a CHOLMOD supernodal factor and its two-core triangular
// solves (single_precision_factor.h).
#include "flow/linalg/single_precision_factor.h"

#include <algorithm>
#include <functional>

#include "flow/linalg/two_threads.h"

// The triangular-solve kernels of SinglePrecisionFactor, compiled for x86-64-v3 (AVX2, FMA) and for the baseline; the
// dynamic loader picks the first one the CPU supports (GCC's function multiversioning).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define CONFORMESH_SOLVE_KERNEL __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define CONFORMESH_SOLVE_KERNEL
#endif

namespace conformesh::intrinsic {

bool SinglePrecisionFactor::analyse(const cholmod_factor* L) {
  valid_ = false;
  if (L == nullptr || !L->is_super || L->itype != CHOLMOD_INT || L->xtype != CHOLMOD_REAL) return false;
  n_ = static_cast<int>(L->n);
  nsuper_ = static_cast<int>(L->nsuper);
  perm_ = static_cast<const int*>(L->Perm);
  super_ = static_cast<const int*>(L->super);
  pi_ = static_cast<const int*>(L->pi);
  px_ = static_cast<const int*>(L->px);
  rows_ = static_cast<const int*>(L->s);
  std::vector<int> columnSuper(n_), parent(nsuper_, -1), first(nsuper_), size(nsuper_, 1);
  std::vector<double> work(nsuper_), subtree(nsuper_, 0.0);
  maxRows_ = 0;
  for (int t = 0; t < nsuper_; ++t) {
    for (int c = super_[t]; c < super_[t + 1]; ++c) columnSuper[c] = t;
    maxRows_ = std::max(maxRows_, pi_[t + 1] - pi_[t]);
  }
  for (int t = 0; t < nsuper_; ++t) {
    const int nscol = super_[t + 1] - super_[t], nsrow = pi_[t + 1] - pi_[t];
    work[t] = double(nscol) * nsrow - 0.5 * double(nscol) * (nscol - 1);
    if (nsrow > nscol) parent[t] = columnSuper[rows_[pi_[t] + nscol]];
    first[t] = t;
  }
  // Children precede their parent; a subtree is the range [first, t] exactly when the tree is postordered.
  bool contiguous = true;
  for (int t = 0; t < nsuper_; ++t) {
    subtree[t] += work[t];
    contiguous = contiguous && size[t] == t - first[t] + 1;
    const int p = parent[t];
    if (p < 0) continue;
    if (p <= t) return false;
    subtree[p] += subtree[t];
    size[p] += size[t];
    first[p] = std::min(first[p], first[t]);
  }
  inTop_.assign(nsuper_, 0);
  for (auto& bin : bins_) bin.clear();
  if (!contiguous) {
    std::fill(inTop_.begin(), inTop_.end(), 1);  // everything serial
  } else {
    std::vector<std::vector<int>> children(nsuper_);
    std::vector<int> frontier;
    for (int t = 0; t < nsuper_; ++t) (parent[t] >= 0 ? children[parent[t]] : frontier).push_back(t);
    auto heavierFirst = [&](int a, int b) { return subtree[a] > subtree[b] || (subtree[a] == subtree[b] && a < b); };
    while (!frontier.empty()) {
      std::sort(frontier.begin(), frontier.end(), heavierFirst);
      double load[2] = {0, 0};
      for (int t : frontier) load[load[0] <= load[1] ? 0 : 1] += subtree[t];
      if (std::max(load[0], load[1]) <= 0.55 * (load[0] + load[1])) break;
      const int heaviest = frontier.front();
      frontier.erase(frontier.begin());
      inTop_[heaviest] = 1;
      frontier.insert(frontier.end(), children[heaviest].begin(), children[heaviest].end());
    }
    double load[2] = {0, 0};
    for (int t : frontier) {
      const int b = load[0] <= load[1] ? 0 : 1;
      load[b] += subtree[t];
      bins_[b].emplace_back(first[t], t + 1);
    }
    for (auto& bin : bins_) std::sort(bin.begin(), bin.end());
  }
  topRow_.assign(n_, 0);
  topRows_.clear();
  for (int t = 0; t < nsuper_; ++t)
    if (inTop_[t])
      for (int c = super_[t]; c < super_[t + 1]; ++c) {
        topRow_[c] = 1;
        topRows_.push_back(c);
      }
  for (auto& buffer : buffer_) buffer.assign(n_, 0.0);
  for (auto& scratch : scratch_) scratch.assign(maxRows_, 0.0);
  return true;
}

void SinglePrecisionFactor::setValues(const cholmod_factor* L) {
  const double* x = static_cast<const double*>(L->x);
  start_.assign(nsuper_ + 1, 0);
  for (int t = 0; t < nsuper_; ++t) {
    const std::ptrdiff_t nscol = super_[t + 1] - super_[t], nsrow = pi_[t + 1] - pi_[t];
    start_[t + 1] = start_[t] + nscol * nsrow - nscol * (nscol - 1) / 2;
  }
  const std::ptrdiff_t size = start_[nsuper_];
  // Two threads for the solves once L has ≥ 10⁶ stored entries (≈ 10⁴ vertices, a solve of ≈ 1 ms).
  parallel_ = size >= 1000000;
  value_.resize(size);
  onTwoCores(nsuper_, 1000, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto t = begin; t < end; ++t) {
      const int nscol = super_[t + 1] - super_[t], nsrow = pi_[t + 1] - pi_[t];
      for (int j = 0; j < nscol; ++j) {
        const double* from = x + px_[t] + static_cast<std::ptrdiff_t>(j) * nsrow;
        float* to = value_.data() + column(t, j, nsrow);
        for (int i = j; i < nsrow; ++i) to[i] = static_cast<float>(from[i]);
      }
    }
  });
  valid_ = true;
}

void SinglePrecisionFactor::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  y_.resize(n_);
  for (int k = 0; k < n_; ++k) y_[k] = b[perm_[k]];
  double* y = y_.data();
  auto bothBins = [&](const std::function<void(int)>& bin) {
    if (parallel_)
      runChunks(2, bin);
    else
      for (int chunk = 0; chunk < 2; ++chunk) bin(chunk);
  };
  bothBins([&](int bin) {
    double* buffer = buffer_[bin].data();
    for (int r : topRows_) buffer[r] = 0;
    for (const auto& range : bins_[bin])
      for (int t = range.first; t < range.second; ++t) forward(t, y, buffer, scratch_[bin].data());
  });
  for (int r : topRows_) y[r] = (y[r] - buffer_[0][r]) - buffer_[1][r];
  for (int t = 0; t < nsuper_; ++t)
    if (inTop_[t]) forward(t, y, nullptr, scratch_[0].data());
  for (int t = nsuper_ - 1; t >= 0; --t)
    if (inTop_[t]) backward(t, y, scratch_[0].data());
  bothBins([&](int bin) {
    for (auto range = bins_[bin].rbegin(); range != bins_[bin].rend(); ++range)
      for (int t = range->second - 1; t >= range->first; --t) backward(t, y, scratch_[bin].data());
  });
  x.resize(n_);
  for (int k = 0; k < n_; ++k) x[perm_[k]] = y[k];
}

// Supernode t: columns k1 … k1 + nscol − 1, rows rows_[pi_[t] …] (its own columns first). w (nsrow entries) holds
// the supernode's rows: its own unknowns, then the rows below.
//
// Forward: solve the diagonal block and accumulate −L21 y1 in w below, then add that to the rows below (for rows of
// the top part, subtract it from the bin's buffer instead).
CONFORMESH_SOLVE_KERNEL void SinglePrecisionFactor::forward(int t, double* y, double* buffer, double* w) const {
  const int k1 = super_[t], nscol = super_[t + 1] - k1, nsrow = pi_[t + 1] - pi_[t];
  const float* L = value_.data();
  for (int i = 0; i < nscol; ++i) w[i] = y[k1 + i];
  std::fill(w + nscol, w + nsrow, 0.0);
  int j = 0;
  for (; j + 4 <= nscol; j += 4) {
    const float *c0 = L + column(t, j, nsrow), *c1 = L + column(t, j + 1, nsrow), *c2 = L + column(t, j + 2, nsrow),
                *c3 = L + column(t, j + 3, nsrow);
    const double y0 = (w[j] /= c0[j]);
    const double y1 = (w[j + 1] = (w[j + 1] - c0[j + 1] * y0) / c1[j + 1]);
    const double y2 = (w[j + 2] = (w[j + 2] - c0[j + 2] * y0 - c1[j + 2] * y1) / c2[j + 2]);
    const double y3 = (w[j + 3] = (w[j + 3] - c0[j + 3] * y0 - c1[j + 3] * y1 - c2[j + 3] * y2) / c3[j + 3]);
    for (int i = j + 4; i < nsrow; ++i) w[i] -= (c0[i] * y0 + c1[i] * y1) + (c2[i] * y2 + c3[i] * y3);
  }
  for (; j < nscol; ++j) {
    const float* c = L + column(t, j, nsrow);
    const double yj = (w[j] /= c[j]);
    for (int i = j + 1; i < nsrow; ++i) w[i] -= c[i] * yj;
  }
  for (int i = 0; i < nscol; ++i) y[k1 + i] = w[i];
  const int* rows = rows_ + pi_[t];
  for (int i = nscol; i < nsrow; ++i) {
    if (buffer != nullptr && topRow_[rows[i]])
      buffer[rows[i]] -= w[i];
    else
      y[rows[i]] += w[i];
  }
}
// Backward: gather the rows below (already final), then solve with the supernode's columns transposed, last first:
// y_j = (y_j − Σ_{i>j} L_ij y_i) / L_jj, four columns at a time (their dot products over the rows below the four
// share the loads of y and run in four partial sums each, added in a fixed order: deterministic).
CONFORMESH_SOLVE_KERNEL void SinglePrecisionFactor::backward(int t, double* y, double* w) const {
  const int k1 = super_[t], nscol = super_[t + 1] - k1, nsrow = pi_[t + 1] - pi_[t];
  const float* L = value_.data();
  const int* rows = rows_ + pi_[t];
  for (int i = 0; i < nscol; ++i) w[i] = y[k1 + i];
  for (int i = nscol; i < nsrow; ++i) w[i] = y[rows[i]];
  int j = nscol;  // columns j … nscol − 1 are solved
  for (; j >= 4; j -= 4) {
    const int b = j - 4;
    const float *c0 = L + column(t, b, nsrow), *c1 = L + column(t, b + 1, nsrow), *c2 = L + column(t, b + 2, nsrow),
                *c3 = L + column(t, b + 3, nsrow);
    double part[4][4] = {};
    int i = j;
    for (; i + 4 <= nsrow; i += 4)
      for (int k = 0; k < 4; ++k) {
        part[0][k] += c0[i + k] * w[i + k];
        part[1][k] += c1[i + k] * w[i + k];
        part[2][k] += c2[i + k] * w[i + k];
        part[3][k] += c3[i + k] * w[i + k];
      }
    double sum[4];
    for (int c = 0; c < 4; ++c) sum[c] = (part[c][0] + part[c][2]) + (part[c][1] + part[c][3]);
    for (; i < nsrow; ++i) {
      sum[0] += c0[i] * w[i];
      sum[1] += c1[i] * w[i];
      sum[2] += c2[i] * w[i];
      sum[3] += c3[i] * w[i];
    }
    w[b + 3] = (w[b + 3] - sum[3]) / c3[b + 3];
    w[b + 2] = (w[b + 2] - sum[2] - c2[b + 3] * w[b + 3]) / c2[b + 2];
    w[b + 1] = (w[b + 1] - sum[1] - c1[b + 2] * w[b + 2] - c1[b + 3] * w[b + 3]) / c1[b + 1];
    w[b] = (w[b] - sum[0] - c0[b + 1] * w[b + 1] - c0[b + 2] * w[b + 2] - c0[b + 3] * w[b + 3]) / c0[b];
  }
  for (; j > 0; --j) {
    const float* c = L + column(t, j - 1, nsrow);
    double sum = 0;
    for (int i = j; i < nsrow; ++i) sum += c[i] * w[i];
    w[j - 1] = (w[j - 1] - sum) / c[j - 1];
  }
  for (int i = 0; i < nscol; ++i) y[k1 + i] = w[i];
}

}  // namespace conformesh::intrinsic
