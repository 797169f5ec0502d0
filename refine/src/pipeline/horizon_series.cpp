// horizon_series.cpp — a time series of horizons run through the sweep engine (horizon_series.h).
#include "conformesh/refine/pipeline/horizon_series.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/refine/pipeline/sweep_state.h"

namespace conformesh::refine {

namespace fs = std::filesystem;
using nlohmann::json;

std::string HorizonSeriesOptions::validate() const {
  if (series.empty()) return "horizons: the SERIES folder is required";
  if (!(epsilon > 0) || !std::isfinite(epsilon))
    return "horizons: --eps: expected a positive number, found " + std::to_string(epsilon);
  return "";
}

namespace {

// The last number in a file name's stem: "t0012.5" → 12.5, "AhA_it000256" → 256.
bool timeFromName(const std::string& stem, double& t) {
  static const std::regex number(R"([-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)");
  bool found = false;
  for (auto it = std::sregex_iterator(stem.begin(), stem.end(), number); it != std::sregex_iterator(); ++it) {
    t = std::stod(it->str());
    found = true;
  }
  return found;
}

HorizonStep stepOf(const std::string& file) {
  HorizonStep s{file, false, 0, "none"};
  try {
    const intrinsic::HorizonFileMetadata m = intrinsic::readHorizonMetadata(file);
    if (m.hasTime) {
      s.hasTime = true;
      s.time = m.time;
      s.timeSource = "file";
      return s;
    }
  } catch (const InputError&) {
    // a file that does not parse still gets its step (and its error in its row); its time comes from its name
  }
  if (timeFromName(fs::path(file).stem().string(), s.time)) {
    s.hasTime = true;
    s.timeSource = "name";
  }
  return s;
}

}  // namespace

std::vector<HorizonStep> listHorizonSteps(const std::string& folder) {
  if (!fs::is_directory(folder))
    throw InputError("horizons: " + folder + ": expected a folder of horizon shape files (*.json), found " +
                     (fs::exists(folder) ? "a file" : "nothing"));
  std::vector<HorizonStep> steps;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file() && e.path().extension() == ".json" && !isTemporaryName(e.path().filename().string()))
      steps.push_back(stepOf(e.path().string()));
  if (steps.empty()) throw InputError("horizons: " + folder + ": no horizon shape file (*.json) in the folder");
  std::sort(steps.begin(), steps.end(), [](const HorizonStep& a, const HorizonStep& b) {
    if (a.hasTime != b.hasTime) return a.hasTime;
    if (a.hasTime && a.time != b.time) return a.time < b.time;
    return a.file < b.file;
  });
  return steps;
}

namespace {

// The spatial metric and parameters of one step: the options' when given, else the file's own, --param on top.
json stepMetric(const HorizonStep& s, const HorizonSeriesOptions& o) {
  json params = json::object();
  std::string name = o.spatialMetric;
  if (name.empty()) {
    name = "kerr-schild";
    try {
      const intrinsic::HorizonFileMetadata m = intrinsic::readHorizonMetadata(s.file);
      name = m.spatialMetric;
      for (const auto& [k, v] : m.params) params[k] = v;
    } catch (const InputError&) {
      // reported by the step itself, in its row
    }
  }
  for (const auto& [k, v] : o.params) params[k] = v;
  return {{"spatial_metric", name}, {"params", params}};
}

}  // namespace

SweepSpec horizonSeriesSpec(const std::vector<HorizonStep>& steps, const HorizonSeriesOptions& o) {
  json studies = json::array();
  for (size_t k = 0; k < steps.size(); ++k) {
    // Named by the file, not its position: a step added to the folder later leaves the other ids (and records) as
    // they were, so a rerun over a growing series computes only the new steps.
    studies.push_back({{"name", fs::path(steps[k].file).stem().string()},
                       {"input", fs::path(steps[k].file).filename().string()},  // relative to the folder
                       {"eps", o.epsilon},
                       {"options", {{"no-check", !o.check}}}});
  }
  const json document = {{"studies", studies}};
  SweepSpec spec = expandSweepSpec(document, (fs::path(o.series) / "series").string());
  for (size_t k = 0; k < spec.cases.size(); ++k) {
    SweepCase& c = spec.cases[k];
    c.horizonMetric = stepMetric(steps[static_cast<size_t>(c.study)], o);
    c.key["horizon_metric"] = c.horizonMetric;
    const std::string slug = c.id.substr(0, c.id.rfind('-'));
    c.id = slug + "-" + fnv1a64Hex(c.key.dump());
  }
  return spec;
}

namespace {

json at(const json& j, std::initializer_list<const char*> path) {
  const json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k)) return nullptr;
    p = &(*p)[k];
  }
  return *p;
}

const std::vector<std::string>& columns() {
  static const std::vector<std::string> c = {
      "step", "file", "time", "time_source", "status", "error_kind", "vertices", "area", "mesh_area",
      "irreducible_mass", "equatorial_circumference", "polar_circumference", "spin", "total_curvature",
      "smooth_total_curvature",
      "gauss_bonnet_residual", "e_G", "min_angle_deg", "wall_seconds", "id", "error"};  // free text last
  return c;
}

json rowOf(size_t k, const HorizonStep& s, const SweepCase& c, const std::optional<json>& r) {
  json row = {{"step", k}, {"file", fs::path(s.file).filename().string()},
              {"time", s.hasTime ? json(s.time) : json(nullptr)}, {"time_source", s.timeSource}, {"id", c.id}};
  if (!r) {
    for (const std::string& col : columns())
      if (!row.contains(col)) row[col] = nullptr;
    row["status"] = "missing";
    return row;
  }
  row["status"] = (*r)["status"];
  row["error_kind"] = at(*r, {"error_kind"});
  row["error"] = at(*r, {"error"});
  if (row["error"].is_string()) {  // the sweep resolved the file against the folder: name it as the user did
    std::string e = row["error"];
    for (size_t p = 0; (p = e.find(c.input, p)) != std::string::npos; p += s.file.size())
      e.replace(p, c.input.size(), s.file);
    row["error"] = e;
  }
  row["vertices"] = at(*r, {"quality", "vertices"});
  row["area"] = at(*r, {"horizon", "area"});
  row["mesh_area"] = at(*r, {"horizon", "mesh_area"});
  row["irreducible_mass"] = at(*r, {"horizon", "irreducible_mass"});
  row["equatorial_circumference"] = at(*r, {"horizon", "equatorial_circumference"});
  row["polar_circumference"] = at(*r, {"horizon", "polar_circumference"});
  row["spin"] = at(*r, {"horizon", "spin"});
  row["total_curvature"] = at(*r, {"smooth_reference", "mesh_total_curvature"});
  row["smooth_total_curvature"] = at(*r, {"smooth_reference", "smooth_total_curvature"});
  row["gauss_bonnet_residual"] = at(*r, {"quality", "gauss_bonnet_residual"});
  row["e_G"] = at(*r, {"gaussian_curvature_measure", "mean_abs_error"});
  row["min_angle_deg"] = at(*r, {"quality", "min_angle_deg"});
  row["wall_seconds"] = at(*r, {"wall_seconds"});
  return row;
}

std::string csvField(const json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) {
    std::string out = "\"";
    for (char ch : v.get<std::string>()) out += ch == '"' ? std::string("\"\"") : std::string(1, ch == '\n' ? ' ' : ch);
    return out + "\"";
  }
  if (v.is_number_float()) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v.get<double>());
    return b;
  }
  return v.dump();
}

std::string csvOf(const json& rows) {
  std::ostringstream out;
  for (size_t i = 0; i < columns().size(); ++i) out << (i ? "," : "") << columns()[i];
  out << "\n";
  for (const json& row : rows) {
    for (size_t i = 0; i < columns().size(); ++i) out << (i ? "," : "") << csvField(row[columns()[i]]);
    out << "\n";
  }
  return out.str();
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

json horizonSeriesRows(const std::vector<HorizonStep>& steps, const SweepSpec& spec, const std::string& dir) {
  json rows = json::array();
  const SweepDir d{dir};
  for (const SweepCase& c : spec.cases) {
    const size_t k = static_cast<size_t>(c.study);
    rows.push_back(rowOf(k, steps[k], c, readRecord(d, c.id)));
  }
  return rows;
}

std::vector<std::string> writeHorizonSeriesTable(const json& rows, const json& run, const std::string& dir) {
  const std::string jsonPath = (fs::path(dir) / "series.json").string(), csvPath = (fs::path(dir) / "series.csv").string();
  const std::string csv = csvOf(rows);
  intrinsic::writeFileAtomically(jsonPath, json{{"rows", rows}, {"run", run}}.dump(1) + "\n");
  intrinsic::writeFileAtomically(csvPath, csv);
  json back;
  try {
    back = json::parse(readText(jsonPath));
  } catch (const json::exception& e) {
    throw InputError(jsonPath + ": verification: the written file does not parse as JSON: " + e.what());
  }
  if (back["rows"] != rows) throw InputError(jsonPath + ": verification: the rows read back differ from those written");
  if (readText(csvPath) != csv) throw InputError(csvPath + ": verification: the file read back differs from the table");
  return {csvPath, jsonPath};
}

std::vector<std::string> writeKerrHorizonSeries(const std::string& dir, int n, double a0, double a1, double mass,
                                                double dt, int lMax) {
  if (n < 1) throw InputError("generate horizon-series: --steps: expected >= 1, found " + std::to_string(n));
  if (!(mass > 0)) throw InputError("generate horizon-series: --M: expected > 0, found " + std::to_string(mass));
  if (!(std::abs(a0) < mass) || !(std::abs(a1) < mass))
    throw InputError("generate horizon-series: the spins must satisfy |a| < M (found a0 = " + std::to_string(a0) +
                     ", a1 = " + std::to_string(a1) + ", M = " + std::to_string(mass) + ")");
  if (lMax < 0) throw InputError("generate horizon-series: --lmax: expected >= 0, found " + std::to_string(lMax));
  fs::create_directories(dir);
  std::vector<std::string> written;
  for (int k = 0; k < n; ++k) {
    const double a = n == 1 ? a0 : a0 + (a1 - a0) * k / (n - 1), t = k * dt;
    const double rp = mass + std::sqrt(mass * mass - a * a), R2 = rp * rp + a * a;
    const auto radius = [&](double theta, double) {
      const double s = std::sin(theta), c = std::cos(theta);
      return 1 / std::sqrt(s * s / R2 + c * c / (rp * rp));
    };
    const intrinsic::Strahlkorper shape = intrinsic::fitStrahlkorper(radius, lMax, Eigen::Vector3d::Zero());
    json j = json::parse(intrinsic::strahlkorperToJson(shape));
    j["spatial_metric"] = "kerr-schild";
    j["params"] = {{"M", mass}, {"a", a}};
    j["time"] = t;
    char name[64];
    std::snprintf(name, sizeof name, "t%06.2f.json", t);
    const std::string path = (fs::path(dir) / name).string();
    intrinsic::writeFileAtomically(path, j.dump(1) + "\n");
    written.push_back(path);
  }
  return written;
}

}  // namespace conformesh::refine
