// signposts.h — the direction of every halfedge in its tail's tangent space (Sharp–Soliman–Crane, "Navigating
// intrinsic triangulations", SIGGRAPH 2019), kept correct through the flips and splits of refinement, which these
// functions wrap. A signpost φ(h) is the angle of h at tail(h), counter-clockwise from the vertex's reference
// direction: its input vertexHalfedge for an input vertex, the canonical frame of the input face containing it for an
// inserted vertex (input_location.h). Angles are reduced to [0, period(v)): the angle sum for interior input vertices,
// 2π otherwise. docs/refinement.md §4.
#pragma once

#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::refine {

struct Signposts {
  std::vector<double> angle;   // per halfedge
  std::vector<double> period;  // per vertex

  double reduce(int v, double a) const;
  // Angle of the direction φ(h) + delta, reduced at tail(h) (tail given explicitly).
  double turned(const intrinsic::IntrinsicTriangulation& tri, int h, double delta) const;
};

// Signposts of a triangulation read as its own input: each vertex's vertexHalfedge has angle 0, the others follow
// counter-clockwise by the corner angles.
Signposts initialSignposts(const intrinsic::IntrinsicTriangulation& tri);

// The outgoing halfedge h of v whose corner wedge [φ(h), φ(h) + angle) contains direction theta, and the offset
// theta − φ(h) in [0, corner angle). Returns kInvalid when no wedge contains it (a direction pointing out of the
// surface at a boundary vertex).
struct Wedge {
  int halfedge = intrinsic::kInvalid;
  double offset = 0;
};
Wedge findWedge(const intrinsic::IntrinsicTriangulation& tri, const Signposts& sp, int v, double theta);

// === updates. Each wraps the HalfedgeMesh mutation and re-derives the signposts of the halfedges it created or moved,
// following the slot layout documented in halfedge_mesh.cpp. The splits throw ConvergenceError (naming the face or edge
// and the lengths) when a new edge length is not finite and positive — before the mesh changes — or when a direction
// they set comes out non-finite: a point inserted on a vertex or computed from a degenerate layout.

// flipEdge (intrinsic_flips.h) plus signposts. Returns false when the edge cannot be flipped.
bool flipWithSignposts(intrinsic::IntrinsicTriangulation& tri, Signposts& sp, int e);

// Splits face f at a new vertex whose three new edges (to the corners k = 0, 1, 2 of f) have lengths `toCorner[k]`,
// and whose outgoing halfedge toward corner 0 has signpost `angleToCorner0` (in the new vertex's frame).
int splitFaceWithSignposts(intrinsic::IntrinsicTriangulation& tri, Signposts& sp, int f,
                           const std::array<double, 3>& toCorner, double angleToCorner0);

// Splits edge e (ha = edgeHalfedge(e): a -> b in face (a, b, c); twin b -> a in (b, a, d) when interior) at a new
// vertex p. Lengths: |ap|, |pb|, |pc|, |pd| (|pd| ignored on the boundary). `angleToB` is φ(p -> b) in p's frame.
// `turnAtA` is added to φ(a -> p) relative to the old φ(a -> b) (zero when p lies on the geodesic edge; nonzero when a
// boundary edge is split at a point on the boundary circle off the chord).
int splitEdgeWithSignposts(intrinsic::IntrinsicTriangulation& tri, Signposts& sp, int e, double ap, double pb,
                           double pc, double pd, double angleToB, double turnAtA);

}  // namespace conformesh::refine
