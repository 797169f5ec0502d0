// geodesic_trace.h — following a geodesic across the triangles of an intrinsic triangulation (point location).
//
// The triangles the geodesic meets are laid out one after another in one copy of the background model
// (background_model.h), each unfolded across the edge the geodesic crossed, so the geodesic is one straight segment
// s → t of that model; which edge it leaves a triangle through is decided by exact orientation signs
// (robust_predicates.h). This is how the refinement finds the triangle containing a circumcentre, and how an inserted
// point is located on the input triangulation (refinement never changes the metric, so the same geodesic exists there).
#pragma once

#include <array>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/trace/background_model.h"
#include "conformesh/refine/trace/signposts.h"

namespace conformesh::refine {

struct TraceResult {
  int face = intrinsic::kInvalid;  // triangle containing the end point (or the last one, see boundaryHalfedge)
  std::array<Vec3, 3> corners;     // its layout: corners[k] = faceVertex(face, k)
  Eigen::Vector3d bary{0, 0, 0};   // projective barycentric coordinates of the end point in `face`
  Vec3 start, end;                 // the segment in the layout's coordinates
  // Set when the geodesic leaves the surface through this boundary halfedge of `face` before reaching its length; `end`
  // and `bary` are then the target extrapolated beyond that edge in the plane of `face` (one coordinate negative).
  int boundaryHalfedge = intrinsic::kInvalid;
  int steps = 0;  // triangles visited

  bool reachedTarget() const { return boundaryHalfedge == intrinsic::kInvalid; }
  // Unit tangent of the geodesic at its end point (pointing forward), in the layout's coordinates.
  Vec3 arrivalTangent(const BackgroundModel& model) const { return -model.tangentToward(end, start); }
};

// The geodesic from vertex v leaving in direction theta (v's signpost frame) with length `length`. `hint`, if given,
// is an outgoing halfedge of v whose wedge is tried first (the refinement knows it: it traces from a triangle's corner
// toward that triangle's circumcentre), sparing the walk around v. Throws ConvergenceError naming v when theta or the
// length is not finite, or when v is an interior vertex and theta lies in none of its corners (corrupt signposts);
// both walks throw it, naming the face and the cap, after 20·faces + 1000 triangles or on non-finite coordinates.
TraceResult traceFromVertex(const intrinsic::IntrinsicTriangulation& tri, const Signposts& sp,
                            const BackgroundModel& model, int v, double theta, double length,
                            int hint = intrinsic::kInvalid);

// The geodesic segment start → target, both given in the coordinates of a layout `corners` of face `face`; `start` may
// lie inside the face, on its boundary, or beyond a boundary edge of the surface (a point of a boundary cap).
TraceResult traceFromPoint(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int face,
                           const std::array<Vec3, 3>& corners, const Vec3& start, const Vec3& target);

// Canonical layout of face f: corner 0 at the origin, corner 1 on the positive x axis, corner 2 on the left.
std::array<Vec3, 3> layoutFace(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int f);

// Layout of face(h) with tail(h) at the origin and tip(h) on the positive x axis, as corners in face order.
std::array<Vec3, 3> layoutAtHalfedge(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int h);

// The third corner of face(g) (the tail of prev(g)), unfolded on the left of g given the layout positions of tail(g)
// and tip(g). The Euclidean background uses the law of cosines (no trigonometric function: this is the innermost
// step of every walk); curved backgrounds rotate by the corner angle and follow the exponential map.
Vec3 unfoldThirdVertex(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int g,
                       const Vec3& tailG, const Vec3& tipG);

}  // namespace conformesh::refine
