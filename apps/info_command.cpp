// info_command.cpp — `conformesh info FILE`: the intrinsic report of a mesh (topology, curvature, Gauss–Bonnet,
// angles, lengths, Delaunay-ness), as text or JSON; optionally writes its intrinsic Delaunay triangulation.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::apps {

namespace {

struct InfoOptions {
  std::string input;
  bool json = false;
  std::string delaunayOutput;
};

double degrees(double radians) {
  return radians * 180.0 / M_PI;
}

nlohmann::json toJson(const intrinsic::MeshSummary& s, const intrinsic::ConversionReport& conv) {
  nlohmann::json j = refine::meshSummaryJson(s);
  j.update(refine::readingJson(conv));
  return j;
}

void printText(const std::string& path, const intrinsic::MeshSummary& s, const intrinsic::ConversionReport& conv) {
  auto line = [](const char* name, const std::string& value) { std::printf("  %-28s %s\n", name, value.c_str()); };
  auto num = [](double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return std::string(buf);
  };
  std::printf("%s\n", path.c_str());
  line("background geometry", intrinsic::toString(s.background));
  line("lengths from", conv.lengthsFromPositions ? "vertex positions" : "edge element");
  line("vertices / edges / faces",
       std::to_string(s.vertices) + " / " + std::to_string(s.edges) + " / " + std::to_string(s.faces));
  line("connected components", std::to_string(s.components.size()));
  line("boundary loops", std::to_string(s.boundaryLoops));
  line("Euler characteristic", std::to_string(s.eulerCharacteristic));
  line("genus", std::to_string(s.genus) + (s.components.size() > 1 ? " (sum over components)" : ""));
  // The first ten components; a mesh of many small parts (boeing.off has 122) lists the rest in --json only.
  const std::size_t shown = std::min<std::size_t>(s.componentFigures.size(), 10);
  if (shown < s.componentFigures.size())
    line("  components listed", "the first " + std::to_string(shown) + " (--json lists all " +
                                    std::to_string(s.componentFigures.size()) + ")");
  for (std::size_t i = 0; i < shown; ++i) {
    const intrinsic::ComponentTopology& c = s.components[i];
    const intrinsic::ComponentFigures& f = s.componentFigures[i];
    line(("  component " + std::to_string(i)).c_str(),
         std::to_string(c.vertices) + " vertices, " + std::to_string(c.faces) + " faces, genus " +
             std::to_string(c.genus) + ", " + std::to_string(c.boundaryLoops) + " boundary loops, area " + num(f.area) +
             ", Gauss-Bonnet residual " + num(f.curvature.gaussBonnetResidual));
  }
  line("total area", num(s.totalArea));
  line("total curvature", num(s.curvature.interiorDeficit + s.curvature.boundaryTurning) + "  (deficits " +
                              num(s.curvature.interiorDeficit) + ", boundary turning " +
                              num(s.curvature.boundaryTurning) + ")");
  if (s.background != intrinsic::Background::Euclidean) line("background K * area", num(s.curvature.backgroundTerm));
  line("Gauss-Bonnet residual", num(s.curvature.gaussBonnetResidual));
  line("corner angles (deg)", num(degrees(s.minCornerAngle)) + " .. " + num(degrees(s.maxCornerAngle)));
  line("edge lengths", num(s.minEdgeLength) + " .. " + num(s.maxEdgeLength));
  line("non-Delaunay edges",
       std::to_string(s.nonDelaunayEdges) + " (" + num(100 * s.nonDelaunayFraction) + " % of interior edges)");
  if (conv.build.reorientedFaces > 0) line("reoriented faces", std::to_string(conv.build.reorientedFaces));
  if (conv.polygonsTriangulated > 0) line("polygons fan-triangulated", std::to_string(conv.polygonsTriangulated));
  if (conv.stripTriangles > 0) line("triangles from tristrips", std::to_string(conv.stripTriangles));
  if (conv.unreferencedVerticesRemoved > 0)
    line("unreferenced vertices", std::to_string(conv.unreferencedVerticesRemoved) + " (ignored)");
}

void runInfo(const InfoOptions& o) {
  progress("reading " + o.input);
  const intrinsic::MeshData data = loadMesh(o.input);
  intrinsic::ConversionReport conv;
  intrinsic::IntrinsicTriangulation tri = intrinsic::toTriangulation(data, &conv);
  const intrinsic::MeshSummary s = intrinsic::summarize(tri);
  nlohmann::json j = toJson(s, conv);
  j["file"] = o.input;
  if (!o.delaunayOutput.empty()) {
    progress("flipping to the intrinsic Delaunay triangulation");
    const intrinsic::DelaunayReport r = intrinsic::makeDelaunay(tri);
    intrinsic::writeMesh(intrinsic::fromTriangulation(tri), o.delaunayOutput);
    j["delaunay"] = {{"output", o.delaunayOutput}, {"flips", r.flips}};
    if (!o.json)
      std::printf("  %-28s %lld flips, written to %s\n", "intrinsic Delaunay", (long long)r.flips,
                  o.delaunayOutput.c_str());
  }
  if (o.json)
    printJson(j);
  else
    printText(o.input, s, conv);
}

}  // namespace

void registerInfoCommand(CLI::App& app) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* sub = app.add_subcommand(
      "info", "Report a mesh's topology, curvature, Gauss-Bonnet residual, angles and Delaunay-ness");
  sub->footer("Example: conformesh info bunny.ply --json\nDetails: docs/cli.md#info");
  sub->add_option("file", o->input, "Mesh file (.obj, .off, .ply)")->required();
  addRepairOption(sub);
  sub->add_flag("--json", o->json, "Print the report as JSON");
  sub->add_option("--delaunay", o->delaunayOutput, "Also write the intrinsic Delaunay triangulation here (PLY)");
  sub->callback([o] { runInfo(*o); });
}

}  // namespace conformesh::apps
