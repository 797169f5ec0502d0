// coarse_to_fine.h — carrying the fitted positions of a coarse mesh to a finer mesh of the same surface through the
// chart both were discretized on: each fine vertex's chart point is located in the coarse mesh's chart triangulation
// and its position interpolated barycentrically from the coarse face's three fitted positions. The result is a start
// for fitIsometricEmbedding (isometric_embedding.h) that uses no true positions, only the common parameter domain of
// the two discretizations. It is flat inside each coarse face, where edge lengths do not tell a fine vertex to which
// side to bend, so the fine fit should take a few weakly regularized steps before the pure fit (regularizerWeight =
// 0.01, maxIterationsRegularized = 1; from w = 0 directly it popped vertices), and each level should refine h by at
// most about 2× (45 → 141 directly popped vertices, 45 → 100 → 141 did not; the full continuation instead of one
// step per stage also works, at 1.5× the cost): docs/embedding.md.
//
// Charts handled (`ChartSurface`), as discretizeMetric (metric_discretization.h) builds them on the pole-free reference
// surface of the chart (smooth_metric.h: referencePoint):
//  * Plane: rectangle and disk charts; chart points (x, y, ·) in the plane (z ignored), coarse faces are plane
//    triangles, barycentric coordinates the usual ones.
//  * UnitSphere: sphere charts (the ellipsoid, the round sphere, Kerr–Newman). Chart points are points of the unit
//    sphere, and the coarse faces are the spherical triangles whose edges are great arcs (the edges discretizeMetric
//    measures). A point x lies in face (a, b, c) iff x = α a + β b + γ c with α, β, γ ≥ 0 (the face's cone from the
//    centre), and its barycentric coordinates are (α, β, γ)/(α + β + γ): those of the central projection of x to the
//    flat triangle abc. Locating on the sphere itself, not in (u, v), avoids the seam at u = 2π and the poles, where
//    (u, v) triangles degenerate.
// Periodic charts (cylinders, tori: grids glued across a seam, whose seam triangles have no single chart triangle
// with wrapped coordinates) are not handled: chartTriangulation refuses them.
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
