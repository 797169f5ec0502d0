// geodesic_half.h (private) — the half of a mirror-symmetric closed triangulation: the uniformization with geodesic
// boundary of a surface whose own flow cannot reach its target because a boundary edge would have to flip
// (docs/ricci_flow.md §3.4, "Geodesic boundary through the double"). Combinatorics and lengths only; reads its inputs.
#pragma once

#include <vector>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic::detail {

struct GeodesicHalf {
  IntrinsicTriangulation half;  // vertices 0..nInput−1 the input's, then one per split crossing edge (on the boundary)
  std::vector<int> splitFrom;   // per inserted vertex nInput + i: the input vertex v whose edge to its mirror it halves
  std::vector<int> splitHalfedge;  // per inserted vertex: a halfedge of `doubled` on that edge (v–v', either way)
  double asymmetry = 0;  // max relative |ℓ(w, v) − ℓ(w, v')| over the split faces: the double's round-off
  int splitFaces = 0, trapezoids = 0, splitLoops = 0;  // how many of each pattern were halved
};

// `doubled`: a closed triangulation whose vertices 0..nInput−1 are the input's (those with mirror[v] == v on the
// boundary) and the rest mirror copies of the interior ones, with lengths of a mirror-symmetric metric after any flips
// (the flow's Delaunay triangulation of the doubled surface; `log` its flip log back to the double's T0 `doubleInput`,
// whose faces below `inputFaces` are the input's). The mirror's fixed set is the input's boundary; an edge that crosses
// it joins v to its mirror image v' and is halved there (a new boundary vertex): a face (v, v', w), w on the boundary,
// is split along the median from w, and a quad (a, b, b', a') of two crossing edges (an isosceles trapezoid, whose
// diagonal the flips chose at a tie) along the median from a — lengths by Stewart's theorem in the background geometry.
// A face with vertices of one side only is on the side its centroid maps to. Returns the faces on the input's side.
// Throws ConvergenceError naming the face where the triangulation is not mirror-symmetric (vertices of both sides in
// another pattern, a centroid on the other side) or a face of the half violates the triangle inequality.
GeodesicHalf halveSymmetricDouble(const IntrinsicTriangulation& doubled, const std::vector<int>& mirror, int nInput,
                                  const FlowCorrespondence& log, const HalfedgeMesh& doubleInput, int inputFaces);

// Where on the input's boundary each inserted vertex of `half` lies: the midpoint of its split edge mapped through the
// double's flip log `log` (from `doubled`, the flow's final triangulation, to the double's T0, whose vertices are the
// input's and their mirror copies: `mirror` as above) lands on a boundary edge of `input` — the mirror's fixed set —
// at `parameter` ∈ [0, 1] from tail(edgeHalfedge(inputEdge)). Throws ConvergenceError naming the inserted vertex when
// its image is farther than 10⁻⁶ (barycentric) from every boundary edge: the map is not mirror-symmetric there.
struct BoundaryPoint {
  int inputEdge = -1;
  double parameter = 0;
};
std::vector<BoundaryPoint> locateOnInputBoundary(const IntrinsicTriangulation& input, const std::vector<int>& mirror,
                                                 const HalfedgeMesh& doubleInput, const IntrinsicTriangulation& doubled,
                                                 const FlowCorrespondence& log, const GeodesicHalf& half);

// The worst angle-sum error of a surface with geodesic boundary: |Θ − 2π| inside, |Θ − π| on the boundary (radians,
// in its own background geometry).
double maxGeodesicBoundaryResidual(const IntrinsicTriangulation& tri);

}  // namespace conformesh::intrinsic::detail
