// boundary_split.h (private) — a circle domain's input with boundary edges split at their midpoints, for a flow that
// cannot reach its target because a face degenerates against a boundary edge (docs/ricci_flow.md §3.3, "Boundary
// edges split"). Combinatorics and Euclidean lengths only; reads its inputs.
#pragma once

#include <vector>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic::detail {

// The boundary edges of `current` — a flow's triangulation of the input, whose boundary edges never flip and keep the
// input's edge indices — whose opposite angle is at least `minAngle` (radians), largest first.
std::vector<int> boundaryEdgesOpposite(const IntrinsicTriangulation& current, double minAngle);

// The boundary edges of `current` at vertex v (its two loop edges); none when v is −1 or not on the boundary.
std::vector<int> boundaryEdgesAt(const IntrinsicTriangulation& current, int v);

struct BoundarySplit {
  IntrinsicTriangulation tri;  // Euclidean: the input's vertices 0..n−1, then one per split edge
  // Per new vertex n + i: the input's boundary edge it halves, parameter ½ from tail(edgeHalfedge(inputEdge)).
  std::vector<Uniformization::InsertedVertex> inserted;
};

// `input` (Euclidean) with each of `edges` (boundary edges with two distinct ends) split at its midpoint: the face on
// it becomes two, the new interior edge the median from the opposite vertex (Stewart: m² = (a² + b²)/2 − ℓ²/4), so
// that the piecewise flat metric is the input's. Throws InputError for an edge that is not such a boundary edge.
BoundarySplit splitBoundaryEdges(const IntrinsicTriangulation& input, const std::vector<int>& edges);

// The inserted vertices of a uniformization of `split.tri` (on split.tri's boundary edges) as points of the input's
// boundary edges, after split's own: the composition of the two subdivisions.
std::vector<Uniformization::InsertedVertex> composeInserted(const IntrinsicTriangulation& input,
                                                            const BoundarySplit& split,
                                                            const std::vector<Uniformization::InsertedVertex>& inner);

}  // namespace conformesh::intrinsic::detail
