// vertex_removal.h — removing an inserted interior vertex from a refined intrinsic triangulation, keeping edge lengths
// and signposts consistent. Chew's second algorithm deletes free vertices near a split segment
// (delaunay_refinement.h, docs/refinement.md §6).
//
// An inserted interior vertex v is a regular point of the constant-curvature background (angle sum 2π), so its star
// lays out isometrically in the straight-line model (background_model.h) as a star-shaped polygon with v in its kernel.
// Intrinsic flips of v's edges bring its degree down to 3 (as geometry-central's removeInsertedVertex does); the three
// faces then tile the triangle of their outer edges, which becomes one face with those edges' unchanged lengths. No
// length, angle or signpost is recomputed: the outer halfedges keep their signposts, and at each neighbour the merged
// corner is the sum of the two corners it replaces (v is flat), so the signpost invariant still holds.
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
