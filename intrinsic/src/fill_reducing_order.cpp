// fill_reducing_order.cpp — METIS nested dissection of a symmetric sparsity pattern (fill_reducing_order.h).
#include "fill_reducing_order.h"

#include <metis.h>

#include <stdexcept>
#include <string>

namespace conformesh::intrinsic {

std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& lower) {
  const auto n = static_cast<idx_t>(lower.cols());
  // Adjacency lists of the pattern's graph: every stored off-diagonal entry (i, j), i > j, is the edge ij, listed at
  // both ends (METIS wants each undirected edge twice and no self-loops).
  std::vector<idx_t> xadj(n + 1, 0);
  for (idx_t j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
      if (it.row() != j) {
        ++xadj[it.row() + 1];
        ++xadj[j + 1];
      }
  for (idx_t v = 0; v < n; ++v) xadj[v + 1] += xadj[v];
  std::vector<idx_t> adjncy(xadj[n]), next(xadj.begin(), xadj.end() - 1);
  for (idx_t j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
      if (it.row() != j) {
        adjncy[next[it.row()]++] = j;
        adjncy[next[j]++] = static_cast<idx_t>(it.row());
      }

  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NITER] = 1;  // see the header: the default 10 passes buy 1.5 % fewer flops for 5–25 % more time
  std::vector<idx_t> perm(n), iperm(n);
  idx_t nv = n;
  const int status = METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS_NodeND failed (status " + std::to_string(status) + ") on a graph of " +
                             std::to_string(n) + " vertices");
  return std::vector<int>(perm.begin(), perm.end());
}

}  // namespace conformesh::intrinsic
