// horizon_input.h — the `--horizon SHAPE.json --spatial-metric NAME` input shared by `remesh` and `convergence`
// (a Strahlkörper in a spatial 3-metric, horizon_surface.h), and the horizon diagnostics of the report
// (horizon_diagnostics.h). Parsing and printing only. Details: docs/cli.md#horizons, docs/horizons.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::apps {

struct HorizonInput {
  std::string shape;                        // --horizon: Strahlkörper JSON; empty when not given
  std::string spatialMetric = "kerr-schild";  // --spatial-metric
  bool given() const { return !shape.empty(); }
};

// Registers --horizon and --spatial-metric.
void addHorizonOptions(CLI::App* sub, HorizonInput& h);

// The metric a command was given: the horizon's induced metric when --horizon is set (the --param values go to the
// spatial metric; a FAMILY or --field as well is an InputError prefixed with `command`), else loadMetric's.
std::unique_ptr<intrinsic::SmoothMetric> loadMetricOrHorizon(const std::string& command, const std::string& family,
                                                             const std::vector<std::string>& params,
                                                             const std::string& field, const HorizonInput& h);

// How --horizon's shape was given (refine::horizonShapeJson: form, l_max, the sampled fit's residual); null without.
nlohmann::json horizonShapeReportJson(const HorizonInput& h);

// The report's "horizon" object: area (smooth metric), mesh_area, irreducible_mass, equatorial_circumference,
// polar_circumference, spin (null when the circumference ratio is outside Kerr's range), and the Kerr values for the
// spatial metric's parameters when it is kerr-schild.
nlohmann::json horizonReportJson(const intrinsic::SmoothMetric& metric, double meshArea);
// Its text lines for the remesh report.
void printHorizonReport(const nlohmann::json& horizon);

}  // namespace conformesh::apps
