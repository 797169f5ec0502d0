// coarse_to_fine.h — carrying the fitted positions of a coarse mesh to a finer mesh of the same surface through the
// chart both were discretized on: each fine vertex's chart point is located in the coarse mesh's chart triangulation
// and its position interpolated barycentrically from the coarse face's three fitted positions — a start for
// fitIsometricEmbedding (isometric_embedding.h) that uses no true positions. The carried start is flat inside each
// coarse face, so the fine fit takes a few weakly regularized steps first, and each level refines h by at most about
// 2× (why: docs/embedding.md, "Coarse-to-fine start").
//
// Charts (`ChartSurface`), as discretizeMetric builds them on the chart's pole-free reference surface:
//  * Plane: rectangle and disk charts; chart points (x, y, ·), plane triangles, the usual barycentric coordinates.
//  * UnitSphere: sphere charts; points of the unit sphere located in the cones of the spherical triangles (no seam,
//    no pole), barycentric coordinates those of the central projection onto the flat triangle.
// Periodic charts (cylinders, tori) are refused by chartTriangulation (InputError).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::embedding {

enum class ChartSurface { Plane, UnitSphere };

// A triangulation of a chart's reference surface: one chart point per vertex, faces as vertex triples.
struct ChartTriangulation {
  ChartSurface surface = ChartSurface::Plane;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> faces;
};

// Where a point lies: the face and its barycentric coordinates there (non-negative, summing to 1).
struct ChartLocation {
  int face = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

// The chart triangulation of a mesh from discretizeMetric: faces from `mesh`, chart points referencePoint(u, v) from
// its vertex properties "u" and "v" (sphere charts give the unit sphere exactly: u = 0 at the poles is harmless
// there). Throws InputError for a periodic chart (cylinder, torus), or for missing or wrongly sized u, v.
ChartTriangulation chartTriangulation(const intrinsic::MeshData& mesh, const intrinsic::ChartDomain& domain);

// Locates every point in `coarse`. Points on an edge or at a vertex, and points outside every face by round-off (a
// barycentric coordinate ≥ −1e-9), are located in the face where they are most inside (the largest smallest
// coordinate), with negative coordinates clamped to 0 and the rest rescaled. Throws InputError naming the point
// (index and coordinates) when it lies in no face, and naming the face when a face is degenerate (zero area; on the
// sphere also a face whose plane passes through the centre) or refers to a vertex that does not exist. Candidate
// faces come from a uniform hash grid of face bounding boxes (on the sphere each box grown by the face's bulge
// 1 − dist(centre, face plane)), so the cost is O(faces + points) for well-shaped triangulations.
std::vector<ChartLocation> locateInChart(const ChartTriangulation& coarse, const std::vector<Eigen::Vector3d>& points);

// The coarse positions (one per coarse chart point) interpolated at each fine chart point: Σ_k λ_k x_{f_k} over the
// located face f and its barycentric coordinates λ. Throws InputError when the sizes differ, a position is not
// finite, or (from locateInChart) a fine point lies in no coarse face.
std::vector<Eigen::Vector3d> carryPositions(const ChartTriangulation& coarse,
                                            const std::vector<Eigen::Vector3d>& coarsePositions,
                                            const std::vector<Eigen::Vector3d>& finePoints);

}  // namespace conformesh::embedding
