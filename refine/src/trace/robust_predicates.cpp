// robust_predicates.cpp — filtered determinant sign with an exact big-integer fallback (see robust_predicates.h).
#include "conformesh/refine/trace/robust_predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/multiprecision/cpp_int.hpp>

namespace conformesh::refine {

namespace {

using BigInt = boost::multiprecision::cpp_int;

// The filter: the cofactor expansion evaluated in doubles has absolute error at most 3u·P + O(u²)·P, P the permanent
// (sum of |products|), u = 2⁻⁵³ (two products per cofactor, one difference, three products with a, two sums). We use
// 8u·P, which covers the second-order terms with a wide margin; below it the sign is decided exactly.
constexpr double kFilterFactor = 8 * std::numeric_limits<double>::epsilon() / 2;

}  // namespace

int orientationSignExact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // Every finite double is m·2^e with an integer m of at most 53 bits. Scaling all nine entries by 2^(−emin) turns them
  // into integers without changing the sign of the determinant; the determinant of integers is then exact.
  const double vals[9] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
  long long mant[9];
  int expo[9];
  int emin = std::numeric_limits<int>::max();
  for (int i = 0; i < 9; ++i) {
    int e = 0;
    const double fr = std::frexp(vals[i], &e);  // vals = fr·2^e, |fr| in [0.5, 1)
    mant[i] = static_cast<long long>(std::ldexp(fr, 53));
    expo[i] = e - 53;
    if (vals[i] != 0) emin = std::min(emin, expo[i]);
  }
  if (emin == std::numeric_limits<int>::max()) return 0;
  BigInt m[9];
  for (int i = 0; i < 9; ++i) {
    m[i] = mant[i];
    if (vals[i] != 0) m[i] <<= (expo[i] - emin);
  }
  // Columns a = m0..2, b = m3..5, c = m6..8.
  const BigInt det =
      m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

int orientationSign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double c0 = b[1] * c[2] - b[2] * c[1], c1 = b[2] * c[0] - b[0] * c[2], c2 = b[0] * c[1] - b[1] * c[0];
  const double det = a[0] * c0 + a[1] * c1 + a[2] * c2;
  const double perm = std::abs(a[0]) * (std::abs(b[1] * c[2]) + std::abs(b[2] * c[1])) +
                      std::abs(a[1]) * (std::abs(b[2] * c[0]) + std::abs(b[0] * c[2])) +
                      std::abs(a[2]) * (std::abs(b[0] * c[1]) + std::abs(b[1] * c[0]));
  const double bound = kFilterFactor * perm;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return orientationSignExact(a, b, c);
}

}  // namespace conformesh::refine
