// killing_vector.cpp — the approximate Killing vector on an intrinsic triangulation (killing_vector.h; derivation in
// docs/horizons.md §4d).
#include "conformesh/intrinsic/measure/killing_vector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"

namespace conformesh::intrinsic {

std::string KillingVectorOptions::validate() const {
  if (modes < 1) return "modes must be at least 1 (got " + std::to_string(modes) + ")";
  if (extraVectors < 1) return "extraVectors must be at least 1 (got " + std::to_string(extraVectors) + ")";
  if (maxIterations < 1) return "maxIterations must be at least 1";
  if (!(tolerance > 0)) return "tolerance must be positive";
  if (!(degeneracyRatio >= 0) || !(degeneracyFloor >= 0)) return "degeneracyRatio must be >= 0 and degeneracyFloor >= 0";
  if (orbitLevels < 4) return "orbitLevels must be at least 4";
  return "";
}

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// The 2D positions of face f's corners laid out from its three lengths: corner k = tail(3f + k).
std::array<Eigen::Vector2d, 3> layoutFace(const IntrinsicTriangulation& tri, int f) {
  const double l0 = tri.length(3 * f), l1 = tri.length(3 * f + 1), l2 = tri.length(3 * f + 2);
  const double x = (l0 * l0 + l2 * l2 - l1 * l1) / (2 * l0);
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(l0, 0), Eigen::Vector2d(x, std::sqrt(std::max(0.0, l2 * l2 - x * x)))};
}

void requireClosedSphere(const IntrinsicTriangulation& tri) {
  if (tri.background != Background::Euclidean)
    throw InputError("approximate Killing vector: needs flat (Euclidean-background) triangles");
  const auto comps = tri.mesh.components();
  if (comps.size() != 1 || comps[0].boundaryLoops != 0 || comps[0].genus != 0)
    throw InputError("approximate Killing vector: needs one closed genus-0 surface (found " +
                     std::to_string(comps.size()) + " component(s), Euler characteristic " +
                     std::to_string(tri.mesh.eulerCharacteristic()) + ")");
}

// The P1 operators of the eigenproblem, with vertex 0 removed (z(0) = 0 fixes the constant).
struct KillingOperators {
  SparseMatrix left, right;  // S M⁻¹ S − S_R  and  S
  double area = 0;
};

// Cotan stiffness of face f (½ cot of the angle opposite each edge), scaled by `scale`, into the triplets.
void addFaceStiffness(const IntrinsicTriangulation& tri, int f, double scale, Triplets& t) {
  for (int k = 0; k < 3; ++k) {
    const int h = 3 * f + k, a = tri.mesh.tail(h), b = tri.mesh.tip(h);
    const double w = 0.5 * scale * cotanOpposite(tri, h);
    t.emplace_back(a, b, -w);
    t.emplace_back(b, a, -w);
    t.emplace_back(a, a, w);
    t.emplace_back(b, b, w);
  }
}

KillingOperators assembleOperators(const IntrinsicTriangulation& tri) {
  const int n = tri.mesh.nVertices();
  std::vector<double> faceA(tri.mesh.nFaces()), vertexA(n, 0.0);
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    faceA[f] = faceArea(tri, f);
    for (int k = 0; k < 3; ++k) vertexA[tri.mesh.faceVertex(f, k)] += faceA[f] / 3;
  }
  const std::vector<double> defect = vertexCurvatures(tri);
  Triplets ts, tr;
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    double R = 0;  // R_f = 2 · mean of K_v = defect_v / A_v over the face's corners
    for (int k = 0; k < 3; ++k) R += 2 * defect[tri.mesh.faceVertex(f, k)] / (3 * vertexA[tri.mesh.faceVertex(f, k)]);
    addFaceStiffness(tri, f, 1.0, ts);
    addFaceStiffness(tri, f, R, tr);
  }
  SparseMatrix S(n, n), SR(n, n);
  S.setFromTriplets(ts.begin(), ts.end());
  SR.setFromTriplets(tr.begin(), tr.end());
  Eigen::VectorXd invM(n);
  for (int v = 0; v < n; ++v) invM[v] = 1 / vertexA[v];
  const SparseMatrix left = SparseMatrix(S * invM.asDiagonal() * S) - SR;
  KillingOperators ops;
  ops.left = left.bottomRightCorner(n - 1, n - 1);
  ops.right = S.bottomRightCorner(n - 1, n - 1);
  for (double a : faceA) ops.area += a;
  return ops;
}

// Subspace iteration for the smallest eigenpairs of left z = λ right z (both symmetric, right positive definite once
// vertex 0 is fixed), shifted by σ = −½·4π/A so that left − σ right is positive definite; Rayleigh–Ritz each step.
class SubspaceIteration {
 public:
  SubspaceIteration(const KillingOperators& ops, const KillingVectorOptions& o) : ops_(ops), o_(o) {}

  void run() {
    factor();
    start();
    std::vector<double> previous;
    for (iterations_ = 1; iterations_ <= o_.maxIterations; ++iterations_) {
      step();
      if (converged(previous)) return;
      previous = scaled(o_.modes);
    }
    throw ConvergenceError("approximate Killing vector: subspace iteration did not converge in " +
                           std::to_string(o_.maxIterations) + " steps");
  }
  const Eigen::VectorXd& values() const { return values_; }
  const Eigen::MatrixXd& vectors() const { return X_; }
  int iterations() const { return iterations_; }
  std::vector<double> scaled(int k) const {
    std::vector<double> s(k);
    for (int i = 0; i < k; ++i) s[i] = values_[i] * ops_.area / (4 * M_PI);
    return s;
  }

 private:
  void factor() {
    const double sigma = -0.5 * 4 * M_PI / ops_.area;
    solver_.compute(SparseMatrix(ops_.left - sigma * ops_.right));
    if (solver_.info() != Eigen::Success)
      throw ConvergenceError("approximate Killing vector: the shifted operator could not be factored");
  }
  void start() {  // fixed seed: the result does not depend on the run
    const int p = o_.modes + o_.extraVectors, n = static_cast<int>(ops_.right.rows());
    if (n < p + 1) throw InputError("approximate Killing vector: the mesh has too few vertices for " +
                                    std::to_string(p) + " iteration vectors");
    std::mt19937 gen(12345);
    std::uniform_real_distribution<double> u(-1, 1);
    X_.resize(n, p);
    for (int j = 0; j < p; ++j)
      for (int i = 0; i < n; ++i) X_(i, j) = u(gen);
  }
  void step() {
    const Eigen::MatrixXd Y = solver_.solve(ops_.right * X_);
    const Eigen::MatrixXd ka = Y.transpose() * (ops_.left * Y), kb = Y.transpose() * (ops_.right * Y);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(0.5 * (ka + ka.transpose()),
                                                                  0.5 * (kb + kb.transpose()));
    if (ritz.info() != Eigen::Success) throw ConvergenceError("approximate Killing vector: Rayleigh–Ritz step failed");
    values_ = ritz.eigenvalues();
    X_ = Y * ritz.eigenvectors();  // right-orthonormal columns, ascending λ
  }
  bool converged(const std::vector<double>& previous) const {
    if (previous.empty()) return false;
    const std::vector<double> now = scaled(o_.modes);
    for (int i = 0; i < o_.modes; ++i)
      if (std::abs(now[i] - previous[i]) > o_.tolerance * std::max(1.0, std::abs(now[i]))) return false;
    return true;
  }

  const KillingOperators& ops_;
  const KillingVectorOptions& o_;
  Eigen::SimplicialLDLT<SparseMatrix> solver_;
  Eigen::MatrixXd X_;
  Eigen::VectorXd values_;
  int iterations_ = 0;
};

// z at every vertex (0 at vertex 0), area-mean zero, ∮ z² dA = A³/(48π²) (lumped mass), largest |z| positive.
std::vector<double> normalizedPotential(const IntrinsicTriangulation& tri, const Eigen::VectorXd& x, double area) {
  const int n = tri.mesh.nVertices();
  std::vector<double> vertexA(n, 0.0), z(n, 0.0);
  for (int f = 0; f < tri.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) vertexA[tri.mesh.faceVertex(f, k)] += faceArea(tri, f) / 3;
  for (int v = 1; v < n; ++v) z[v] = x[v - 1];
  double mean = 0, norm = 0;
  for (int v = 0; v < n; ++v) mean += vertexA[v] * z[v] / area;
  for (int v = 0; v < n; ++v) norm += vertexA[v] * (z[v] - mean) * (z[v] - mean);
  const double target = std::pow(area, 3) / (48 * M_PI * M_PI);
  const auto big = std::max_element(z.begin(), z.end(), [&](double a, double b) {
    return std::abs(a - mean) < std::abs(b - mean);
  });
  const double scale = std::sqrt(target / norm) * (*big - mean < 0 ? -1 : 1);
  for (double& value : z) value = (value - mean) * scale;
  return z;
}

// The longest level set of z: a scan over orbitLevels interior levels, then golden-section search in the best bracket.
std::pair<double, double> longestOrbit(const IntrinsicTriangulation& tri, const std::vector<double>& z, int levels) {
  const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
  const double step = (*hi - *lo) / levels;
  int best = 1;
  double bestLength = 0;
  for (int k = 1; k < levels; ++k) {
    const double L = levelSetLength(tri, z, *lo + k * step);
    if (L > bestLength) bestLength = L, best = k;
  }
  double a = *lo + (best - 1) * step, b = *lo + (best + 1) * step;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60 && b - a > 1e-14 * (*hi - *lo); ++it) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    if (levelSetLength(tri, z, c) > levelSetLength(tri, z, d)) b = d; else a = c;
  }
  const double level = 0.5 * (a + b), length = levelSetLength(tri, z, level);
  return length >= bestLength ? std::make_pair(level, length) : std::make_pair(*lo + best * step, bestLength);
}

double spinFromOrbit(double area, double circumference) {
  const double s = 2 * M_PI * area / (circumference * circumference) - 1;  // √(1 − χ²) for Kerr
  if (!(s >= 0 && s <= 1)) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(1 - s * s);
}

void fillAxisAndOrbits(const IntrinsicTriangulation& tri, const KillingVectorOptions& o, KillingVectorResult& r) {
  const auto [lo, hi] = std::minmax_element(r.potential.begin(), r.potential.end());
  r.northVertex = static_cast<int>(hi - r.potential.begin());
  r.southVertex = static_cast<int>(lo - r.potential.begin());
  r.midLevel = 0.5 * (*hi + *lo);
  r.midLevelCircumference = levelSetLength(tri, r.potential, r.midLevel);
  std::tie(r.longestOrbitLevel, r.longestOrbit) = longestOrbit(tri, r.potential, o.orbitLevels);
  r.spin = spinFromOrbit(r.area, r.longestOrbit);
}

}  // namespace

KillingVectorResult approximateKillingVector(const IntrinsicTriangulation& tri, const KillingVectorOptions& options) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError("approximate Killing vector: " + e);
  requireClosedSphere(tri);
  const KillingOperators ops = assembleOperators(tri);
  SubspaceIteration solver(ops, options);
  solver.run();
  KillingVectorResult r;
  r.area = ops.area;
  r.iterations = solver.iterations();
  r.scaledEigenvalues = solver.scaled(options.modes);
  for (int i = 0; i < options.modes; ++i) r.eigenvalues.push_back(solver.values()[i]);
  r.potential = normalizedPotential(tri, solver.vectors().col(0), ops.area);
  const std::vector<double> s = solver.scaled(std::min(2, options.modes + options.extraVectors));
  r.degenerate = s.size() > 1 && !(s[1] - s[0] > options.degeneracyRatio * std::abs(s[0]) + options.degeneracyFloor);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (r.degenerate) {
    r.midLevelCircumference = r.longestOrbit = r.spin = nan;
    return r;
  }
  fillAxisAndOrbits(tri, options, r);
  return r;
}

double levelSetLength(const IntrinsicTriangulation& tri, const std::vector<double>& z, double level) {
  if (static_cast<int>(z.size()) != tri.mesh.nVertices())
    throw InputError("levelSetLength: " + std::to_string(z.size()) + " values for " +
                     std::to_string(tri.mesh.nVertices()) + " vertices");
  double total = 0;
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    double zc[3];
    bool above[3];
    for (int k = 0; k < 3; ++k) zc[k] = z[tri.mesh.faceVertex(f, k)], above[k] = zc[k] >= level;
    if (above[0] == above[1] && above[1] == above[2]) continue;
    const auto p = layoutFace(tri, f);
    Eigen::Vector2d ends[2];
    int found = 0;
    for (int k = 0; k < 3 && found < 2; ++k) {
      const int j = (k + 1) % 3;
      if (above[k] == above[j]) continue;
      const double t = (level - zc[k]) / (zc[j] - zc[k]);
      ends[found++] = p[k] + t * (p[j] - p[k]);
    }
    total += (ends[1] - ends[0]).norm();
  }
  return total;
}

namespace {

// The vertex and its neighbours out to two rings.
std::vector<int> twoRing(const HalfedgeMesh& m, int vertex) {
  std::vector<int> ring{vertex};
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<int> current = ring;
    for (int v : current) {
      const int h0 = m.vertexHalfedge(v);
      int h = h0;
      do {
        if (std::find(ring.begin(), ring.end(), m.tip(h)) == ring.end()) ring.push_back(m.tip(h));
        h = m.nextOutgoing(h);
      } while (h != h0 && h != kInvalid);
    }
  }
  return ring;
}

}  // namespace

Eigen::Vector3d refinedExtremum(const IntrinsicTriangulation& tri, const std::vector<double>& z, int vertex,
                                const std::vector<Eigen::Vector3d>& reference) {
  const int n = tri.mesh.nVertices();
  if (static_cast<int>(z.size()) != n || static_cast<int>(reference.size()) != n || vertex < 0 || vertex >= n)
    throw InputError("refinedExtremum: z, reference and the vertex must match the mesh's " + std::to_string(n) +
                     " vertices");
  const Eigen::Vector3d p = reference[vertex].normalized();
  const Eigen::Vector3d t1 = p.unitOrthogonal(), t2 = p.cross(t1);
  const std::vector<int> ring = twoRing(tri.mesh, vertex);
  if (ring.size() < 6) return p;
  Eigen::MatrixXd A(ring.size(), 6);
  Eigen::VectorXd b(ring.size());
  double radius = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector3d q = reference[ring[i]].normalized();
    const double x = q.dot(t1), y = q.dot(t2);  // orthographic coordinates in p's tangent plane
    radius = std::max(radius, std::hypot(x, y));
    A.row(i) << 1, x, y, 0.5 * x * x, x * y, 0.5 * y * y;
    b[i] = z[ring[i]];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  Eigen::Matrix2d H;
  H << c[3], c[4], c[4], c[5];
  const double det = H.determinant();
  if (!(det > 0)) return p;  // not a strict extremum
  const Eigen::Vector2d x = -H.inverse() * Eigen::Vector2d(c[1], c[2]);
  if (!(x.norm() < 0.5 * radius)) return p;
  return (p + x[0] * t1 + x[1] * t2).normalized();
}

}  // namespace conformesh::intrinsic
