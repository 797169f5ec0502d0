// view_command.cpp — `conformesh view MESH -o page.html [--vtu OUT.vtu]`: one self-contained HTML page (three.js
// inlined) that draws a mesh coloured by any of its per-vertex fields, and/or the same scene as VTU for ParaView.
// Parsing and printing only: the scene, the page and the VTU are embedding/view/view_page.h and intrinsic/io.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/embedding/view/view_page.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/vtu_writer.h"

namespace conformesh::apps {

namespace {

struct ViewOptions {
  std::string input, output, vtu, report, viewerDir, threeDir = "/usr/share/javascript/three";
  bool json = false;
};

// viewer/view.html: the installed copy, else the source tree's (a build folder's binary).
std::string defaultViewerDir() {
  namespace fs = std::filesystem;
  if (fs::exists(fs::path(CONFORMESH_INSTALLED_VIEWER_DIR) / "view.html")) return CONFORMESH_INSTALLED_VIEWER_DIR;
  return CONFORMESH_SOURCE_VIEWER_DIR;
}

std::string scalarText(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
    return buf;
  }
  return v.dump();
}

// The report's scalar figures (remesh --json and the like), one level of nesting as "group.key".
void addReportFigures(const std::string& path, embedding::ViewScene& scene) {
  std::ifstream in(path);
  if (!in) throw InputError(describeAt(path, "cannot read the report"));
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(describeAt(path, std::string("not a JSON report: ") + e.what()));
  }
  if (!j.is_object()) throw InputError(describeAt(path, "expected a JSON object (e.g. remesh --json)"));
  scene.figures.push_back({"— report", path});
  for (const auto& [key, value] : j.items()) {
    if (value.is_primitive() && !value.is_null()) scene.figures.push_back({key, scalarText(value)});
    if (value.is_object())
      for (const auto& [k2, v2] : value.items())
        if (v2.is_primitive() && !v2.is_null()) scene.figures.push_back({key + "." + k2, scalarText(v2)});
  }
}

void runView(const ViewOptions& o) {
  if (o.output.empty() && o.vtu.empty()) throw CLI::ValidationError("view", "give -o PAGE.html, --vtu OUT.vtu or both");
  progress("reading " + o.input);
  const intrinsic::MeshData data = loadMesh(o.input);
  embedding::ViewSceneOptions so;
  so.uniformization.progress = [](const std::string& s) { progress(s); };
  if (data.positions.empty()) progress("no positions in the file: uniformizing to draw it in its conformal domain");
  embedding::ViewScene scene = embedding::makeViewScene(data, so);
  if (!o.report.empty()) addReportFigures(o.report, scene);
  nlohmann::json j = {{"file", o.input},
                      {"vertices", scene.points.size()},
                      {"faces", scene.triangles.size()},
                      {"drawn_on", scene.domain}};
  nlohmann::json fields = nlohmann::json::array();
  for (const auto& [name, values] : scene.fields) fields.push_back(name);
  j["fields"] = fields;
  if (!o.output.empty()) {
    const embedding::ViewAssets assets =
        embedding::readViewAssets(o.viewerDir.empty() ? defaultViewerDir() : o.viewerDir, o.threeDir);
    embedding::writeViewPage(scene, assets, o.output);
    j["output"] = o.output;
  }
  if (!o.vtu.empty()) {
    intrinsic::VtkMesh vtk;
    vtk.title = "conformesh view: " + o.input;
    vtk.points = scene.points;
    vtk.triangles = scene.triangles;
    vtk.pointFields = scene.fields;
    intrinsic::writeVtu(vtk, o.vtu, scene.chart);
    j["vtu"] = o.vtu;
  }
  if (o.json) return printJson(j);
  std::printf("%s: %zu vertices, %zu faces, drawn on %s\n", o.input.c_str(), scene.points.size(),
              scene.triangles.size(), scene.domain.c_str());
  std::printf("  fields: %s\n", fields.empty() ? "(none)" : fields.dump().c_str());
  if (!o.output.empty())
    std::printf("  page written to %s (open it in a browser; no network needed)\n", o.output.c_str());
  if (!o.vtu.empty()) std::printf("  VTU written to %s\n", o.vtu.c_str());
}

}  // namespace

void registerViewCommand(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* sub = app.add_subcommand("view", "Write an interactive HTML page (three.js inlined) or VTU of a mesh");
  sub->footer("Example: conformesh view kerr.ply -o kerr.html --report kerr.json\nDetails: docs/cli.md#view");
  sub->add_option("file", o->input, "Mesh file (.ply from remesh, .obj, .off)")->required();
  sub->add_option("-o,--output", o->output, "The HTML page to write");
  sub->add_option("--vtu", o->vtu, "Also (or only) write the scene as VTU for ParaView (default: none)");
  sub->add_option("--report", o->report, "A JSON report (remesh --json) to show beside (default: none)");
  sub->add_option("--three-dir", o->threeDir, "three.min.js's folder (default: libjs-three's, /usr/share/...)");
  sub->add_option("--viewer-dir", o->viewerDir, "Where view.html is (default: installed, else source tree)");
  sub->add_flag("--json", o->json, "Print what was written as JSON");
  sub->callback([o] { runView(*o); });
}

}  // namespace conformesh::apps
