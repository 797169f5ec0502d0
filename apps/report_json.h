// report_json.h — the library's report structs as JSON, shared by the subcommands that print them.
#pragma once

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"

namespace conformesh::apps {

nlohmann::json qualityJson(const refine::QualityReport& q);
nlohmann::json uniformizationJson(const intrinsic::UniformizationReport& u);
nlohmann::json refineStatisticsJson(const refine::RefineStatistics& s);
// Summary figures and the histogram; per-vertex values are left to the output files.
nlohmann::json curvatureMeasureJson(const intrinsic::CurvatureMeasureResult& c,
                                    const intrinsic::CurvatureMeasureOptions& o);

}  // namespace conformesh::apps
