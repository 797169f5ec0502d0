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
// diagonal the flips chose at a tie; one crossing side may be a loop at a boundary vertex b = b' that the mirror
// crosses) along the median from a — lengths by Stewart's theorem in the background geometry.
// A face with vertices of one side only is on the side its centroid maps to. Returns the faces on the input's side.
// Throws ConvergenceError naming the face where the triangulation is not mirror-symmetric (vertices of both sides in
// another pattern, a centroid on the other side) or a face of the half violates the triangle inequality.
GeodesicHalf halveSymmetricDouble(const IntrinsicTriangulation& doubled, const std::vector<int>& mirror, int nInput,
                                  const FlowCorrespondence& log, const HalfedgeMesh& doubleInput, int inputFaces);


}  // namespace conformesh::intrinsic::detail
