// delaunay_refinement.h — Delaunay refinement of an intrinsic triangulation of constant curvature (paper §4.2.2),
// graded by the conformal factor (§4.2.3), with Ruppert's (or Chew's) boundary rules: refineDelaunay and its options,
// statistics and result. Bad triangles (circumradius r > ε·e^(−λ(c)) or r / shortest edge > B) are split at their
// circumcentre, located by geodesic tracing (geodesic_trace.h) and kept on the input by signposts (signposts.h,
// input_location.h); Lawson flips restore the Delaunay property. Encroached boundary edges are split on their circle
// (cocircular loops) or at their geodesic midpoint. The algorithm, the boundary rules and what is guaranteed are in
// docs/refinement.md §1, §5, §6. Reads the input triangulation; returns a new one.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/delaunay/vertex_smoothing.h"
#include "conformesh/refine/trace/input_location.h"

namespace conformesh::refine {

enum class BoundarySplit {
  Auto,      // on the circle for a cocircular loop in the Euclidean background, at the geodesic midpoint otherwise
  Circle,    // always on the circle; a loop that is not cocircular (or a curved background) is an InputError, except a
             // loop that turns nowhere (a closed geodesic: an end of a flat cylinder), split at geodesic midpoints
  Geodesic,  // always at the geodesic midpoint (a polygonal domain)
};

// What happens at boundary segments (docs/refinement.md §5–6).
enum class SegmentRule {
  // Ruppert 1995: an encroached segment is split before any triangle; a circumcentre outside the domain or inside a
  // diametral circle is rejected and that segment split. Conforming Delaunay output; terminates for B ≥ √2.
  Ruppert,
  // Chew's second algorithm (Chew 1993, Shewchuk 2002): constrained Delaunay; a circumcentre is rejected only when the
  // geodesic to it crosses a segment s, and then the free vertices inside s's diametral disk are deleted before s is
  // split (vertex_removal.h). Terminates for B ≥ √5/2 on convex planar domains.
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
  // Shape bound B ≥ 1 = circumradius / shortest edge (smallest angle ≥ arcsin(1/(2B))). Default √2, Ruppert's bound;
  // which B terminate where: docs/refinement.md §6.
  double ratioBound = 1.4142135623730951;
  // Conformal factor λ per INPUT vertex, interpolated at circumcentres; empty means λ ≡ 0 (uniform refinement).
  std::vector<double> lambda;
  BoundarySplit boundarySplit = BoundarySplit::Auto;
  SegmentRule segmentRule = SegmentRule::Ruppert;
  // Euclidean background only: split a bad-SHAPED triangle at Üngör's off-centre instead of its circumcentre when
  // that is nearer (docs/refinement.md §6). Same bounds.
  bool offCenters = false;
  // Split a triangle that is bad by SIZE only at Rebay's frontal point instead of its circumcentre, and serve the
  // faces next to good ones first (docs/refinement.md §6). Same bounds; all backgrounds.
  bool frontal = false;
  // Smoothing passes after refinement (vertex_smoothing.h); after each, Lawson flips and the refinement loop re-run,
  // so the output meets the bounds as without smoothing. 0 = the paper's algorithm.
  int smoothingPasses = 0;
  SmoothingRule smoothingRule = SmoothingRule::OptimalDelaunay;
  // A loop counts as cocircular when every vertex of its layout lies within this distance (relative to the radius) of
  // the fitted circle (docs/refinement.md §5).
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

  // What is wrong with these options ("" when they are valid), with the expected and the found value: ε finite and
  // positive, 1 ≤ B < ∞, λ finite, maxInsertions > 0, smoothingPasses ≥ 0. (λ's count is checked against the input
  // by refineDelaunay.)
  std::string validate() const;
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

// Refines `input`. Throws InputError on bad input lengths, on options that fail RefineOptions::validate (its text), on
// a λ count other than the input's vertex count, and on a boundary loop that BoundarySplit::Circle cannot split on a
// circle; ConvergenceError when a cap is hit, with the cap, the face and the numbers involved in the message.
RefineResult refineDelaunay(const intrinsic::IntrinsicTriangulation& input, const RefineOptions& options);

}  // namespace conformesh::refine
