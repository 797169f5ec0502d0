// test_fill_reducing_order.cpp — SCOTCH nested dissection as the flow calls it (src/fill_reducing_order.h): the result
// is a permutation in the documented convention (perm[k] = the k-th unknown eliminated), and its Cholesky fill on
// k×k grid Laplacians grows like n log n (George 1973), against n^1.5 for the natural (banded) order, both orders
// measured by a log–log fit over four grids.
#include <catch2/catch.hpp>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <vector>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "flow/linalg/fill_reducing_order.h"

using namespace conformesh::intrinsic;
using SparseMatrix = Eigen::SparseMatrix<double>;

namespace {

// Lower triangle of the 5-point Laplacian of a k×k grid plus a small shift (positive definite).
SparseMatrix gridLaplacian(int k) {
  std::vector<Eigen::Triplet<double>> entries;
  auto id = [k](int i, int j) { return i * k + j; };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      entries.emplace_back(id(i, j), id(i, j), 4.001);
      if (i + 1 < k) entries.emplace_back(id(i + 1, j), id(i, j), -1.0);
      if (j + 1 < k) entries.emplace_back(id(i, j + 1), id(i, j), -1.0);
    }
  SparseMatrix lower(k * k, k * k);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

// Stored entries of the Cholesky factor of P A Pᵀ, row k of P A Pᵀ being row order[k] of A (identity when empty).
double factorEntries(const SparseMatrix& lower, const std::vector<int>& order) {
  SparseMatrix a = lower.selfadjointView<Eigen::Lower>();
  if (!order.empty()) {
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(a.rows());
    for (int k = 0; k < static_cast<int>(order.size()); ++k) p.indices()[order[k]] = k;  // unknown order[k] → row k
    a = lower.selfadjointView<Eigen::Lower>().twistedBy(p);
  }
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> llt(a);
  REQUIRE(llt.info() == Eigen::Success);
  return static_cast<double>(llt.matrixL().nestedExpression().nonZeros());
}

}  // namespace

TEST_CASE("nested dissection is a permutation whose fill grows like n log n, the natural order's like n^1.5") {
  std::vector<double> n, nested, natural;
  for (int k : {32, 64, 128, 256}) {
    const SparseMatrix lower = gridLaplacian(k);
    std::vector<int> order = nestedDissectionOrder(lower);
    REQUIRE(static_cast<int>(order.size()) == k * k);
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < k * k; ++i) REQUIRE(sorted[i] == i);
    n.push_back(k * k);
    nested.push_back(factorEntries(lower, order));
    natural.push_back(factorEntries(lower, {}));
    INFO("k = " << k << ": " << nested.back() << " entries nested, " << natural.back() << " natural");
    CHECK(nested.back() < natural.back());
    // The other convention (order[k] = the position of unknown k) scatters the grid: measured 4× the fill at k = 32.
    std::vector<int> inverse(order.size());
    for (int i = 0; i < k * k; ++i) inverse[order[i]] = i;
    CHECK(factorEntries(lower, inverse) > 2 * nested.back());
  }
  // n log n between n = 2¹⁰ and 2¹⁶ has log–log slope 1 + log(16/10)/log(2¹⁶/2¹⁰) = 1.11; the band of width k fills
  // completely, n·k = n^1.5. The test separates the two laws at the midpoint 1.3 (SCOTCH's separators are not George's
  // optimal ones on small grids: 1.18 is measured, 1.17 with METIS before).
  const double nestedSlope = fitLogLogSlope(n, nested), naturalSlope = fitLogLogSlope(n, natural);
  INFO("slopes: nested " << nestedSlope << ", natural " << naturalSlope);
  CHECK(nestedSlope > 1.0);
  CHECK(nestedSlope < 1.3);
  CHECK(std::abs(naturalSlope - 1.5) < 0.02);
}
