// circle_packing.h — the circle-packing discrete Ricci flow of Jin–Kim–Luo–Gu (TVCG 2008): uniformization of a closed
// surface of genus ≥ 1 by circle packing metrics, tangential (Thurston; Chow–Luo 2003) or with the inversive distances
// of the input (Bowers–Stephenson 2004; Guo 2011 local rigidity, Luo 2011 global rigidity), for comparison with the
// vertex-scaling flow of uniformization.h.
//
// A circle packing metric is a triangulation, a weight I_ij per edge and a radius r_i = e^{u_i} per vertex; the edge
// lengths are ℓ_ij² = r_i² + r_j² + 2 r_i r_j I_ij (Euclidean) or cosh ℓ = cosh r_i cosh r_j + I sinh r_i sinh r_j
// (hyperbolic, with u_i = log tanh(r_i/2) as Chow–Luo). Newton's method on the energy whose Hessian is −∂Θ/∂u finds
// the radii with every angle sum 2π; no flips are done, so a solution need not exist (docs/ricci_flow.md, "Circle
// packing").
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::intrinsic {

// Tangential: I_ij = 1 on every edge (neighbouring circles touch). The input lengths only choose the initial radii,
// which do not influence the solution (Koebe–Andreev–Thurston: unique up to scale), so the result depends on the
// connectivity alone: the metric changes, not only by a conformal factor.
// InversiveDistance: I_ij = (ℓ_ij² − r_i² − r_j²)/(2 r_i r_j) from the input lengths and the initial radii, kept fixed
// (I is Möbius-invariant); the initial packing reproduces the input lengths exactly.
enum class CirclePackingScheme { Tangential, InversiveDistance };
std::string toString(CirclePackingScheme scheme);  // "circle-packing" (tangential), "inversive-distance"

// Initial radius of vertex i: one third of the shortest (default) or of the mean length of the edges at i. A third of
// the shortest keeps every pair of neighbouring circles disjoint (I_ij ≥ 3.5 > 1); a third of the mean can produce
// I_ij < 0 next to short edges, where the energy is not convex: that is an InputError naming the edge.
enum class InitialRadii { ThirdOfShortestEdge, ThirdOfMeanEdge };

struct CirclePackingOptions {
  CirclePackingScheme scheme = CirclePackingScheme::InversiveDistance;
  InitialRadii initialRadii = InitialRadii::ThirdOfShortestEdge;
  // Stop when max_i |2π − Θ_i| ≤ max(tolerance, relativeFloor · sqrt(#vertices)) — the criterion of ricci_flow.h and
  // for the same reason (the condition of the Laplacian-like Hessian grows with the vertex count).
  double tolerance = 1e-10;
  double relativeFloor = 3e-13;
  int maxNewtonSteps = 100;
  // Armijo constant on the merit ½|Θ̂ − Θ|² (the Newton direction has slope −|Θ̂ − Θ|²), and the smallest step length
  // tried before the line search reports that it cannot make progress.
  double armijo = 1e-4;
  double minStep = 1e-12;
  // Newton is declared blocked by the boundary of the admissible region (every radius finite, every triangle existing)
  // after this many consecutive steps whose length had to be cut below 1/16 to stay inside it: measured on CGAL's
  // elk.off, the inversive-distance flow then creeps along the boundary (steps 10⁻⁴..10⁻¹, residual 1.4 → 0.74 rad in
  // 100 steps) instead of converging; every converging run measured needed no such step.
  int maxBlockedSteps = 20;
  // Added to the initial u (log radius, resp. log tanh(r/2)) per vertex; empty = none. The solution does not depend
  // on the start when it is unique (Luo 2011), which is what the tests use this for.
  std::vector<double> startPerturbation;
  // Progress messages, one per Newton step; may be empty.
  std::function<void(const std::string&)> progress;
};

struct CirclePacking {
  // T0* in its background (Euclidean flat torus of area 1, or hyperbolic with curvature −1), same connectivity and
  // vertex/face numbering as the input (no flips). λ_i = log(Σ_{j~i} ℓ⁰_ij / Σ_{j~i} ℓ*_ij) over the edges at i: the
  // original metric ≈ e^{2λ} × the uniform one (an O(h) estimate, not the exact relation of vertex scaling). The
  // correspondence has no flips and log scale 0: T0* → T0 is the face-wise affine (barycentric) map, a piecewise-linear
  // homeomorphism, hence K-quasi-conformal as the paper's Remark 1 needs. report.flips is 0.
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
// when that triangle does not exist. Exposed so that tests can check it against finite differences, its symmetry and,
// in the Euclidean plane, the power-diagram form ∂θ_i/∂u_j = h_ij/ℓ_ij (h_ij the signed distance from the power centre
// of the three circles to side ij).
std::array<std::array<double, 3>, 3> circlePackingAngleJacobian(Background g, const std::array<double, 3>& radii,
                                                                const std::array<double, 3>& I);
// The initial radii of `tri` (its own lengths and background) by `rule`.
std::vector<double> initialCircleRadii(const IntrinsicTriangulation& tri, InitialRadii rule);

// Uniformizes a closed surface of genus ≥ 1 (Euclidean or hyperbolic lengths) by the circle-packing flow: genus 1 to a
// flat torus of area 1, genus ≥ 2 to curvature −1 (a Euclidean input is placed in the hyperbolic class by keeping its
// inversive distances; the flow starts from the Euclidean radii scaled so that the area is about −2πχ). Throws
// InputError for more than one component, a boundary, genus 0, a spherical input, invalid lengths or I_ij < 0;
// ConvergenceError with the residual reached when Newton leaves the region where every triangle exists (naming the
// face), meets an indefinite Hessian (naming the face), stalls, or hits the step cap.
CirclePacking uniformizeByCirclePacking(const IntrinsicTriangulation& input, const CirclePackingOptions& options = {});

}  // namespace conformesh::intrinsic
