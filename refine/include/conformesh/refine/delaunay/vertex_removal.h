// vertex_removal.h — removing an inserted interior vertex from a refined intrinsic triangulation by isometric flips
// down to degree 3 and the merge of its last three faces, keeping edge lengths and signposts consistent (no length,
// angle or signpost is recomputed). Chew's second algorithm deletes free vertices near a split segment
// (delaunay_refinement.h). Changes the triangulation and its signposts, compacted swap-with-last; the caller applies
// the returned moves to its own per-element arrays. Why it works: docs/refinement.md §4, *Vertex removal*.
#pragma once

#include <functional>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/trace/signposts.h"

namespace conformesh::refine {

struct VertexRemovalResult {
  bool removed = false;
  int flips = 0;                         // flips of v's edges (made, and kept, even when removal fails)
  int mergedFace = intrinsic::kInvalid;  // the face that replaced v's last three, after compaction
  intrinsic::ElementMoves moves;         // apply to the caller's own per-element arrays (applyMoves)
  std::vector<int> regionEdges;          // the edges of the faces that replaced v's star (final indices)
};

// Removes vertex v if it is an inserted (v ≥ inputVertices), interior vertex without a self-loop whose angle sum is 2π
// to 1e-9 rad. Flips v's edges while its degree exceeds 3, each flip isometric and only where the quad is strictly
// convex (flipWithSignposts), calling `onFlip(edge)` after each. In exact arithmetic a flip always exists for degree ≥
// 4 unless v lies on a diagonal of its link polygon (see vertex_removal.cpp); when none does, or after 10·degree flips,
// it gives up: v stays, the flips made remain (the triangulation is valid, not necessarily Delaunay: restore it from
// `regionEdges`). On success the mesh, tri.edgeLengths and the signposts (angle per halfedge, period per vertex) are
// compacted (HalfedgeMesh::removeDegree3Vertex); the caller applies `moves` to its other arrays.
VertexRemovalResult removeInsertedVertex(intrinsic::IntrinsicTriangulation& tri, Signposts& sp, int v,
                                         int inputVertices, const std::function<void(int)>& onFlip = {});

}  // namespace conformesh::refine
