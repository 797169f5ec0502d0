// horizon_input.cpp — `--horizon` / `--spatial-metric` and the horizon report (horizon_input.h).
#include "horizon_input.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/horizon_diagnostics.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/spatial_metric_registry.h"
#include "conformesh/intrinsic/metric/strahlkorper_io.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::apps {

void addHorizonOptions(CLI::App* sub, HorizonInput& h) {
  sub->add_option("--horizon", h.shape,
                  "Strahlkorper shape instead of a family: JSON or FILE.h5[:/group], coefficients or a sampled "
                  "theta-phi radius. Details: docs/cli.md#horizons");
  sub->add_option("--spatial-metric", h.spatialMetric,
                  "3-metric of --horizon: kerr-schild, schwarzschild-isotropic, flat (--param M=, a=, cx=, ...) or a sampled "
                  "grid FILE.h5[:/group]. "
                  "Details: docs/cli.md#horizons")
      ->capture_default_str();
}

std::unique_ptr<intrinsic::SmoothMetric> loadMetricOrHorizon(const std::string& command, const std::string& family,
                                                             const std::vector<std::string>& params,
                                                             const std::string& field, const HorizonInput& h) {
  if (!h.given()) return loadMetric(command, family, params, field);
  if (!family.empty() || !field.empty())
    throw InputError(command + ": --horizon replaces the FAMILY and --field; give only one of them");
  progress("reading horizon shape " + h.shape + " in " + h.spatialMetric);
  intrinsic::HorizonShapeRecord shape = intrinsic::readHorizonShape(h.shape);
  if (shape.sampled) {
    char line[200];
    std::snprintf(line, sizeof line, "sampled radius fitted at l_max = %d: residual at the nodes max %.3g, rms %.3g",
                  shape.fit.lMax, shape.fit.maxResidual, shape.fit.rmsResidual);
    progress(line);
  }
  return std::make_unique<intrinsic::HorizonSurfaceMetric>(
      std::move(shape.shape), intrinsic::makeSpatialMetric(h.spatialMetric, parseParameters(params)));
}

nlohmann::json horizonShapeReportJson(const HorizonInput& h) {
  if (!h.given()) return nullptr;
  return refine::horizonShapeJson(intrinsic::readHorizonShape(h.shape));
}

nlohmann::json horizonReportJson(const intrinsic::SmoothMetric& metric, double meshArea) {
  progress("horizon diagnostics (area, circumferences, spin)");
  return refine::horizonJson(metric, meshArea);
}

namespace {
// One report line for the approximate Killing vector: null figures (degenerate, no axis) print as "none".
std::string figure(const nlohmann::json& value, const char* format) {
  if (!value.is_number()) return "none";
  char text[64];
  std::snprintf(text, sizeof text, format, value.get<double>());
  return text;
}

void printKillingLine(const nlohmann::json& k) {
  std::printf("  %-34s lambda*A/4pi %.3g%s, C_eq %s, spin %s\n", "approximate Killing vector",
              k["scaled_eigenvalues"][0].get<double>(), k["degenerate"].get<bool>() ? " (degenerate: no single axis)" : "",
              figure(k["equatorial_circumference_killing"], "%.9g").c_str(), figure(k["spin_from_killing"], "%.6f").c_str());
}
}  // namespace

void printHorizonReport(const nlohmann::json& h) {
  std::printf("  %-34s %.12g (mesh %.12g)\n", "horizon area", h["area"].get<double>(), h["mesh_area"].get<double>());
  std::printf("  %-34s %.12g\n", "irreducible mass sqrt(A/16pi)", h["irreducible_mass"].get<double>());
  std::printf("  %-34s equatorial %.12g, polar %.12g\n", "circumferences", h["equatorial_circumference"].get<double>(),
              h["polar_circumference"].get<double>());
  if (h["spin"].is_null())
    std::printf("  %-34s none (ratio %.6g outside Kerr's [0.608, 1])\n", "spin from C_polar/C_eq",
                h["circumference_ratio"].get<double>());
  else
    std::printf("  %-34s %.9f\n", "spin from C_polar/C_eq", h["spin"].get<double>());
  if (h.contains("killing") && h["killing"].contains("degenerate"))  // killingJson (remesh_json.h)
    printKillingLine(h["killing"]);
}

}  // namespace conformesh::apps
