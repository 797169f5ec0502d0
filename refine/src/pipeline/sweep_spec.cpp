// sweep_spec.cpp — reading and expanding a sweep specification into cases with stable ids (see sweep_spec.h).
#include "conformesh/refine/pipeline/sweep_spec.h"

#include <glob.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/strahlkorper_io.h"

namespace conformesh::refine {

namespace fs = std::filesystem;
using nlohmann::json;

std::string fnv1a64Hex(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

const json& sweepOptionDefaults() {
  static const json defaults = {{"ratio", 1.4142135623730951}, {"uniform", false},        {"t0-resolution", 0},
                                {"disk-target", "auto"},       {"segment-rule", "ruppert"}, {"smoothing", 0},
                                {"smoothing-rule", "odt"},     {"refine-in", "uniformized"}, {"region", "ball"},
                                {"no-check", false},           {"vtk", false}};
  return defaults;
}

json SweepCase::inputsJson() const {
  json j = {{"study", study},
            {"group", group},
            {"level", level},
            {"input", input},
            {"kind", kind == SweepInputKind::Family  ? "family"
                     : kind == SweepInputKind::Field ? "field"
                     : kind == SweepInputKind::Mesh  ? "mesh"
                                                     : "horizon"},
            {"params", params},
            {"options", options}};
  if (targetVertices > 0)
    j["vertices"] = targetVertices;
  else
    j["eps"] = epsilon;
  return j;
}

namespace {

const std::map<std::string, std::vector<std::string>>& optionChoices() {
  static const std::map<std::string, std::vector<std::string>> choices = {
      {"disk-target", {"auto", "circle", "keep-boundary"}},
      {"segment-rule", {"ruppert", "chew"}},
      {"smoothing-rule", {"odt", "centroid"}},
      {"refine-in", {"uniformized", "input"}},
      {"region", {"ball", "union"}}};
  return choices;
}

std::string typeName(const json& v) {
  if (v.is_boolean()) return "a boolean";
  if (v.is_number_integer()) return "an integer";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "a list";
  if (v.is_object()) return "an object";
  return "null";
}

std::string slugOf(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += (std::isalnum(c) || c == '-' || c == '_' || c == '.') ? char(c) : '_';
  return out.empty() ? "case" : out;
}

bool isMeshPath(const std::string& p) {
  std::string lower = p;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* ext : {".off", ".obj", ".ply"})
    if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, ext) == 0) return true;
  return false;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Errors name the spec, the study and the key: "spec.json: studies[2].params.a: expected ..., found ...".
class StudyReader {
 public:
  StudyReader(const std::string& path, int index) : path_(path), index_(index) {}
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(path_ + ": studies[" + std::to_string(index_) + "]" + (key.empty() ? "" : "." + key) + ": " +
                     what);
  }
  // A value or a list of values, each checked by `ok`, as a non-empty list.
  std::vector<json> listOf(const json& v, const std::string& key, const std::string& expected,
                           bool (*ok)(const json&)) const {
    std::vector<json> out;
    if (v.is_array()) {
      for (const json& x : v) out.push_back(x);
      if (out.empty()) fail(key, "expected " + expected + " or a non-empty list of them, found an empty list");
    } else {
      out.push_back(v);
    }
    for (size_t i = 0; i < out.size(); ++i)
      if (!ok(out[i]))
        fail(key + (v.is_array() ? "[" + std::to_string(i) + "]" : ""),
             "expected " + expected + ", found " + typeName(out[i]) + " " + out[i].dump());
    return out;
  }

 private:
  std::string path_;
  int index_;
};

// The content a case id hashes: the file's bytes; for a shape group of an HDF5 file the group's shape and metadata
// (so that a rerun over a file with groups added recomputes only the new ones), the file's bytes if it does not read.
std::string contentHash(const std::string& path, const std::string& group, bool horizon) {
  if (!horizon || group.empty()) return fnv1a64Hex(readBytes(path));
  try {
    const intrinsic::HorizonShapeRecord rec = intrinsic::readHorizonShapeHdf5(path + group);
    json meta = {{"spatial_metric", rec.meta.spatialMetric}, {"params", rec.meta.params},
                 {"time", rec.meta.hasTime ? json(rec.meta.time) : json(nullptr)}};
    return fnv1a64Hex(intrinsic::strahlkorperToJson(rec.shape) + meta.dump());
  } catch (const InputError&) {
    return fnv1a64Hex(readBytes(path) + group);
  }
}

struct ResolvedInput {
  SweepInputKind kind;
  std::string input;  // family name or resolved path
  json key;           // family name, or {file, content}
  std::string slug;
};

std::vector<ResolvedInput> resolveInput(const StudyReader& r, const std::string& text, const fs::path& base,
                                        const std::string& key) {
  for (const auto& f : intrinsic::metricFamilies())
    if (f.name == text) return {{SweepInputKind::Family, text, text, slugOf(text)}};
  std::vector<std::string> paths;
  std::string group;  // FILE.h5:/group
  std::string file = text;
  if (const auto colon = text.find(":/"); colon != std::string::npos) {
    file = text.substr(0, colon);
    group = text.substr(colon);
  }
  const fs::path resolved = fs::path(file).is_absolute() ? fs::path(file) : base / file;
  if (file.find_first_of("*?[") != std::string::npos) {
    glob_t g{};
    const int rc = glob(resolved.string().c_str(), 0, nullptr, &g);
    for (size_t i = 0; rc == 0 && i < g.gl_pathc; ++i) paths.push_back(g.gl_pathv[i]);
    globfree(&g);
    if (paths.empty())
      r.fail(key, "the glob '" + text + "' (as " + resolved.string() + ") matches no file, and '" + text +
                      "' is not a family name (conformesh discretize --list)");
    std::sort(paths.begin(), paths.end());
  } else {
    if (!fs::is_regular_file(resolved))
      r.fail(key, "'" + text + "' is neither a family name (conformesh discretize --list) nor a file (looked for " +
                      resolved.string() + ")");
    paths.push_back(resolved.string());
  }
  std::vector<ResolvedInput> out;
  for (const std::string& p : paths) {
    const bool mesh = isMeshPath(p);
    if (mesh && !group.empty()) r.fail(key, "'" + text + "': a group (':/...') applies to HDF5 fields, not meshes");
    const std::string name = fs::path(p).filename().string() + group;
    // A .json file is a horizon shape (a Strahlkörper naming its own spatial metric, horizon_surface.h), and so is
    // an HDF5 group holding `coefficients` or `radius` (strahlkorper_io.h); other HDF5 inputs are metric fields.
    const bool horizon = !mesh && (group.empty() ? fs::path(p).extension() == ".json"
                                                 : intrinsic::hdf5GroupHoldsShape(p + group));
    out.push_back({mesh ? SweepInputKind::Mesh : horizon ? SweepInputKind::Horizon : SweepInputKind::Field, p + group,
                   json{{"file", name}, {"content", contentHash(p, group, horizon)}}, slugOf(fs::path(p).stem().string())});
  }
  return out;
}

// The cartesian product of named lists, keys in order: [{k1: v, k2: w}, ...]; one empty point for no keys.
std::vector<json> grid(const std::vector<std::pair<std::string, std::vector<json>>>& axes) {
  std::vector<json> points = {json::object()};
  for (const auto& [name, values] : axes) {
    std::vector<json> next;
    for (const json& p : points)
      for (const json& v : values) {
        json q = p;
        q[name] = v;
        next.push_back(q);
      }
    points = std::move(next);
  }
  return points;
}

bool isNumber(const json& v) {
  return v.is_number() && std::isfinite(v.get<double>());
}
bool isPositiveNumber(const json& v) {
  return isNumber(v) && v.get<double>() > 0;
}
bool isVertexCount(const json& v) {
  return v.is_number_integer() && v.get<long long>() >= 10 && v.get<long long>() <= 100000000;
}
bool isString(const json& v) {
  return v.is_string();
}

std::vector<std::pair<std::string, std::vector<json>>> optionAxes(const StudyReader& r, const json& options) {
  if (!options.is_object()) r.fail("options", "expected an object of remesh options, found " + typeName(options));
  std::vector<std::pair<std::string, std::vector<json>>> axes;
  std::set<std::string> seen;
  for (const auto& [given, value] : options.items()) {
    std::string name = given;
    std::replace(name.begin(), name.end(), '_', '-');
    const std::string key = "options." + given;
    if (!sweepOptionDefaults().contains(name)) {
      std::string known;
      for (const auto& [k, d] : sweepOptionDefaults().items()) known += (known.empty() ? "" : ", ") + k;
      r.fail(key, "unknown option (expected one of " + known + ")");
    }
    if (!seen.insert(name).second) r.fail(key, "given twice (as '-' and '_' spellings)");
    const json& def = sweepOptionDefaults()[name];
    std::vector<json> values = r.listOf(value, key, "a value", [](const json& v) { return !v.is_structured(); });
    for (size_t i = 0; i < values.size(); ++i) {
      json& v = values[i];
      const std::string where = key + (value.is_array() ? "[" + std::to_string(i) + "]" : "");
      if (def.is_boolean() && !v.is_boolean()) r.fail(where, "expected true or false, found " + v.dump());
      if (def.is_number_integer() && !(v.is_number_integer() && v.get<long long>() >= 0))
        r.fail(where, "expected a non-negative integer, found " + v.dump());
      if (def.is_number_float()) {
        if (!isPositiveNumber(v)) r.fail(where, "expected a positive number, found " + v.dump());
        v = v.get<double>();
      }
      if (def.is_string()) {
        const auto& choices = optionChoices().at(name);
        if (!v.is_string() || std::find(choices.begin(), choices.end(), v.get<std::string>()) == choices.end()) {
          std::string list;
          for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
          r.fail(where, "expected one of " + list + ", found " + v.dump());
        }
      }
    }
    axes.emplace_back(name, values);
  }
  return axes;
}

void expandStudy(const json& s, int index, const std::string& path, const fs::path& base,
                 std::vector<SweepCase>& cases) {
  const StudyReader r(path, index);
  if (!s.is_object()) r.fail("", "expected an object with input, eps or vertices, params, options");
  for (const auto& [k, v] : s.items())
    if (k != "name" && k != "input" && k != "params" && k != "eps" && k != "vertices" && k != "options")
      r.fail(k, "unknown key (expected name, input, params, eps, vertices, options)");
  if (!s.contains("input")) r.fail("input", "missing (a family name, a mesh or field file, or a glob)");
  if (s.contains("eps") == s.contains("vertices"))
    r.fail("eps", "give exactly one of eps (circumradius bounds) and vertices (target vertex counts)");
  std::string name;
  if (s.contains("name")) {
    if (!s["name"].is_string() || s["name"].get<std::string>().empty())
      r.fail("name", "expected a non-empty string, found " + s["name"].dump());
    name = s["name"];
  }

  std::vector<ResolvedInput> inputs;
  const std::vector<json> texts = r.listOf(s["input"], "input", "a string", isString);
  for (size_t i = 0; i < texts.size(); ++i) {
    const auto more =
        resolveInput(r, texts[i], base, "input" + (s["input"].is_array() ? "[" + std::to_string(i) + "]" : ""));
    inputs.insert(inputs.end(), more.begin(), more.end());
  }

  std::vector<std::pair<std::string, std::vector<json>>> paramAxes;
  if (s.contains("params")) {
    if (!s["params"].is_object()) r.fail("params", "expected an object of family parameters, found " + typeName(s["params"]));
    for (const auto& [k, v] : s["params"].items()) {
      std::vector<json> values = r.listOf(v, "params." + k, "a number", isNumber);
      for (json& x : values) x = x.get<double>();
      paramAxes.emplace_back(k, values);
    }
  }
  for (const ResolvedInput& in : inputs) {
    if (in.kind != SweepInputKind::Family && !paramAxes.empty())
      r.fail("params", "parameters apply to metric families; '" + in.input + "' is a file");
    if (in.kind == SweepInputKind::Family)
      for (const auto& f : intrinsic::metricFamilies())
        if (f.name == in.input)
          for (const auto& [k, v] : paramAxes) {
            bool known = false;
            std::string list;
            for (const auto& p : f.parameters) {
              known = known || p.name == k;
              list += (list.empty() ? "" : ", ") + p.name;
            }
            if (!known) r.fail("params." + k, "family '" + f.name + "' has no parameter '" + k + "' (it has " + list + ")");
          }
  }
  const bool byVertices = s.contains("vertices");
  std::vector<json> levels = byVertices ? r.listOf(s["vertices"], "vertices", "a vertex count (integer, >= 10)", isVertexCount)
                                        : r.listOf(s["eps"], "eps", "a positive number", isPositiveNumber);
  const std::vector<json> optionPoints = grid(optionAxes(r, s.value("options", json::object())));
  const std::vector<json> paramPoints = grid(paramAxes);

  for (const ResolvedInput& in : inputs)
    for (const json& p : paramPoints)
      for (const json& o : optionPoints) {
        json options = sweepOptionDefaults();
        // refine-in defaults as on `remesh`: a mesh file is refined in its own metric (it keeps the angle bound
        // there; docs/cli.md#remesh-meshfile), a metric uniformized (its only route). Filled in before hashing, so
        // the id says which route ran.
        if (in.kind == SweepInputKind::Mesh) options["refine-in"] = "input";
        for (const auto& [k, v] : o.items()) options[k] = v;
        const json groupKey = {{"input", in.key}, {"params", p}, {"options", options}};
        const std::string slug = name.empty() ? in.slug : slugOf(name);
        for (size_t l = 0; l < levels.size(); ++l) {
          SweepCase c;
          c.index = static_cast<int>(cases.size());
          c.study = index;
          c.level = static_cast<int>(l);
          c.kind = in.kind;
          c.input = in.input;
          for (const auto& [k, v] : p.items()) c.params[k] = v.get<double>();
          c.options = options;
          c.key = groupKey;
          if (byVertices) {
            c.targetVertices = levels[l].get<int>();
            c.key["vertices"] = c.targetVertices;
            c.cost = c.targetVertices;
          } else {
            c.epsilon = levels[l].get<double>();
            c.key["eps"] = c.epsilon;
            c.cost = 1 / (c.epsilon * c.epsilon);
          }
          c.group = slug + "-" + fnv1a64Hex(groupKey.dump()).substr(0, 8);
          c.id = slug + "-" + fnv1a64Hex(c.key.dump());
          cases.push_back(std::move(c));
        }
      }
}

}  // namespace

SweepSpec expandSweepSpec(const json& document, const std::string& path) {
  SweepSpec spec;
  spec.path = path;
  spec.document = document;
  if (!document.is_object() || !document.contains("studies") || !document["studies"].is_array() ||
      document["studies"].empty())
    throw InputError(path + ": studies: expected {\"studies\": [ {\"input\": ..., \"eps\": [...]}, ... ]}");
  for (const auto& [k, v] : document.items())
    if (k != "studies" && k != "comment") throw InputError(path + ": " + k + ": unknown key (expected studies, comment)");
  const fs::path base = fs::absolute(fs::path(path)).parent_path();
  for (size_t i = 0; i < document["studies"].size(); ++i)
    expandStudy(document["studies"][i], static_cast<int>(i), path, base, spec.cases);
  std::map<std::string, int> seen;
  for (const SweepCase& c : spec.cases)
    if (auto [it, fresh] = seen.emplace(c.id, c.study); !fresh)
      throw InputError(path + ": studies[" + std::to_string(c.study) + "]: case " + c.id +
                       " (input " + c.input + ", " + (c.targetVertices ? "vertices " + std::to_string(c.targetVertices)
                                                                      : "eps " + json(c.epsilon).dump()) +
                       ") is also a case of studies[" + std::to_string(it->second) + "]; a case is run once");
  return spec;
}

SweepSpec readSweepSpec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the sweep specification");
  json document;
  try {
    document = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(path + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  return expandSweepSpec(document, path);
}

}  // namespace conformesh::refine
