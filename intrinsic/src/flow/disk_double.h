// disk_double.h (private) — the double of a disk: the disk glued to its mirror copy along the boundary, a closed
// genus-0 surface in which every edge is interior (flippable), for the variational route to circle domains
// (docs/ricci_flow.md §3.3, "The double"). Combinatorics and lengths only; reads its input.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic::detail {

struct DiskDouble {
  IntrinsicTriangulation surface;  // closed; vertices 0..n−1 the disk's, then one mirror copy per interior vertex
  std::vector<int> mirror;         // per vertex of `surface`: its mirror image (a boundary vertex is its own)
  int diskFaces = 0;               // faces 0..diskFaces−1 are the disk's, the rest their mirror images
};

// The double of `disk` (one component with boundary: a disk for the circle domains, any genus and number of loops for
// the geodesic-boundary targets, geodesic_half.h; any background, lengths copied): mirror face of
// (a, b, c) is (c', b', a') (reversed, so the double is oriented), glued to the disk along the boundary edges; an
// interior edge between two boundary vertices appears twice (a multi-edge, kept apart by edge ids). Throws InputError
// when `disk` has no boundary.
DiskDouble doubleDisk(const IntrinsicTriangulation& disk);

// A vertex of the disk's half that is not a vertex of the disk: where an edge of the double's final Delaunay
// triangulation crosses the reflection's great circle. It lies on the input boundary edge `inputEdge` (an edge of the
// disk) at `parameter` t ∈ (0, 1) from tail(edgeHalfedge(inputEdge)) toward its tip, in the input's own lengths
// (the double's correspondence maps it there; the mirror symmetry puts it on the fixed set).
struct HalfBoundaryVertex {
  int vertex = -1;          // its id in DiskHalf::plane (≥ the disk's vertex count)
  int inputEdge = -1;       // the disk's boundary edge it lies on
  double parameter = 0;     // position along that edge, in the input's lengths
  double offEdge = 0;       // the smallest barycentric coordinate the correspondence gave it (0 on the edge)
  bool selfMirror = false;  // the crossing edge joins a vertex to its own mirror image (crossing at its midpoint)
};

// Where the new boundary vertices of a half lie on the input (the disk's half below and geodesic_half.h): each of
// `crossings`, a point of `doubled` (the flow's final triangulation of twin.surface; `log` its flip log), maps to a
// point of the double's T0 that the mirror symmetry puts on the fixed set, an input boundary edge (a mirror face
// (c′, b′, a′) of (a, b, c) has its coordinates reversed). Writes inputEdge, parameter and offEdge of inserted[i];
// throws ConvergenceError naming inserted[i].vertex when its point is farther than 1e-8 (barycentric) from an input
// boundary edge.
void locateOnInputBoundary(const IntrinsicTriangulation& disk, const DiskDouble& twin, const HalfedgeMesh& doubled,
                           const FlowCorrespondence& log, const std::vector<FacePoint>& crossings,
                           std::vector<HalfBoundaryVertex>& inserted);

// The disk's half of the double's sphere, stereographically projected from the mirror pole onto the unit disk: a
// straight-line triangulation of the unit disk whose boundary loop holds the disk's boundary vertices plus one new
// vertex per crossing edge (docs/ricci_flow.md §3.3, "The half").
struct DiskHalf {
  IntrinsicTriangulation plane;            // Euclidean, lengths |z_i − z_j|, then flipped to intrinsic Delaunay
  std::vector<Eigen::Vector3d> positions;  // z per vertex (z = 0 plane), the boundary on the unit circle
  std::vector<double> lambda;  // per vertex: input vertices exact (−w − log 2 + 2 log|x − p|), new ones
                               // interpolated linearly along their input edge
  std::vector<HalfBoundaryVertex> inserted;
  int crossingEdges = 0, selfMirrorCrossings = 0, delaunayFlips = 0;
};

// The half of `sphere` (uniformize's result on twin.surface, which must be that of `disk`). Throws ConvergenceError
// when the double's solution is not mirror-symmetric enough to take a half (a disk vertex on the mirror side, a face
// with all three vertices on the great circle), when a projected face is not positively oriented (a fold), or when the
// correspondence does not put a new vertex on an input boundary edge (to 1e-8).
DiskHalf halveDoubleSphere(const IntrinsicTriangulation& disk, const DiskDouble& twin, const Uniformization& sphere);

}  // namespace conformesh::intrinsic::detail
