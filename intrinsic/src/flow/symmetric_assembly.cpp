// symmetric_assembly.cpp — pattern and values of the symmetric Newton Hessian (symmetric_assembly.h).
#include "flow/symmetric_assembly.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "flow/linalg/two_threads.h"

namespace conformesh::intrinsic::detail {

using SparseMatrix = Eigen::SparseMatrix<double>;

void SymmetricAssembly::rebuild(const DiscreteConformalMetric& metric, const std::vector<int>& unknownIndex, int n,
                                SparseMatrix& H) {
  const HalfedgeMesh& m = metric.mesh();
  const int nF = m.nFaces(), nE = m.nEdges();
  // Column c holds its diagonal and a row r > c for every edge joining the unknowns r and c that lies in a
  // non-frozen face (any two corners of a triangle are joined by one of its edges); built by edges, sorted, made
  // unique (multiple edges).
  auto lower = [&](int e, int& row, int& col) {
    const int h = m.edgeHalfedge(e), t = m.twin(h);
    const int a = unknownIndex[m.tail(h)], b = unknownIndex[m.tip(h)];
    row = std::max(a, b);
    col = std::min(a, b);
    return col >= 0 && row > col &&
           (!metric.isFrozen(HalfedgeMesh::face(h)) || (t != kInvalid && !metric.isFrozen(HalfedgeMesh::face(t))));
  };
  std::vector<int> start(n + 1, 0);
  for (int c = 0; c < n; ++c) start[c + 1] = 1;
  int row, col;
  for (int e = 0; e < nE; ++e)
    if (lower(e, row, col)) ++start[col + 1];
  for (int c = 0; c < n; ++c) start[c + 1] += start[c];
  std::vector<int> rows(start[n]), fill(start.begin(), start.end() - 1);
  for (int c = 0; c < n; ++c) rows[fill[c]++] = c;  // the diagonal: the smallest row of its column
  for (int e = 0; e < nE; ++e)
    if (lower(e, row, col)) rows[fill[col]++] = row;
  std::vector<int> outer(n + 1, 0);
  onTwoCores(n, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto c = begin; c < end; ++c) {
      std::sort(rows.begin() + start[c] + 1, rows.begin() + start[c + 1]);
      outer[c + 1] = static_cast<int>(std::unique(rows.begin() + start[c], rows.begin() + start[c + 1]) -
                                      (rows.begin() + start[c]));
    }
  });
  for (int c = 0; c < n; ++c) outer[c + 1] += outer[c];
  H.resize(n, n);
  H.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), H.outerIndexPtr());
  int* inner = H.innerIndexPtr();
  onTwoCores(n, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto c = begin; c < end; ++c) std::copy_n(rows.begin() + start[c], outer[c + 1] - outer[c], inner + outer[c]);
  });
  // The slot of every edge's entry (a loop edge: its vertex's diagonal), then of every face's entries.
  std::vector<int> edgeSlot(nE, -1);
  onTwoCores(nE, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto e = static_cast<int>(begin); e < end; ++e) {
      const int h = m.edgeHalfedge(e);
      const int a = unknownIndex[m.tail(h)], b = unknownIndex[m.tip(h)];
      const int r = std::max(a, b), c = std::min(a, b);
      if (c >= 0) edgeSlot[e] = static_cast<int>(std::lower_bound(inner + outer[c], inner + outer[c + 1], r) - inner);
    }
  });
  slot_.assign(9 * static_cast<std::size_t>(nF), -1);
  onTwoCores(nF, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f) {
      if (metric.isFrozen(f)) continue;
      int idx[3];
      for (int k = 0; k < 3; ++k) idx[k] = unknownIndex[m.faceVertex(f, k)];
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) {
          if (idx[k] < 0 || idx[j] < idx[k]) continue;
          // Halfedge 3f + k runs from corner k to corner k + 1.
          slot_[9 * std::size_t(f) + 3 * k + j] =
              j == k ? outer[idx[k]] : edgeSlot[m.edge(3 * f + (j == (k + 1) % 3 ? k : j))];
        }
    }
  });
  identitySlot_.assign(n, -1);
  for (int i = 0; i < n; ++i)
    if (identity_[i]) identitySlot_[i] = outer[i];
}

void SymmetricAssembly::assemble(const DiscreteConformalMetric& metric, const std::vector<FaceGeometry>& faces,
                                 SparseMatrix& H) {
  const HalfedgeMesh& m = metric.mesh();
  const Background bg = metric.geometry();
  const int nF = m.nFaces();
  // The six distinct symmetrized entries of a face: k = j (0, 1, 2), then {0,1}, {0,2}, {1,2}.
  static constexpr int kPair[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  value_.resize(6 * static_cast<std::size_t>(nF));
  onTwoCores(nF, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f) {
      if (metric.isFrozen(f)) continue;
      double J[3][3];
      angleJacobian(bg, faces[f], J);
      for (int k = 0; k < 3; ++k)
        for (int j = k; j < 3; ++j) value_[6 * std::size_t(f) + kPair[k][j]] = -0.5 * (J[k][j] + J[j][k]);
    }
  });
  double* x = H.valuePtr();
  std::fill(x, x + H.nonZeros(), -0.0);
  for (int f = 0; f < nF; ++f) {
    if (metric.isFrozen(f)) continue;
    const int* s = &slot_[9 * static_cast<std::size_t>(f)];
    const double* v = &value_[6 * static_cast<std::size_t>(f)];
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        if (s[3 * k + j] >= 0) x[s[3 * k + j]] += v[kPair[k][j]];
  }
  for (std::size_t i = 0; i < identitySlot_.size(); ++i)
    if (identitySlot_[i] >= 0) x[identitySlot_[i]] += 1.0;
}

}  // namespace conformesh::intrinsic::detail
