// report_json.cpp — JSON for QualityReport, UniformizationReport, RefineStatistics, CurvatureMeasureResult.
#include "report_json.h"

namespace conformesh::apps {

nlohmann::json qualityJson(const refine::QualityReport& q) {
  return {{"vertices", q.vertices},
          {"triangles", q.triangles},
          {"min_angle_deg", q.minAngleDeg},
          {"mean_min_angle_deg", q.meanMinAngleDeg},
          {"max_angle_deg", q.maxAngleDeg},
          {"max_circumradius", q.maxCircumradius},
          {"mean_circumradius", q.meanCircumradius},
          {"max_radius_edge_ratio", q.maxRadiusEdgeRatio},
          {"fraction_below_30_deg", q.fractionBelow30},
          {"angle_histogram_bin_deg", q.histogramBinDeg},
          {"angle_histogram", q.angleHistogram},
          {"non_delaunay_edges", q.nonDelaunayEdges},
          {"gauss_bonnet_residual", q.gaussBonnetResidual}};
}

nlohmann::json uniformizationJson(const intrinsic::UniformizationReport& u) {
  return {{"target", intrinsic::toString(u.target)},
          {"genus", u.genus},
          {"boundary_loops", u.boundaryLoops},
          {"newton_steps", u.newtonSteps},
          {"flips", u.flips},
          {"max_residual", u.maxResidual},
          {"tolerance", u.effectiveTolerance},
          {"puncture_vertex", u.punctureVertex},
          {"seconds", u.seconds}};
}

nlohmann::json refineStatisticsJson(const refine::RefineStatistics& s) {
  return {{"input_vertices", s.inputVertices},
          {"circumcenter_insertions", s.circumcenterInsertions},
          {"centroid_insertions", s.centroidInsertions},
          {"boundary_splits", s.boundarySplits},
          {"rejected_circumcenters", s.rejectedCircumcenters},
          {"deleted_vertices", s.deletedVertices},
          {"refused_deletions", s.refusedDeletions},
          {"flips", s.flips},
          {"trace_steps", s.traceSteps}};
}

nlohmann::json curvatureMeasureJson(const intrinsic::CurvatureMeasureResult& c,
                                    const intrinsic::CurvatureMeasureOptions& o) {
  return {{"region", o.region == intrinsic::MeasureRegion::GeodesicBall ? "geodesic-ball" : "triangle-union"},
          {"radius", c.radius},
          {"mean_abs_error", c.meanAbsoluteError},
          {"max_abs_error", c.maxAbsoluteError},
          {"fraction_within", c.fractionWithinBand},
          {"within_band", o.withinBand},
          {"histogram_range", o.histogramRange},
          {"histogram", c.histogram},
          {"smooth_total_curvature", c.smoothTotalCurvature}};
}

}  // namespace conformesh::apps
