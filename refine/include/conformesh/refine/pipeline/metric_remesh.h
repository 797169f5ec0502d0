// remesh.h — the whole pipeline for a surface given by a smooth metric (the paper's §5.1, intrinsically):
// discretize the chart into T0 → uniformize T0 by discrete Ricci flow (T0*, conformal factor λ) → Delaunay refinement
// of T0* graded by e^(−λ) (T1*) → pull back: each vertex of T1* goes to its point of T0 through the flow's
// correspondence, then to the chart by T0's piecewise-linear parametrization, and every edge of the output T1 gets the
// length of its curve in the ORIGINAL metric.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"

namespace conformesh::refine {

// What a chart with one boundary loop (a topological disk) is uniformized to.
enum class DiskTarget {
  // KeepBoundary when the chart has corners (a Rectangle chart: a Bézier patch, a graph over a square), Circle
  // otherwise (a polar Disk chart, whose boundary is smooth).
  Auto,
  // The unit disk (uniformization.h, CircleDomain); refinement splits the boundary on the circle. At a boundary corner
  // of angle α the conformal map behaves like z^{π/α}, so λ is unbounded there (docs/refinement.md).
  Circle,
  // The flat metric with the boundary's lengths kept (boundary_flattening.h): λ = 0 on the boundary, bounded, every
  // corner keeps its angle; the domain is the polygon of T0's boundary chords and refinement splits its sides at their
  // midpoints (BoundarySplit::Geodesic).
  KeepBoundary,
};
std::string toString(DiskTarget target);
// Parses "auto", "circle", "keep-boundary"; InputError naming the value otherwise.
DiskTarget parseDiskTarget(const std::string& name);

struct RemeshOptions {
  // Size bound ε in the ORIGINAL metric: circumradii of the output are ≈ ε or less (paper §4.2.3: the uniformized
  // bound ε·e^(−λ) pulls back to ε). Required, > 0.
  double epsilon = 0;
  // Shape bound B (circumradius / shortest edge) of the refinement; see RefineOptions::ratioBound.
  double ratioBound = 1.4142135623730951;
  // λ ≡ 0: uniform in the uniformized domain (not on the surface); for comparisons only.
  bool uniform = false;
  // T0: resolution of the discretization of the chart (DiscretizationOptions::resolution); the discrete conformal map
  // of T0 is the only approximation of the smooth one, so it should be fine enough that its angle distortion is well
  // below the refinement's angle bound. 0 = automatic: about a quarter of the output's expected vertex count, at a
  // resolution between 8 and 32 (≈ 650 to 10⁴ vertices for sphere charts; other charts are sized by a probe at
  // resolution 8), since refinement only adds vertices to T0.
  int t0Resolution = 0;
  // Target of the uniformization when the chart is a topological disk (ignored for closed charts).
  DiskTarget diskTarget = DiskTarget::Auto;
  intrinsic::DiscretizationOptions discretization;
  intrinsic::UniformizationOptions uniformization;
  // Passed through to the refinement (epsilon, ratioBound and lambda are set from the fields above). Unsmoothed by
  // default (the paper's refinement, and the fast one: a smoothing pass makes the refinement stage ~3.5× slower);
  // `refinement.smoothingPasses = 1` lifts the mean smallest angle above 46° on every mesh of docs/studies.md at the
  // cost documented there (the convergence study's default).
  RefineOptions refinement;
  std::function<void(const std::string&)> progress;
};

struct RemeshTimes {
  double discretize = 0, uniformize = 0, refine = 0, pullBack = 0;
};

struct RemeshResult {
  // T1: the output triangulation; lengths are metric lengths of the edges' curves in the original metric (Euclidean
  // background: each triangle is the flat triangle with those lengths).
  intrinsic::IntrinsicTriangulation mesh;
  std::vector<Eigen::Vector2d> chart;      // per vertex: chart coordinates (u, v)
  std::vector<Eigen::Vector3d> reference;  // per vertex: point of the chart's pole-free reference surface
  std::vector<Eigen::Vector3d> positions;  // per vertex: the embedding, when the metric has one; else empty
  std::vector<double> lambda;              // per vertex: conformal factor interpolated at the vertex
  std::vector<int> t0Face;                 // per vertex: face of T0 containing it
  std::vector<Eigen::Vector3d> t0Bary;     // and its barycentric coordinates there
  int t0Vertices = 0, t0Faces = 0;
  int invertedTriangles = 0;  // output triangles whose image in the chart's reference surface is inverted (should be 0)
  intrinsic::UniformizationReport uniformization;
  DiskTarget diskTarget = DiskTarget::Circle;  // as in UniformizedMetric
  RefineStatistics refinement;
  QualityReport uniformQuality;  // of T1* in its background metric
  QualityReport quality;         // of T1 in the original metric
  RemeshTimes seconds;
};

// Throws InputError for bad parameters (naming them) and ConvergenceError when a stage does not converge.
RemeshResult remeshMetric(const intrinsic::SmoothMetric& metric, const RemeshOptions& options);

// The first two stages alone, for sweeps that refine one uniformization at several ε (`conformesh convergence`).
struct UniformizedMetric {
  intrinsic::IntrinsicTriangulation t0;
  std::vector<Eigen::Vector3d> t0Reference;  // per T0 vertex: its point on the chart's reference surface
  std::vector<Eigen::Vector2d> t0Chart;      // per T0 vertex: chart coordinates
  intrinsic::Uniformization uniformization;
  // The disk target used (Auto resolved; Circle also stands for charts without boundary, where it plays no role).
  // KeepBoundary refines with BoundarySplit::Geodesic.
  DiskTarget diskTarget = DiskTarget::Circle;
  double discretizeSeconds = 0, uniformizeSeconds = 0;
};
UniformizedMetric uniformizeMetric(const intrinsic::SmoothMetric& metric, const RemeshOptions& options);
// Stages 3 and 4 on a prepared uniformization (options.epsilon, ratioBound, uniform and refinement are used).
RemeshResult remeshUniformized(const UniformizedMetric& prepared, const intrinsic::SmoothMetric& metric,
                               const RemeshOptions& options);

// The output for files: faces, edges with their lengths, positions where the metric has an embedding, and per-vertex
// properties u, v (chart), lambda, curvature (angle deficit / boundary turning), smooth_curvature (K of the metric at
// the vertex), input_face and input_b0..2 (the vertex's place on T0); comments name the metric and ε.
intrinsic::MeshData toMeshData(const RemeshResult& result, const intrinsic::SmoothMetric& metric, double epsilon);
// The same for ParaView: points are the embedding where known, else the chart's reference surface (the unit sphere
// for sphere charts); the per-vertex properties become point fields.
intrinsic::VtkMesh toVtkMesh(const intrinsic::MeshData& data, const RemeshResult& result);

}  // namespace conformesh::refine
