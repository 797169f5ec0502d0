// conformal_energy.h — the convex energy of Euclidean vertex scaling whose gradient is the angle residual Θ̂ − Θ and
// whose Hessian is the cotangent Laplacian −∂Θ/∂u (Springborn–Schröder–Pinkall 2008; Bobenko–Pinkall–Springborn 2015,
// eq. 4.1, extended to all of u-space by the angles (π, 0, 0) of faces violating the triangle inequality and, with
// Ptolemy flips keeping the triangulation Delaunay, by Gu–Luo–Sun–Wu 2018), and Milnor's Lobachevsky function.
// The Newton flow (ricci_flow.h) backtracks on this energy. Reads its arguments only. Derivation: docs/ricci_flow.md
// §2 "The energy and the line search".
#pragma once

#include <vector>

#include "conformesh/intrinsic/flow/discrete_conformal.h"

namespace conformesh::intrinsic {

// Milnor's Lobachevsky function Л(x) = −∫₀ˣ log|2 sin t| dt = ½ Cl₂(2x) (π-periodic, odd), by the Bernoulli series of
// the Clausen function on |2x| ≤ π, to a few units of round-off.
double lobachevsky(double x);

// E(u) = Σ_v Θ̂_v u_v + Σ_f [Σ_k (α_k λ_k + 2 Л(α_k)) − (π/2) Σ_k λ_k], λ_k = 2 log ℓ_k, over the non-frozen faces of
// the metric's current triangulation (which should be Delaunay: then E is C¹ and convex in u, with ∂E/∂u_v = Θ̂_v −
// Θ_v). Vertices whose target is not finite are left out of the first sum (they only add constants where u is held).
// `magnitude`, when given, receives Σ of the absolute values of the terms, the scale of E's round-off.
// Throws InputError for a non-Euclidean background or a target of the wrong size.
double conformalEnergy(const DiscreteConformalMetric& metric, const std::vector<double>& targetAngleSum,
                       double* magnitude = nullptr);

}  // namespace conformesh::intrinsic
