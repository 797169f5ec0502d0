// delaunay_refinement.h — Delaunay refinement of an intrinsic triangulation of constant curvature (paper §4.2.2),
// graded by the conformal factor (§4.2.3), with Ruppert's boundary rules on boundary circles.
//
// The triangulation is refined where it lies, intrinsically: a bad triangle's circumcentre is found by tracing the
// geodesic from one of its vertices across triangles (geodesic_trace.h), inserted there, and the Delaunay property of
// the background geometry is restored by Lawson's intrinsic flips. A triangle with circumcentre c and circumradius r is
//   bad-sized  when r > ε·e^(−λ(c))   (λ the conformal factor, interpolated on the input at c; λ ≡ 0: uniform),
//   bad-shaped when r / (shortest edge) > B.
// Every inserted vertex records its place on the input (input_location.h), kept through later flips by signposts.
//
// Boundaries (Euclidean background): each boundary loop of a uniformized disk / circle domain is inscribed in a circle
// whose centre and radius are computed from the loop's own edge lengths and turning angles (a loop counts as a circle
// when its vertices lie on one to `circleTolerance`, it has at least 6 of them and it turns by at most 60° at each). An
// encroached boundary edge (its apex angle exceeds 90°, i.e. a vertex lies inside its diametral circle) is split at the
// midpoint of its ARC — on the circle, not on the chord — and a circumcentre that lies outside the domain or encroaches
// a boundary edge is not inserted; the edge is split instead (Ruppert 1995). For loops that are not cocircular, and in
// curved backgrounds, boundary edges are split at their geodesic midpoint. At boundary corners below 60° segments are
// split on concentric shells and the shape test is waived for the corner's triangles (their size is still enforced),
// so that refinement does not cascade into the corner. With SegmentRule::Chew the boundary rules are Chew's second
// algorithm instead (constrained Delaunay; free vertices deleted from a split segment's diametral disk,
// vertex_removal.h). docs/refinement.md states what is guaranteed.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/trace/input_location.h"
#include "conformesh/refine/delaunay/vertex_smoothing.h"

namespace conformesh::refine {

enum class BoundarySplit {
  Auto,      // on the circle for a cocircular loop in the Euclidean background, at the geodesic midpoint otherwise
  Circle,    // always on the circle; a loop that is not cocircular (or a curved background) is an InputError, except a
             // loop that turns nowhere (a closed geodesic: an end of a flat cylinder), split at geodesic midpoints
  Geodesic,  // always at the geodesic midpoint (a polygonal domain)
};

// What happens at boundary segments (docs/refinement.md §5–6).
enum class SegmentRule {
  // Ruppert 1995: a segment with a vertex inside its diametral circle (encroached) is split before any triangle; a
  // circumcentre outside the domain or inside a diametral circle is rejected and that segment split. The output is
  // conforming Delaunay. Termination proved for B ≥ √2 (corners ≥ 60°, planar).
  Ruppert,
  // Chew's second algorithm (Chew 1993; analysed by Shewchuk 2002): the triangulation is constrained Delaunay (boundary
  // edges are never flipped; a vertex may lie inside a segment's diametral circle); a circumcentre is rejected only
  // when
  // it is not visible — the geodesic to it crosses a segment s — and then every free vertex (inserted, interior) inside
  // the diametral disk of s and reachable from s without crossing the boundary is deleted before s is split. Shewchuk
  // proves termination for B ≥ √5/2 ≈ 1.118 (26.57°) in the plane.
  Chew,
};

// "ruppert" / "chew"; InputError naming the accepted values otherwise.
SegmentRule parseSegmentRule(const std::string& name);

struct RefineProgress {
  std::int64_t insertions = 0;
  int vertices = 0;
  std::size_t queuedTriangles = 0;
};

struct RefineOptions {
  // Size bound ε > 0: circumradii end at most ε·e^(−λ) in the background metric.
  double epsilon = 0;
  // Shape bound B = circumradius / shortest edge. √2 is Ruppert's bound (smallest angle ≥ arcsin(1/(2√2)) ≈ 20.7°),
  // guaranteed to terminate with boundaries whose corners are ≥ 60°; with SegmentRule::Chew, B ≥ √5/2 (Shewchuk, convex
  // planar domains); on closed surfaces every B ≥ 1 terminates (smallest angle ≥ 30° at B = 1). Values below 1 are
  // rejected.
  double ratioBound = 1.4142135623730951;
  // Conformal factor λ per INPUT vertex, interpolated at circumcentres; empty means λ ≡ 0 (uniform refinement).
  std::vector<double> lambda;
  BoundarySplit boundarySplit = BoundarySplit::Auto;
  SegmentRule segmentRule = SegmentRule::Ruppert;
  // Euclidean background: split a bad-SHAPED triangle at Üngör's off-centre (the point on the bisector of its shortest
  // edge that makes a triangle of ratio exactly B with it) instead of its circumcentre when that is nearer. Same
  // bounds, usually fewer vertices when shape drives the refinement (grading); off by default, as the paper inserts
  // circumcentres. Ignored in curved backgrounds.
  bool offCenters = false;
  // Split a triangle that is bad by SIZE only (not by shape) at Rebay's frontal point instead of its circumcentre: on
  // the bisector of its longest edge shared with a triangle that already meets its size target, at the apex of the
  // isosceles triangle of circumradius ε·e^(−λ) on that edge (never beyond the circumcentre). Meshes grow from good
  // regions in near-equilateral triangles of the target size: higher mean smallest angle, fewer vertices for the same
  // ε. Same bounds (they are the stopping criterion) and the same termination argument (the point lies inside the
  // bad triangle's empty circumdisk, at least the target size away from every vertex). All backgrounds.
  bool frontal = false;
  // Smoothing passes after refinement (vertex_smoothing.h). Each pass moves every inserted interior vertex within its
  // star to the point, searched from the star's optimal-Delaunay point (`smoothingRule`: or its centroid average),
  // that most raises its triangles' smallest angles, never lowering the star's smallest angle nor breaking the bounds;
  // re-traces its input location; then restores Delaunay by flips and re-runs the refinement loop, so the output
  // meets the bounds as without smoothing (they remain the stopping criterion). Raises the mean smallest angle
  // (docs/refinement.md §6); 0 = the paper's algorithm, unsmoothed.
  int smoothingPasses = 0;
  SmoothingRule smoothingRule = SmoothingRule::OptimalDelaunay;
  // A loop counts as cocircular when every vertex of its layout lies within this distance (relative to the radius) of
  // the fitted circle. 1e-8 is above the round-off of laying out a loop of 10⁶ edges by lengths and turning
  // angles (headings accumulate ~10⁶ · 1e-16 rad, i.e. ~1e-10) and far below any visible departure from a circle.
  double circleTolerance = 1e-8;
  // Caps that stop a run on impossible parameters with a ConvergenceError instead of running away: insertions, and the
  // smallest circumradius a bad triangle may have (0 = 10⁻⁶ · min(ε·e^(−max λ), shortest input edge)).
  std::int64_t maxInsertions = 50'000'000;
  double minCircumradius = 0;
  // Passed to the Delaunay test (delaunayMargin); see intrinsic_flips.h.
  double delaunayTolerance = 1e-12;
  // Called every `progressEvery` insertions and at least every 2 s of refinement (may be empty).
  std::function<void(const RefineProgress&)> progress;
  std::int64_t progressEvery = 100000;
};

struct RefineStatistics {
  int inputVertices = 0;
  std::int64_t circumcenterInsertions = 0;
  std::int64_t centroidInsertions = 0;  // hyperbolic triangles without a circumcircle
  std::int64_t offCenterInsertions = 0;
  std::int64_t frontalInsertions = 0;
  std::int64_t boundarySplits = 0;
  std::int64_t rejectedCircumcenters = 0;  // outside the domain or encroaching: a boundary edge was split instead
  // SegmentRule::Chew: free vertices deleted from diametral disks, and deletions refused (no admissible flip brought
  // the vertex to degree 3; it stays, vertex_removal.h).
  std::int64_t deletedVertices = 0;
  std::int64_t refusedDeletions = 0;
  std::int64_t flips = 0;
  std::int64_t traceSteps = 0;
  int boundaryLoops = 0;
  int circleLoops = 0;  // loops split on their circle
  // Smoothing (RefineOptions::smoothingPasses), summed over the passes: vertex moves made and refused, and the
  // insertions of the refinement loops re-run after the passes (included in the insertion counts above).
  std::int64_t smoothingMoves = 0;
  std::int64_t smoothingRefused = 0;
  std::int64_t insertionsAfterSmoothing = 0;
};

struct RefineResult {
  intrinsic::IntrinsicTriangulation triangulation;  // same background as the input; vertices 0..n−1 are the input's
  std::vector<InputLocation> locations;             // per vertex: where it lies on the input
  std::vector<double> lambda;                       // per vertex: λ interpolated at its location
  Signposts signposts;                              // per halfedge direction, in the frames of signposts.h
  RefineStatistics statistics;
};

// Refines `input` (validated first; InputError naming the element on bad lengths, bad λ, ε ≤ 0 or B < 1). Throws
// ConvergenceError when a cap is hit, with the cap, the face and the numbers involved in the message.
RefineResult refineDelaunay(const intrinsic::IntrinsicTriangulation& input, const RefineOptions& options);

}  // namespace conformesh::refine
