// remesh_json.cpp — the libraries' report structs and one remesh as JSON (see remesh_json.h).
#include "conformesh/refine/pipeline/remesh_json.h"

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
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

nlohmann::json readingJson(const intrinsic::ConversionReport& reading) {
  return {{"reoriented_faces", reading.build.reorientedFaces},
          {"unreferenced_vertices_removed", reading.unreferencedVerticesRemoved},
          {"polygons_fan_triangulated", reading.polygonsTriangulated},
          {"tristrip_triangles", reading.stripTriangles},
          {"lengths_from", reading.lengthsFromPositions ? "positions" : "edge element"}};
}

nlohmann::json verificationJson(const OutputVerification& check) {
  return {{"passed", check.passed()},
          {"failures", check.failures},
          {"faces_checked", check.facesChecked},
          {"area_relative_error", check.areaRelativeError}};
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
          {"smooth_total_curvature", c.smoothTotalCurvature},
          {"sampled_centres", static_cast<int>(c.centres.size())},  // 0: the exact all-vertex check
          {"mean_abs_error_half_width_95", c.meanAbsoluteErrorHalfWidth}};
}

nlohmann::json meshSummaryJson(const intrinsic::MeshSummary& s) {
  const auto degrees = [](double radians) { return radians * 180.0 / M_PI; };
  nlohmann::json comps = nlohmann::json::array();
  for (const auto& c : s.components)
    comps.push_back({{"vertices", c.vertices},
                     {"edges", c.edges},
                     {"faces", c.faces},
                     {"boundary_loops", c.boundaryLoops},
                     {"euler_characteristic", c.eulerCharacteristic},
                     {"genus", c.genus}});
  // Several components: each one's own area and Gauss–Bonnet (a connected surface's are the totals below).
  for (std::size_t i = 0; i < s.componentFigures.size(); ++i) {
    const intrinsic::ComponentFigures& f = s.componentFigures[i];
    comps[i]["total_area"] = f.area;
    comps[i]["total_curvature"] = f.curvature.interiorDeficit + f.curvature.boundaryTurning;
    comps[i]["gauss_bonnet_residual"] = f.curvature.gaussBonnetResidual;
  }
  return {{"background", intrinsic::toString(s.background)},
          {"vertices", s.vertices},
          {"edges", s.edges},
          {"faces", s.faces},
          {"components", comps},
          {"boundary_loops", s.boundaryLoops},
          {"euler_characteristic", s.eulerCharacteristic},
          {"genus", s.genus},
          {"total_area", s.totalArea},
          {"interior_angle_deficit", s.curvature.interiorDeficit},
          {"boundary_turning", s.curvature.boundaryTurning},
          {"background_curvature_term", s.curvature.backgroundTerm},
          {"total_curvature", s.curvature.interiorDeficit + s.curvature.boundaryTurning},
          {"gauss_bonnet_residual", s.curvature.gaussBonnetResidual},
          {"min_corner_angle_deg", degrees(s.minCornerAngle)},
          {"max_corner_angle_deg", degrees(s.maxCornerAngle)},
          {"min_angle_sum_deg", degrees(s.minAngleSum)},
          {"min_angle_sum_vertex", s.minAngleSumVertex},
          {"min_edge_length", s.minEdgeLength},
          {"max_edge_length", s.maxEdgeLength},
          {"non_delaunay_edges", s.nonDelaunayEdges},
          {"non_delaunay_fraction", s.nonDelaunayFraction}};
}

nlohmann::json uniformizedJson(const intrinsic::Uniformization& u) {
  const auto& r = u.report;
  nlohmann::json j = {{"target", intrinsic::toString(r.target)},
                      {"background", intrinsic::toString(u.uniform.background)},
                      {"genus", r.genus},
                      {"boundary_loops", r.boundaryLoops},
                      {"newton_steps", r.newtonSteps},
                      {"flips", r.flips},
                      {"max_curvature_residual", r.maxResidual},
                      {"tolerance", r.effectiveTolerance},
                      {"max_interior_angle_sum_error", intrinsic::maxInteriorAngleSumError(u.uniform)},
                      {"gauss_bonnet_residual", intrinsic::curvatureTotals(u.uniform).gaussBonnetResidual},
                      {"total_area", intrinsic::totalArea(u.uniform)},
                      {"seconds", r.seconds}};
  if (r.target == intrinsic::UniformizationTarget::Sphere) {
    j["puncture_vertex"] = r.punctureVertex;
    j["puncture_attempts"] = r.punctureAttempts;
    j["centring_iterations"] = r.centringIterations;
  }
  if (r.target == intrinsic::UniformizationTarget::FlatCylinder) j["cylinder_height"] = r.cylinderHeight;
  if (!u.insertedVertices.empty()) {
    // The half of the double or boundary edges split (uniformization.h): vertices V.. of T0* on input boundary edges.
    nlohmann::json inserted = nlohmann::json::array();
    for (const auto& q : u.insertedVertices)
      inserted.push_back({{"vertex", q.vertex}, {"input_edge", q.inputEdge}, {"parameter", q.parameter}});
    j["inserted_boundary_vertex_count"] = u.insertedVertices.size();
    j["inserted_boundary_vertices"] = inserted;
    j["inserted_by"] =
        u.insertion == intrinsic::Uniformization::Insertion::BoundarySplits ? "boundary-splits" : "mirror-crossings";
  }
  return j;
}

nlohmann::json componentTopologyJson(int index, const intrinsic::ComponentTopology& t) {
  return {{"component", index},
          {"vertices", t.vertices},
          {"edges", t.edges},
          {"faces", t.faces},
          {"boundary_loops", t.boundaryLoops},
          {"euler_characteristic", t.eulerCharacteristic},
          {"genus", t.genus}};
}

nlohmann::json componentUniformizationJson(const intrinsic::ComponentUniformization& u) {
  nlohmann::json parts = nlohmann::json::array();
  double area = 0;
  for (std::size_t i = 0; i < u.parts.size(); ++i) {
    nlohmann::json j = uniformizedJson(u.parts[i]);
    j.update(componentTopologyJson(static_cast<int>(i), u.components[i].topology));
    j["target_curvature"] = intrinsic::backgroundCurvature(u.parts[i].uniform.background);
    area += j["total_area"].get<double>();
    parts.push_back(j);
  }
  return {{"component_count", u.parts.size()}, {"total_area", area}, {"seconds", u.seconds}, {"components", parts}};
}

nlohmann::json refineJson(const RefineResult& r, const intrinsic::IntrinsicTriangulation& input,
                          const RefineOptions& o, const QualityReport& q, double seconds) {
  const RefineStatistics& s = r.statistics;
  return {{"background", intrinsic::toString(input.background)},
          {"epsilon", o.epsilon},
          {"ratio_bound", o.ratioBound},
          {"graded", !o.lambda.empty()},
          {"seconds", seconds},
          {"statistics",
           {{"input_vertices", s.inputVertices},
            {"circumcenter_insertions", s.circumcenterInsertions},
            {"centroid_insertions", s.centroidInsertions},
            {"off_center_insertions", s.offCenterInsertions},
            {"boundary_splits", s.boundarySplits},
            {"rejected_circumcenters", s.rejectedCircumcenters},
            {"segment_rule", segmentRuleName(o.segmentRule)},
            {"deleted_vertices", s.deletedVertices},
            {"refused_deletions", s.refusedDeletions},
            {"flips", s.flips},
            {"trace_steps", s.traceSteps},
            {"boundary_loops", s.boundaryLoops},
            {"circle_loops", s.circleLoops},
            {"smoothing_passes", o.smoothingPasses},
            {"smoothing_moves", s.smoothingMoves},
            {"smoothing_refused", s.smoothingRefused},
            {"insertions_after_smoothing", s.insertionsAfterSmoothing}}},
          {"quality", qualityJson(q)}};
}

nlohmann::json embeddingJson(const embedding::EmbeddingResult& fit, const intrinsic::IntrinsicTriangulation& input) {
  return {{"vertices", input.mesh.nVertices()},
          {"edges", input.mesh.nEdges()},
          {"start", fit.start},
          {"tolerance", fit.tolerance},
          {"isometric", fit.isometric},
          {"max_relative_residual", fit.maxRelativeResidual},
          {"rms_relative_residual", fit.rmsRelativeResidual},
          {"worst_edge", fit.worstEdge},
          {"regularized_iterations", fit.regularizedIterations},
          {"iterations", fit.iterations},
          {"start_seconds", fit.startSeconds},
          {"fit_seconds", fit.fitSeconds},
          {"verdict", fit.verdict}};
}

nlohmann::json remeshEmbeddingJson(const embedding::EmbeddingResult& fit, const intrinsic::IntrinsicTriangulation& mesh) {
  nlohmann::json j = embeddingJson(fit, mesh);
  j["known_embedding"] = false;
  j["positions_written"] = fit.isometric;
  j["drawn_in"] = fit.isometric ? "fitted embedding" : "canonical domain";
  return j;
}

nlohmann::json remeshKnownEmbeddingJson() {
  return {{"known_embedding", true}, {"positions_written", false}, {"drawn_in", "known embedding"}};
}

nlohmann::json remeshEmbeddingErrorJson(const std::string& error) {
  return {{"known_embedding", false}, {"positions_written", false}, {"drawn_in", "canonical domain"}, {"error", error}};
}

nlohmann::json smoothReferenceJson(const intrinsic::SmoothReferenceComparison& c) {
  const auto finiteOrNull = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  return {{"mesh_area", c.meshArea},
          {"smooth_area", c.smoothArea},
          {"smooth_area_error_estimate", c.smoothAreaErrorEstimate},
          {"area_relative_difference", c.areaRelativeDifference},
          {"mesh_total_curvature", c.meshTotalCurvature},
          {"smooth_total_curvature", c.smoothTotalCurvature},
          {"smooth_total_curvature_error_estimate", c.smoothTotalCurvatureErrorEstimate},
          {"total_curvature_difference", c.totalCurvatureDifference},
          {"total_curvature_relative_difference", finiteOrNull(c.totalCurvatureRelativeDifference)},
          {"euler_characteristic", c.eulerCharacteristic},
          {"gauss_bonnet", c.boundaryLoops == 0 ? nlohmann::json(2 * M_PI * c.eulerCharacteristic) : nlohmann::json(nullptr)}};
}

nlohmann::json convergenceLevelJson(const ConvergenceLevel& L, bool extrinsic, const ConvergenceOptions& o) {
  nlohmann::json level = {{"target_vertices", L.targetVertices},
                          {"vertices", L.vertices},
                          {"triangles", L.triangles},
                          {"eps", L.epsilon},
                          {"quality", qualityJson(L.quality)},
                          {"inverted_triangles", L.invertedTriangles},
                          {"total_area", L.totalArea},
                          {"gaussian_curvature_measure", curvatureMeasureJson(L.measure, o.measure)},
                          {"seconds", L.seconds}};
  if (extrinsic)
    level["extrinsic"] = {{"e_H", L.meanCurvature.meanAbsoluteError},
                          {"max_abs_error", L.meanCurvature.maxAbsoluteError},
                          {"mean_relative_error", L.meanCurvature.meanRelativeError},
                          {"fraction_within", L.meanCurvature.fractionWithinBand},
                          {"within_band", o.meanCurvature.withinBand},
                          {"histogram_range", o.meanCurvature.histogramRange},
                          {"histogram", L.meanCurvature.histogram},
                          {"radius", L.meanCurvature.radius},
                          {"discrete_total", L.meanCurvature.discreteTotal},
                          {"smooth_total", L.meanCurvature.smoothTotal},
                          {"hausdorff", L.deviation.hausdorffClosest},
                          {"hausdorff_natural", L.deviation.hausdorffNatural},
                          {"mean_distance", L.deviation.meanClosest},
                          {"normal_deviation", L.deviation.normalDeviation},
                          {"mean_normal_deviation", L.deviation.meanNormalDeviation},
                          {"normal_deviation_natural", L.deviation.normalDeviationNatural},
                          {"flipped_faces", L.deviation.flippedFaces}};
  return level;
}

nlohmann::json convergenceStudyJson(const ConvergenceStudy& study, const ConvergenceOptions& o) {
  nlohmann::json levels = nlohmann::json::array();
  for (const auto& L : study.levels) levels.push_back(convergenceLevelJson(L, study.extrinsic, o));
  nlohmann::json j = {{"metric", study.metric},
                      {"smooth_area", study.smoothArea},
                      {"t0_vertices", study.t0Vertices},
                      {"ratio_bound", o.remesh.ratioBound},
                      {"smoothing_passes", o.remesh.refinement.smoothingPasses},
                      {"uniformization", uniformizationJson(study.uniformization)},
                      {"orders",
                       {{"e_G_vs_mean_circumradius", study.orderErrorVsCircumradius},
                        {"mean_circumradius_vs_vertices", study.orderCircumradiusVsVertices},
                        {"area_error_vs_mean_circumradius", study.orderAreaVsCircumradius}}},
                      {"levels", levels}};
  if (study.extrinsic) {
    j["orders"]["e_H_vs_mean_circumradius"] = study.orderMeanCurvatureVsCircumradius;
    j["orders"]["hausdorff_vs_mean_circumradius"] = study.orderHausdorffVsCircumradius;
    j["orders"]["normal_deviation_vs_mean_circumradius"] = study.orderNormalDeviationVsCircumradius;
  }
  return j;
}

nlohmann::json metricRemeshJson(const RemeshResult& r, const intrinsic::SmoothMetric& metric,
                                const RemeshOptions& o) {
  return {{"metric", metric.description()},
          {"eps", r.epsilon},
          {"expected_vertices", r.expected.expected},
          {"notices", r.notices},
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
          {"smooth_reference", smoothReferenceJson(intrinsic::compareWithSmoothMetric(r.mesh, metric))},
          {"seconds",
           {{"discretize", r.seconds.discretize},
            {"uniformize", r.seconds.uniformize},
            {"refine", r.seconds.refine},
            {"pull_back", r.seconds.pullBack}}}};
}

nlohmann::json meshRemeshJson(const MeshRemeshResult& r, const intrinsic::IntrinsicTriangulation& input,
                              const std::string& source, const MeshRemeshOptions& o) {
  nlohmann::json j = {
      {"input", source},
      {"eps", r.epsilon},
      {"expected_vertices", r.expected.expected},
      {"notices", r.notices},
      {"ratio_bound", o.ratioBound},
      {"refine_in", toString(r.refinedIn)},
      {"smoothing_passes", o.refinement.smoothingPasses},
      {"segment_rule", segmentRuleName(o.refinement.segmentRule)},
      {"input_mesh",
       {{"vertices", r.inputVertices}, {"faces", r.inputFaces}, {"area", intrinsic::totalArea(input)}}},
      {"refinement", refineStatisticsJson(r.refinement)},
      {"quality", qualityJson(r.quality)},
      {"inverted_triangles", r.invertedTriangles},
      {"orientation_checked_triangles", r.orientationChecked},
      {"same_face_edges", r.sameFaceEdges},
      {"max_same_face_length_error", r.maxSameFaceLengthError},
      {"max_same_face_scaled_error", r.maxSameFaceScaledError},
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

nlohmann::json horizonJson(const intrinsic::SmoothMetric& metric, double meshArea,
                           const intrinsic::HorizonDiagnosticsOptions& options) {
  const intrinsic::HorizonDiagnostics d = intrinsic::horizonDiagnostics(metric, options);
  return {{"area", d.area},
          {"mesh_area", meshArea},
          {"irreducible_mass", d.irreducibleMass},
          {"equatorial_circumference", d.equatorialCircumference},
          {"polar_circumference", d.polarCircumference},
          {"min_polar_circumference", d.minPolarCircumference},
          {"circumference_ratio", d.circumferenceRatio},
          {"spin", std::isfinite(d.spin) ? nlohmann::json(d.spin) : nlohmann::json(nullptr)},
          {"curves", "smooth metric, chart equator and polar great circles"}};
}

namespace {

nlohmann::json finiteOrNull(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json poleJson(const intrinsic::IntrinsicTriangulation& mesh, const intrinsic::KillingVectorResult& k, int v,
                        const std::vector<Eigen::Vector3d>& reference, const intrinsic::ChartDomain& domain) {
  const Eigen::Vector2d uv = intrinsic::chartPoint(domain, intrinsic::refinedExtremum(mesh, k.potential, v, reference));
  return {{"vertex", v}, {"u", uv[0]}, {"v", uv[1]}};
}

}  // namespace

nlohmann::json horizonShapeJson(const intrinsic::HorizonShapeRecord& shape) {
  const Eigen::Vector3d& c = shape.shape.center();
  nlohmann::json j = {{"form", shape.sampled ? "sampled" : "coefficients"},
                      {"l_max", shape.shape.lMax()},
                      {"center", {c.x(), c.y(), c.z()}}};
  if (shape.sampled) {
    j["l_max"] = shape.fit.lMax;
    j["theta_nodes"] = intrinsic::toString(shape.fit.nodes);
    j["grid"] = {shape.fit.nTheta, shape.fit.nPhi};
    j["max_residual"] = shape.fit.maxResidual;
    j["rms_residual"] = shape.fit.rmsResidual;
  }
  return j;
}

nlohmann::json killingJson(const intrinsic::IntrinsicTriangulation& mesh, const std::vector<Eigen::Vector3d>& reference,
                           const intrinsic::ChartDomain& domain, const intrinsic::KillingVectorOptions& options) {
  intrinsic::KillingVectorResult k;
  try {
    k = intrinsic::approximateKillingVector(mesh, options);
  } catch (const ConvergenceError& e) {
    return {{"error", e.what()}};
  }
  nlohmann::json j = {{"eigenvalue", k.eigenvalues[0]},
                      {"scaled_eigenvalues", k.scaledEigenvalues},
                      {"degenerate", k.degenerate},
                      {"north_pole", nullptr},
                      {"south_pole", nullptr},
                      {"equatorial_circumference_killing", finiteOrNull(k.longestOrbit)},
                      {"mid_level_circumference", finiteOrNull(k.midLevelCircumference)},
                      {"spin_from_killing", finiteOrNull(k.spin)}};
  if (!k.degenerate) {
    j["north_pole"] = poleJson(mesh, k, k.northVertex, reference, domain);
    j["south_pole"] = poleJson(mesh, k, k.southVertex, reference, domain);
  }
  return j;
}

nlohmann::json componentRemeshJson(const ComponentRemesh& r, const intrinsic::IntrinsicTriangulation& input,
                                   const std::string& source, const MeshRemeshOptions& options) {
  nlohmann::json parts = nlohmann::json::array();
  double area = 0;
  int vertices = 0, faces = 0;
  for (std::size_t i = 0; i < r.parts.size(); ++i) {
    nlohmann::json j = meshRemeshJson(r.parts[i], r.components[i].triangulation, source, options);
    j.erase("input");
    j.update(componentTopologyJson(static_cast<int>(i), r.components[i].topology));
    area += intrinsic::totalArea(r.parts[i].mesh);
    vertices += r.parts[i].mesh.mesh.nVertices();
    faces += r.parts[i].mesh.mesh.nFaces();
    parts.push_back(j);
  }
  return {
      {"input", source},
      {"eps", r.epsilon},
      {"refine_in", toString(options.refineIn)},
      {"component_count", r.parts.size()},
      {"input_mesh",
       {{"vertices", input.mesh.nVertices()}, {"faces", input.mesh.nFaces()}, {"area", intrinsic::totalArea(input)}}},
      {"output_mesh", {{"vertices", vertices}, {"faces", faces}}},
      {"total_area", area},
      {"components", parts}};
}

}  // namespace conformesh::refine
