// image_path.h — points on the flat input T0 and the image paths of output edges across its faces (internal header
// of the mesh pipeline, pull_back.h): flat distances in a face, re-expressing a point in a neighbouring face, the exact
// crossing of an input edge, and the development of a path into the plane. Reads T0 only.
// Derivations: docs/refinement.md, "Mesh pull-back".
#pragma once

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::refine::detail {

// A point of T0* (face + projective barycentric coordinates) or of T0 (face + affine ones); `vertex` ≥ 0 when the
// point is that input vertex exactly (it can then be re-expressed in any face around it).
struct Point {
  int face = intrinsic::kInvalid;
  Eigen::Vector3d bary{0, 0, 0};
  int vertex = intrinsic::kInvalid;
};

Point toPoint(const intrinsic::FacePoint& p);
Point vertexPoint(const intrinsic::HalfedgeMesh& m, int v);  // corner of the face of v's first outgoing halfedge

// Drops the negative coordinates of a point of a boundary cap (beyond a boundary chord, input_location.h) and
// renormalises: the cap is mapped onto its chord at the same fraction.
Eigen::Vector3d clampToFace(Eigen::Vector3d b);

// Distance in face f of the Euclidean T0 between barycentric points x and y (input length units).
double flatDistance(const intrinsic::IntrinsicTriangulation& t0, int f, const Eigen::Vector3d& x,
                    const Eigen::Vector3d& y);

// Re-expresses p in face f when it is an input vertex that is a corner of f, or lies on an edge of its face whose
// twin is in f; returns false otherwise.
bool expressIn(const intrinsic::HalfedgeMesh& m, const Point& p, int f, Eigen::Vector3d& bary);

// A resolved straight piece of an image path on T0: from `a` in face faceA to `b` in face faceB, which is faceA, or
// the face across halfedge `crossing` of faceA, or (a path through an input vertex) a face sharing the corner
// `viaCorner` of faceA.
struct Resolved {
  int faceA = intrinsic::kInvalid, faceB = intrinsic::kInvalid;
  Eigen::Vector3d a, b;
  int crossing = intrinsic::kInvalid, viaCorner = -1;
  double length = 0;  // of the straight piece(s), each measured in its face
};

// Resolves the image of a piece with ends A and B on T0 when they lie in one input face or in two adjacent ones (the
// crossing found exactly in the light-cone model), or, when `tiny`, in two faces sharing a corner; false when it must
// be bisected.
bool resolvePiece(const intrinsic::IntrinsicTriangulation& t0, const Point& A, const Point& B, bool tiny, Resolved& r);

// The faces an image path crosses, unfolded one onto the next across the edges it crosses, in the plane.
class Development {
 public:
  explicit Development(const intrinsic::IntrinsicTriangulation& t) : t_(t) {}

  void start(int face);  // face laid out canonically: corner 0 at 0, corner 1 on the x axis
  int face() const { return face_; }
  Eigen::Vector2d point(const Eigen::Vector3d& b) const { return b[0] * c_[0] + b[1] * c_[1] + b[2] * c_[2]; }
  const Eigen::Vector2d& corner(int k) const { return c_[k]; }

  // Unfolds the neighbour across side k (corner k → k+1) of the current face. False on the boundary.
  bool across(int k);

  // Moves to face `target`: across a shared side when there is one (the side whose opposite coordinate of the current
  // point `b` is smallest, in case of multi-edges), else around the shared corner `corner` (if ≥ 0; else the corner
  // where b is 1) the way that crosses fewer faces. False when neither joins them.
  bool moveTo(int target, const Eigen::Vector3d& b, int corner);

 private:
  const intrinsic::IntrinsicTriangulation& t_;
  int face_ = intrinsic::kInvalid;
  Eigen::Vector2d c_[3];
};

}  // namespace conformesh::refine::detail
