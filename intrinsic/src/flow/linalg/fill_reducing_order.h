// fill_reducing_order.h — the elimination order of the Ricci flow's sparse Cholesky factorizations at large sizes
// (RicciFlowOptions::nestedDissectionMin): nested dissection by SCOTCH with its speed-oriented strategy. Private to
// the flow (flow_solver_cache.cpp); owns its SCOTCH objects. Choice and figures: docs/ricci_flow.md §2.
#pragma once

#include <vector>

#include <Eigen/SparseCore>

namespace conformesh::intrinsic {

// A fill-reducing permutation of the symmetric matrix whose lower triangle `lower` holds (column-major): perm[k] is the
// k-th unknown to eliminate. SCOTCH_graphOrder on the adjacency graph of the pattern (diagonal dropped), strategy
// SCOTCH_STRATSPEED (nested dissection by multilevel vertex separators, approximate minimum degree on the leaves),
// in a SCOTCH context set to deterministic behaviour (fixed random seed), so the order is the same on every run.
// Throws std::runtime_error if SCOTCH fails.
std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& lower);

}  // namespace conformesh::intrinsic
