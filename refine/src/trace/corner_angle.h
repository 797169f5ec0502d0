// corner_angle.h — the corner angle of a halfedge, with a fast path for the Euclidean background (internal header,
// pure inline functions). Euclidean: A = atan2(4·area, b² + c² − a²) with Kahan's ordering of Heron's formula, one
// square root and one arctangent, accurate for needles and caps alike; curved backgrounds use intrinsic::cornerAngle.
#pragma once

#include <algorithm>
#include <cmath>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::refine::detail {

// 4·area of the Euclidean triangle with sides a, b, c (0 if degenerate).
inline double fourAreaEuclidean(double a, double b, double c) {
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  const double p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return p > 0 ? std::sqrt(p) : 0.0;
}

// Angle at tail(h) in face(h), between h and prev(h).
inline double fastCornerAngle(const intrinsic::IntrinsicTriangulation& tri, int h) {
  if (tri.background != intrinsic::Background::Euclidean) return intrinsic::cornerAngle(tri, h);
  const double a = tri.length(intrinsic::HalfedgeMesh::next(h)), b = tri.length(h),
               c = tri.length(intrinsic::HalfedgeMesh::prev(h));
  return std::atan2(fourAreaEuclidean(a, b, c), b * b + c * c - a * a);
}

}  // namespace conformesh::refine::detail
