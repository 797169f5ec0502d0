// remesh_json.h — the report of one remesh as the JSON dict that `conformesh remesh --json` prints, built in the
// library so that `conformesh sweep` records the same keys. A copy of apps/report_json.h's converters in the library
// (the command still uses its own; switching it over is a separate change). No files, no global state.
#pragma once

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

namespace conformesh::refine {

nlohmann::json qualityJson(const QualityReport& q);
nlohmann::json uniformizationJson(const intrinsic::UniformizationReport& u);
nlohmann::json refineStatisticsJson(const RefineStatistics& s);
// Summary figures and the histogram; per-vertex values are left to the output files.
nlohmann::json curvatureMeasureJson(const intrinsic::CurvatureMeasureResult& c,
                                    const intrinsic::CurvatureMeasureOptions& o);

// The dict of `remesh FAMILY --json` (without "output" / "vtk", and without "gaussian_curvature_measure", which the
// caller adds when it ran the check): metric, eps, ratio_bound, smoothing_passes, segment_rule, t0, uniformization,
// disk_target, refinement, quality_uniformized, quality, inverted_triangles, total_area, seconds.
nlohmann::json metricRemeshJson(const RemeshResult& r, const intrinsic::SmoothMetric& metric,
                                const RemeshOptions& options);
// The dict of `remesh MESHFILE --json` (the same omissions): input, eps, ratio_bound, refine_in, smoothing_passes,
// segment_rule, input_mesh, refinement, quality, inverted_triangles, orientation_checked_triangles, same_face_edges,
// max_same_face_length_error, loop_edges, total_area, seconds; on the uniformized route also uniformization,
// quality_uniformized, path_pieces, input_edge_crossings, max_path_excess.
nlohmann::json meshRemeshJson(const MeshRemeshResult& r, const MeshInput& input, const MeshRemeshOptions& options);

}  // namespace conformesh::refine
