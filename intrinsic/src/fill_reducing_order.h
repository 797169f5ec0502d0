// fill_reducing_order.h — the elimination order of the Ricci flow's sparse Cholesky factorizations at large sizes
// (RicciFlowOptions::nestedDissectionMin): METIS nested dissection called directly, with one refinement pass per level
// instead of the default ten that CHOLMOD's own call uses.
#pragma once

#include <vector>

#include <Eigen/SparseCore>

namespace conformesh::intrinsic {

// A fill-reducing permutation of the symmetric matrix whose lower triangle `lower` holds (column-major): perm[k] is the
// k-th unknown to eliminate. METIS_NodeND on the adjacency graph of the pattern (diagonal dropped) with
// METIS_OPTION_NITER = 1: measured at 998 048 unknowns (box → sphere), 5.4–6.4 s instead of 6.6–6.9 s of METIS time
// (METIS's time varies by ±10 % between identical runs) for 1.5 % more factorization flops (3.34e10 instead of
// 3.29e10) and 0.2 % more stored entries in the supernodal factor.
// METIS seeds its own random choices, so the order is the same on every run. Throws std::runtime_error if METIS fails.
std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& lower);

}  // namespace conformesh::intrinsic
