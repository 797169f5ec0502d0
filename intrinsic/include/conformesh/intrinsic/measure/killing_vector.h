// killing_vector.h — the approximate Killing vector of a closed genus-0 surface known only by its edge lengths (an
// intrinsic triangulation), after Cook & Whiting, Phys. Rev. D 76, 041501(R) (2007), arXiv:0706.0199: write the
// vector as ξ^a = ε^{ab} ∇_b z (divergence-free on S²) and minimize the Killing defect ½∮ |∇_a ξ_b + ∇_b ξ_a|² dA at
// fixed ∮ |ξ|² dA. By Bochner's identity the defect is ∮ (Δz)² − R |∇z|² dA (R = 2K the scalar curvature), and the
// minimizers solve the generalized eigenproblem
//     Δ²z + ∇_a(R ∇^a z) = −λ Δz,   λ = defect / ∮|ξ|² ≥ 0,
// which SpECTRE and SpEC write with the opposite sign of λ. λ = 0 exactly when ξ is a Killing vector (Kerr's
// horizon); the round sphere has three (λ₁ = λ₂ = λ₃ = 0, λ₄ = 4/r²). Derivation and discretization:
// docs/horizons.md §4d.
//
// Discretization (P1 finite elements on the triangulation's flat triangles): stiffness S (cotan weights), lumped
// mass M (a third of each incident face's area), curvature from angle defects (R_f = 2 Σ_{v∈f} defect_v / (3 A_v),
// which keeps Σ_f R_f A_f = 4πχ exactly), so  (S M⁻¹ S − S_R) z = λ S z  with S_R the R-weighted stiffness.
// Constants (the kernel of both sides) are removed by fixing z at vertex 0; the smallest eigenpairs come from
// subspace iteration with a sparse LDLᵀ factorization of the shifted operator and Rayleigh–Ritz on each iterate.
//
// Outputs: eigenvalues, the potential z per vertex (mean zero, Kerr normalization ∮ z² dA = A³/(48π²) as in
// SpECTRE's StrahlkorperGr), the axis as the extremal vertices of z (optionally refined on the chart's reference
// sphere), and the orbits: the level set of z through its mid value and the longest level set, both measured
// intrinsically (each segment inside a flat triangle), with the Kerr spin they imply, χ = √(1 − (2πA/C² − 1)²)
// (Kerr: C_eq = 4πM, A = 8πMr₊).
//
// Throws InputError for a triangulation that is not one closed genus-0 surface or for invalid options,
// ConvergenceError when the subspace iteration does not reach its tolerance in maxIterations.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

struct KillingVectorOptions {
  int modes = 3;             // eigenpairs reported (≥ 3 so that the round sphere's triple is visible)
  int extraVectors = 3;      // additional subspace-iteration vectors (the iteration converges as λ_modes/λ_{modes+extra})
  int maxIterations = 200;   // subspace-iteration steps
  // On the change of the dimensionless eigenvalues λ·A/4π between steps. The operator S M⁻¹ S scales like h⁻⁴, so
  // Rayleigh–Ritz values jitter by ~1e-16·(A/h²)² (1e-10 at 6000 vertices); discretization errors are ≥ 1e-5.
  double tolerance = 1e-9;
  // The axis is reported only when the first eigenvalue is isolated: λ̂₂ − λ̂₁ > degeneracyRatio·|λ̂₁| + degeneracyFloor
  // (λ̂ = λ·A/4π: 0, 0, 0, 4 on a round sphere). For a surface with a Killing vector |λ̂₁| is pure discretization
  // error (O(h²)), and the splitting of a round sphere's triple on an irregular mesh measured 0.013–0.1 of it
  // (docs/horizons.md §4d); below the bar the surface has (nearly) more than one rotational symmetry at this resolution
  // and no axis is chosen.
  double degeneracyRatio = 0.2;
  double degeneracyFloor = 1e-6;
  int orbitLevels = 64;  // levels scanned for the longest orbit before golden-section refinement
  std::string validate() const;  // "" when valid: modes ≥ 1, extraVectors ≥ 1, maxIterations ≥ 1, tolerance > 0, ...
};

struct KillingVectorResult {
  std::vector<double> eigenvalues;        // λ₁ ≤ λ₂ ≤ ..., `modes` of them (units 1/length²)
  std::vector<double> scaledEigenvalues;  // λ_k · A / 4π (dimensionless; 0, 0, 0, 4, ... for a round sphere)
  std::vector<double> potential;          // z per vertex for λ₁: area-mean zero, ∮ z² dA = A³/(48π²), max |z| > 0
  bool degenerate = false;                // λ₁ not isolated (see options): no axis, no orbits
  int iterations = 0;
  double area = 0;                        // Σ face areas
  int northVertex = -1, southVertex = -1; // argmax z, argmin z (−1 when degenerate)
  double midLevel = 0;                    // (z_max + z_min) / 2
  double midLevelCircumference = 0;       // length of the level set z = midLevel (NaN when degenerate)
  double longestOrbitLevel = 0;           // the level whose orbit is longest
  double longestOrbit = 0;                // its length: the equatorial circumference (NaN when degenerate)
  double spin = 0;  // χ = √(1 − (2πA/C² − 1)²) with C = longestOrbit; NaN when 2πA/C² ∉ [1, 2] or degenerate
};

KillingVectorResult approximateKillingVector(const IntrinsicTriangulation& tri, const KillingVectorOptions& options = {});

// Length of the level set {z = level} of the piecewise-linear z (one value per vertex), summed over the flat
// triangles it crosses. Throws InputError when z has the wrong size.
double levelSetLength(const IntrinsicTriangulation& tri, const std::vector<double>& z, double level);

// A pole refined below the mesh spacing: z is fitted by a quadratic in the tangent plane of the reference sphere over
// the vertex's 2-ring (`reference`: per vertex, a point of the unit sphere, e.g. RemeshResult::reference) and its
// stationary point is returned (normalized to the unit sphere); the vertex's own point when the fit is not a strict
// extremum inside the ring. Throws InputError when the sizes disagree.
Eigen::Vector3d refinedExtremum(const IntrinsicTriangulation& tri, const std::vector<double>& z, int vertex,
                                const std::vector<Eigen::Vector3d>& reference);

}  // namespace conformesh::intrinsic
