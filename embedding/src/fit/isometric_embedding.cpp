// isometric_embedding.cpp — landmark-MDS start, then Levenberg–Marquardt on relative edge-length residuals in two
// solves (dihedral regularizer on, then off), then the verdict (see isometric_embedding.h and docs/embedding.md).
#include "conformesh/embedding/fit/isometric_embedding.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <string>

#include <ceres/ceres.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"

namespace conformesh::embedding {

using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string sci(double x, int digits = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", digits, x);
  return buf;
}

// ===================================================================================================================
// input checks

void validateInput(const IntrinsicTriangulation& tri, const EmbeddingOptions& options) {
  const auto& m = tri.mesh;
  if (tri.background != intrinsic::Background::Euclidean)
    throw InputError("embed: the mesh's lengths are meant in the " + intrinsic::toString(tri.background) +
                     " background; only Euclidean (flat-triangle) lengths can be realized by straight edges in R³");
  if (m.nFaces() == 0 || m.nVertices() < 3)
    throw InputError("embed: need at least one triangle (3 vertices), found " + std::to_string(m.nVertices()) +
                     " vertices and " + std::to_string(m.nFaces()) + " faces");
  intrinsic::validateLengths(tri, "embed");
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    if (m.tail(h) == m.tip(h))
      throw InputError("embed: edge " + std::to_string(e) + " is a self-loop at vertex " + std::to_string(m.tail(h)) +
                       " with length " + sci(tri.edgeLengths[e], 6) +
                       "; no straight segment joins a point to itself — flip it away (intrinsic Delaunay) first");
  }
  const auto comps = m.components();
  if (comps.size() > 1)
    throw InputError("embed: the mesh has " + std::to_string(comps.size()) +
                     " connected components; edge lengths do not fix their relative placement — fit each component "
                     "separately");
  if (!options.initialPositions.empty()) {
    if (static_cast<int>(options.initialPositions.size()) != m.nVertices())
      throw InputError("embed: " + std::to_string(options.initialPositions.size()) + " initial positions for " +
                       std::to_string(m.nVertices()) + " vertices");
    for (int v = 0; v < m.nVertices(); ++v)
      if (!options.initialPositions[v].allFinite())
        throw InputError("embed: initial position of vertex " + std::to_string(v) + " is not finite");
  }
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError(problem);
}

// ===================================================================================================================
// landmark MDS start

// Adjacency by edges (multi-edges kept: Dijkstra takes the shortest) plus the diagonal of every convex diamond. Edge
// paths zig-zag: on a regular triangulation their lengths overestimate geodesic distance by up to ~15% depending on
// the direction, and that error is smooth and large-scale — the landmark-MDS start then carries a low-frequency
// distortion that the inexact (CGNR) steps of the first solve remove only slowly (on a 100k-vertex ellipsoid they had
// not after 100 iterations). Adding the diagonal cd of each edge ab's diamond (a, b, c, d), at its length in the
// two triangles' planar unfolding, gives paths a direction every 30° instead of 60° and cuts that error by about
// four. A non-convex diamond's diagonal runs outside it: it is skipped (its length would undercut the geodesic).
struct DistanceGraph {
  std::vector<int> offset, target;
  std::vector<double> weight;
};

DistanceGraph buildGraph(const IntrinsicTriangulation& tri) {
  const auto& m = tri.mesh;
  const auto bg = intrinsic::Background::Euclidean;
  std::vector<std::array<int, 2>> pairs;
  std::vector<double> lengths;
  pairs.reserve(2 * static_cast<std::size_t>(m.nEdges()));
  lengths.reserve(2 * static_cast<std::size_t>(m.nEdges()));
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e), t = m.twin(h);
    const int a = m.tail(h), b = m.tip(h);
    pairs.push_back({a, b});
    lengths.push_back(tri.edgeLengths[e]);
    if (t == kInvalid) continue;
    const int c = m.tip(HalfedgeMesh::next(h)), d = m.tip(HalfedgeMesh::next(t));
    if (c == d) continue;
    const double ab = tri.edgeLengths[e];
    const double bc = tri.edgeLengths[m.edge(HalfedgeMesh::next(h))],
                 ca = tri.edgeLengths[m.edge(HalfedgeMesh::prev(h))];
    const double ad = tri.edgeLengths[m.edge(HalfedgeMesh::next(t))],
                 db = tri.edgeLengths[m.edge(HalfedgeMesh::prev(t))];
    // Angles at a and at b of both triangles (angleOpposite(g, opposite side, adjacent, adjacent)).
    const double atA = intrinsic::angleOpposite(bg, bc, ab, ca) + intrinsic::angleOpposite(bg, db, ab, ad);
    const double atB = intrinsic::angleOpposite(bg, ca, ab, bc) + intrinsic::angleOpposite(bg, ad, ab, db);
    if (!(atA < M_PI && atB < M_PI)) continue;
    pairs.push_back({c, d});
    lengths.push_back(intrinsic::thirdSide(bg, ca, ad, atA));
  }
  DistanceGraph g;
  g.offset.assign(m.nVertices() + 1, 0);
  for (const auto& [p, q] : pairs) {
    ++g.offset[p + 1];
    ++g.offset[q + 1];
  }
  for (int v = 0; v < m.nVertices(); ++v) g.offset[v + 1] += g.offset[v];
  g.target.resize(g.offset.back());
  g.weight.resize(g.offset.back());
  std::vector<int> fill(g.offset.begin(), g.offset.end() - 1);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [p, q] = pairs[k];
    g.target[fill[p]] = q;
    g.weight[fill[p]++] = lengths[k];
    g.target[fill[q]] = p;
    g.weight[fill[q]++] = lengths[k];
  }
  return g;
}

std::vector<double> dijkstra(const DistanceGraph& g, int source) {
  const int n = static_cast<int>(g.offset.size()) - 1;
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  d[source] = 0;
  q.push({0.0, source});
  while (!q.empty()) {
    const auto [dv, v] = q.top();
    q.pop();
    if (dv > d[v]) continue;
    for (int k = g.offset[v]; k < g.offset[v + 1]; ++k) {
      const double nd = dv + g.weight[k];
      if (nd < d[g.target[k]]) {
        d[g.target[k]] = nd;
        q.push({nd, g.target[k]});
      }
    }
  }
  return d;
}

// ===================================================================================================================
// Ceres residuals

// (|x_i − x_j| − ℓ)/ℓ.
struct EdgeLengthResidual {
  explicit EdgeLengthResidual(double length) : inverseLength(1 / length) {}
  template <typename T>
  bool operator()(const T* xi, const T* xj, T* r) const {
    const T dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2];
    r[0] = ceres::sqrt(dx * dx + dy * dy + dz * dz) * inverseLength - T(1);
    return true;
  }
  double inverseLength;
};

// 2w·sin(β/2) for faces (a, b, c) and (b, a, d) sharing edge ab, β the signed angle between their unit normals n₁, n₂
// (positive where convex, as in mean_curvature_measure.h). Its square is w²|n₁ − n₂|² (|n₁ − n₂| = 2 sin(|β|/2)), so
// the regularizer's energy — and the first solve's optimum — is that of the vector residual w·(n₁ − n₂), but in one
// Jacobian row instead of three: per interior edge the Jacobian holds 6 + 12 entries instead of 6 + 36, and the
// conjugate-gradient iterations of the first solve, a product with J and one with Jᵀ each, get cheaper in proportion
// (20 252 vertices: the same 7 + 9 steps, CG iteration counts within 1, the same polyhedron, 39 s CPU instead of 54 s).
// At β = ±π (a diamond folded flat onto itself) the residual jumps from 2w to −2w, its energy does not. A zero normal
// or edge (a degenerate face) leaves β undefined: the residual returns false, which LM treats as a
// rejected step.
struct DihedralResidual {
  explicit DihedralResidual(double w) : weight(w) {}
  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, const T* d, T* r) const {
    using V = Eigen::Matrix<T, 3, 1>;
    const V A(a[0], a[1], a[2]), B(b[0], b[1], b[2]), C(c[0], c[1], c[2]), D(d[0], d[1], d[2]);
    const V e = B - A, n1 = e.cross(C - A), n2 = (A - B).cross(D - B);
    const T l1 = n1.norm(), l2 = n2.norm(), le = e.norm();
    if (!(l1 > T(0)) || !(l2 > T(0)) || !(le > T(0))) return false;
    const T beta = ceres::atan2(n1.cross(n2).dot(e) / (l1 * l2 * le), n1.dot(n2) / (l1 * l2));
    r[0] = T(2 * weight) * ceres::sin(beta / T(2));
    return true;
  }
  double weight;
};

class ProgressCallback : public ceres::IterationCallback {
 public:
  ProgressCallback(const std::function<void(const std::string&)>& progress, std::string stage, double edges)
      : progress_(progress), stage_(std::move(stage)), edges_(edges) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (progress_)
      progress_(stage_ + " iteration " + std::to_string(s.iteration) + ": cost " + sci(s.cost) + " (RMS residual " +
                sci(std::sqrt(2 * s.cost / edges_)) + "), step " + sci(s.step_norm) +
                (s.step_is_successful ? "" : " rejected") + ", " + std::to_string(s.linear_solver_iterations) +
                " linear-solver iterations, trust region " + sci(s.trust_region_radius));
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<void(const std::string&)>& progress_;
  std::string stage_;
  double edges_;
};

// ===================================================================================================================
// elimination order for the exact solve

// Nested dissection of the vertex graph by coordinate bisection of the current positions, as a Ceres elimination
// order: each leaf (≤ 64 vertices) and each separator is one group, groups are eliminated in increasing id, and Ceres
// orders each group's vertices by constrained minimum degree (CAMD). The normal equations JᵀJ of the pure fit couple
// the 1-ring; Ceres' default ordering for them is approximate minimum degree, whose fill on a fine surface mesh grows
// like a 2-D grid's under AMD. Cutting a surface by a plane leaves a separator of O(√V) vertices, and ordering every
// separator after both halves it splits bounds the dense fronts by those separators (George 1973): CHOLMOD's own
// count for the ellipsoid's JᵀJ is 4.4e9 → 3.1e9 flops per factorization at 20 252 vertices and 1.9e11 → 1.0e11 at
// 198 812 (METIS: 2.6e9, 8.3e10). The positions only steer the cut: an ordering changes the cost of a step, not the
// step (up to round-off). Separator of a bisection: the vertices below the median that have a neighbour above it —
// removing them disconnects the two sides, since every crossing edge has its lower end among them.
std::shared_ptr<ceres::ParameterBlockOrdering> nestedDissectionOrdering(const HalfedgeMesh& m, std::vector<double>& x) {
  const int n = m.nVertices();
  std::vector<int> offset(n + 1, 0), neighbour(2 * static_cast<std::size_t>(m.nEdges()));
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    ++offset[m.tail(h) + 1];
    ++offset[m.tip(h) + 1];
  }
  for (int v = 0; v < n; ++v) offset[v + 1] += offset[v];
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e), a = m.tail(h), b = m.tip(h);
    neighbour[fill[a]++] = b;
    neighbour[fill[b]++] = a;
  }
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  std::vector<signed char> above(n, 0);
  int group = 0;
  // Explicit stack of (vertex set, separator to emit after it): a separator's group id must exceed those of both
  // halves, so it is pushed below them and emitted when it is popped.
  struct Task {
    std::vector<int> vertices;
    bool isSeparator;
  };
  std::vector<Task> stack;
  stack.push_back({std::vector<int>(n), false});
  std::iota(stack.back().vertices.begin(), stack.back().vertices.end(), 0);
  while (!stack.empty()) {
    Task task = std::move(stack.back());
    stack.pop_back();
    auto& S = task.vertices;
    if (task.isSeparator || S.size() <= 64) {
      for (int v : S) ordering->AddElementToGroup(&x[3 * v], group);
      if (!S.empty()) ++group;
      continue;
    }
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int v : S) {
      const Eigen::Vector3d p(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const std::size_t mid = S.size() / 2;
    std::nth_element(S.begin(), S.begin() + mid, S.end(),
                     [&](int a, int b) { return x[3 * a + axis] < x[3 * b + axis]; });
    for (std::size_t k = mid; k < S.size(); ++k) above[S[k]] = 1;
    std::vector<int> lower, separator;
    for (std::size_t k = 0; k < mid; ++k) {
      const int v = S[k];
      bool touches = false;
      for (int j = offset[v]; j < offset[v + 1] && !touches; ++j) touches = above[neighbour[j]];
      (touches ? separator : lower).push_back(S[k]);
    }
    for (std::size_t k = mid; k < S.size(); ++k) above[S[k]] = 0;
    std::vector<int> upper(S.begin() + mid, S.end());
    stack.push_back({std::move(separator), true});
    stack.push_back({std::move(upper), false});
    stack.push_back({std::move(lower), false});
  }
  return ordering;
}

ceres::Solver::Summary solve(ceres::Problem& problem, ceres::LinearSolverType linearSolver, int maxIterations,
                             double functionTolerance, int threads, ceres::IterationCallback* cb,
                             std::shared_ptr<ceres::ParameterBlockOrdering> ordering = nullptr) {
  ceres::Solver::Options o;
  o.minimizer_type = ceres::TRUST_REGION;
  o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  o.linear_solver_type = linearSolver;
  o.max_num_iterations = maxIterations;
  o.num_threads = std::max(1, threads);
  o.function_tolerance = functionTolerance;
  o.gradient_tolerance = 1e-20;
  o.parameter_tolerance = 1e-15;
  o.linear_solver_ordering = std::move(ordering);
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  if (cb) {
    o.callbacks.push_back(cb);
    o.update_state_every_iteration = false;
  }
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  return summary;
}

}  // namespace

std::string EmbeddingOptions::validate() const {
  if (tolerance <= 0 || !std::isfinite(tolerance)) return "embed: tolerance must be positive, found " + sci(tolerance);
  if (regularizerWeight < 0 || !std::isfinite(regularizerWeight))
    return "embed: regularizer weight must be ≥ 0, found " + sci(regularizerWeight);
  return "";
}

// =====================================================================================================================

std::vector<double> relativeEdgeResiduals(const IntrinsicTriangulation& tri,
                                          const std::vector<Eigen::Vector3d>& positions) {
  const auto& m = tri.mesh;
  if (static_cast<int>(positions.size()) != m.nVertices())
    throw InputError("embed: " + std::to_string(positions.size()) + " positions for " + std::to_string(m.nVertices()) +
                     " vertices");
  std::vector<double> r(m.nEdges());
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    r[e] = ((positions[m.tail(h)] - positions[m.tip(h)]).norm() - tri.edgeLengths[e]) / tri.edgeLengths[e];
  }
  return r;
}

std::vector<Eigen::Vector3d> landmarkMdsStart(const IntrinsicTriangulation& tri, int landmarks) {
  const int n = tri.mesh.nVertices();
  const DistanceGraph graph = buildGraph(tri);
  const int k = std::max(4, std::min(landmarks, n));
  // Farthest-point landmarks: each new one maximizes the graph distance to those chosen, so they spread evenly.
  std::vector<int> marks;
  std::vector<std::vector<double>> dist;  // dist[l][v]
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  int next = 0;
  while (static_cast<int>(marks.size()) < std::min(k, n)) {
    marks.push_back(next);
    dist.push_back(dijkstra(graph, next));
    for (int v = 0; v < n; ++v) {
      if (!std::isfinite(dist.back()[v]))
        throw InputError("embed: vertex " + std::to_string(v) + " is not connected to vertex " + std::to_string(next));
      nearest[v] = std::min(nearest[v], dist.back()[v]);
    }
    next = static_cast<int>(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
    if (nearest[next] == 0) break;  // every vertex is a landmark
  }
  const int L = static_cast<int>(marks.size());
  // Classical MDS on the landmarks (Torgerson): B = −½ J Δ J with Δ the squared distances; coordinates from the top
  // three eigenpairs. The other vertices by distance-based triangulation (de Silva & Tenenbaum 2004, eq. 3):
  // x = −½ Λ^(−1/2) Vᵀ (δ_x − δ̄), δ̄ the mean column of Δ.
  Eigen::MatrixXd D2(L, L);
  for (int i = 0; i < L; ++i)
    for (int j = 0; j < L; ++j) D2(i, j) = dist[i][marks[j]] * dist[i][marks[j]];
  const Eigen::VectorXd mean = D2.rowwise().mean();
  const Eigen::MatrixXd J = Eigen::MatrixXd::Identity(L, L) - Eigen::MatrixXd::Constant(L, L, 1.0 / L);
  const Eigen::MatrixXd B = -0.5 * J * D2 * J;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(B);
  Eigen::Matrix<double, 3, Eigen::Dynamic> P(3, L);  // rows: Λ^(−1/2) Vᵀ of the top three
  const double top = std::max(eig.eigenvalues()(L - 1), 1e-300);
  bool flat = false;
  for (int c = 0; c < 3; ++c) {
    const double lambda = eig.eigenvalues()(L - 1 - c);
    // An eigenvalue below 1e-8 of the largest is numerically zero: the landmarks are (nearly) coplanar.
    if (lambda <= 1e-8 * top) {
      P.row(c).setZero();
      flat = true;
    } else {
      P.row(c) = eig.eigenvectors().col(L - 1 - c).transpose() / std::sqrt(lambda);
    }
  }
  std::vector<Eigen::Vector3d> x(n);
  Eigen::VectorXd delta(L);
  for (int v = 0; v < n; ++v) {
    for (int l = 0; l < L; ++l) delta(l) = dist[l][v] * dist[l][v];
    x[v] = -0.5 * P * (delta - mean);
  }
  if (flat) {
    // A planar start is a saddle of the fit for a curved patch (z ↦ −z symmetry): bend it into a gentle paraboloid,
    // height 1% of the squared distance from the centroid over the diameter, to pick a side.
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& p : x) c += p;
    c /= n;
    double diam2 = 0;
    for (const auto& p : x) diam2 = std::max(diam2, (p - c).squaredNorm());
    for (auto& p : x) p.z() += 0.01 * (p - c).squaredNorm() / std::sqrt(std::max(diam2, 1e-300));
  }
  // Graph distances overestimate geodesics (zig-zag paths), so the MDS scale is off by a few percent: rescale by the
  // least-squares factor s minimizing Σ (s·d_e/ℓ_e − 1)².
  const auto r = relativeEdgeResiduals(tri, x);
  double s1 = 0, s2 = 0;
  for (double q : r) {
    s1 += 1 + q;
    s2 += (1 + q) * (1 + q);
  }
  const double s = s2 > 0 ? s1 / s2 : 1.0;
  for (auto& p : x) p *= s;
  return x;
}

EmbeddingResult fitIsometricEmbedding(const IntrinsicTriangulation& tri, const EmbeddingOptions& options) {
  validateInput(tri, options);
  const auto& m = tri.mesh;
  const int n = m.nVertices();
  EmbeddingResult res;
  res.tolerance = options.tolerance;

  auto t0 = Clock::now();
  std::vector<Eigen::Vector3d> start;
  if (!options.initialPositions.empty()) {
    start = options.initialPositions;
    res.start = "initial positions";
  } else {
    if (options.progress)
      options.progress("embed: landmark MDS start (" + std::to_string(options.landmarks) + " landmarks, Dijkstra on " +
                       std::to_string(m.nEdges()) + " edges)");
    start = landmarkMdsStart(tri, options.landmarks);
    res.start = "landmark MDS (" + std::to_string(std::min(std::max(4, options.landmarks), n)) + " landmarks)";
  }
  res.startSeconds = secondsSince(t0);

  std::vector<double> x(3 * static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) x[3 * v + c] = start[v][c];

  ceres::Problem::Options po;
  po.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  auto addEdges = [&](ceres::Problem& problem) {
    for (int e = 0; e < m.nEdges(); ++e) {
      const int h = m.edgeHalfedge(e);
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<EdgeLengthResidual, 1, 3, 3>(new EdgeLengthResidual(tri.edgeLengths[e])),
          nullptr, &x[3 * m.tail(h)], &x[3 * m.tip(h)]);
    }
  };

  t0 = Clock::now();
  // Continuation in the weight: w, w/10, w/100, each stage started at the previous one's optimum, then the pure fit.
  // The regularizer's bias (its optimum's distance from the realization) shrinks with w, so the pure fit starts next
  // to the realization instead of a bias away from it. Started from the w = 1 optimum directly, the pure fit's first,
  // nearly undamped Gauss–Newton steps (at 50 412 vertices of length 0.18 over all 3V coordinates) popped vertices
  // through their links — along the normal a vertex's edges change only by ≈ tκ/2, so the linear model asks for moves
  // larger than the vertex's height over its link, ≈ κℓ²/2 — and reached a round-off residual at a non-convex
  // polyhedron (90 edges bent the wrong way); after the w/100 stage its first step is 3e-4 long at 20k. The smaller
  // weights also cost little: from the previous optimum their CG solves take 20–250 iterations (20k–100k vertices),
  // not the cap.
  std::vector<double> weights;
  if (options.regularizerWeight > 0)
    weights = {options.regularizerWeight, options.regularizerWeight / 10, options.regularizerWeight / 100};
  for (const double w : weights) {
    ceres::Problem problem(po);
    addEdges(problem);
    for (int e = 0; e < m.nEdges(); ++e) {
      const int h = m.edgeHalfedge(e), t = m.twin(h);
      if (t == kInvalid) continue;
      const int a = m.tail(h), b = m.tip(h), c = m.tip(HalfedgeMesh::next(h)), d = m.tip(HalfedgeMesh::next(t));
      // Ceres needs four distinct parameter blocks; in a Δ-complex c may equal d (or a, b): skip such edges.
      if (c == d || c == a || c == b || d == a || d == b) continue;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<DihedralResidual, 1, 3, 3, 3, 3>(new DihedralResidual(w)), nullptr, &x[3 * a],
          &x[3 * b], &x[3 * c], &x[3 * d]);
    }
    ProgressCallback cb(options.progress, "embed: regularized fit (w = " + sci(w, 1) + ")", m.nEdges());
    // The regularized optimum is only a start: its RMS residual is the regularizer's bias (~1e-3 on the ellipsoid), and
    // once LM stops gaining 1e-6 of the cost per step it has reached the basin the second solve needs. Converging it
    // further (to the 1e-15 of the final solve) cost a third of the 20k-vertex fit and most of the 200k one. Stopping
    // sooner is not safe: at 20 252 vertices a stop at 1e-2 (5 steps instead of 7; the two skipped steps have norm 0.08
    // over all 3V coordinates) led the second solve to a different polyhedron with the same lengths (Procrustes
    // RMS 3.584e-5 against the convex one's 3.572e-5). Jacobi rather than Ceres' SUBSET preconditioner on the edge
    // terms: the edge-only JᵀJ barely resists normal motion (an edge leaves the tangent plane at angle ≈ κℓ/2, so a
    // vertex moved by t along the normal changes its edges by ≈ tκ/2 relative, against ≈ t/ℓ for the dihedral terms),
    // so the preconditioned matrix keeps eigenvalues up to ≈ w²/(κℓ)² (≈ 10³ at 20k vertices) on all V normal
    // directions, and CG needed as many iterations as with Jacobi (187–500 per step at 20k), each with two triangular
    // solves (docs/benchmarks.md).
    const auto summary = solve(problem, ceres::CGNR, options.maxIterationsRegularized, 1e-6, options.threads, &cb);
    res.regularizedIterations += static_cast<int>(summary.iterations.size()) - 1;
  }
  res.regularizedSeconds = secondsSince(t0);
  const auto t1 = Clock::now();
  {
    ceres::Problem problem(po);
    addEdges(problem);
    ProgressCallback cb(options.progress, "embed: fit", m.nEdges());
    // Stop only at round-off: the cost of a realizable length set falls to ~1e-28·E, and the verdict needs the fit to
    // get there. Relative cost change 1e-15 and gradient 1e-20 are below what double precision can still improve.
    const auto summary = solve(problem, ceres::SPARSE_NORMAL_CHOLESKY, options.maxIterations, 1e-15, options.threads,
                               &cb, nestedDissectionOrdering(m, x));
    res.iterations = static_cast<int>(summary.iterations.size()) - 1;
  }
  res.finalSeconds = secondsSince(t1);
  res.fitSeconds = secondsSince(t0);

  res.positions.resize(n);
  for (int v = 0; v < n; ++v) res.positions[v] = Eigen::Vector3d(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
  const auto r = relativeEdgeResiduals(tri, res.positions);
  double sum2 = 0;
  for (int e = 0; e < m.nEdges(); ++e) {
    sum2 += r[e] * r[e];
    if (std::abs(r[e]) >= res.maxRelativeResidual) {
      res.maxRelativeResidual = std::abs(r[e]);
      res.worstEdge = e;
    }
  }
  res.rmsRelativeResidual = std::sqrt(sum2 / m.nEdges());
  res.isometric = res.maxRelativeResidual <= options.tolerance;
  const std::string figures = "max relative edge residual " + sci(res.maxRelativeResidual) + " at edge " +
                              std::to_string(res.worstEdge) + ", RMS " + sci(res.rmsRelativeResidual);
  if (res.isometric) {
    res.verdict = "isometric to tolerance " + sci(options.tolerance, 1) + " (" + figures + ")";
  } else {
    res.verdict = "not isometric: residual " + sci(res.maxRelativeResidual) + " cannot be removed (" + figures +
                  ", above tolerance " + sci(options.tolerance, 1) + " after " +
                  std::to_string(res.regularizedIterations + res.iterations) +
                  " LM iterations): Levenberg–Marquardt finds no polyhedron with these edge lengths near this fit";
  }
  if (options.progress) options.progress("embed: " + res.verdict);
  return res;
}

}  // namespace conformesh::embedding
