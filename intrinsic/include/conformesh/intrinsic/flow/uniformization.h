// uniformization.h — uniformize: a triangulated surface (one component) to constant curvature by the discrete Ricci
// (Yamabe) flow of vertex scaling, the paper's §4.1 step T0 → T0*, with the conformal factor λ and the correspondence
// T0* → T0. The target follows the topology (UniformizationTarget):
//   closed genus 0 → the unit sphere (puncture, flat Dirichlet problem, inverse stereographic projection, Möbius
//   centring); closed genus 1 → flat, area 1; closed genus ≥ 2 → curvature −1; genus 0 with boundary → a circle
//   domain (the longest loop the unit circle), an annulus too thin for double precision → the flat cylinder;
//   genus ≥ 1 with boundary → curvature −1 with geodesic boundary loops.
// Reads its input only. Builds on ricci_flow.h (the Newton solver) and planar_layout.h (layoutFlat).
// docs/ricci_flow.md §3 and "Uniformization targets and the genus-0 puncture" derive each target.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/flow/planar_layout.h"
#include "conformesh/intrinsic/flow/ricci_flow.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_components.h"

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
  RicciFlowOptions flow;  // the options of every flow solve (ricci_flow.h)
  // Genus 0: how many puncture vertices to try before giving up (≥ 1; a puncture fails when its spherical image is
  // not an embedded triangulation).
  int maxPunctureAttempts = 8;
  // Genus 0: a link vertex of the puncture whose disk angle sum exceeds π by more than this many times the flow's
  // residual (radians) is released from the link without waiting for the solve to converge; 0: only at solutions.
  double earlyReflexFactor = 10;
  // Möbius centring: stop when the area-weighted centroid of the vertices is within this distance of the origin.
  double centringTolerance = 1e-12;
  // Progress messages (one per Newton step and per stage); may be empty.
  std::function<void(const std::string&)> progress;

  // "" when valid, else "UniformizationOptions::<field>: expected …, found …" (the flow's options not included).
  std::string validate() const;
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
  // Genus 0: the spherical lengths are the Penner form e^{(w_i+w_j)/2} c⁰_ij, not the chords of the points (some chord
  // was below 10⁻⁴; `positions` of tiny regions then coincide in double precision).
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
  // Only for a T0* taken as the half of the double (circle domains, docs/ricci_flow.md §3.3 "The half"; geodesic
  // boundary, §3.4) or flowed on the input with boundary edges split (circle domains of several loops, §3.3 "Boundary
  // edges split"; `insertion` says which): the vertices of T0* that are not vertices of T0, each on an input boundary
  // edge at `parameter` ∈ [0, 1] from tail(edgeHalfedge(inputEdge)), in the input's (reference) lengths. When
  // non-empty, T0* has T0's vertices 0..V−1 plus these, its connectivity is not reached from T0's by flips, and
  // `correspondence` is empty (0 faces: its maps throw InputError) — the flip log cannot carry inserted vertices.
  struct InsertedVertex {
    int vertex = -1, inputEdge = -1;
    double parameter = 0;
  };
  std::vector<InsertedVertex> insertedVertices;
  enum class Insertion { MirrorCrossings, BoundarySplits } insertion = Insertion::MirrorCrossings;
};

// Uniformizes `input` (any background: its Penner lengths are its chords). A disk whose circle-domain flow fails is
// restarted once from its double's sphere (docs/ricci_flow.md §3.3, "The double"); when that restart fails too, its
// circle domain is the half of the double's sphere, with boundary vertices inserted (insertedVertices, "The half of
// the double"); a disk without interior vertices is developed onto its circle directly. A target with geodesic
// boundary (hyperbolic, flat cylinder — also an annulus whose circle-domain flow fails) whose own flow fails is the
// half of its double's closed uniformization, again with boundary vertices inserted (§3.4); a circle domain of three or
// more loops whose flow fails is flowed again with boundary edges split at their midpoints (§3.3). Throws InputError
// for invalid options (options.validate()), more than one connected component (uniformizeComponents below takes those)
// or invalid lengths; ConvergenceError (with the residual reached) when a flow does not converge, when a circle
// domain's layout does not reproduce a loop's circle (three or more loops; an annulus falls back to the flat cylinder),
// or when a flat cylinder's two ends differ in length (docs/ricci_flow.md §3.3).
Uniformization uniformize(const IntrinsicTriangulation& input, const UniformizationOptions& options = {});

// Why `u.correspondence` cannot map T0* back to T0, for callers that need it (the pull-back, a written flip log), or
// "" when it can: "the circle domain (the surface with geodesic boundary) has N boundary vertices inserted where the
// double's flipped edges cross its mirror" (or "… inserted by splitting boundary edges"; u.insertedVertices
// non-empty).
std::string correspondenceUnavailable(const Uniformization& u);
// Where u's inserted vertices come from: "where the double's flipped edges cross its mirror" or "by splitting boundary
// edges".
std::string insertionReason(const Uniformization& u);

// A surface of several connected components, each uniformized to its own target by its own topology (the targets
// above), in splitComponents' order.
struct ComponentUniformization {
  std::vector<MeshComponent> components;  // the input's components, with their maps back to its vertices and faces
  std::vector<Uniformization> parts;      // parts[i]: components[i] uniformized (its own vertex numbering)
  double seconds = 0;                     // the whole call
};

// Splits `input` (splitComponents) and runs `flow` (empty: uniformize with `options`) on each component, its progress
// lines prefixed "component i/N: ". A connected input gives one part, the same as uniformize(input, options). Throws
// what the flow throws (InputError, ConvergenceError), the message prefixed "uniformize: " and describeComponent()
// of the failing component, e.g. "uniformize: component 3 of 26 (40 vertices, 76 faces, genus 0, 0 boundary loops):
// …"; invalid options or lengths are refused before any component runs.
using ComponentFlow = std::function<Uniformization(const IntrinsicTriangulation&, const UniformizationOptions&)>;
ComponentUniformization uniformizeComponents(const IntrinsicTriangulation& input,
                                             const UniformizationOptions& options = {}, const ComponentFlow& flow = {});

// The worst |angle sum − 2π| over the interior vertices of `tri` (radians, in its own background geometry): the
// check a reader of T0* can redo from the written lengths (0 for a surface with no interior vertex).
double maxInteriorAngleSumError(const IntrinsicTriangulation& tri);

// The worst angle-sum error of a surface with geodesic boundary (hyperbolic, flat cylinder): |Θ − 2π| inside, |Θ − π|
// on the boundary (radians, in its own background geometry); the vertex where it is in `worstVertex` if given.
double maxGeodesicBoundaryResidual(const IntrinsicTriangulation& tri, int* worstVertex = nullptr);

// The worst |Θ̂ − Θ| of a Euclidean circle domain recomputed from `tri`'s lengths (radians): Θ̂ = target.angleSum
// off the loops, and π − σ (φ_prev + φ_next) on each of target.circleLoops from the inscribed polygon of its sides
// (inscribedPolygon; docs/ricci_flow.md §3.3), the flow's residual but read from the lengths as written rather than
// from u. The vertex where it is in `worstVertex` if given. Throws ConvergenceError when a loop cannot be inscribed.
double maxCircleDomainResidual(const IntrinsicTriangulation& tri, const ConformalTarget& target,
                               int* worstVertex = nullptr);

}  // namespace conformesh::intrinsic
