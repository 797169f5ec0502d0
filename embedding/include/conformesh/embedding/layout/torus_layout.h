// torus_layout.h — a flat torus (intrinsic::uniformize's T0* of genus 1, or any flat genus-1 triangulation) laid out in
// its fundamental domain in the plane, with its periods ω₁, ω₂ (the translations of the deck transformations of the
// two tree–cotree generators) and its conformal modulus τ = ω₂/ω₁ reduced into the standard fundamental domain
// F = {|Re τ| ≤ ½, |τ| ≥ 1, Im τ > 0} of the modular group PSL(2, Z). docs/layout.md §3.
#pragma once

#include <complex>

#include "conformesh/embedding/layout/fundamental_domain.h"

namespace conformesh::embedding {

struct ModularReduction {
  Complex tau;                  // in F
  std::array<int, 4> matrix{};  // (a, b, c, d) ∈ SL(2, Z) with τ_reduced = (aτ + b)/(cτ + d)
};

// Reduces τ (Im τ > 0) into F by τ → τ − round(Re τ) and τ → −1/τ (Gauss' algorithm for binary quadratic forms);
// throws InputError when Im τ ≤ 0 or τ is not finite.
ModularReduction reduceModulus(Complex tau);

struct TorusLayout {
  // The developed disk D, rotated so that reducedOmega1 is real and positive; deck transformations = translations.
  FundamentalDomain domain;
  Complex omega1, omega2;                // the periods of the generators, ordered so that Im(ω₂/ω₁) > 0
  Complex reducedOmega1, reducedOmega2;  // a basis of the same lattice with τ = reducedOmega2/reducedOmega1 ∈ F
  Complex tau;                           // reduced modulus
  double maxRotation =
      0;  // max |arg α| over the generators' linear parts (0 for a flat metric: holonomy is a translation)
};

// Throws InputError for a surface that is not a closed Euclidean genus-1 triangulation.
TorusLayout layoutTorus(const intrinsic::IntrinsicTriangulation& tri, const FundamentalDomainOptions& options = {});

}  // namespace conformesh::embedding
