// extended_angles.cpp — angle sums in long double (extended_angles.h). The half-angle formula of face_angles.cpp,
// tan(θ_k/2) = sqrt((s−L_{k+1})(s−L_{k+2}) / (s (s−L_k))), with the half-perimeter differences of halfPerimeter
// (sorted sides, Kahan's order of operations) in 64-bit-mantissa arithmetic: on x86-64 long double has ε = 5.4·10⁻²⁰,
// 2¹¹ times finer than double, which is what the sliver faces of docs/ricci_flow.md §2 need.
#include "flow/extended_angles.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace conformesh::intrinsic::detail {

namespace {

// The three corner angles of a face with sides L[k] opposite corner k; (π, 0, 0) when the triangle inequality fails.
void extendedFaceAngles(const long double L[3], long double theta[3]) {
  int idx[3] = {0, 1, 2};
  auto order = [&](int i, int j) {
    if (L[idx[i]] < L[idx[j]]) std::swap(idx[i], idx[j]);
  };
  order(0, 1);
  order(1, 2);
  order(0, 1);
  const long double x = L[idx[0]], y = L[idx[1]], z = L[idx[2]];
  long double d[3];
  d[idx[0]] = 0.5L * (z - (x - y));
  d[idx[1]] = 0.5L * (z + (x - y));
  d[idx[2]] = 0.5L * (x + (y - z));
  const long double s = 0.5L * (x + (y + z));
  if (!(d[0] > 0 && d[1] > 0 && d[2] > 0)) {
    for (int k = 0; k < 3; ++k) theta[k] = k == idx[0] ? static_cast<long double>(M_PI) : 0.0L;
    // π as the double M_PI: the flow's extension uses the same constant, so sums agree where faces are degenerate.
    return;
  }
  for (int k = 0; k < 3; ++k) theta[k] = 2.0L * std::atan(std::sqrt(d[(k + 1) % 3] * d[(k + 2) % 3] / (s * d[k])));
}

}  // namespace

void extendedAngleSums(const DiscreteConformalMetric& metric, const std::vector<long double>& du,
                       std::vector<long double>& sums) {
  const HalfedgeMesh& m = metric.mesh();
  const int nV = metric.nVertices();
  std::vector<long double> half(nV);
  for (int v = 0; v < nV; ++v) half[v] = std::exp(0.5L * (static_cast<long double>(metric.u()[v]) + du[v]));
  sums.assign(nV, 0.0L);
  for (int f = 0; f < m.nFaces(); ++f) {
    if (metric.isFrozen(f)) continue;
    long double L[3], theta[3];
    // Side k is opposite corner k: the edge of halfedge 3f + k + 1 (as faceGeometry of face_angles.cpp).
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + (k + 1) % 3, e = m.edge(h);
      L[k] = static_cast<long double>(metric.referencePenner(e)) * half[m.tail(h)] * half[m.tip(h)];
    }
    extendedFaceAngles(L, theta);
    for (int k = 0; k < 3; ++k) sums[m.faceVertex(f, k)] += theta[k];
  }
}

}  // namespace conformesh::intrinsic::detail
