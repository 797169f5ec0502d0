// remesh_json.h — the library's reports as the JSON dicts that `conformesh remesh --json` (and info, uniformize,
// refine, embed, convergence) print: one definition shared by the commands, `conformesh sweep`'s records and the Python module's `.report`.
// No files, no global state.
#pragma once

#include <nlohmann/json.hpp>

#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/measure/horizon_diagnostics.h"
#include "conformesh/intrinsic/measure/killing_vector.h"
#include "conformesh/intrinsic/measure/smooth_reference.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/intrinsic/metric/strahlkorper_io.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/pipeline/component_remesh.h"
#include "conformesh/refine/pipeline/convergence_study.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "conformesh/refine/pipeline/output_verification.h"

namespace conformesh::refine {

nlohmann::json qualityJson(const QualityReport& q);
nlohmann::json uniformizationJson(const intrinsic::UniformizationReport& u);
nlohmann::json refineStatisticsJson(const RefineStatistics& s);
// What reading a mesh file did (mesh_data.h ConversionReport): reoriented_faces, unreferenced_vertices_removed,
// polygons_fan_triangulated, tristrip_triangles, lengths_from ("positions" or "edge element").
nlohmann::json readingJson(const intrinsic::ConversionReport& reading);

// An output's verification (output_verification.h): passed, failures, faces_checked, area_relative_error. The
// command adds the name it wrote ("written").
nlohmann::json verificationJson(const OutputVerification& check);

// Summary figures and the histogram; per-vertex values are left to the output files.
nlohmann::json curvatureMeasureJson(const intrinsic::CurvatureMeasureResult& c,
                                    const intrinsic::CurvatureMeasureOptions& o);

// The dict of `refine --json` without the file names: background, epsilon, ratio_bound, graded (a conformal factor
// was given), seconds (the caller's wall clock of refineDelaunay), statistics (with the options' segment rule and
// smoothing passes), quality (`q`, measureQuality of the output).
nlohmann::json refineJson(const RefineResult& r, const intrinsic::IntrinsicTriangulation& input,
                          const RefineOptions& options, const QualityReport& q, double seconds);
// The dict of `embed --json` without the file names: vertices, edges, start, tolerance, isometric, residuals, worst
// edge, iterations, seconds, verdict.
nlohmann::json embeddingJson(const embedding::EmbeddingResult& fit, const intrinsic::IntrinsicTriangulation& input);
// The "embedding" dict of `remesh --embed --json`: embeddingJson's keys plus positions_written (the fit was isometric and
// its positions are in the outputs) and drawn_in ("fitted embedding" or "canonical domain").
nlohmann::json remeshEmbeddingJson(const embedding::EmbeddingResult& fit, const intrinsic::IntrinsicTriangulation& mesh);
// The same dict when the metric has a known embedding (no fit: known_embedding true, positions_written false, drawn_in
// "known embedding") or when the fit threw (`error` is its message, positions_written false, drawn_in "canonical domain").
nlohmann::json remeshKnownEmbeddingJson();
nlohmann::json remeshEmbeddingErrorJson(const std::string& error);

// The dict of `info --json` without what depends on how the file was read (file, reoriented_faces,
// unreferenced_vertices_removed, lengths_from): topology, curvature totals, angle and length ranges, Delaunay-ness.
nlohmann::json meshSummaryJson(const intrinsic::MeshSummary& s);
// The dict of `uniformize --json` without the file names and the method: target, background, genus, boundary loops,
// Newton steps, flips, residuals, the worst interior angle sum error, Gauss–Bonnet, area, seconds, and the sphere's
// puncture figures or the cylinder's height where they apply; for the half of the double or boundary edges split
// (uniformization.h) inserted_boundary_vertex_count, inserted_boundary_vertices (vertex, input_edge, parameter each)
// and inserted_by ("mirror-crossings" or "boundary-splits").
nlohmann::json uniformizedJson(const intrinsic::Uniformization& u);
// A component's topology as the component dicts carry it: component (index), vertices, edges, faces, boundary_loops,
// euler_characteristic, genus.
nlohmann::json componentTopologyJson(int index, const intrinsic::ComponentTopology& t);
// The dict of `uniformize --json` for several components: component_count, total_area (the sum), seconds, and
// components, one uniformizedJson per component with its componentTopologyJson and target_curvature (+1, 0, −1).
nlohmann::json componentUniformizationJson(const intrinsic::ComponentUniformization& u);

// The mesh against its smooth metric (smooth_reference.h): mesh_area, smooth_area (with smooth_area_error_estimate), area_relative_difference,
// mesh_total_curvature, smooth_total_curvature, total_curvature_difference, total_curvature_relative_difference (null
// when ∫K dA vanishes), euler_characteristic, gauss_bonnet (2πχ; null with boundary).
nlohmann::json smoothReferenceJson(const intrinsic::SmoothReferenceComparison& c);
// The "horizon" dict of `remesh --horizon ... --json` and of a sweep's horizon case (horizon_diagnostics.h on the smooth
// metric): area, mesh_area (`meshArea`), irreducible_mass, equatorial_circumference, polar_circumference,
// min_polar_circumference, circumference_ratio, spin (null outside Kerr's range), curves.
nlohmann::json horizonJson(const intrinsic::SmoothMetric& metric, double meshArea,
                           const intrinsic::HorizonDiagnosticsOptions& options = {});
// The "shape" dict inside "horizon": how the Strahlkörper was given (strahlkorper_io.h) — form ("coefficients" or
// "sampled"), l_max, center, and for a sampled radius theta_nodes, grid [nθ, nφ], max_residual and rms_residual of
// the fit at the nodes.
nlohmann::json horizonShapeJson(const intrinsic::HorizonShapeRecord& shape);
// The "killing" dict inside "horizon" (killing_vector.h on the output triangulation T1, from its edge lengths alone):
// eigenvalue (λ₁, 1/length²), scaled_eigenvalues (λ_k·A/4π, k = 1..3), degenerate, and unless degenerate north_pole /
// south_pole ({vertex, u, v}: the extremal vertices of z refined on `reference`, in the chart (u, v) = (φ, θ)),
// equatorial_circumference_killing (the longest orbit), mid_level_circumference and spin_from_killing
// (χ = √(1 − (2πA/C² − 1)²), null outside Kerr's range); null entries when degenerate. A subspace iteration that does
// not converge gives {"error": message} instead of failing the command.
nlohmann::json killingJson(const intrinsic::IntrinsicTriangulation& mesh, const std::vector<Eigen::Vector3d>& reference,
                           const intrinsic::ChartDomain& domain, const intrinsic::KillingVectorOptions& options = {});

// One level of `convergence --json`: target_vertices, vertices, triangles, eps, quality, inverted_triangles,
// total_area, gaussian_curvature_measure, seconds; with `extrinsic` also the e_H, Hausdorff and normal-deviation
// figures ("extrinsic").
nlohmann::json convergenceLevelJson(const ConvergenceLevel& level, bool extrinsic, const ConvergenceOptions& options);
// The dict of `convergence --json` without the finest level's per-vertex errors: metric, smooth_area, t0_vertices,
// ratio_bound, smoothing_passes, uniformization, orders (the fitted log-log slopes), levels.
nlohmann::json convergenceStudyJson(const ConvergenceStudy& study, const ConvergenceOptions& options);

// The dict of `remesh FAMILY --json` (without "output" / "vtk", and without "gaussian_curvature_measure", which the
// caller adds when it ran the check): metric, eps, ratio_bound, smoothing_passes, segment_rule, t0, uniformization,
// disk_target, refinement, quality_uniformized, quality, inverted_triangles, total_area, smooth_reference
// (smoothReferenceJson: two quadratures over the chart, milliseconds for the analytic families), seconds.
nlohmann::json metricRemeshJson(const RemeshResult& r, const intrinsic::SmoothMetric& metric,
                                const RemeshOptions& options);
// The dict of `remesh MESHFILE --json` (the same omissions): input, eps, ratio_bound, refine_in, smoothing_passes,
// segment_rule, input_mesh, refinement, quality, inverted_triangles, orientation_checked_triangles, same_face_edges,
// max_same_face_length_error, loop_edges, total_area, seconds; on the uniformized route also uniformization,
// quality_uniformized, path_pieces, input_edge_crossings, max_path_excess.
// `input` is the triangulation remeshMesh was given, `source` the name of its file (the "input" key).
nlohmann::json meshRemeshJson(const MeshRemeshResult& r, const intrinsic::IntrinsicTriangulation& input,
                              const std::string& source, const MeshRemeshOptions& options);
// The dict of `remesh MESHFILE --json` for several components: input, eps, refine_in, component_count, input_mesh
// (vertices, faces, area of the whole input), output_mesh (vertices, faces), total_area (the sum of the components'),
// and components, one meshRemeshJson per component (against its own input component) with its
// componentTopologyJson.
nlohmann::json componentRemeshJson(const ComponentRemesh& r, const intrinsic::IntrinsicTriangulation& input,
                                   const std::string& source, const MeshRemeshOptions& options);

}  // namespace conformesh::refine
