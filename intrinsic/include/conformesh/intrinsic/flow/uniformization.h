// uniformization.h — uniformizing a triangulated surface to constant curvature by the discrete Ricci (Yamabe) flow of
// vertex scaling: the paper's §4.1 step T0 → T0*, with the conformal factor λ and the correspondence T0* → T0.
//
// Targets by topology (one connected component):
//   closed genus 0  → the unit sphere: puncture a vertex ∞, flatten the rest with Dirichlet data u_a = −2 log ℓ_a∞ on
//                     its link (the limit of vertex scaling with ∞ sent to infinity), lay out, inverse stereographic
//                     projection, Möbius centring; spherical lengths from the chords of the points, or (when a
//                     chord is below 10⁻⁴, e.g. thin appendages) from the exact Penner form e^{(w_i+w_j)/2} c⁰_ij;
//   closed genus 1  → flat, total area 1;
//   closed genus ≥ 2 → hyperbolic, curvature −1;
//   genus 0 with b ≥ 1 boundary loops → flat, every loop a circle (a disk to the unit disk, b ≥ 2 to a circle domain,
//                     the longest loop the outer unit circle): the boundary targets are the turning angles of the
//                     polygon inscribed in a circle with the current boundary lengths, solved together with the
//                     interior by Newton on the coupled system (ricci_flow.h, CircleLoop) rather than by iterating;
//                     An annulus whose inner circle would be below e^{−17.6} of the outer one (log(R/r) beyond what
//                     planar double coordinates resolve to 10⁻⁸) → the flat cylinder instead: both loops closed
//                     geodesics of circumference 2π, height Λ = log(R/r) (the circle domain is its image by e^{iz});
//   genus ≥ 1 with boundary → hyperbolic with geodesic boundary loops (zero geodesic curvature).
// docs/ricci_flow.md derives each step and states what is guaranteed.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/flow/ricci_flow.h"

namespace conformesh::intrinsic {

// FlatKeepBoundary: a disk flattened with its boundary lengths kept (boundary_flattening.h), not reached by uniformize.
enum class UniformizationTarget {
  Sphere,
  FlatTorus,
  Hyperbolic,
  CircleDomain,
  FlatCylinder,
  HyperbolicGeodesicBoundary,
  FlatKeepBoundary
};
std::string toString(UniformizationTarget target);

struct UniformizationOptions {
  RicciFlowOptions flow;
  // Genus 0: how many puncture vertices to try before giving up (a puncture fails when the flattened link polygon is
  // not convex, so the stereographic image would not be embedded).
  int maxPunctureAttempts = 8;
  // Genus 0: a vertex of the puncture's link whose disk angle sum exceeds π by more than this many times the flow's
  // residual is released from the link without waiting for the solve to converge (0: reflex vertices are judged at
  // solutions only). 10: once Newton converges quadratically the sums move by about the residual per step, so such a
  // vertex is reflex at the solution too; each vertex is judged early at most once (docs/ricci_flow.md, "Map back").
  double earlyReflexFactor = 10;
  // Möbius centring: stop when the area-weighted centroid of the vertices is within this distance of the origin.
  double centringTolerance = 1e-12;
  // Progress messages (one per Newton step and per stage); may be empty.
  std::function<void(const std::string&)> progress;
};

struct UniformizationReport {
  UniformizationTarget target = UniformizationTarget::FlatTorus;
  int genus = 0, boundaryLoops = 0;
  int newtonSteps = 0;
  std::int64_t flips = 0;
  int factorizations = 0, cgIterations = 0;  // Newton linear algebra, summed over the flow solves (ricci_flow.h)
  double maxResidual = 0;                    // of the last flow solve (radians)
  double effectiveTolerance = 0;
  int punctureVertex = -1;  // genus 0 only
  int punctureAttempts = 0;
  int centringIterations = 0;
  // FlatCylinder only: the height of the cylinder of circumference 2π, i.e. log(R/r) = 2π × the annulus's modulus.
  double cylinderHeight = 0;
  // Genus 0: the spherical lengths were taken from the Penner form e^{(w_i+w_j)/2} c⁰_ij instead of the chords of the
  // points, because some chord was below 10⁻⁴ (thin appendages; then `positions` of tiny regions coincide in double).
  bool pennerLengths = false;
  double seconds = 0;
};

struct Uniformization {
  IntrinsicTriangulation uniform;  // T0*: connectivity after flips, lengths in its background geometry
  // Per vertex: the original metric is ≈ e^{2λ} × the uniform metric (λ = −w with w the total vertex scaling,
  // exact in Penner coordinates: c*_ij = e^{(w_i+w_j)/2} c_ij, so a constant w scales lengths by e^{w}).
  std::vector<double> lambda;
  // Points of T0* in a model space when it has one: the unit sphere (genus 0) or the plane z = 0 (circle domains).
  // Empty for flat tori and hyperbolic surfaces.
  std::vector<Eigen::Vector3d> positions;
  FlowCorrespondence correspondence;
  UniformizationReport report;
};

// Uniformizes `input` (any background: its Penner lengths are its chords). Throws InputError for more than one
// connected component or invalid lengths; ConvergenceError (with the residual reached) when a flow does not converge,
// when a circle domain's layout does not reproduce a loop's circle (three or more loops; an annulus falls back to the
// flat cylinder), or when a flat cylinder's two ends differ in length (docs/ricci_flow.md §3.3).
Uniformization uniformize(const IntrinsicTriangulation& input, const UniformizationOptions& options = {});

// Lays out a flat (Euclidean) triangulation of a topological disk or a planar domain in the plane by breadth-first
// unfolding from face 0, placing each new vertex from its face's first placed edge by the angle there; edge directions
// are carried along by rotation, not recomputed from coordinates (round-off would grow across short edges). Throws
// InputError when the surface is not Euclidean, and ConvergenceError when a vertex reached twice lands more than
// `mismatch` (relative to the mean edge length) away from itself — i.e. the metric is not flat or has holonomy.
std::vector<Eigen::Vector2d> layoutFlat(const IntrinsicTriangulation& tri, double mismatch = 1e-6,
                                        const std::vector<char>& skipFaces = {});

}  // namespace conformesh::intrinsic
