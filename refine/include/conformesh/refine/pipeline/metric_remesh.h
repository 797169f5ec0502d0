// metric_remesh.h — the pipeline for a surface given by a SMOOTH METRIC (the paper's §5.1, intrinsically):
// discretize the chart into T0 → uniformize T0 by discrete Ricci flow (T0*, conformal factor λ) → Delaunay-refine T0*
// graded by e^(−λ) (T1*) → pull back: each vertex of T1* to its point of T0 through the flow's correspondence, then
// to the chart, and every edge of the output T1 gets the length of its curve in the ORIGINAL metric.
// Pure functions of their arguments: no files, no global state (progress only through the callback).
// Derivations: docs/refinement.md §9 and "Surfaces whose boundary has corners"; the command: docs/cli.md.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/pipeline/vertex_budget.h"

namespace conformesh::refine {

// What a chart with one boundary loop (a topological disk) is uniformized to (docs/refinement.md, "Surfaces whose
// boundary has corners").
enum class DiskTarget {
  Auto,          // KeepBoundary for a Rectangle chart (it has corners), Circle otherwise
  Circle,        // the unit disk (CircleDomain); the boundary is split on the circle; λ unbounded at corners
  KeepBoundary,  // flat, boundary lengths kept (boundary_flattening.h); sides split at midpoints (Geodesic)
};
std::string toString(DiskTarget target);
// Parses "auto", "circle", "keep-boundary"; InputError naming the value otherwise.
DiskTarget parseDiskTarget(const std::string& name);

struct RemeshOptions {
  // Size bound ε in the ORIGINAL metric: circumradii of the output are ≈ ε or less (paper §4.2.3: the uniformized
  // bound ε·e^(−λ) pulls back to ε). Required, > 0.
  double epsilon = 0;
  double ratioBound = 1.4142135623730951;  // shape bound B (circumradius / shortest edge), RefineOptions::ratioBound
  bool uniform = false;                    // λ ≡ 0: uniform in the uniformized domain, for comparisons
  // Resolution of T0 (DiscretizationOptions::resolution). 0 = automatic: about a quarter of the output's expected
  // vertex count, at a resolution between 8 and 32.
  int t0Resolution = 0;
  DiskTarget diskTarget = DiskTarget::Auto;  // when the chart is a topological disk (ignored for closed charts)
  intrinsic::DiscretizationOptions discretization;
  intrinsic::UniformizationOptions uniformization;
  // Passed through to the refinement (epsilon, ratioBound and lambda are set from the fields above); unsmoothed by
  // default, the paper's refinement.
  RefineOptions refinement;
  // ε as a fraction of √area instead (--eps-rel; area of the T0): used when > 0, and then epsilon must be 0.
  double epsilonRelative = 0;
  // Refuse, before refining, an ε whose expected vertex count (vertex_budget.h) exceeds this; the refinement's
  // insertion cap is lowered to twice it. ≤ 0: no cap.
  std::int64_t maxVertices = kDefaultMaxVertices;
  std::function<void(const std::string&)> progress;

  // What is wrong with these options ("" when valid): ε must be positive and finite.
  std::string validate() const;
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
  double epsilon = 0;         // the ε used (options.epsilon, or epsilonRelative · √(T0's area))
  VertexEstimate expected;    // before refining (vertex_budget.h)
  std::vector<std::string> notices;  // e.g. ε above T0's spacing (nothing inserted)
  intrinsic::UniformizationReport uniformization;
  DiskTarget diskTarget = DiskTarget::Circle;  // as in UniformizedMetric
  RefineStatistics refinement;
  QualityReport uniformQuality;  // of T1* in its background metric
  QualityReport quality;         // of T1 in the original metric
  RemeshTimes seconds;
};

// The whole pipeline. Throws InputError with options.validate()'s text or for a chart the disk target does not fit,
// ConvergenceError when a stage does not converge (or T0 is too coarse for the metric's lengths).
RemeshResult remeshMetric(const intrinsic::SmoothMetric& metric, const RemeshOptions& options);

// The first two stages alone, for sweeps that refine one uniformization at several ε (`conformesh convergence`).
struct UniformizedMetric {
  intrinsic::IntrinsicTriangulation t0;
  std::vector<Eigen::Vector3d> t0Reference;  // per T0 vertex: its point on the chart's reference surface
  std::vector<Eigen::Vector2d> t0Chart;      // per T0 vertex: chart coordinates
  intrinsic::Uniformization uniformization;
  DiskTarget diskTarget = DiskTarget::Circle;  // Auto resolved (Circle also for charts without boundary)
  double discretizeSeconds = 0, uniformizeSeconds = 0;
};
UniformizedMetric uniformizeMetric(const intrinsic::SmoothMetric& metric, const RemeshOptions& options);
// Stages 3 and 4 on a prepared uniformization (options.epsilon, ratioBound, uniform and refinement are used); throws
// as remeshMetric.
RemeshResult remeshUniformized(const UniformizedMetric& prepared, const intrinsic::SmoothMetric& metric,
                               const RemeshOptions& options);

// The output for files (remesh_output.cpp): faces, edges with their lengths, positions where the metric has an
// embedding, and per-vertex properties u, v (chart), lambda, curvature (angle deficit / boundary turning),
// smooth_curvature (K of the metric at the vertex), input_face and input_b0..2 (the vertex's place on T0).
intrinsic::MeshData toMeshData(const RemeshResult& result, const intrinsic::SmoothMetric& metric, double epsilon);
// The same for ParaView: points are the embedding where known, else the chart's reference surface (the unit sphere
// for sphere charts), and then the title ends with kDrawnOnReferenceSurface; the per-vertex properties become point
// fields.
intrinsic::VtkMesh toVtkMesh(const intrinsic::MeshData& data, const RemeshResult& result);
inline constexpr const char* kDrawnOnReferenceSurface =
    "; no embedding in R3: points on the chart's reference surface (canonical domain), not the surface's shape";

}  // namespace conformesh::refine
