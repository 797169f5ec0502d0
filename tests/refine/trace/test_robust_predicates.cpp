// Tests for robust_predicates.h: the filtered sign agrees with the exact one on nearly degenerate configurations where
// the plain floating-point determinant is wrong, exactly collinear / cocircular-derived inputs give 0, and the sign is
// antisymmetric under swapping two points.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "conformesh/refine/trace/robust_predicates.h"

using conformesh::refine::orientationSign;
using conformesh::refine::orientationSignExact;
using Eigen::Vector3d;

TEST_CASE("exactly collinear homogeneous points have orientation 0, in any order and at any scale") {
  // Points on the line y = x with coordinates exact in binary: every determinant term is exact, the sum is 0.
  for (double s : {1.0, 1e-200, 1e200, 3.0}) {
    const Vector3d a(0.5 * s, 0.5 * s, 1), b(12 * s, 12 * s, 1), c(24 * s, 24 * s, 1);
    CHECK(orientationSign(a, b, c) == 0);
    CHECK(orientationSign(c, a, b) == 0);
  }
  CHECK(orientationSign(Vector3d(0, 0, 1), Vector3d(1, 0, 1), Vector3d(0, 1, 1)) == 1);
  CHECK(orientationSign(Vector3d(0, 0, 1), Vector3d(0, 1, 1), Vector3d(1, 0, 1)) == -1);
}

TEST_CASE("near-degenerate orientations: the filter never disagrees with exact arithmetic, naive doubles do") {
  // Shewchuk's classic: p = (0.5 + i·u, 0.5 + j·u) against the line through (12, 12) and (24, 24), u = 2⁻⁵³. The true
  // sign is sign(j − i) for these exactly representable points; the naive determinant gets many of them wrong.
  const double u = std::ldexp(1.0, -53);
  const Vector3d q(12, 12, 1), r(24, 24, 1);
  int naiveWrong = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const Vector3d p(0.5 + i * u, 0.5 + j * u, 1);
      const int truth = (j > i) - (j < i);
      // Orientation of (p, q, r): q, r on y = x, p above it (j > i) means p is to the left of q→r: positive.
      REQUIRE(orientationSignExact(q, r, p) == truth);
      CHECK(orientationSign(q, r, p) == truth);
      CHECK(orientationSign(p, q, r) == truth);
      // The textbook orient2d in doubles, (q − p) × (r − p).
      const double naive = (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
      if ((naive > 0) - (naive < 0) != truth) ++naiveWrong;
    }
  CHECK(naiveWrong > 0);  // the test exercises configurations where plain doubles fail
}

TEST_CASE("random nearly coplanar unit vectors (spherical orientation): filter equals exact, antisymmetric") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int trial = 0; trial < 20000; ++trial) {
    const Vector3d a = Vector3d(U(rng), U(rng), U(rng)).normalized();
    const Vector3d b = Vector3d(U(rng), U(rng), U(rng)).normalized();
    // c on the great circle through a and b, then nudged off it by a few ulps.
    const double t = U(rng);
    Vector3d c = (a + t * b).normalized();
    c += std::ldexp(U(rng), -52 - trial % 8) * a.cross(b);
    const int s = orientationSignExact(a, b, c);
    CHECK(orientationSign(a, b, c) == s);
    CHECK(orientationSign(b, a, c) == -s);
  }
}
