// torus_layout.cpp — periods of a developed flat torus and the modular reduction of its modulus. See torus_layout.h
// and docs/layout.md §3.
#include "conformesh/embedding/layout/torus_layout.h"

#include <cmath>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

ModularReduction reduceModulus(Complex tau) {
  if (!std::isfinite(tau.real()) || !std::isfinite(tau.imag()) || !(tau.imag() > 0))
    throw InputError("reduceModulus: expected Im tau > 0, found tau = " + std::to_string(tau.real()) + " + " +
                     std::to_string(tau.imag()) + "i");
  // Track (a b; c d) with τ_current = (a τ₀ + b)/(c τ₀ + d).
  long a = 1, b = 0, c = 0, d = 1;
  // Each −1/τ step with |τ| < 1 increases Im τ by the factor 1/|τ|² > 1, and |Re τ| ≤ ½ after the translation, so the
  // loop ends; 1e-15 keeps a point on the boundary arc |τ| = 1 from flipping back and forth on round-off.
  for (int iter = 0; iter < 1000; ++iter) {
    const long n = std::lround(tau.real());
    tau -= static_cast<double>(n);
    a -= n * c;
    b -= n * d;
    if (std::norm(tau) < 1 - 1e-15) {
      tau = -1.0 / tau;
      const long na = -c, nb = -d, nc = a, nd = b;
      a = na, b = nb, c = nc, d = nd;
    } else {
      break;
    }
  }
  if (c < 0 || (c == 0 && d < 0)) a = -a, b = -b, c = -c, d = -d;
  ModularReduction r;
  r.tau = tau;
  r.matrix = {static_cast<int>(a), static_cast<int>(b), static_cast<int>(c), static_cast<int>(d)};
  return r;
}

TorusLayout layoutTorus(const intrinsic::IntrinsicTriangulation& tri, const FundamentalDomainOptions& options) {
  if (tri.background != intrinsic::Background::Euclidean)
    throw InputError("layoutTorus: expected a Euclidean (flat) triangulation, found background " +
                     intrinsic::toString(tri.background));
  TorusLayout t;
  t.domain = developFundamentalDomain(tri, options);
  if (t.domain.basis.genus != 1)
    throw InputError("layoutTorus: expected genus 1, found genus " + std::to_string(t.domain.basis.genus));
  // A_h = [[α, β], [0, 1]]: z ↦ αz + β; for a flat torus α = 1 and β is the period.
  for (const Mobius& g : t.domain.generators)
    t.maxRotation = std::max(t.maxRotation, std::abs(std::arg(g(0, 0) / g(1, 1))));
  t.omega1 = t.domain.generators[0](0, 1) / t.domain.generators[0](1, 1);
  t.omega2 = t.domain.generators[1](0, 1) / t.domain.generators[1](1, 1);
  if (std::imag(t.omega2 / t.omega1) < 0) std::swap(t.omega1, t.omega2);
  const ModularReduction r = reduceModulus(t.omega2 / t.omega1);
  t.tau = r.tau;
  // (ω₂', ω₁') = (a ω₂ + b ω₁, c ω₂ + d ω₁) gives ω₂'/ω₁' = (aτ + b)/(cτ + d).
  const auto [a, b, c, d] = r.matrix;
  t.reducedOmega2 = double(a) * t.omega2 + double(b) * t.omega1;
  t.reducedOmega1 = double(c) * t.omega2 + double(d) * t.omega1;
  // Rotate the picture so that the reduced ω₁ points along +x: D then sits in the plane as the lattice C/(Z + τZ)
  // scaled by |ω₁| (conjugating every translation by the rotation z ↦ rz rotates its period by r).
  const Complex turn = std::conj(t.reducedOmega1) / std::abs(t.reducedOmega1);
  Mobius rot = Mobius::Identity(), rotInv = Mobius::Identity();
  rot(0, 0) = turn;
  rotInv(0, 0) = std::conj(turn);
  for (auto& face : t.domain.corners)
    for (Complex& z : face) z *= turn;
  for (Mobius& m : t.domain.faceMap) m = rot * m;
  for (Mobius& m : t.domain.crossing) m = rot * m * rotInv;
  for (Mobius& m : t.domain.generators) m = rot * m * rotInv;
  for (Complex* w : {&t.omega1, &t.omega2, &t.reducedOmega1, &t.reducedOmega2}) *w *= turn;
  return t;
}

}  // namespace conformesh::embedding
