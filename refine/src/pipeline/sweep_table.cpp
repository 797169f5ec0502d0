// sweep_table.cpp — gathering a sweep's records into its table and per-group orders (see sweep_table.h).
#include "conformesh/refine/pipeline/sweep_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/refine/pipeline/sweep_state.h"

namespace conformesh::refine {

namespace fs = std::filesystem;
using nlohmann::json;

json withoutTimes(const json& record) {
  if (record.is_object()) {
    json out = json::object();
    for (const auto& [k, v] : record.items())
      if (k != "seconds" && k != "wall_seconds") out[k] = withoutTimes(v);
    return out;
  }
  if (record.is_array()) {
    json out = json::array();
    for (const json& v : record) out.push_back(withoutTimes(v));
    return out;
  }
  return record;
}

namespace {

json slope(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> px, py;
  for (size_t i = 0; i < x.size(); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
      px.push_back(x[i]);
      py.push_back(y[i]);
    }
  if (px.size() < 2) return nullptr;
  // Equal abscissae leave the slope undefined (e.g. two levels that gave the same mesh).
  if (*std::max_element(px.begin(), px.end()) == *std::min_element(px.begin(), px.end())) return nullptr;
  return intrinsic::fitLogLogSlope(px, py);
}

std::string csvField(const json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) {
    std::string s = v.get<std::string>(), out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return out + "\"";
  }
  if (v.is_number_float()) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v.get<double>());
    return b;
  }
  return v.dump();
}

json at(const json& j, const std::vector<const char*>& path) {
  const json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k)) return nullptr;
    p = &(*p)[k];
  }
  return *p;
}

std::string csvTable(const json& records) {
  std::ostringstream out;
  out << "id,status,study,group,level,kind,input,params,eps_target,vertices_target,eps,vertices,triangles,"
         "max_circumradius,mean_circumradius,min_angle_deg,mean_min_angle_deg,e_G,max_error,fraction_within,"
         "inverted_triangles,total_area,gauss_bonnet_residual,wall_seconds,error_kind,where,error,"
         "time,horizon_area,irreducible_mass,equatorial_circumference,polar_circumference,spin\n";
  for (const json& r : records) {
    const json& c = r["case"];
    std::string params;
    for (const auto& [k, v] : c["params"].items()) params += (params.empty() ? "" : ";") + k + "=" + csvField(v);
    const std::vector<json> row = {r["id"], r["status"], c["study"], c["group"], c["level"], c["kind"], c["input"],
                                   params, at(c, {"eps"}), at(c, {"vertices"}), at(r, {"eps"}),
                                   at(r, {"quality", "vertices"}), at(r, {"quality", "triangles"}),
                                   at(r, {"quality", "max_circumradius"}), at(r, {"quality", "mean_circumradius"}),
                                   at(r, {"quality", "min_angle_deg"}), at(r, {"quality", "mean_min_angle_deg"}),
                                   at(r, {"gaussian_curvature_measure", "mean_abs_error"}),
                                   at(r, {"gaussian_curvature_measure", "max_abs_error"}),
                                   at(r, {"gaussian_curvature_measure", "fraction_within"}),
                                   at(r, {"inverted_triangles"}), at(r, {"total_area"}),
                                   at(r, {"quality", "gauss_bonnet_residual"}), at(r, {"wall_seconds"}),
                                   at(r, {"error_kind"}), at(r, {"where"}), at(r, {"error"}),
                                   // horizon inputs (docs/horizons.md §5c); empty for the others
                                   at(r, {"time"}), at(r, {"horizon", "area"}), at(r, {"horizon", "irreducible_mass"}),
                                   at(r, {"horizon", "equatorial_circumference"}),
                                   at(r, {"horizon", "polar_circumference"}), at(r, {"horizon", "spin"})};
    for (size_t i = 0; i < row.size(); ++i)
      out << (i ? "," : "") << (row[i].is_string() && i == 7 ? row[i].get<std::string>() : csvField(row[i]));
    out << "\n";
  }
  return out.str();
}

}  // namespace

json groupOrders(const std::vector<json>& ok) {
  std::vector<double> meanR, vertices, eG, areaError;
  for (const json& r : ok) {
    meanR.push_back(at(r, {"quality", "mean_circumradius"}).get<double>());
    vertices.push_back(at(r, {"quality", "vertices"}).get<double>());
    const json e = at(r, {"gaussian_curvature_measure", "mean_abs_error"});
    eG.push_back(e.is_number() ? e.get<double>() : 0.0);
    const json smooth = r.contains("smooth_area") ? r["smooth_area"] : at(r, {"input_mesh", "area"});
    areaError.push_back(smooth.is_number() ? std::abs(r["total_area"].get<double>() - smooth.get<double>()) : 0.0);
  }
  return {{"e_G_vs_mean_circumradius", slope(meanR, eG)},
          {"mean_circumradius_vs_vertices", slope(vertices, meanR)},
          {"area_error_vs_mean_circumradius", slope(meanR, areaError)}};
}

SweepTable writeSweepTable(const SweepSpec& spec, const std::string& dir) {
  SweepTable t;
  const SweepDir d{dir};
  t.total = static_cast<int>(spec.cases.size());
  std::map<std::string, std::vector<json>> okByGroup;
  std::vector<std::string> groupOrder;
  std::map<std::string, const SweepCase*> firstOfGroup;
  for (const SweepCase& c : spec.cases) {
    if (!firstOfGroup.count(c.group)) {
      firstOfGroup[c.group] = &c;
      groupOrder.push_back(c.group);
    }
    const auto record = readRecord(d, c.id);
    if (!record) {
      ++t.missing;
      continue;
    }
    const std::string status = (*record)["status"];
    (status == "ok" ? t.ok : status == "timeout" ? t.timeout : t.failed)++;
    if (status == "ok") okByGroup[c.group].push_back(*record);
    t.records.push_back(*record);
  }
  fs::create_directories(fs::path(dir) / "groups");
  for (const std::string& g : groupOrder) {
    const SweepCase& c = *firstOfGroup[g];
    std::vector<json>& ok = okByGroup[g];
    std::sort(ok.begin(), ok.end(), [](const json& a, const json& b) {
      return a["quality"]["vertices"].get<int>() < b["quality"]["vertices"].get<int>();
    });
    json entry = {{"group", g}, {"study", c.study}, {"input", c.input}, {"params", c.params},
                  {"options", c.options}, {"ok_levels", ok.size()}, {"orders", nullptr}};
    if (ok.size() >= 2) {
      entry["orders"] = groupOrders(ok);
      // The study file plot_convergence.py reads: levels with vertices, eps, quality, the curvature measure.
      json levels = json::array();
      bool checked = true;
      for (const json& r : ok) {
        checked = checked && r.contains("gaussian_curvature_measure");
        levels.push_back({{"id", r["id"]}, {"vertices", r["quality"]["vertices"]}, {"triangles", r["quality"]["triangles"]},
                          {"eps", r["eps"]}, {"quality", r["quality"]}, {"total_area", r["total_area"]},
                          {"gaussian_curvature_measure", r.value("gaussian_curvature_measure", json(nullptr))}});
      }
      if (checked) {
        const std::string title = ok.front().contains("metric") ? ok.front()["metric"].get<std::string>()
                                                                : ok.front().value("input", c.input);
        json study = {{"metric", title}, {"group", g}, {"orders", entry["orders"]}, {"levels", levels}};
        // The finest level's per-vertex relative errors (its PLY), for the histogram of Fig. 12.
        try {
          const intrinsic::MeshData finest =
              intrinsic::readMesh((fs::path(d.caseDir(ok.back()["id"])) / "mesh.ply").string());
          if (finest.vertexProperties.count("relative_error"))
            study["finest_relative_errors"] = finest.vertexProperties.at("relative_error");
        } catch (const std::exception&) {
        }
        const std::string path = (fs::path(dir) / "groups" / (g + ".json")).string();
        writeFileAtomically(path, study.dump(1) + "\n");
        t.groupFiles.push_back(path);
        t.written.push_back(path);
        entry["study_file"] = "groups/" + g + ".json";
      }
    }
    t.orders.push_back(entry);
  }
  const std::string tj = (fs::path(dir) / "table.json").string(), tc = (fs::path(dir) / "table.csv").string(),
                    oj = (fs::path(dir) / "orders.json").string();
  writeFileAtomically(tj, t.records.dump(1) + "\n");
  writeFileAtomically(tc, csvTable(t.records));
  writeFileAtomically(oj, t.orders.dump(1) + "\n");
  t.written.insert(t.written.begin(), {tc, tj, oj});
  return t;
}

}  // namespace conformesh::refine
