// horizon_series.cpp — a time series of horizons run through the sweep engine (horizon_series.h).
#include "conformesh/refine/pipeline/horizon_series.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/strahlkorper_io.h"
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

// A step of an HDF5 series is "FILE.h5:/group"; of a folder, a JSON file.
std::pair<std::string, std::string> splitStep(const std::string& file) {
  const size_t colon = file.find(":/");
  if (colon == std::string::npos) return {file, ""};
  return {file.substr(0, colon), file.substr(colon + 1)};
}
// What the step's time is parsed from when its metadata has none: the file's stem, or the group's last component.
std::string stepStem(const std::string& file) {
  const auto [path, group] = splitStep(file);
  if (group.empty()) return fs::path(path).stem().string();
  const std::string last = group.substr(group.rfind('/') + 1);
  return last.empty() ? fs::path(path).stem().string() : last;
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
  if (timeFromName(stepStem(file), s.time)) {
    s.hasTime = true;
    s.timeSource = "name";
  }
  return s;
}

}  // namespace

std::string horizonStepLabel(const std::string& file) {
  const auto [path, group] = splitStep(file);
  return fs::path(path).filename().string() + (group.empty() ? "" : ":" + group);
}

namespace {

std::vector<HorizonStep> sortedSteps(std::vector<HorizonStep> steps) {
  std::sort(steps.begin(), steps.end(), [](const HorizonStep& a, const HorizonStep& b) {
    if (a.hasTime != b.hasTime) return a.hasTime;
    if (a.hasTime && a.time != b.time) return a.time < b.time;
    return a.file < b.file;
  });
  return steps;
}

}  // namespace

std::vector<HorizonStep> listHorizonSteps(const std::string& folder) {
  if (fs::is_regular_file(folder) && intrinsic::isHdf5ShapePath(folder)) {  // one group per step
    std::vector<HorizonStep> steps;
    for (const std::string& g : intrinsic::listHorizonShapeGroups(folder)) steps.push_back(stepOf(folder + ":" + g));
    if (steps.empty())
      throw InputError("horizons: " + folder + ": no group holding a horizon shape (a dataset 'coefficients' or " +
                       "'radius', or a 'center' or 'time')");
    return sortedSteps(std::move(steps));
  }
  if (!fs::is_directory(folder))
    throw InputError("horizons: " + folder + ": expected a folder of horizon shape files (*.json) or an HDF5 file of shape groups, found " +
                     (fs::exists(folder) ? "a file" : "nothing"));
  std::vector<HorizonStep> steps;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file() && e.path().extension() == ".json" && !isTemporaryName(e.path().filename().string()))
      steps.push_back(stepOf(e.path().string()));
  if (steps.empty()) throw InputError("horizons: " + folder + ": no horizon shape file (*.json) in the folder");
  return sortedSteps(std::move(steps));
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
    studies.push_back({{"name", stepStem(steps[k].file)},
                       {"input", horizonStepLabel(steps[k].file)},  // relative to the folder (of the HDF5 file)
                       {"eps", o.epsilon},
                       {"options", {{"no-check", !o.check}}}});
  }
  const json document = {{"studies", studies}};
  const bool hdf5 = fs::is_regular_file(o.series);
  const fs::path folder = hdf5 ? fs::path(o.series).parent_path() : fs::path(o.series);
  SweepSpec spec = expandSweepSpec(document, (folder / "series").string());
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
      "irreducible_mass", "equatorial_circumference", "polar_circumference", "spin", "spin_killing", "total_curvature",
      "smooth_total_curvature",
      "gauss_bonnet_residual", "e_G", "min_angle_deg", "wall_seconds", "id", "error"};  // free text last
  return c;
}

json rowOf(size_t k, const HorizonStep& s, const SweepCase& c, const std::optional<json>& r) {
  json row = {{"step", k}, {"file", horizonStepLabel(s.file)},
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
  row["spin_killing"] = at(*r, {"horizon", "killing", "spin_from_killing"});
  row["total_curvature"] = at(*r, {"smooth_reference", "mesh_total_curvature"});
  row["smooth_total_curvature"] = at(*r, {"smooth_reference", "smooth_total_curvature"});
  row["gauss_bonnet_residual"] = at(*r, {"quality", "gauss_bonnet_residual"});
  row["e_G"] = at(*r, {"gaussian_curvature_measure", "mean_abs_error"});
  row["min_angle_deg"] = at(*r, {"quality", "min_angle_deg"});
  row["wall_seconds"] = at(*r, {"wall_seconds"});
  return row;
}

std::string exactCsvField(const json& v) {
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
    for (size_t i = 0; i < columns().size(); ++i) out << (i ? "," : "") << exactCsvField(row[columns()[i]]);
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

namespace {

void checkKerrSeries(int n, double a0, double a1, double mass, int lMax) {
  if (n < 1) throw InputError("generate horizon-series: --steps: expected >= 1, found " + std::to_string(n));
  if (!(mass > 0)) throw InputError("generate horizon-series: --M: expected > 0, found " + std::to_string(mass));
  if (!(std::abs(a0) < mass) || !(std::abs(a1) < mass))
    throw InputError("generate horizon-series: the spins must satisfy |a| < M (found a0 = " + std::to_string(a0) +
                     ", a1 = " + std::to_string(a1) + ", M = " + std::to_string(mass) + ")");
  if (lMax < 0) throw InputError("generate horizon-series: --lmax: expected >= 0, found " + std::to_string(lMax));
}

// The Kerr–Schild horizon r = r₊ of spin a: the spheroid (x² + y²)/(r₊² + a²) + z²/r₊² = 1.
std::function<double(double, double)> kerrSchildHorizonRadius(double mass, double a) {
  const double rp = mass + std::sqrt(mass * mass - a * a), R2 = rp * rp + a * a;
  return [rp, R2](double theta, double) {
    const double s = std::sin(theta), c = std::cos(theta);
    return 1 / std::sqrt(s * s / R2 + c * c / (rp * rp));
  };
}

}  // namespace

std::vector<std::string> writeKerrHorizonSeries(const std::string& dir, int n, double a0, double a1, double mass,
                                                double dt, int lMax) {
  checkKerrSeries(n, a0, a1, mass, lMax);
  fs::create_directories(dir);
  std::vector<std::string> written;
  for (int k = 0; k < n; ++k) {
    const double a = n == 1 ? a0 : a0 + (a1 - a0) * k / (n - 1), t = k * dt;
    const intrinsic::Strahlkorper shape =
        intrinsic::fitStrahlkorper(kerrSchildHorizonRadius(mass, a), lMax, Eigen::Vector3d::Zero());
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

std::vector<std::string> writeKerrHorizonSeriesHdf5(const std::string& path, int n, double a0, double a1, double mass,
                                                    double dt, int lMax, bool sampled) {
  checkKerrSeries(n, a0, a1, mass, lMax);
  std::vector<intrinsic::HorizonShapeGroup> groups;
  std::vector<std::string> names;
  for (int k = 0; k < n; ++k) {
    const double a = n == 1 ? a0 : a0 + (a1 - a0) * k / (n - 1), t = k * dt;
    char name[64];
    std::snprintf(name, sizeof name, "/t%06.2f", t);
    intrinsic::HorizonShapeGroup g;
    g.group = name;
    g.record.meta.spatialMetric = "kerr-schild";
    g.record.meta.params = {{"M", mass}, {"a", a}};
    g.record.meta.hasTime = true, g.record.meta.time = t;
    if (sampled) {  // the spheroid itself on a 2(l_max + 1) × 4(l_max + 1) Gauss–Legendre × uniform grid
      g.record.sampled = true;
      g.samples.nodes = intrinsic::ThetaNodes::GaussLegendre;
      g.samples.lMax = lMax;
      const std::vector<double> theta = intrinsic::thetaNodes(g.samples.nodes, 2 * (lMax + 1));
      const int np = 4 * (lMax + 1);
      g.samples.r.resize(static_cast<Eigen::Index>(theta.size()), np);
      const auto r = kerrSchildHorizonRadius(mass, a);
      for (size_t i = 0; i < theta.size(); ++i)
        for (int j = 0; j < np; ++j) g.samples.r(static_cast<Eigen::Index>(i), j) = r(theta[i], 2 * M_PI * j / np);
    } else {
      g.record.shape = intrinsic::fitStrahlkorper(kerrSchildHorizonRadius(mass, a), lMax, Eigen::Vector3d::Zero());
    }
    groups.push_back(std::move(g));
    names.push_back(path + ":" + name);
  }
  intrinsic::writeHorizonShapesHdf5(path, groups);
  return names;
}

}  // namespace conformesh::refine
