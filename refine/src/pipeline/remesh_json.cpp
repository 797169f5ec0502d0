// remesh_json.cpp — the `remesh --json` dict of one remesh (see remesh_json.h); the converters are apps/report_json's.
#include "conformesh/refine/pipeline/remesh_json.h"

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::refine {

namespace {
const char* segmentRuleName(SegmentRule s) {
  return s == SegmentRule::Chew ? "chew" : "ruppert";
}
}  // namespace

nlohmann::json qualityJson(const QualityReport& q) {
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

nlohmann::json refineStatisticsJson(const RefineStatistics& s) {
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

nlohmann::json metricRemeshJson(const RemeshResult& r, const intrinsic::SmoothMetric& metric,
                                const RemeshOptions& o) {
  return {{"metric", metric.description()},
          {"eps", o.epsilon},
          {"ratio_bound", o.ratioBound},
          {"smoothing_passes", o.refinement.smoothingPasses},
          {"segment_rule", segmentRuleName(o.refinement.segmentRule)},
          {"t0", {{"vertices", r.t0Vertices}, {"faces", r.t0Faces}}},
          {"uniformization", uniformizationJson(r.uniformization)},
          {"disk_target", toString(r.diskTarget)},
          {"refinement", refineStatisticsJson(r.refinement)},
          {"quality_uniformized", qualityJson(r.uniformQuality)},
          {"quality", qualityJson(r.quality)},
          {"inverted_triangles", r.invertedTriangles},
          {"total_area", intrinsic::totalArea(r.mesh)},
          {"seconds",
           {{"discretize", r.seconds.discretize},
            {"uniformize", r.seconds.uniformize},
            {"refine", r.seconds.refine},
            {"pull_back", r.seconds.pullBack}}}};
}

nlohmann::json meshRemeshJson(const MeshRemeshResult& r, const MeshInput& in, const MeshRemeshOptions& o) {
  nlohmann::json j = {
      {"input", in.source},
      {"eps", o.epsilon},
      {"ratio_bound", o.ratioBound},
      {"refine_in", toString(r.refinedIn)},
      {"smoothing_passes", o.refinement.smoothingPasses},
      {"segment_rule", segmentRuleName(o.refinement.segmentRule)},
      {"input_mesh",
       {{"vertices", r.inputVertices}, {"faces", r.inputFaces}, {"area", intrinsic::totalArea(in.triangulation)}}},
      {"refinement", refineStatisticsJson(r.refinement)},
      {"quality", qualityJson(r.quality)},
      {"inverted_triangles", r.invertedTriangles},
      {"orientation_checked_triangles", r.orientationChecked},
      {"same_face_edges", r.sameFaceEdges},
      {"max_same_face_length_error", r.maxSameFaceLengthError},
      {"loop_edges", r.loopEdges},
      {"total_area", intrinsic::totalArea(r.mesh)},
      {"seconds",
       {{"uniformize", r.seconds.uniformize}, {"refine", r.seconds.refine}, {"pull_back", r.seconds.pullBack}}}};
  if (r.refinedIn == RefineMetric::Uniformized) {
    j["uniformization"] = uniformizationJson(r.uniformization);
    j["quality_uniformized"] = qualityJson(r.uniformQuality);
    j["path_pieces"] = r.pathPieces;
    j["input_edge_crossings"] = r.inputEdgeCrossings;
    j["max_path_excess"] = r.maxBendExcess;
  }
  return j;
}

}  // namespace conformesh::refine
