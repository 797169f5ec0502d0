// surface_projection.h — the two maps from a mesh in R³ to the smooth surface it approximates (paper §4.4), and the
// distances they measure: the natural projection η (through the parametrization: a point of a mesh triangle goes to
// the surface point of the same barycentric place in the triangle's reference image), the closest-point projection π
// (Newton on the parametrization), the Hausdorff distance max |q − π(q)| and |q − η(q)| (Lemmas 4.8, 4.9: O(ε²)) and
// the normal deviation, the angle between a triangle's normal and the surface normal at π(q) or η(q) (O(ε)).
//
// The mesh's vertices carry their points on the chart's reference surface (remesh's `reference`, or the chart points
// of any mesh made from the metric): they are η of the vertices and the starts of the Newton iterations for π.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/embedding/extrinsic/embedded_surface.h"
#include "conformesh/intrinsic/mesh/halfedge_mesh.h"

namespace conformesh::embedding {

struct ProjectionOptions {
  // Gauss–Newton on min |X(y) − q|² over reference points y stops when the step moves X by less than stepTolerance
  // times the distance scale max(|q − X|, 1e-3·diameter of the bounding box of the mesh): below the O(ε²) distances
  // compared, above the ~1e-10 accuracy of the finite-difference tangents (embedded_surface.h).
  double stepTolerance = 1e-9;
  int maxIterations = 50;
  // Each triangle is sampled at the barycentric points (i, j, k)/n, i + j + k = n (its corners included): n = 4 gives
  // 15 points per triangle, enough to see the maximum of the O(ε²) gap, which sits inside the triangle.
  int samplesPerEdge = 4;

  // What is wrong with these options ("" when valid): samplesPerEdge ≥ 1.
  std::string validate() const;
};

struct ProjectedPoint {
  Eigen::Vector3d reference;  // π(q) on the reference surface
  Eigen::Vector3d position;   // π(q) in R³
  Eigen::Vector3d normal;     // unit surface normal there, oriented as the reference frame (outward on sphere charts)
  double distance = 0;        // |q − π(q)|
  int iterations = 0;
};

// π(q), starting Newton from `startReference` (a nearby reference point, e.g. η of q). The start must lie in π(q)'s
// basin — within the surface's reach of it, which a mesh vertex's own reference point always is for meshes fine enough
// to be compared. Throws ConvergenceError (naming q and the last step) when Newton does not settle.
ProjectedPoint closestPointProjection(const EmbeddedSurface& surface, const Eigen::Vector3d& q,
                                      const Eigen::Vector3d& startReference, const ProjectionOptions& options = {});

// η at barycentric coordinates `bary` of the triangle whose corners have reference points `corners`: the reference
// point Σ bᵢ xᵢ (straight on planar charts, the geodesic triangle on the unit sphere), mapped to the surface.
Eigen::Vector3d naturalProjection(const EmbeddedSurface& surface, const std::array<Eigen::Vector3d, 3>& corners,
                                  const Eigen::Vector3d& bary);

struct SurfaceDeviation {
  int samples = 0;
  double hausdorffClosest = 0;  // max |q − π(q)| over samples (one-sided: mesh to surface)
  double meanClosest = 0;       // mean |q − π(q)|
  double hausdorffNatural = 0;  // max |q − η(q)|
  double normalDeviation = 0;   // max over samples of the angle (radians) between n_T(q) and n_M(π(q))
  double meanNormalDeviation = 0;
  double normalDeviationNatural = 0;  // max angle between n_T(q) and n_M(η(q))
  int worstFace = -1;                 // where hausdorffClosest is attained
  // Triangles whose normal points against the surface's (angle > π/2) after fixing the global orientation by the
  // majority: inverted or folded triangles.
  int flippedFaces = 0;
};

// Compares the mesh (faces of `mesh`, vertex `positions` in R³) with the smooth surface. `referencePoints` gives each
// vertex's point on the reference surface. Throws InputError for arrays of the wrong size or non-finite entries.
SurfaceDeviation surfaceDeviation(const intrinsic::HalfedgeMesh& mesh, const std::vector<Eigen::Vector3d>& positions,
                                  const std::vector<Eigen::Vector3d>& referencePoints, const EmbeddedSurface& surface,
                                  const ProjectionOptions& options = {});

}  // namespace conformesh::embedding
