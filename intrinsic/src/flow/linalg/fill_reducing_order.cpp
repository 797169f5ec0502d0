// fill_reducing_order.cpp — SCOTCH nested dissection of a symmetric sparsity pattern (fill_reducing_order.h).
#include "flow/linalg/fill_reducing_order.h"

// scotch.h uses the standard integer types and FILE without including their headers.
#include <cstdint>
#include <cstdio>

#include <scotch.h>

#include <stdexcept>
#include <string>

namespace conformesh::intrinsic {

namespace {

// SCOTCH's objects, released whatever happens, each before what it refers to (the bound graph before its context and
// the graph it views).
struct ScotchOrdering {
  SCOTCH_Graph graph, bound;
  SCOTCH_Context context;
  SCOTCH_Strat strategy;
  ScotchOrdering() {
    SCOTCH_graphInit(&graph);
    SCOTCH_graphInit(&bound);
    SCOTCH_contextInit(&context);
    SCOTCH_stratInit(&strategy);
  }
  ~ScotchOrdering() {
    SCOTCH_stratExit(&strategy);
    SCOTCH_graphExit(&bound);
    SCOTCH_contextExit(&context);
    SCOTCH_graphExit(&graph);
  }
};

void check(int status, const char* call, SCOTCH_Num n) {
  if (status != 0)
    throw std::runtime_error(std::string(call) + " failed (status " + std::to_string(status) + ") on a graph of " +
                             std::to_string(n) + " vertices");
}

}  // namespace

std::vector<int> nestedDissectionOrder(const Eigen::SparseMatrix<double>& lower) {
  const auto n = static_cast<SCOTCH_Num>(lower.cols());
  // Adjacency lists of the pattern's graph: every stored off-diagonal entry (i, j), i > j, is the edge ij, listed at
  // both ends (SCOTCH wants each undirected edge as two arcs and no loops).
  std::vector<SCOTCH_Num> start(n + 1, 0);
  for (SCOTCH_Num j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
      if (it.row() != j) {
        ++start[it.row() + 1];
        ++start[j + 1];
      }
  for (SCOTCH_Num v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<SCOTCH_Num> arcs(start[n]), next(start.begin(), start.end() - 1);
  for (SCOTCH_Num j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
      if (it.row() != j) {
        arcs[next[it.row()]++] = j;
        arcs[next[j]++] = static_cast<SCOTCH_Num>(it.row());
      }

  ScotchOrdering s;
  check(SCOTCH_graphBuild(&s.graph, 0, n, start.data(), nullptr, nullptr, nullptr, start[n], arcs.data(), nullptr),
        "SCOTCH_graphBuild", n);
  // One thread, fixed seed: the order (and with it the factor's round-off) is reproducible. Two threads gave the same
  // order and no speed-up at 10⁶ unknowns (measured).
  check(SCOTCH_contextOptionSetNum(&s.context, SCOTCH_OPTIONNUMDETERMINISTIC, 1), "SCOTCH_contextOptionSetNum", n);
  check(SCOTCH_contextRandomClone(&s.context), "SCOTCH_contextRandomClone", n);
  check(SCOTCH_contextBindGraph(&s.context, &s.graph, &s.bound), "SCOTCH_contextBindGraph", n);
  check(SCOTCH_stratGraphOrderBuild(&s.strategy, SCOTCH_STRATSPEED, 0, 0.2), "SCOTCH_stratGraphOrderBuild", n);
  std::vector<SCOTCH_Num> position(n), order(n);  // SCOTCH: permtab (vertex → position), peritab (position → vertex)
  check(SCOTCH_graphOrder(&s.bound, &s.strategy, position.data(), order.data(), nullptr, nullptr, nullptr),
        "SCOTCH_graphOrder", n);
  return std::vector<int>(order.begin(), order.end());
}

}  // namespace conformesh::intrinsic
