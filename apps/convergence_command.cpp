// convergence_command.cpp — `conformesh convergence FAMILY [--vertices 1k,2k,...]`: the paper's §6 study on any smooth
// metric: a table (CSV and JSON) of vertices, triangles, circumradii, angles, e_G and time per mesh, the fitted orders,
// and PNG plots of Figs. 10 (a–d), 11 (a, c) and 12 (histogram) drawn by scripts/plot_convergence.py (matplotlib).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/refine/pipeline/convergence_study.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "horizon_input.h"
#include "usage_errors.h"

namespace conformesh::apps {

namespace {

struct ConvergenceArgs {
  std::string family;
  std::vector<std::string> params;
  std::string field;
  std::string vertices;
  int levels = 0;
  double ratio = 1.4142135623730951;
  int t0Resolution = 10;
  std::string diskTarget = "auto";
  int smoothing = refine::ConvergenceOptions{}.remesh.refinement.smoothingPasses;
  std::string smoothingRule = "odt";
  std::string prefix = "convergence";
  bool json = false, noPlot = false;
  HorizonInput horizon;
};

// "1k,2k,4500" → {1000, 2000, 4500}.
std::vector<int> parseCounts(const std::string& list) {
  std::vector<int> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    double x = std::strtod(item.c_str(), &end);
    if (end && (*end == 'k' || *end == 'K')) {
      x *= 1000;
      ++end;
    }
    if (item.empty() || !end || *end != '\0' || !(x >= 10) || x > 1e8)
      throw UsageError("--vertices: '" + item + "' is not a vertex count (expected e.g. 1k,2k,4500)");
    out.push_back(static_cast<int>(x));
  }
  return out;
}

// The library's "convergence: what" as "what": the usage error's line names the command itself.
std::string withoutCommand(const std::string& message) {
  const std::string prefix = "convergence: ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// Step 1 (parse): the study's options from the command line.
refine::ConvergenceOptions studyOptions(const ConvergenceArgs& a) {
  refine::ConvergenceOptions o;
  if (!a.vertices.empty()) {
    o.targetVertices = parseCounts(a.vertices);
  } else if (a.levels > 0) {
    // The first `levels` of the paper's Table 2 counts.
    if (a.levels < 3 || a.levels > 11)
      throw UsageError("--levels: expected 3 to 11, found " + std::to_string(a.levels));
    o.targetVertices.resize(a.levels);
  }
  o.remesh.ratioBound = a.ratio;
  o.remesh.t0Resolution = a.t0Resolution;
  o.remesh.diskTarget = refine::parseDiskTarget(a.diskTarget);
  o.remesh.refinement.smoothingPasses = a.smoothing;
  o.remesh.refinement.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.progress = [](const std::string& s) { progress(s); };
  o.extrinsic = true;  // used when the metric has an embedding
  if (const std::string problem = o.validate(); !problem.empty()) throw UsageError(withoutCommand(problem));
  return o;
}

// Step 3a: PREFIX.csv, one row per level; the extrinsic columns (embedding/) are empty without an embedding.
void writeCsv(const refine::ConvergenceStudy& study, const std::string& csvPath) {
  std::ofstream csv(csvPath);
  if (!csv) throw InputError(csvPath + ": cannot open for writing");
  csv << "target_vertices,vertices,triangles,eps,max_circumradius,mean_circumradius,min_angle_deg,"
         "mean_min_angle_deg,e_G,max_error,fraction_within,inverted_triangles,total_area,gauss_bonnet_residual,"
         "seconds,e_H,hausdorff,normal_deviation\n";
  for (const auto& L : study.levels) {
    char row[512];
    std::snprintf(row, sizeof row, "%d,%d,%d,%.10g,%.10g,%.10g,%.6f,%.6f,%.10g,%.10g,%.6f,%d,%.15g,%.3e,%.3f\n",
                  L.targetVertices, L.vertices, L.triangles, L.epsilon, L.quality.maxCircumradius,
                  L.quality.meanCircumradius, L.quality.minAngleDeg, L.quality.meanMinAngleDeg,
                  L.measure.meanAbsoluteError, L.measure.maxAbsoluteError, L.measure.fractionWithinBand,
                  L.invertedTriangles, L.totalArea, L.quality.gaussBonnetResidual, L.seconds);
    csv << std::string(row, std::strlen(row) - 1);
    if (study.extrinsic)
      csv << "," << L.meanCurvature.meanAbsoluteError << "," << L.deviation.hausdorffClosest << ","
          << L.deviation.normalDeviation;
    else
      csv << ",,,";
    csv << "\n";
  }
}

// Step 3b: the JSON report (written to PREFIX.json; printed, without the per-vertex errors, with --json): the
// library's dict plus the finest level's per-vertex relative errors, which the plots draw.
nlohmann::json studyJson(const refine::ConvergenceStudy& study, const refine::ConvergenceOptions& o) {
  nlohmann::json j = refine::convergenceStudyJson(study, o);
  j["finest_relative_errors"] = study.levels.back().measure.relativeError;
  if (study.extrinsic) j["finest_mean_curvature_relative_errors"] = study.levels.back().meanCurvature.relativeError;
  return j;
}

// Step 3c: the PNG plots by scripts/plot_convergence.py; returns the files it wrote (none when python3-matplotlib is
// missing: then a progress line says so).
std::vector<std::string> drawPlots(const std::string& jsonPath, const std::string& prefix, bool extrinsic) {
  std::vector<std::string> written;
  // The installed script, else the source tree's (running from a build folder).
  const std::string script = std::filesystem::exists(CONFORMESH_INSTALLED_PLOT_SCRIPT)
                                 ? CONFORMESH_INSTALLED_PLOT_SCRIPT
                                 : CONFORMESH_SOURCE_PLOT_SCRIPT;
  const std::string python = scriptInterpreter();  // CMake's CONFORMESH_PYTHON (cli_common.h)
  const std::string cmd = python + " '" + script + "' '" + jsonPath + "' '" + prefix + "'";
  if (std::system(cmd.c_str()) != 0)
    progress("plots skipped: `" + cmd + "` failed (needs python3-matplotlib); the CSV and JSON are written");
  else
    for (const char* s : {"_fig10.png", "_fig11.png", "_fig12.png"}) written.push_back(prefix + s);
  if (extrinsic && std::filesystem::exists(prefix + "_fig13.png")) written.push_back(prefix + "_fig13.png");
  return written;
}

// Step 4 (print): the text table, the fitted orders and the files written.
void printStudy(const refine::ConvergenceStudy& study, const std::vector<std::string>& written) {
  std::printf("%s: %zu meshes, T0 of %d vertices\n", study.metric.c_str(), study.levels.size(), study.t0Vertices);
  std::printf("%9s %9s %11s %11s %9s %9s %11s %8s %7s\n", "vertices", "triangles", "max R", "mean R", "min ang",
              "mean min", "e_G", "within", "sec");
  for (const auto& L : study.levels)
    std::printf("%9d %9d %11.4e %11.4e %9.3f %9.3f %11.4e %7.1f%% %7.2f\n", L.vertices, L.triangles,
                L.quality.maxCircumradius, L.quality.meanCircumradius, L.quality.minAngleDeg, L.quality.meanMinAngleDeg,
                L.measure.meanAbsoluteError, 100 * L.measure.fractionWithinBand, L.seconds);
  std::printf("fitted orders: e_G ~ R^%.3f, mean R ~ V^%.3f, |area error| ~ R^%.3f\n", study.orderErrorVsCircumradius,
              study.orderCircumradiusVsVertices, study.orderAreaVsCircumradius);
  if (study.extrinsic) {
    std::printf(
        "extrinsic (the metric's embedding): e_H over balls of radius 0.08*sqrt(area), "
        "Hausdorff max|q - pi(q)|, max normal deviation\n");
    std::printf("%9s %11s %11s %11s %8s\n", "vertices", "e_H", "Hausdorff", "normal dev", "within");
    for (const auto& L : study.levels)
      std::printf("%9d %11.4e %11.4e %11.4e %7.1f%%\n", L.vertices, L.meanCurvature.meanAbsoluteError,
                  L.deviation.hausdorffClosest, L.deviation.normalDeviation, 100 * L.meanCurvature.fractionWithinBand);
    std::printf("fitted orders: e_H ~ R^%.3f (>= 1), Hausdorff ~ R^%.3f (2), normal deviation ~ R^%.3f (1)\n",
                study.orderMeanCurvatureVsCircumradius, study.orderHausdorffVsCircumradius,
                study.orderNormalDeviationVsCircumradius);
  }
  for (const auto& w : written) std::printf("written: %s\n", w.c_str());
}

// parse → compute (refine::runConvergenceStudy) → write CSV, JSON, plots → print.
void run(const ConvergenceArgs& a) {
  const std::unique_ptr<intrinsic::SmoothMetric> metric =
      loadMetricOrHorizon("convergence", a.family, a.params, a.field, a.horizon);
  const refine::ConvergenceOptions o = studyOptions(a);
  refine::ConvergenceStudy study;
  try {
    study = refine::runConvergenceStudy(*metric, o);
  } catch (const refine::UnrefinedLevelError& e) {
    throw UsageError(withoutCommand(e.what()));  // targets or --t0-resolution to change: exit status 2
  }

  const std::string csvPath = a.prefix + ".csv", jsonPath = a.prefix + ".json";
  writeCsv(study, csvPath);
  nlohmann::json j = studyJson(study, o);
  std::ofstream(jsonPath) << j.dump(1) << '\n';
  std::vector<std::string> written = {csvPath, jsonPath};
  if (!a.noPlot)
    for (const std::string& w : drawPlots(jsonPath, a.prefix, study.extrinsic)) written.push_back(w);
  if (a.json) {
    j.erase("finest_relative_errors");
    j.erase("finest_mean_curvature_relative_errors");
    j["written"] = written;
    printJson(j);
    return;
  }
  printStudy(study, written);
}

}  // namespace

void registerConvergenceCommand(CLI::App& app) {
  auto a = std::make_shared<ConvergenceArgs>();
  CLI::App* sub = app.add_subcommand(
      "convergence", "Measure curvature convergence over a sweep of meshes (paper §6, Table 2, Figs. 10-13)");
  sub->footer(
      "Example: conformesh convergence kerr-newman --param a=0.95 --vertices 1k,2k,4k,8k -o kerr95\n"
      "Details: docs/cli.md#convergence");
  sub->add_option("family", a->family, "Metric family (see `conformesh discretize --list`)");
  addFieldOption(sub, a->field);
  addHorizonOptions(sub, a->horizon);
  sub->add_option("--param", a->params, "Family parameter key=value (repeatable)");
  sub->add_option("--vertices", a->vertices, "Target vertex counts, e.g. 1k,2k,4k,8k (default: the paper's Table 2)");
  sub->add_option("--levels", a->levels, "Use the first N counts of the paper's Table 2 (3..11)");
  sub->add_option("--ratio", a->ratio, "Shape bound B = circumradius / shortest edge (sqrt 2: 20.7 deg)")
      ->capture_default_str();
  sub->add_option("--t0-resolution", a->t0Resolution, "Resolution of T0, shared by all meshes")->capture_default_str();
  sub->add_option("--disk-target", a->diskTarget, "Disk charts: auto, circle (unit disk) or keep-boundary")
      ->check(oneOf({"auto", "circle", "keep-boundary"}))
      ->capture_default_str();
  addSmoothingOptions(sub, a->smoothing, a->smoothingRule, "; at every level");
  sub->add_option("-o,--output", a->prefix, "Prefix of the files written")->capture_default_str();
  sub->add_flag("--json", a->json, "Print the table and orders as JSON");
  sub->add_flag("--no-plot", a->noPlot, "Do not draw the PNG plots");
  sub->callback([a] { run(*a); });
}

}  // namespace conformesh::apps
