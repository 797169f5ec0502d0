// face_angles.cpp — per-face angles, cotangents, angle sums and ∂θ/∂u of a vertex-scaling metric (face_angles.h).
#include "flow/face_angles.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include "flow/linalg/two_threads.h"

namespace conformesh::intrinsic::detail {

namespace {

double sineLike(Background bg, double x) {
  return bg == Background::Euclidean ? x : (bg == Background::Hyperbolic ? std::sinh(x) : std::sin(x));
}

}  // namespace

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

}  // namespace conformesh::intrinsic::detail
