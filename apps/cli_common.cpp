// cli_common.cpp — shared plumbing of the conformesh subcommands (see cli_common.h).
#include "cli_common.h"

#include <filesystem>

#include "conformesh/refine/pipeline/remesh_json.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/mesh_repair.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::apps {

namespace {
bool gQuiet = false;
bool gRepair = false;  // --repair of the command being run (one command per process)
}

void printJson(const nlohmann::json& j) {
  std::cout << j.dump(2) << '\n';
}

void progress(const std::string& what) {
  if (!gQuiet) std::cerr << "conformesh: " << what << std::endl;
}

void setQuiet(bool quiet) {
  gQuiet = quiet;
}

std::function<void(int, int)> countingProgress(const std::string& what) {
  using Clock = std::chrono::steady_clock;
  auto last = std::make_shared<Clock::time_point>(Clock::now());
  return [what, last](int done, int total) {
    const auto now = Clock::now();
    if (done >= total || now - *last < std::chrono::seconds(5)) return;
    *last = now;
    progress(what + ": " + std::to_string(done) + " of " + std::to_string(total) + " (" +
             std::to_string(static_cast<int>(100.0 * done / total)) + " %)");
  };
}

intrinsic::MeshData loadMesh(const std::string& path) {
  if (!gRepair) {
    intrinsic::MeshData data = intrinsic::readMesh(path);
    intrinsic::requireNoRepairNeeded(data);
    return data;
  }
  intrinsic::ReadOptions read;
  read.keepDegenerateFaces = true;
  intrinsic::RepairReport report;
  intrinsic::MeshData data = intrinsic::repairMesh(intrinsic::readMesh(path, read), {}, &report);
  std::istringstream lines(report.summary());
  for (std::string line; std::getline(lines, line);) progress("repair of " + path + ": " + line);
  if (!report.changedAnything()) progress("repair of " + path + ": nothing to repair");
  return data;
}

void addRepairOption(CLI::App* sub) {
  sub->add_flag("--repair", gRepair,
                "Repair the input mesh first, as `conformesh repair` does (off)");
}

std::map<std::string, double> parseParameters(const std::vector<std::string>& args) {
  std::map<std::string, double> params;
  for (const std::string& a : args) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--param '" + a + "': expected key=value, e.g. --param a=0.95");
    const std::string key = a.substr(0, eq), value = a.substr(eq + 1);
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(x))
      throw InputError("--param '" + a + "': value '" + value + "' is not a number (expected a finite value)");
    if (!params.emplace(key, x).second) throw InputError("--param '" + key + "' is given twice");
  }
  return params;
}

std::unique_ptr<intrinsic::SmoothMetric> loadMetric(const std::string& command, const std::string& family,
                                                    const std::vector<std::string>& params, const std::string& field) {
  if (family.empty() == field.empty())
    throw InputError(command +
                     ": give exactly one of a FAMILY name (see `conformesh discretize --list`) or --field FILE");
  if (field.empty()) return intrinsic::makeMetric(family, parseParameters(params));
  if (!params.empty()) throw InputError(command + ": --param applies to families, not to --field");
  progress("reading metric field " + field);
  return std::make_unique<intrinsic::SampledMetric>(intrinsic::readSampledField(field));
}

void addFieldOption(CLI::App* sub, std::string& field) {
  sub->add_option("--field", field, "Sampled metric field instead of a family: text or HDF5 (FILE.h5:/group)");
}

void addCurvatureMeasureProperties(intrinsic::MeshData& data, const intrinsic::CurvatureMeasureResult& c) {
  if (!c.centres.empty()) return;  // sampled check: no value at most vertices, so no per-vertex fields
  std::vector<double> error(c.discrete.size());
  for (std::size_t v = 0; v < error.size(); ++v) error[v] = c.discrete[v] - c.smooth[v];
  data.vertexProperties["error"] = std::move(error);
  data.vertexProperties["relative_error"] = c.relativeError;
}

void writeMeshOutputs(const intrinsic::MeshData& data, const std::string& path, bool ascii, const std::string& vtkPath,
                      const std::function<intrinsic::VtkMesh()>& makeVtk, nlohmann::json& report) {
  intrinsic::WriteOptions w;
  if (ascii) w.plyEncoding = intrinsic::PlyEncoding::Ascii;
  intrinsic::writeMesh(data, path, w);
  report["output"] = path;
  if (!vtkPath.empty()) {
    intrinsic::writeVtk(makeVtk(), vtkPath);
    report["vtk"] = vtkPath;
  }
}

void addSmoothingOptions(CLI::App* sub, int& passes, std::string& rule, const std::string& note) {
  sub->add_option("--smoothing", passes, "Smoothing passes after refinement (0: none, the paper's)" + note)
      ->capture_default_str();
  sub->add_option("--smoothing-rule", rule, "Start of each vertex's search: odt or centroid")
      ->check(oneOf({"odt", "centroid"}))
      ->capture_default_str();
}

CLI::Validator untyped(CLI::Validator v) {
  v.description("");
  return v;
}

CLI::Validator oneOf(std::vector<std::string> choices) {
  return untyped(CLI::IsMember(std::move(choices)));
}

std::string verifiedOutputPath(const refine::OutputVerification& check, bool keepFailed, const std::string& path,
                               nlohmann::json& report) {
  const std::string written = check.passed() ? path : keepFailed ? refine::failedOutputName(path) : "";
  report["verification"] = refine::verificationJson(check);
  report["verification"]["written"] = written;
  return written;
}

void rejectIfFailed(const refine::OutputVerification& check, const std::string& path, const std::string& keptPath,
                    bool json, const nlohmann::json& report) {
  if (check.passed()) return;
  if (json) printJson(report);
  throw OutputRejected(check.message() + (keptPath.empty() ? " (" + path + " not written; --keep-failed writes it as " +
                                                                 refine::failedOutputName(path) + ")"
                                                           : " (written as " + keptPath + ")"));
}

void writeVerifiedMeshOutputs(const refine::OutputVerification& check, bool keepFailed, const intrinsic::MeshData& data,
                              const std::string& path, bool ascii, const std::string& vtkPath,
                              const std::function<intrinsic::VtkMesh()>& makeVtk, bool json, nlohmann::json& report) {
  const std::string written = verifiedOutputPath(check, keepFailed, path, report);
  if (!written.empty())
    writeMeshOutputs(data, written, ascii, vtkPath.empty() || check.passed() ? vtkPath : refine::failedOutputName(vtkPath),
                     makeVtk, report);
  rejectIfFailed(check, path, written, json, report);
}

void printNotices(const std::vector<std::string>& notices) {
  for (const std::string& n : notices) std::fprintf(stderr, "conformesh: notice: %s\n", n.c_str());
}

void addKeepFailedOption(CLI::App* sub, bool& keepFailed) {
  sub->add_flag("--keep-failed", keepFailed,
                "An output that fails verification is written as NAME.failed.EXT (exit 3)");
}

std::string scriptInterpreter() {
#ifdef CONFORMESH_PYTHON_INTERPRETER
  if (std::filesystem::exists(CONFORMESH_PYTHON_INTERPRETER)) return CONFORMESH_PYTHON_INTERPRETER;
#endif
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

}  // namespace conformesh::apps
