// geodesic_trace.h — following a geodesic across the triangles of an intrinsic triangulation (point location), for
// the refinement (circumcentres), input_location.h and the mesh pipeline's pull-back (the faces an edge crosses).
//
// The triangles met are unfolded one after another into one copy of the background model (background_model.h), so the
// geodesic is one straight segment s → t there; which edge it leaves a triangle through is decided by exact
// orientation signs (robust_predicates.h). Reads the triangulation and its signposts; changes nothing.
// Derivation: docs/refinement.md, "Geodesic tracing".
#pragma once

#include <array>
#include <vector>

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
  // traceFromVertex: the outgoing halfedge of the start vertex whose corner the geodesic leaves through (the start is
  // corner startHalfedge % 3 of its face); kInvalid for traceFromPoint and for a geodesic leaving the surface at once.
  int startHalfedge = intrinsic::kInvalid;
  int steps = 0;  // triangles visited

  bool reachedTarget() const { return boundaryHalfedge == intrinsic::kInvalid; }
  // Unit tangent of the geodesic at its end point (pointing forward), in the layout's coordinates.
  Vec3 arrivalTangent(const BackgroundModel& model) const { return -model.tangentToward(end, start); }
};

// Where a traced geodesic crosses an interior edge into the next face.
struct EdgeCrossing {
  int halfedge = intrinsic::kInvalid;  // 3·f + k: side k of the face f it leaves (into face(twin(halfedge)))
  Eigen::Vector3d bary{0, 0, 0};       // the crossing in f's barycentric coordinates: ≥ 0, sum 1, bary[(k+2)%3] = 0
};

// How a walk unfolds the next triangle on the Euclidean background (curved backgrounds always use the corner angle).
enum class Unfolding {
  LawOfCosines,  // unfoldThirdVertex: no trigonometric function (the refinement's walks)
  CornerAngle,   // BackgroundModel::thirdVertex by the corner angle, on every background (the mesh pull-back)
};

// What traceFromVertex does with a direction outside the fan of a boundary vertex.
enum class OutwardDirection {
  LeaveSurface,    // the geodesic leaves at once through the nearer boundary edge (boundaryHalfedge set)
  FollowBoundary,  // the direction is snapped onto the nearer boundary edge, and traced along it
};

struct TraceOptions {
  Unfolding unfolding = Unfolding::LawOfCosines;
  OutwardDirection outward = OutwardDirection::LeaveSurface;
  std::vector<EdgeCrossing>* crossings = nullptr;  // when set, every crossing of the walk is appended, in order
};

// The geodesic from vertex v leaving in direction theta (rad, v's signpost frame) for `length` (background units).
// `hint`, if given, is an outgoing halfedge of v whose wedge is tried first. Throws ConvergenceError naming v when
// theta or the length is not finite, or when v is interior and theta lies in none of its corners (corrupt
// signposts); both traces throw it, naming the face, after 20·faces + 1000 triangles or on non-finite coordinates.
TraceResult traceFromVertex(const intrinsic::IntrinsicTriangulation& tri, const Signposts& sp,
                            const BackgroundModel& model, int v, double theta, double length,
                            int hint = intrinsic::kInvalid, const TraceOptions& options = {});

// The geodesic segment start → target, both in the coordinates of a layout `corners` of face `face`; `start` may lie
// inside the face, on its boundary, or beyond a boundary edge of the surface (a point of a boundary cap).
TraceResult traceFromPoint(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int face,
                           const std::array<Vec3, 3>& corners, const Vec3& start, const Vec3& target,
                           const TraceOptions& options = {});

// Canonical layout of face f: corner 0 at the origin, corner 1 on the positive x axis, corner 2 on the left.
std::array<Vec3, 3> layoutFace(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int f);

// Layout of face(h) with tail(h) at the origin and tip(h) on the positive x axis, as corners in face order.
std::array<Vec3, 3> layoutAtHalfedge(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int h);

// The third corner of face(g) (the tail of prev(g)), unfolded on the left of g given the layout positions of tail(g)
// and tip(g): the law of cosines on the Euclidean background, the corner angle and exponential map on curved ones.
Vec3 unfoldThirdVertex(const intrinsic::IntrinsicTriangulation& tri, const BackgroundModel& model, int g,
                       const Vec3& tailG, const Vec3& tipG);

}  // namespace conformesh::refine
