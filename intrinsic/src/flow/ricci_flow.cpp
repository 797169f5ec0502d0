// ricci_flow.cpp — Newton's method with Ptolemy flips and an Armijo line search for vertex-scaling conformal metrics;
// the Hessian −∂Θ/∂u is factored by CHOLMOD's supernodal Cholesky. See ricci_flow.h and docs/ricci_flow.md.
#include "conformesh/intrinsic/flow/ricci_flow.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "flow/linalg/fill_reducing_order.h"
#include "flow/linalg/single_precision_factor.h"
#include "flow/linalg/two_threads.h"

namespace conformesh::intrinsic {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The three side lengths, angles and angle cotangents of a face: L[k] is opposite corner k. A face violating the
// triangle inequality gets the angles (π, 0, 0), π opposite its longest side: the continuous extension of the angles
// that makes the energy C¹ and convex on all of u-space (Luo; Bobenko–Pinkall–Springborn 2015, §4). Such faces only
// occur next to unflippable (boundary, frozen) edges; interior ones are repaired by the Ptolemy flips.
struct FaceGeometry {
  double L[3], theta[3], cot[3];
  bool degenerate = false;
};

// The half-angle formulas of triangle_geometry.h (tan(θ_k/2) = sqrt(f(s−L_{k+1}) f(s−L_{k+2}) / (f(s) f(s−L_k))), f =
// identity, sin or sinh) evaluated once per face for all three corners — the same numbers as angleOpposite and
// cotOpposite (isValidTriangle's test), at a quarter of the cost: every Newton step and every line-search trial
// evaluates all faces, and this is most of the flow's non-factorization time.
FaceGeometry faceGeometry(Background bg, double L0, double L1, double L2) {
  FaceGeometry g;
  g.L[0] = L0;
  g.L[1] = L1;
  g.L[2] = L2;
  const HalfPerimeter p = halfPerimeter(L0, L1, L2);
  const bool valid = std::isfinite(L0) && std::isfinite(L1) && std::isfinite(L2) && L0 > 0 && L1 > 0 && L2 > 0 &&
                     p.sa > 0 && p.sb > 0 && p.sc > 0 && (bg != Background::Spherical || p.s < M_PI);
  if (!valid) {
    g.degenerate = true;
    const int longest = L0 >= L1 ? (L0 >= L2 ? 0 : 2) : (L1 >= L2 ? 1 : 2);
    for (int k = 0; k < 3; ++k) {
      g.theta[k] = k == longest ? M_PI : 0.0;
      g.cot[k] = 0;
    }
    return g;
  }
  auto f = [bg](double x) {
    return bg == Background::Euclidean ? x : (bg == Background::Hyperbolic ? std::sinh(x) : std::sin(x));
  };
  const double fs = f(p.s), fd[3] = {f(p.sa), f(p.sb), f(p.sc)};
  for (int k = 0; k < 3; ++k) {
    const double num = fd[(k + 1) % 3] * fd[(k + 2) % 3], den = fs * fd[k];
    g.theta[k] = 2.0 * std::atan(std::sqrt(num / den));  // as angleOpposite (den > 0 in a valid face)
    g.cot[k] = (den - num) / (2.0 * std::sqrt(num * den));
  }
  return g;
}

// Current background length of every edge: ℓ(e^{(u_i+u_j)/2} c⁰_ij), with one exponential per vertex. Every element
// is computed from shared inputs by one of the two threads of onTwoCores.
void currentLengths(const DiscreteConformalMetric& metric, std::vector<double>& length) {
  const HalfedgeMesh& m = metric.mesh();
  const int nV = metric.nVertices(), nE = m.nEdges();
  std::vector<double> half(nV);
  onTwoCores(nV, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto v = begin; v < end; ++v) half[v] = std::exp(0.5 * metric.u()[v]);
  });
  length.resize(nE);
  onTwoCores(nE, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto e = begin; e < end; ++e) {
      const int h = m.edgeHalfedge(static_cast<int>(e));
      length[e] = lengthFromPenner(metric.geometry(),
                                   metric.referencePenner(static_cast<int>(e)) * half[m.tail(h)] * half[m.tip(h)]);
    }
  });
}

FaceGeometry faceGeometry(const DiscreteConformalMetric& metric, const std::vector<double>& length, int f) {
  const HalfedgeMesh& m = metric.mesh();
  return faceGeometry(metric.geometry(), length[m.edge(3 * f + 1)], length[m.edge(3 * f + 2)], length[m.edge(3 * f)]);
}

// Angle sums over the non-frozen faces, and each face's geometry (for the Jacobian at the same point). The faces are
// evaluated in parallel (the three arctangents per face are most of the cost), the sums are then added in face order on
// one thread, so that they are bit for bit those of a serial run whatever the number of threads.
void evaluateFaces(const DiscreteConformalMetric& metric, std::vector<double>& length, std::vector<double>& sums,
                   std::vector<FaceGeometry>& faces) {
  const HalfedgeMesh& m = metric.mesh();
  const int nF = m.nFaces();
  currentLengths(metric, length);
  faces.resize(nF);
  onTwoCores(nF, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto f = static_cast<int>(begin); f < end; ++f)
      if (!metric.isFrozen(f)) faces[f] = faceGeometry(metric, length, f);
  });
  sums.assign(m.nVertices(), 0.0);
  for (int f = 0; f < nF; ++f) {
    if (metric.isFrozen(f)) continue;
    for (int k = 0; k < 3; ++k) sums[m.faceVertex(f, k)] += faces[f].theta[k];
  }
}

double sineLike(Background bg, double x) {
  return bg == Background::Euclidean ? x : (bg == Background::Hyperbolic ? std::sinh(x) : std::sin(x));
}

// J[k][j] = ∂θ_k/∂u_{v_j} for the corners of face f.
void angleJacobian(Background bg, const FaceGeometry& g, double J[3][3]) {
  if (g.degenerate) {  // the extended angles are locally constant
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) J[k][j] = 0;
    return;
  }
  if (bg == Background::Euclidean) {
    // Springborn–Schröder–Pinkall 2008: ∂θ_k/∂u_j = ½ cot θ_l for the third corner l, ∂θ_k/∂u_k = −Σ of those.
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      J[k][k1] = 0.5 * g.cot[k2];
      J[k][k2] = 0.5 * g.cot[k1];
      J[k][k] = -J[k][k1] - J[k][k2];
    }
    return;
  }
  // General background: dθ_k = A_k (dL_k − cos θ_{k+2} dL_{k+1} − cos θ_{k+1} dL_{k+2}),
  // A_k = S(L_k)/(S(L_{k+1}) S(L_{k+2}) sin θ_k), and dL_k = D_k (du_{k+1} + du_{k+2}).
  double D[3];
  for (int k = 0; k < 3; ++k) D[k] = lengthDerivativeInU(bg, g.L[k]);
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    const double A = sineLike(bg, g.L[k]) / (sineLike(bg, g.L[k1]) * sineLike(bg, g.L[k2]) * std::sin(g.theta[k]));
    const double cL = A, c1 = -A * std::cos(g.theta[k2]), c2 = -A * std::cos(g.theta[k1]);
    // u_k enters L_{k+1} (joins k+2, k) and L_{k+2} (joins k, k+1); u_{k+1} enters L_k, L_{k+2}; u_{k+2}: L_k, L_{k+1}.
    J[k][k] = c1 * D[k1] + c2 * D[k2];
    J[k][k1] = cL * D[k] + c2 * D[k2];
    J[k][k2] = cL * D[k] + c1 * D[k1];
  }
}

// H = −∂Θ/∂u of the symmetric problems, assembled straight into its compressed lower triangle. Face f contributes
// −½(J[k][j] + J[j][k]) at (row, column) = (i_j, i_k) for its corners' unknowns i_j ≥ i_k (J = angleJacobian), and an
// identity row gets 1. The pattern, and for every face the position of each of its entries in it, depend only on the
// connectivity and change only with flips, so they are rebuilt only then. The faces' Jacobians (transcendental
// functions in the hyperbolic case) are evaluated in parallel; they are then added into their slots on one thread in
// face order, starting from −0 — which is what summing the triplets in that order gives (Eigen's setFromTriplets, used
// before: the first value, then the rest added in order), so H is the same to the bit, whatever the number of threads.
class SymmetricAssembly {
 public:
  void rebuild(const DiscreteConformalMetric& metric, const std::vector<int>& unknownIndex, int n, SparseMatrix& H) {
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
      for (auto c = begin; c < end; ++c)
        std::copy_n(rows.begin() + start[c], outer[c + 1] - outer[c], inner + outer[c]);
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

  // Which unknowns have identity rows (Dirichlet vertices kept as unknowns); their faces' entries are left out.
  void setIdentityRows(const std::vector<char>& identity) { identity_ = identity; }

  void assemble(const DiscreteConformalMetric& metric, const std::vector<FaceGeometry>& faces, SparseMatrix& H) {
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

 private:
  std::vector<char> identity_;
  std::vector<int> slot_;  // 9 per face, pair (k, j) at 3k + j: the position of its entry in H, −1 when not stored
  std::vector<int> identitySlot_;
  std::vector<double> value_;  // 6 per face (kPair)
};

// The arrays of one flow solve — the last evaluation (edge lengths, angle sums, face geometry) and the Newton system.
// Kept in the solver cache when solves share one (RicciFlowOptions::solverCache): the genus-0 star repair solves again
// and again on the same mesh, and fresh arrays of this size cost page faults on first touch (at 10⁶ vertices ≈ 0.3 s
// per solve, measured).
struct FlowWorkspace {
  std::vector<double> lengths, sums;
  std::vector<FaceGeometry> faces;
  SymmetricAssembly assembly;
  SparseMatrix H;
};

// Eigen's CHOLMOD wrapper with access to the factor it holds (for SinglePrecisionFactor), and a symbolic analysis in a
// given elimination order (nestedDissectionOrder at large sizes, fill_reducing_order.h).
class SupernodalCholesky : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* factor() const { return m_cholmodFactor; }

  using Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>::analyzePattern;
  // As Eigen's analyzePattern, with CHOLMOD told to use `order` (perm[k] = the k-th unknown eliminated), postordered
  // by the elimination tree as CHOLMOD does its own orders.
  void analyzePattern(const SparseMatrix& lower, std::vector<int> order) {
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

}  // namespace

// === the symmetric Newton systems

// H δ = b for the symmetric positive definite Hessian (lower triangle stored). A sparse Cholesky factorization costs
// O(n^1.5) flops on these planar-graph Laplacians (≈ 0.4 s at 10⁵, ≈ 10 s at 10⁶ unknowns with the installed BLAS),
// a solve with the factor O(n log n) (≈ 0.02 s at 10⁵). Between consecutive Newton steps H changes by O(|δ|) (and by
// the few rows a flip touches), so the previous factor is an excellent preconditioner: conjugate gradients with it
// converge in a handful of iterations, and a new factorization is only computed when they do not reach the requested
// relative residual within `maxIterations` (then the factor is refreshed and the solve is direct). The iterations apply
// the factor in single precision on two cores (SinglePrecisionFactor). The sparsity analysis — the fill-reducing
// ordering (CHOLMOD's choice, or SCOTCH nested dissection from RicciFlowOptions::nestedDissectionMin unknowns on:
// ≈ 2.3 s at 10⁶, half the factorization) and the supernodal symbolic factorization — is redone only when flips changed
// the pattern. Consecutive solves may share it (RicciFlowOptions::solverCache) when their unknowns keep their number.
class FlowSolverCache {
 public:
  FlowSolverCache(int maxIterations, int nestedDissectionMin)
      : maxIterations_(maxIterations), nestedDissectionMin_(nestedDissectionMin) {}
  void patternChanged() { patternValid_ = false; }
  // A factor of another dimension cannot precondition: forget it.
  void setDimension(int n) {
    if (n != dimension_) haveFactor_ = patternValid_ = false;
    dimension_ = n;
  }
  int factorizations() const { return factorizations_; }
  int cgIterations() const { return cgIterations_; }
  FlowWorkspace& workspace() { return workspace_; }
  bool nestedDissection() const { return nestedDissection_; }

  // Returns false when the factorization fails (H not positive definite).
  bool solve(const SparseMatrix& H, const Eigen::VectorXd& b, double relativeTolerance, Eigen::VectorXd& x) {
    if (haveFactor_ && maxIterations_ > 0 && preconditionedCG(H, b, relativeTolerance, x)) return true;
    if (!patternValid_) {
      nestedDissection_ = H.rows() >= nestedDissectionMin_;
      if (nestedDissection_)
        solver_.analyzePattern(H, nestedDissectionOrder(H));
      else
        solver_.analyzePattern(H);
      if (solver_.factor() == nullptr)
        throw ConvergenceError("discrete Ricci flow: CHOLMOD's symbolic analysis of the " + std::to_string(H.rows()) +
                               "-unknown Newton system failed (CHOLMOD status " +
                               std::to_string(solver_.cholmod().status) + "; −2 is out of memory)");
      patternValid_ = true;
      analysed_ = false;
    }
    solver_.factorize(H);
    ++factorizations_;
    haveFactor_ = solver_.info() == Eigen::Success;
    if (!haveFactor_) return false;
    if (!analysed_) analysed_ = single_.analyse(solver_.factor());
    single_.invalidate();  // rounded when the conjugate gradients first need it (a torus at 10⁶ never does)
    x = solver_.solve(b);
    return true;
  }

 private:
  bool preconditionedCG(const SparseMatrix& H, const Eigen::VectorXd& b, double relativeTolerance, Eigen::VectorXd& x) {
    const double bound = relativeTolerance * b.norm();
    x.setZero(b.size());
    if (analysed_ && !single_.valid()) single_.setValues(solver_.factor());
    auto precondition = [&](const Eigen::VectorXd& residual, Eigen::VectorXd& out) {
      if (single_.valid())
        single_.solve(residual, out);
      else
        out = solver_.solve(residual);
    };
    Eigen::VectorXd r = b, z, p, q;
    precondition(r, z);
    p = z;
    double rz = r.dot(z);
    for (int it = 1; it <= maxIterations_; ++it) {
      q = H.selfadjointView<Eigen::Lower>() * p;
      const double pq = p.dot(q);
      if (!(pq > 0)) return false;
      const double alpha = rz / pq;
      x += alpha * p;
      r -= alpha * q;
      ++cgIterations_;
      if (r.norm() <= bound) return true;
      precondition(r, z);
      const double rzNew = r.dot(z);
      p = z + (rzNew / rz) * p;
      rz = rzNew;
    }
    return false;
  }

  SupernodalCholesky solver_;
  SinglePrecisionFactor single_;
  FlowWorkspace workspace_;
  int maxIterations_, nestedDissectionMin_;
  int dimension_ = -1;
  bool patternValid_ = false, haveFactor_ = false, analysed_ = false, nestedDissection_ = false;
  int factorizations_ = 0, cgIterations_ = 0;
};

InscribedPolygon inscribedPolygon(const std::vector<double>& sides, int loop) {
  const int n = static_cast<int>(sides.size());
  const int m = static_cast<int>(std::max_element(sides.begin(), sides.end()) - sides.begin());
  const double longest = sides[m];
  double perimeter = 0;
  for (double l : sides) perimeter += l;
  if (n < 3 || !(longest < perimeter - longest))
    throw ConvergenceError("boundary loop " + std::to_string(loop) +
                           " has a side at least as long as all others together; it cannot be inscribed in a circle");
  // Centre inside iff f(R) = Σ 2 asin(ℓ_j/2R) − 2π ≥ 0 at R = ℓ_max/2. Then f is convex and decreasing on
  // [ℓ_max/2, ∞) and Newton from R₀ = max(perimeter/2π, ℓ_max/2) (where f ≥ 0 since asin x ≥ x) increases
  // monotonically to the root. Otherwise the root of g(R) = Σ_{j≠m} asin(ℓ_j/2R) − asin(ℓ_m/2R), negative at ℓ_max/2
  // and positive for large R, is bracketed and bisected.
  auto f = [&](double R, double& df) {
    double s = 0;
    df = 0;
    for (double l : sides) {
      const double x = std::min(1.0, l / (2 * R));
      s += 2 * std::asin(x);
      df -= x < 1 ? 2 * x / (R * std::sqrt((1 - x) * (1 + x))) : 0;
    }
    return s - 2 * M_PI;
  };
  InscribedPolygon out;
  out.side.assign(n, 1);
  double df;
  if (f(0.5 * longest, df) >= 0) {
    double R = std::max(perimeter / (2 * M_PI), 0.5 * longest);
    for (int it = 0; it < 100; ++it) {
      const double value = f(R, df);
      if (!(value > 0) || !(df < 0)) break;
      const double next = R - value / df;
      if (!(next > R * (1 + 1e-16))) break;
      R = next;
    }
    out.radius = R;
  } else {
    auto g = [&](double R) {
      double s = 0;
      for (int j = 0; j < n; ++j) s += (j == m ? -1 : 1) * std::asin(std::min(1.0, sides[j] / (2 * R)));
      return s;
    };
    double lo = 0.5 * longest, hi = longest;
    while (g(hi) < 0) hi *= 2;
    for (int it = 0; it < 200 && hi - lo > 4e-16 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (g(mid) < 0 ? lo : hi) = mid;
    }
    out.radius = 0.5 * (lo + hi);
    out.side[m] = -1;
  }
  out.halfAngle.resize(n);
  for (int j = 0; j < n; ++j) {
    const double a = std::asin(std::min(1.0, sides[j] / (2 * out.radius)));
    out.halfAngle[j] = out.side[j] > 0 ? a : M_PI - a;
  }
  return out;
}

std::shared_ptr<FlowSolverCache> makeFlowSolverCache(int maxReuseIterations, int nestedDissectionMin) {
  return std::make_shared<FlowSolverCache>(maxReuseIterations, nestedDissectionMin);
}

std::vector<double> flowAngleSums(const DiscreteConformalMetric& metric) {
  std::vector<double> length, sums;
  std::vector<FaceGeometry> faces;
  evaluateFaces(metric, length, sums, faces);
  return sums;
}

RicciFlowReport solveConformalFlow(DiscreteConformalMetric& metric, const ConformalTarget& target,
                                   const RicciFlowOptions& options, FlowCorrespondence* log) {
  const auto start = std::chrono::steady_clock::now();
  const HalfedgeMesh& m = metric.mesh();
  const int nV = m.nVertices();
  const Background bg = metric.geometry();
  if (static_cast<int>(target.angleSum.size()) != nV)
    throw InputError("conformal target: expected " + std::to_string(nV) + " target angle sums, found " +
                     std::to_string(target.angleSum.size()));
  if (!target.fixed.empty() && static_cast<int>(target.fixed.size()) != nV)
    throw InputError("conformal target: expected " + std::to_string(nV) + " fixed flags, found " +
                     std::to_string(target.fixed.size()));
  if (bg == Background::Spherical)
    throw InputError(
        "conformal target: the spherical vertex-scaling energy is not convex; genus-0 surfaces are "
        "uniformized through a punctured Euclidean problem (uniformization.h)");
  auto isFixed = [&](int v) { return !target.fixed.empty() && target.fixed[v]; };
  const bool circles = !target.circleLoops.empty();
  if (circles && bg != Background::Euclidean)
    throw InputError("conformal target: circle boundary loops are implemented for the Euclidean background only");
  std::vector<double> targetSum = target.angleSum;  // circle-loop entries follow the metric
  std::vector<char> onCircle(nV, 0);
  for (const auto& loop : target.circleLoops)
    for (int v : loop.vertices) {
      onCircle[v] = 1;
      targetSum[v] = M_PI;  // placeholder, only for the admissibility checks below (the turning angles sum correctly)
    }

  // Which vertices carry an angle-sum equation: free, and in at least one non-frozen face.
  std::vector<char> inActiveFace(nV, 0);
  bool anyFrozen = false;
  for (int f = 0; f < m.nFaces(); ++f) {
    if (metric.isFrozen(f)) {
      anyFrozen = true;
      continue;
    }
    for (int k = 0; k < 3; ++k) inActiveFace[m.faceVertex(f, k)] = 1;
  }
  bool anyFixed = false;
  double targetCurvature = 0;  // Σ (2π or π) − Θ̂ over free vertices
  for (int v = 0; v < nV; ++v) {
    if (isFixed(v)) {
      anyFixed = true;
      continue;
    }
    if (!inActiveFace[v] || onCircle[v]) continue;
    const double t = target.angleSum[v];
    if (!std::isfinite(t) || !(t > 0)) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "conformal target: vertex " << v << " has target angle sum " << t
          << "; a cone angle must be finite and positive";
      throw InputError(msg.str());
    }
    targetCurvature += (m.isBoundaryVertex(v) ? M_PI : 2 * M_PI) - t;
  }
  const double twoPiChi = 2 * M_PI * m.eulerCharacteristic();
  if (!anyFixed && !anyFrozen && !circles) {
    // Gauss–Bonnet: Σ K̂ = 2πχ − K_bg · Area. Euclidean: equality; hyperbolic: Area = Σ K̂ − 2πχ must be positive.
    // 1e-9 rad absorbs the round-off of summing 10⁶ targets of size 2π.
    if (bg == Background::Euclidean && std::abs(targetCurvature - twoPiChi) > 1e-9 * std::max(1.0, std::sqrt(nV))) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "conformal target is inadmissible: a flat metric needs total curvature 2πχ = " << twoPiChi
          << " (Gauss–Bonnet), the targets sum to " << targetCurvature;
      throw InputError(msg.str());
    }
    if (bg == Background::Hyperbolic && !(targetCurvature - twoPiChi > 0)) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "conformal target is inadmissible: a hyperbolic metric has area Σ K̂ − 2πχ = " << targetCurvature - twoPiChi
          << ", which must be positive";
      throw InputError(msg.str());
    }
  }

  // Unknowns: free vertices in an active face; the Euclidean scale invariance is removed by pinning the first one when
  // nothing else fixes it (its equation then holds automatically by Gauss–Bonnet).
  RicciFlowReport report;
  std::vector<int> index(nV, -1);
  std::vector<int> unknowns;
  // With a shared solver cache the Dirichlet vertices of active faces stay unknowns with the equation δ_v = 0 (an
  // identity row), so that the dimension — and with it the cached factor — survives changes of the Dirichlet set.
  const bool shared = options.solverCache != nullptr && !circles;
  std::vector<char> identityRow;
  std::vector<int> equations;  // vertices whose residual is checked
  for (int v = 0; v < nV; ++v)
    if (inActiveFace[v] && (!isFixed(v) || shared)) {
      index[v] = static_cast<int>(unknowns.size());
      unknowns.push_back(v);
      identityRow.push_back(isFixed(v));
      if (!isFixed(v)) equations.push_back(v);
    }
  if (bg == Background::Euclidean && !anyFixed && !unknowns.empty()) {
    // Prefer an interior vertex: circle vertices may carry the Möbius gauge rows below.
    auto pin = std::find_if(unknowns.begin(), unknowns.end(), [&](int v) { return !onCircle[v]; });
    if (pin == unknowns.end()) pin = unknowns.begin();
    index[*pin] = -1;
    identityRow.erase(identityRow.begin() + (pin - unknowns.begin()));
    unknowns.erase(pin);
    for (std::size_t i = 0; i < unknowns.size(); ++i) index[unknowns[i]] = static_cast<int>(i);
    report.gaugeFixed = true;
  }
  const int n = static_cast<int>(unknowns.size());
  report.effectiveTolerance = std::max(options.tolerance, options.relativeFloor * std::sqrt(double(nV)));

  // Residual r_v = Θ̂_v − Θ_v on `equations`; returns max |r| and fills the unknowns' part and |r|².
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  // Circle loops: current sides, radius, and the targets of their vertices.
  std::vector<std::vector<double>> loopSides(target.circleLoops.size());
  std::vector<InscribedPolygon> loopPolygons(target.circleLoops.size());
  report.circleRadii.assign(target.circleLoops.size(), 0.0);
  auto updateCircleTargets = [&]() {
    for (std::size_t i = 0; i < target.circleLoops.size(); ++i) {
      const auto& loop = target.circleLoops[i];
      const int len = static_cast<int>(loop.edges.size());
      loopSides[i].resize(len);
      for (int j = 0; j < len; ++j) loopSides[i][j] = metric.length(loop.edges[j]);
      loopPolygons[i] = inscribedPolygon(loopSides[i], static_cast<int>(i));
      report.circleRadii[i] = loopPolygons[i].radius;
      const std::vector<double>& phi = loopPolygons[i].halfAngle;
      for (int j = 0; j < len; ++j) targetSum[loop.vertices[j]] = M_PI - loop.sign * (phi[j] + phi[(j + 1) % len]);
    }
  };
  // Möbius gauge of circle domains. A Möbius automorphism of the outer disk maps the solution to another solution
  // (it rescales straight-line lengths by vertex factors, so it preserves the Penner class, and keeps circles
  // circles): the solutions form a 3-parameter family, the Jacobian has a 2-dimensional kernel beyond the scale, and
  // Newton steps blow up along it. Two equations, those of the outer-loop vertices q1 and q2, are replaced by the
  // gauge "the outer-loop arcs q0→q1 and q1→q2 subtend the central angles they have at the start" (q_i =
  // vertices[k_i], k_i = 0, n/3, 2n/3 of n outer vertices); a disk automorphism can send any three boundary points to
  // any three, so the gauge is always attainable, and near the solution the replaced equations hold automatically (the
  // reduced system is square and regular). The final check uses all angle residuals.
  int gaugeLoop = -1, gaugeK[3] = {0, 0, 0};
  int gaugeRow[2] = {-1, -1};
  for (std::size_t i = 0; i < target.circleLoops.size() && gaugeLoop < 0; ++i)
    if (target.circleLoops[i].sign > 0 && target.circleLoops[i].vertices.size() >= 3) gaugeLoop = static_cast<int>(i);
  if (gaugeLoop >= 0) {
    const auto& loop = target.circleLoops[gaugeLoop];
    const int len = static_cast<int>(loop.vertices.size());
    gaugeK[1] = len / 3;
    gaugeK[2] = (2 * len) / 3;
    gaugeRow[0] = index[loop.vertices[gaugeK[1]]];
    gaugeRow[1] = index[loop.vertices[gaugeK[2]]];
    if (gaugeRow[0] < 0 || gaugeRow[1] < 0) gaugeLoop = -1;  // a Dirichlet vertex already fixes the gauge
  }
  // Arc k of the gauge: edges j with gaugeK[k] < j ≤ gaugeK[k+1] (vertices[j] joins edges j and j+1). The gauge
  // angles are those of the starting metric, so the gauge never fights the first Newton steps.
  double gaugeTarget[2] = {0, 0};
  auto gaugeAngle = [&](int k) {
    double angle = 0;
    for (int j = gaugeK[k] + 1; j <= gaugeK[k + 1]; ++j) angle += 2 * loopPolygons[gaugeLoop].halfAngle[j];
    return angle;
  };
  auto gaugeValue = [&](int k) { return gaugeAngle(k) - gaugeTarget[k]; };
  // The kernel only matters once the residual is small (far away the Jacobian is regular enough, and imposing the
  // gauge early fights the large initial steps). For a disk the gauge rows are switched on below gaugeSwitch; with
  // holes, the left kernel is not carried by the outer loop alone, so replacing outer-loop rows is only a fallback,
  // switched on when the line search stalls (measured: docs/ricci_flow.md).
  const double gaugeSwitch = target.circleLoops.size() == 1 ? 1e-6 : 0.0;
  bool gaugeOn = false;
  int row0 = -1, row1 = -1;  // the active gauge rows (−1 while off)
  std::string circleFailure;
  // The last evaluation: edge lengths, angle sums and face geometry at the current u (the Jacobian's point); the
  // solver and the arrays of the solve, the cache's when it is shared.
  FlowSolverCache local(options.maxReuseIterations, options.nestedDissectionMin);
  FlowSolverCache& solver = shared ? *options.solverCache : local;
  FlowWorkspace& work = solver.workspace();
  std::vector<double>&lengths = work.lengths, &sums = work.sums;
  std::vector<FaceGeometry>& faces = work.faces;
  auto residual = [&](double& maxAbs, double& norm2) {
    if (circles) {
      // A trial step can make a short loop uninscribable (one side longer than the rest): an infinite merit rejects
      // the step; at the starting point it is reported.
      try {
        updateCircleTargets();
      } catch (const ConvergenceError& e) {
        circleFailure = e.what();
        maxAbs = norm2 = std::numeric_limits<double>::infinity();
        return;
      }
    }
    evaluateFaces(metric, lengths, sums, faces);
    maxAbs = 0;
    norm2 = 0;
    for (int v : equations) {
      const double rv = targetSum[v] - sums[v];
      if (!std::isfinite(rv)) {
        maxAbs = norm2 = std::numeric_limits<double>::infinity();
        return;
      }
      maxAbs = std::max(maxAbs, std::abs(rv));
      if (index[v] >= 0) r[index[v]] = rv;
    }
    if (gaugeOn)
      for (int k = 0; k < 2; ++k) {
        r[gaugeRow[k]] = gaugeValue(k);
        maxAbs = std::max(maxAbs, std::abs(r[gaugeRow[k]]));
      }
    norm2 = r.squaredNorm();
  };

  auto anyDegenerateFace = [&]() {
    for (int f = 0; f < m.nFaces(); ++f)
      if (!metric.isFrozen(f) && faces[f].degenerate) return true;
    return false;
  };

  report.flips += metric.makeDelaunay(options.delaunayTolerance, log);
  double maxAbs = 0, norm2 = 0;
  residual(maxAbs, norm2);
  if (!std::isfinite(maxAbs))
    throw ConvergenceError(
        "discrete Ricci flow cannot start: " +
        (circleFailure.empty() ? std::string("the initial angle sums are not finite") : circleFailure));
  report.maxResidual = maxAbs;

  solver.setDimension(n);
  const int factorizationsBefore = solver.factorizations(), cgBefore = solver.cgIterations();
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  std::vector<Eigen::Triplet<double>> triplets;  // circle domains
  // Symmetric problems: the unknown of each vertex as its faces see it (identity rows have no face entries).
  SymmetricAssembly& assembly = work.assembly;
  std::vector<int> faceIndex(nV, -1);
  if (!circles) {
    for (int v = 0; v < nV; ++v)
      if (index[v] >= 0 && !identityRow[index[v]]) faceIndex[v] = index[v];
    assembly.setIdentityRows(identityRow);
  }
  bool patternValid = false;
  SparseMatrix& H = work.H;
  H.resize(n, n);
  while (maxAbs > report.effectiveTolerance) {
    if (report.newtonSteps >= options.maxNewtonSteps) {
      std::ostringstream msg;
      msg.precision(3);
      msg << "discrete Ricci flow did not converge in " << options.maxNewtonSteps
          << " Newton steps: max |Θ̂ − Θ| = " << maxAbs << " rad, tolerance " << report.effectiveTolerance;
      throw ConvergenceError(msg.str());
    }
    if (gaugeLoop >= 0 && !gaugeOn && maxAbs < gaugeSwitch) {
      gaugeOn = true;
      row0 = gaugeRow[0];
      row1 = gaugeRow[1];
      for (int k = 0; k < 2; ++k) gaugeTarget[k] = gaugeAngle(k);
      residual(maxAbs, norm2);
      patternValid = false;
    }
    // Assemble H = −∂Θ/∂u on the unknowns.
    Eigen::VectorXd delta;
    if (!circles) {
      if (!patternValid) {
        assembly.rebuild(metric, faceIndex, n, H);
        solver.patternChanged();
        patternValid = true;
      }
      assembly.assemble(metric, faces, H);
      // Inexact Newton with forcing term η = 10⁻² min(1, max|r|): the linear residual adds at most η|r|₂ to the next
      // residual, which keeps the convergence quadratic (Dembo–Eisenstat–Steihaug 1982) and the direction a descent
      // direction for the merit (slope ≤ −(1 − η)|r|²). Quadratic convergence is only needed down to the stopping
      // tolerance ε: any η ≤ ε/(4|r|₂) keeps the linear part of the next residual below ε/4 in every component, so the
      // step lands below ε whenever the exact Newton step lands below 3ε/4 — the last step's conjugate gradients need
      // not go to 10⁻¹⁰ relative (measured: 12 iterations at 10⁵ vertices). 10⁻¹³ is the floor a preconditioned solve
      // reaches in double.
      const double eta = std::max(
          {1e-13, 1e-2 * std::min(1.0, maxAbs), std::min(1e-2, 0.25 * report.effectiveTolerance / std::sqrt(norm2))});
      if (!solver.solve(H, r, eta, delta)) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "discrete Ricci flow: the Hessian is not positive definite at Newton step " << report.newtonSteps
            << " (max |Θ̂ − Θ| = " << maxAbs << " rad); a triangle has probably degenerated";
        throw ConvergenceError(msg.str());
      }
      delta = -delta;
      for (int i = 0; i < n; ++i)
        if (identityRow[i]) delta[i] = 0;  // exactly: the conjugate gradients leave round-off there
    } else {
      triplets.clear();
      triplets.reserve(9 * static_cast<std::size_t>(m.nFaces()));
      for (int f = 0; f < m.nFaces(); ++f) {
        if (metric.isFrozen(f)) continue;
        double J[3][3];
        angleJacobian(bg, faces[f], J);
        int idx[3];
        for (int k = 0; k < 3; ++k) idx[k] = index[m.faceVertex(f, k)];
        for (int k = 0; k < 3; ++k) {
          if (idx[k] < 0) continue;
          for (int j = 0; j < 3; ++j)
            if (idx[j] >= 0 && idx[j] != row0 && idx[j] != row1) triplets.emplace_back(idx[j], idx[k], -J[j][k]);
        }
      }
      // J = ∂(Θ̂ − Θ)/∂u = H + (local terms of Θ̂ through ℓ_prev, ℓ_next) + Σ_loops U Vᵀ (through R), with
      // dℓ_e = (ℓ_e/2)(du_a + du_b), c_e = dφ_e/dx_e = ±1/sqrt(1 − x_e²) (x_e = ℓ_e/2R), dR = R Σ c_e dℓ_e / Σ c_e ℓ_e
      // and dΘ̂_v = −σ/(2R) (c_p dℓ_p + c_n dℓ_n) + σ (c_p ℓ_p + c_n ℓ_n)/(2R²) dR.
      const int nLoops = static_cast<int>(target.circleLoops.size());
      Eigen::MatrixXd U = Eigen::MatrixXd::Zero(n, nLoops), V = Eigen::MatrixXd::Zero(n, nLoops);
      for (int i = 0; i < nLoops; ++i) {
        const auto& loop = target.circleLoops[i];
        const int len = static_cast<int>(loop.edges.size());
        const double R = report.circleRadii[i], sigma = loop.sign;
        std::vector<double> c(len);
        double sumCl = 0;
        for (int j = 0; j < len; ++j) {
          const double x = std::min(1.0 - 1e-16, loopSides[i][j] / (2 * R));
          c[j] = loopPolygons[i].side[j] / std::sqrt((1 - x) * (1 + x));  // dφ_j/dx_j
          sumCl += c[j] * loopSides[i][j];
        }
        for (int j = 0; j < len; ++j) {
          const int e = loop.edges[j], h = m.edgeHalfedge(e);
          const int ends[2] = {index[m.tail(h)], index[m.tip(h)]};
          const double dl = 0.5 * loopSides[i][j];  // ∂ℓ_e/∂u at either end
          // Rows of the two loop vertices that edge j borders: vertices[j−1] (edge j is its "next") and vertices[j].
          const int rows[2] = {index[loop.vertices[(j + len - 1) % len]], index[loop.vertices[j]]};
          for (int row : rows)
            if (row >= 0 && row != row0 && row != row1)
              for (int col : ends)
                if (col >= 0) triplets.emplace_back(row, col, -sigma / (2 * R) * c[j] * dl);
          for (int col : ends)
            if (col >= 0) V(col, i) += R / sumCl * c[j] * dl;
        }
        for (int j = 0; j < len; ++j) {
          const int row = index[loop.vertices[j]];
          if (row >= 0 && row != row0 && row != row1)
            U(row, i) = sigma * (c[j] * loopSides[i][j] + c[(j + 1) % len] * loopSides[i][(j + 1) % len]) / (2 * R * R);
        }
        if (gaugeOn && i == gaugeLoop)
          // Gauge rows: d(Σ_arc 2 φ_j) = Σ_arc (c_j/R) dℓ_j − (Σ_arc c_j ℓ_j / R²) dR.
          for (int k = 0; k < 2; ++k) {
            double sumArc = 0;
            for (int j = gaugeK[k] + 1; j <= gaugeK[k + 1]; ++j) {
              const int h = m.edgeHalfedge(loop.edges[j]);
              for (int col : {index[m.tail(h)], index[m.tip(h)]})
                if (col >= 0) triplets.emplace_back(gaugeRow[k], col, c[j] / R * 0.5 * loopSides[i][j]);
              sumArc += c[j] * loopSides[i][j];
            }
            U(gaugeRow[k], i) = -sumArc / (R * R);
          }
      }
      H.setFromTriplets(triplets.begin(), triplets.end());
      H.makeCompressed();
      if (!patternValid) {
        lu.analyzePattern(H);
        patternValid = true;
      }
      lu.factorize(H);
      if (lu.info() != Eigen::Success) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "discrete Ricci flow: the circle-domain Jacobian is singular at Newton step " << report.newtonSteps
            << " (max |Θ̂ − Θ| = " << maxAbs << " rad)";
        throw ConvergenceError(msg.str());
      }
      // Sherman–Morrison–Woodbury: (S + U Vᵀ)⁻¹ r = y − Z (I + Vᵀ Z)⁻¹ Vᵀ y with S y = r, S Z = U.
      const Eigen::VectorXd y = lu.solve(r);
      Eigen::MatrixXd Z(n, nLoops);
      for (int i = 0; i < nLoops; ++i) Z.col(i) = lu.solve(Eigen::VectorXd(U.col(i)));
      const Eigen::MatrixXd small = Eigen::MatrixXd::Identity(nLoops, nLoops) + V.transpose() * Z;
      delta = -(y - Z * small.fullPivLu().solve(V.transpose() * y));
    }

    // Armijo backtracking on ½|r|²: the Newton direction has slope −|r|².
    std::vector<double> u0 = metric.u();
    double t = 1.0;
    NewtonStepInfo info;
    info.step = report.newtonSteps + 1;
    info.maxResidual = maxAbs;
    const double norm2Old = norm2;
    bool startChecked = false;
    while (true) {
      for (int i = 0; i < n; ++i) metric.u()[unknowns[i]] = u0[unknowns[i]] + t * delta[i];
      const std::int64_t flips = metric.makeDelaunay(options.delaunayTolerance, log);
      info.flips += flips;
      report.flips += flips;
      if (flips > 0) patternValid = false;
      double newMax = 0, newNorm2 = 0;
      residual(newMax, newNorm2);
      if (std::isfinite(newNorm2) && newNorm2 <= (1 - 2 * options.armijo * t) * norm2Old) {
        maxAbs = newMax;
        norm2 = newNorm2;
        break;
      }
      t *= 0.5;
      if (options.allowDegenerateFaces && options.returnAtDegenerateStall && t <= 0.5 && !startChecked) {
        // Back to the step's start, where the degenerate faces that the caller can repair are (once per step).
        startChecked = true;
        for (int i = 0; i < n; ++i) metric.u()[unknowns[i]] = u0[unknowns[i]];
        report.flips += metric.makeDelaunay(options.delaunayTolerance, log);
        double startMax = 0, startNorm2 = 0;
        residual(startMax, startNorm2);
        if (anyDegenerateFace()) {
          maxAbs = startMax;
          norm2 = startNorm2;
          report.maxResidual = maxAbs;
          report.stoppedAtDegenerate = true;
          break;
        }
      }
      if (t < options.minStep && gaugeLoop >= 0 && !gaugeOn) {
        for (int i = 0; i < n; ++i) metric.u()[unknowns[i]] = u0[unknowns[i]];
        metric.makeDelaunay(options.delaunayTolerance, log);
        gaugeOn = true;
        row0 = gaugeRow[0];
        row1 = gaugeRow[1];
        residual(maxAbs, norm2);
        for (int k = 0; k < 2; ++k) gaugeTarget[k] = gaugeAngle(k);
        residual(maxAbs, norm2);
        patternValid = false;
        break;
      }
      if (t < options.minStep) {
        // Restore a consistent residual vector before reporting.
        for (int i = 0; i < n; ++i) metric.u()[unknowns[i]] = u0[unknowns[i]];
        metric.makeDelaunay(options.delaunayTolerance, log);
        residual(maxAbs, norm2);
        std::ostringstream msg;
        msg.precision(3);
        msg << "discrete Ricci flow stalled at Newton step " << info.step
            << ": no step decreases |Θ̂ − Θ|, max |Θ̂ − Θ| = " << maxAbs << " rad, tolerance "
            << report.effectiveTolerance;
        throw ConvergenceError(msg.str());
      }
    }
    if (report.stoppedAtDegenerate) {
      ++report.newtonSteps;
      break;
    }
    info.stepLength = t;
    ++report.newtonSteps;
    report.maxResidual = maxAbs;
    if (options.onStep) options.onStep(info);
    if (options.stopAfterStep && maxAbs > report.effectiveTolerance && options.stopAfterStep(sums, maxAbs)) {
      report.stoppedByCaller = true;
      break;
    }
  }
  report.maxResidual = maxAbs;
  report.factorizations = solver.factorizations() - factorizationsBefore;
  report.cgIterations = solver.cgIterations() - cgBefore;
  report.nestedDissection = solver.nestedDissection();
  if (report.stoppedAtDegenerate || report.stoppedByCaller) {
    report.angleSums = sums;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }
  // The extended angles (π, 0, 0) make the energy convex everywhere, but a solution with such a face is not a metric:
  // it happens only next to edges that may not flip (boundary, frozen), when the conformal class has no triangulation
  // of this boundary with valid triangles.
  for (int f = 0; f < m.nFaces() && !options.allowDegenerateFaces; ++f)
    if (!metric.isFrozen(f) && faces[f].degenerate)
      throw ConvergenceError("discrete Ricci flow converged to a degenerate face " + std::to_string(f) + " (" +
                             std::to_string(m.faceVertex(f, 0)) + ", " + std::to_string(m.faceVertex(f, 1)) + ", " +
                             std::to_string(m.faceVertex(f, 2)) +
                             "): the target needs a flip of an edge that may not flip (a boundary edge)");
  report.angleSums = sums;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace conformesh::intrinsic
