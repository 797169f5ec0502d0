// fill_reducing_order.h — the elimination order of the Ricci flow's sparse Cholesky factorizations at large sizes
// (RicciFlowOptions::nestedDissectionMin): nested dissection by SCOTCH with its speed-oriented ordering strategy,
// three times faster than METIS's for 15 % more factorization flops.
#pragma once

#include <vector>

#include <Eigen/SparseCore>

namespace conformesh::intrinsic {

// A fill-reducing permutation of the symmetric matrix whose lower triangle `lower` holds (column-major): perm[k] is the
// k-th unknown to eliminate. SCOTCH_graphOrder on the adjacency graph of the pattern (diagonal dropped), strategy
// SCOTCH_STRATSPEED (nested dissection by multilevel vertex separators, approximate minimum degree on the leaves),
// in a SCOTCH context set to deterministic behaviour (fixed random seed), so the order is the same on every run.
// Measured at 998 048 unknowns (the box → sphere Newton system's graph): 2.1–2.5 s, against 6.7–6.9 s for METIS_NodeND
// with one refinement pass (5.4–7.8 s inside the flow), for 3.86·10¹⁰ factorization flops instead of 3.34·10¹⁰ and
// 6.9·10⁷ factor entries instead of 6.0·10⁷; SCOTCH's default (quality) strategy takes 4.3 s for 3.75·10¹⁰.
// Throws std::runtime_error if SCOTCH fails.
std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& lower);

}  // namespace conformesh::intrinsic
