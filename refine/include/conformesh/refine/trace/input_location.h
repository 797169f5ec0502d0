// input_location.h — where a vertex of the refined triangulation lies on the INPUT triangulation (input face +
// barycentric coordinates), found by following on the input the same geodesic that placed it in the refined one.
//
// Refinement inserts points but never changes the metric, so a geodesic from a vertex in a given direction is the same
// curve in both triangulations; the signposts (signposts.h) give that direction in a frame both share. Barycentric
// coordinates are affine for a Euclidean face and projective (gnomonic for the sphere, Klein for the hyperbolic plane)
// for curved faces, in the face's canonical layout (geodesic_trace.h: layoutFace). They are therefore the coordinates a
// pull-back interpolates in. A point on a boundary circle beyond an input boundary chord (boundary splits, see
// delaunay_refinement.h) gets the coordinates of the boundary face extended past that chord: one is negative.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/trace/background_model.h"
#include "conformesh/refine/trace/signposts.h"

namespace conformesh::refine {

struct InputLocation {
  int face = intrinsic::kInvalid;
  Eigen::Vector3d bary{0, 0, 0};
};

// The input triangulation prepared for point location: its own signposts and model.
class InputSurface {
 public:
  explicit InputSurface(const intrinsic::IntrinsicTriangulation& input);

  const intrinsic::IntrinsicTriangulation& triangulation() const { return tri_; }
  const Signposts& signposts() const { return sp_; }
  const BackgroundModel& model() const { return model_; }

  // Location of input vertex v: a corner of one of its faces.
  InputLocation vertexLocation(int v) const;

  struct Arrival {
    InputLocation location;
    double angle = 0;          // direction of the geodesic at its end, in the canonical frame of location.face's layout
    bool leftSurface = false;  // the geodesic crossed an input boundary edge (end point in a boundary cap)
  };
  // Follows the geodesic leaving a vertex in direction theta for `length`. For an input vertex (`isInputVertex`), theta
  // is in its input signpost frame; for an inserted vertex at `from`, in the canonical frame at that point.
  Arrival follow(int vertex, bool isInputVertex, const InputLocation& from, double theta, double length) const;

  // Σ bary_k · values[faceVertex(face, k)]: piecewise-linear interpolation of a per-input-vertex field.
  double interpolate(const std::vector<double>& values, const InputLocation& at) const;

 private:
  const intrinsic::IntrinsicTriangulation& tri_;
  Signposts sp_;
  BackgroundModel model_;
};

// Positions of located points on a Euclidean input (flat faces) with vertex positions `positions` (per input vertex):
// Σ_k bary_k · positions[faceVertex(face, k)] per location, extended linearly beyond a boundary chord (a negative
// coordinate). Returns one position per location, or nothing when `positions` is empty.
std::vector<Eigen::Vector3d> interpolatePositions(const intrinsic::HalfedgeMesh& input,
                                                  const std::vector<Eigen::Vector3d>& positions,
                                                  const std::vector<InputLocation>& locations);

}  // namespace conformesh::refine
