// view_page.cpp — a mesh file's content as a scene for `conformesh view`, and the scene as one HTML page
// (view_page.h): points from the file or the uniformization domain, figures from the intrinsic summary, JSON by hand.
#include "conformesh/embedding/view/view_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"

namespace conformesh::embedding {

using namespace conformesh::intrinsic;

namespace {

std::string number(double x, const char* format = "%.9g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

// Points of a metric-only surface: its uniformization's model space (sphere or plane), with the page's wording.
std::vector<Eigen::Vector3d> domainPoints(const IntrinsicTriangulation& tri, const MeshData& data,
                                          const ViewSceneOptions& o, ViewScene& scene) {
  const MeshSummary s = summarize(tri);
  if (s.genus > 0)
    throw InputError(describeAt(data.source, "a metric-only surface of genus " + std::to_string(s.genus) +
                                                 " has no model-space picture to draw it on; `conformesh layout` "
                                                 "draws its fundamental domain"));
  Uniformization u = uniformize(tri, o.uniformization);
  if (u.positions.size() != static_cast<size_t>(tri.mesh.nVertices()))
    throw InputError(describeAt(data.source, "its uniformization has no model-space points to draw"));
  scene.domain = s.boundaryLoops == 0 ? "the unit sphere of its uniformization (the file has no positions: the "
                                        "surface is drawn in its conformal domain, not embedded in R³)"
                                      : "the plane of its uniformization (circle domain; the file has no positions)";
  scene.figures.push_back({"uniformization", std::to_string(u.report.newtonSteps) + " Newton steps"});
  return u.positions;
}

void addFigures(const IntrinsicTriangulation& tri, ViewScene& scene) {
  const MeshSummary s = summarize(tri);
  const double integral = s.curvature.interiorDeficit + s.curvature.boundaryTurning + s.curvature.backgroundTerm;
  std::vector<std::pair<std::string, std::string>> rows = {
      {"vertices", std::to_string(s.vertices)},
      {"faces", std::to_string(s.faces)},
      {"genus, boundary loops", std::to_string(s.genus) + ", " + std::to_string(s.boundaryLoops)},
      {"total area", number(s.totalArea, "%.10g")},
      {"∫K dA (Σ angle defects)", number(integral, "%.10g") + " = 2πχ " + number(2 * M_PI * s.eulerCharacteristic)},
      {"Gauss–Bonnet residual", number(s.curvature.gaussBonnetResidual, "%.2e")},
      {"corner angles (°)",
       number(s.minCornerAngle * 180 / M_PI, "%.2f") + " … " + number(s.maxCornerAngle * 180 / M_PI, "%.2f")}};
  scene.figures.insert(scene.figures.begin(), rows.begin(), rows.end());
  for (const auto& [name, values] : scene.fields) {
    double lo = INFINITY, hi = -INFINITY;
    int bad = 0;
    for (double x : values)
      if (std::isfinite(x))
        lo = std::min(lo, x), hi = std::max(hi, x);
      else
        ++bad;
    scene.figures.push_back({name + " range", number(lo, "%.4g") + " … " + number(hi, "%.4g") +
                                                  (bad ? " (" + std::to_string(bad) + " non-finite)" : "")});
  }
}

void appendString(std::string& out, const std::string& s) {
  out += '"';
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '"' || c == '\\')
      out += '\\', out += c;
    else if (c == '\n')
      out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += number(static_cast<unsigned char>(c), "\\u%04.0f");
    else if (c == '<' && i + 1 < s.size() && s[i + 1] == '/')
      out += "<\\";
    else
      out += c;
  }
  out += '"';
}

void appendNumbers(std::string& out, const std::vector<double>& values) {
  out += '[';
  for (size_t i = 0; i < values.size(); ++i) {
    if (i) out += ',';
    out += std::isfinite(values[i]) ? number(values[i]) : "null";
  }
  out += ']';
}

std::string slurp(const std::string& path, const std::string& hint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(describeAt(path, "cannot read" + hint));
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The template with each marker replaced once; markers are found in the template itself, so text inlined for one marker
// is never searched for another.
std::string fillTemplate(const std::string& html, std::vector<std::pair<std::string, const std::string*>> parts) {
  std::vector<std::pair<size_t, size_t>> at;  // (position, part)
  for (size_t i = 0; i < parts.size(); ++i) {
    const auto pos = html.find(parts[i].first);
    if (pos == std::string::npos) throw InputError("view template: the marker " + parts[i].first + " is missing");
    at.push_back({pos, i});
  }
  std::sort(at.begin(), at.end());
  std::string page;
  size_t done = 0;
  for (const auto& [pos, i] : at) {
    page.append(html, done, pos - done);
    page += *parts[i].second;
    done = pos + parts[i].first.size();
  }
  return page.append(html, done, std::string::npos);
}

}  // namespace

ViewScene makeViewScene(const MeshData& data, const ViewSceneOptions& options) {
  if (const std::string bad = options.validate(); !bad.empty()) throw InputError("ViewSceneOptions: " + bad);
  ConversionReport report;
  const IntrinsicTriangulation tri = toTriangulation(data, &report);
  ViewScene scene;
  scene.title = data.source;
  scene.comments = data.comments;
  const int n = tri.mesh.nVertices();
  for (const auto& [name, values] : data.vertexProperties) {
    auto& field = scene.fields[name];
    field.assign(n, NAN);
    for (size_t v = 0; v < values.size() && v < report.vertexMap.size(); ++v)
      if (report.vertexMap[v] >= 0) field[report.vertexMap[v]] = values[v];
  }
  for (int f = 0; f < tri.mesh.nFaces(); ++f)
    scene.triangles.push_back({tri.mesh.tail(3 * f), tri.mesh.tail(3 * f + 1), tri.mesh.tail(3 * f + 2)});
  if (!data.positions.empty()) {
    scene.domain = "positions from the file";
    scene.points.resize(n);
    for (size_t v = 0; v < data.positions.size(); ++v)
      if (report.vertexMap[v] >= 0) scene.points[report.vertexMap[v]] = data.positions[v];
  } else {
    scene.points = domainPoints(tri, data, options, scene);
  }
  if (scene.fields.count("u") && scene.fields.count("v"))
    for (int v = 0; v < n; ++v) scene.chart.emplace_back(scene.fields["u"][v], scene.fields["v"][v]);
  addFigures(tri, scene);
  return scene;
}

ViewAssets readViewAssets(const std::string& viewerDir, const std::string& threeDir) {
  const std::string hint = " (three.js: apt-get install libjs-three)";
  return {slurp(viewerDir + "/view.html", " (the viewer template, installed with conformesh)"),
          slurp(threeDir + "/three.min.js", hint), slurp(threeDir + "/examples/js/controls/OrbitControls.js", hint)};
}

std::string sceneJson(const ViewScene& scene) {
  std::string out = "{\"title\":";
  appendString(out, scene.title);
  out += ",\"domain\":";
  appendString(out, scene.domain);
  std::vector<double> xyz;
  for (const auto& p : scene.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  out += ",\"positions\":";
  appendNumbers(out, xyz);
  out += ",\"triangles\":[";
  for (size_t f = 0; f < scene.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) out += (f || k ? "," : "") + std::to_string(scene.triangles[f][k]);
  out += "],\"fields\":{";
  bool first = true;
  for (const auto& [name, values] : scene.fields) {
    if (!first) out += ',';
    first = false;
    appendString(out, name);
    out += ':';
    appendNumbers(out, values);
  }
  out += "},\"figures\":[";
  for (size_t i = 0; i < scene.figures.size(); ++i) {
    out += i ? ",[" : "[";
    appendString(out, scene.figures[i].first);
    out += ',';
    appendString(out, scene.figures[i].second);
    out += ']';
  }
  out += "],\"comments\":[";
  for (size_t i = 0; i < scene.comments.size(); ++i) {
    if (i) out += ',';
    appendString(out, scene.comments[i]);
  }
  return out + "]}";
}

std::string viewPageHtml(const ViewScene& scene, const ViewAssets& assets) {
  const std::string json = sceneJson(scene);
  return fillTemplate(
      assets.templateHtml,
      {{"/*@THREE@*/", &assets.threeJs}, {"/*@ORBIT_CONTROLS@*/", &assets.orbitControlsJs}, {"/*@SCENE@*/", &json}});
}

void writeViewPage(const ViewScene& scene, const ViewAssets& assets, const std::string& path) {
  const std::string page = viewPageHtml(scene, assets);
  intrinsic::writeFileAtomically(path, page);
}

}  // namespace conformesh::embedding
