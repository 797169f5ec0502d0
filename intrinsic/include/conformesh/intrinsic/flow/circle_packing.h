// circle_packing.h — the circle-packing discrete Ricci flow of Jin–Kim–Luo–Gu (TVCG 2008): uniformization of a closed
// surface of genus ≥ 1 by circle packing metrics, tangential or with the input's inversive distances, for comparison
// with the vertex-scaling flow of uniformization.h. Newton on the convex energy with Hessian −∂Θ/∂u; no flips, so a
// solution need not exist.
//
// Reads its input triangulation only; returns a new one. Metric, energy, schemes and guarantees: docs/ricci_flow.md,
// "Circle packing".
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::intrinsic {

// Tangential: I_ij = 1 on every edge (neighbouring circles touch); the result depends on the connectivity alone.
// InversiveDistance: I_ij = (ℓ_ij² − r_i² − r_j²)/(2 r_i r_j) from the input lengths and the initial radii, kept
// fixed; the initial packing reproduces the input lengths exactly.
enum class CirclePackingScheme { Tangential, InversiveDistance };
std::string toString(CirclePackingScheme scheme);  // "circle-packing" (tangential), "inversive-distance"

// Initial radius of vertex i: one third of the shortest (default: keeps neighbouring circles disjoint, I_ij ≥ 3.5) or
// of the mean length of the edges at i (can give I_ij < 0, an InputError naming the edge).
enum class InitialRadii { ThirdOfShortestEdge, ThirdOfMeanEdge };

struct CirclePackingOptions {
  CirclePackingScheme scheme = CirclePackingScheme::InversiveDistance;
  InitialRadii initialRadii = InitialRadii::ThirdOfShortestEdge;
  // Stop when max_i |2π − Θ_i| ≤ max(tolerance, relativeFloor · sqrt(#vertices)) (radians), as RicciFlowOptions.
  double tolerance = 1e-10;
  double relativeFloor = 3e-13;
  int maxNewtonSteps = 100;
  // Armijo constant on the merit ½|Θ̂ − Θ|² (0 < armijo < 0.5), and the smallest step length tried before the line
  // search reports that it cannot make progress (0 < minStep ≤ 1).
  double armijo = 1e-4;
  double minStep = 1e-12;
  // Newton is declared blocked by the boundary of the admissible region (every radius finite, every triangle existing)
  // after this many consecutive steps (≥ 1) cut below 1/16 to stay inside it; converging runs need no such step.
  int maxBlockedSteps = 20;
  // Added to the initial u (log radius, resp. log tanh(r/2)) per vertex; empty = none (tests: the solution does not
  // depend on the start).
  std::vector<double> startPerturbation;
  // Progress messages, one per Newton step; may be empty.
  std::function<void(const std::string&)> progress;

  // What is wrong with these options ("" when valid), as "CirclePackingOptions::<field>: expected …, found …".
  std::string validate() const;
};

struct CirclePacking {
  // T0* in its background (Euclidean flat torus of area 1, or hyperbolic with curvature −1), same connectivity and
  // numbering as the input. λ_i = log(Σ_{j~i} ℓ⁰_ij / Σ_{j~i} ℓ*_ij), an O(h) estimate of the conformal factor. The
  // correspondence has no flips and log scale 0 (the face-wise affine map); report.flips is 0.
  Uniformization result;
  CirclePackingScheme scheme = CirclePackingScheme::InversiveDistance;
  std::vector<double> radii;              // per vertex, final radius in the background geometry (after area scaling)
  std::vector<double> inversiveDistance;  // per edge: I_ij (1 for tangential packings)
  std::vector<double> residualHistory;    // max |2π − Θ| before each Newton step, then at exit
};

// Circle-packing metric edge length in background g (Euclidean or hyperbolic) from the radii of its endpoints and I.
double circlePackingLength(Background g, double ri, double rj, double inversiveDistance);
// The inversive distance of two circles of radii ri, rj whose centres are `length` apart (inverse of the above).
double inversiveDistanceOf(Background g, double ri, double rj, double length);
// ∂θ_k/∂u_n of one triangle of a circle packing metric (the per-face block of −H): radii[k] at corner k, I[k] the
// inversive distance of the side opposite corner k, u as in the flow (log r, resp. log tanh(r/2)). Throws InputError
// when that triangle does not exist or the background is spherical. Exposed for tests (finite differences, symmetry,
// the power-diagram form ∂θ_i/∂u_j = h_ij/ℓ_ij).
std::array<std::array<double, 3>, 3> circlePackingAngleJacobian(Background g, const std::array<double, 3>& radii,
                                                                const std::array<double, 3>& I);
// The initial radii of `tri` (its own lengths and background) by `rule`.
std::vector<double> initialCircleRadii(const IntrinsicTriangulation& tri, InitialRadii rule);

// Uniformizes a closed surface of genus ≥ 1 (Euclidean or hyperbolic lengths) by the circle-packing flow: genus 1 to a
// flat torus of area 1, genus ≥ 2 to curvature −1 (a Euclidean input is placed in the hyperbolic class by keeping its
// inversive distances; the flow starts from the Euclidean radii scaled so that the area is about −2πχ). Throws
// InputError for more than one component, a boundary, genus 0, a spherical input, invalid lengths or I_ij < 0;
// ConvergenceError with the residual reached when Newton leaves the region where every triangle exists (naming the
// face), meets an indefinite Hessian (naming the face), stalls, or hits the step cap. InputError also for invalid
// options (CirclePackingOptions::validate).
CirclePacking uniformizeByCirclePacking(const IntrinsicTriangulation& input, const CirclePackingOptions& options = {});

}  // namespace conformesh::intrinsic
