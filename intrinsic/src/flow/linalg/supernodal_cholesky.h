// supernodal_cholesky.h — Eigen's CHOLMOD supernodal Cholesky wrapper, opened up for the Ricci flow's Newton systems:
// access to the factor (for SinglePrecisionFactor) and a symbolic analysis in a given elimination order (for
// nestedDissectionOrder). Private to the flow (flow_solver_cache.cpp, circle_packing.cpp, the annulus bound in
// uniformization.cpp); touches only the CHOLMOD state it owns.
#pragma once

#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

namespace conformesh::intrinsic {

// Eigen's CHOLMOD wrapper with access to the factor it holds (for SinglePrecisionFactor), and a symbolic analysis in a
// given elimination order (nestedDissectionOrder at large sizes, fill_reducing_order.h), silent.
class SupernodalCholesky : public Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
 public:
  // CHOLMOD's own messages off: it prints "CHOLMOD warning: matrix not positive definite" on stdout (through printf),
  // which corrupted `--json` output; every caller reports a failed factorization itself (info(), with the step).
  SupernodalCholesky() { cholmod().print = 0; }

  const cholmod_factor* factor() const { return m_cholmodFactor; }

  using Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>::analyzePattern;
  // As Eigen's analyzePattern, with CHOLMOD told to use `order` (perm[k] = the k-th unknown eliminated), postordered
  // by the elimination tree as CHOLMOD does its own orders.
  void analyzePattern(const Eigen::SparseMatrix<double>& lower, std::vector<int> order) {
    cholmod_common& common = cholmod();
    if (m_cholmodFactor != nullptr) cholmod_free_factor(&m_cholmodFactor, &common);
    cholmod_sparse A = Eigen::viewAsCholmod(lower.selfadjointView<Eigen::Lower>());
    const int methods = common.nmethods, ordering = common.method[0].ordering;
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    m_cholmodFactor = cholmod_analyze_p(&A, order.data(), nullptr, 0, &common);
    common.nmethods = methods;
    common.method[0].ordering = ordering;
    m_isInitialized = true;
    m_info = m_cholmodFactor != nullptr ? Eigen::Success : Eigen::NumericalIssue;
    m_analysisIsOk = m_cholmodFactor != nullptr;
    m_factorizationIsOk = false;
  }
};

}  // namespace conformesh::intrinsic
