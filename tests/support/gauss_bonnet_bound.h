// gauss_bonnet_bound.h — the round-off bound the tests hold Gauss–Bonnet residuals to, from the face count.
//
// curvatureTotals (intrinsic/mesh/curvature.cpp) adds 2π − Σθ (π − Σθ on the boundary) over the vertices and
// subtracts 2πχ. For any edge lengths the exact value is 0 (each Euclidean face's angles sum to π; on the spherical
// and hyperbolic backgrounds the area term ±Σ area closes it), so the residual is round-off alone:
//   * each of the 3F corner angles θ = 2 atan(√(num/den)) (triangle_geometry.cpp) carries an absolute error of at most
//     c_θ·u, u = 2⁻⁵³: the half-perimeter differences s − a are one rounding each (relative ≤ u·s/(s − a) ≤ 32u for
//     the ≥ 20° meshes the refinement writes, where (s − a)/s = tan(B/2) tan(C/2) ≥ tan²(10°) = 0.031), the two
//     products and the quotient three more, the square root halves the sum, and 2 atan(t) turns a relative error δ of
//     t into an absolute one ≤ δ: c_θ ≤ ½(4·32 + 3) + 2 ≈ 68 in the worst corner, a handful in a typical one;
//   * the vertex sums add the 3F angles into partial sums ≤ 2π (one rounding ≤ 2πu each), the V ≤ F/2 + 2 deficits
//     subtract once more (≤ 2πu each), and the compensated (Neumaier) totals add O(u·Σ|k_v|), negligible;
//   * the background term K·A on curved backgrounds: l'Huilier areas to a few u relative, |A| ≤ 4π|χ| + …, negligible.
// Summed, |residual| ≤ 3F·c_θ·u + 3F·2πu + F·πu + O(u) ≤ (3 c_θ + 7π) F u. The bound below takes c_θ = 68 (the worst
// corner everywhere): kGaussBonnetFaceFactor·F·π·u with kGaussBonnetFaceFactor = (3·68 + 7π)/π ≈ 72, rounded up to 80.
// Measured residuals stay 2–4 orders below it (errors of both signs cancel), so a systematic error of 1e-13 per angle
// (≈ 450u) already exceeds it on a few thousand faces, where the former fixed 1e-9 (1e-8) let it pass.
#pragma once

#include <cmath>
#include <limits>

namespace conformesh::testing {

constexpr double kGaussBonnetFaceFactor = 80;

// The largest Gauss–Bonnet residual round-off can produce on a triangulation of `faces` faces (derivation above).
inline double gaussBonnetRoundoff(long long faces) {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  return kGaussBonnetFaceFactor * static_cast<double>(faces + 4) * M_PI * u;
}

}  // namespace conformesh::testing
