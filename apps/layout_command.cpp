// layout_command.cpp — `conformesh layout IN -o OUT.svg|.png|.ply`: uniformizes a triangulation and lays it out in its
// canonical domain (disk or circle domain, sphere, flat torus with its periods and modulus, Poincaré disk with its
// deck group), as a picture (SVG; PNG through scripts/plot_layout.py and matplotlib) or as a PLY with per-corner
// domain coordinates. The geometry is in conformesh_embedding (docs/layout.md); this file parses and prints.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/embedding/layout/layout_picture.h"
#include "conformesh/embedding/layout/layout_ply.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::apps {

namespace {

using namespace conformesh::embedding;

struct LayoutCommandOptions {
  std::string input, output;
  double tolerance = 1e-12;
  int tiles = 1, pixels = 900, centreVertex = -1, directionVertex = -1;
  bool json = false;
};

nlohmann::json complexJson(Complex z) {
  return {z.real(), z.imag()};
}

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// scripts/plot_layout.py next to the convergence plot script (installed or in the source tree).
std::string plotScript() {
  for (const char* s : {CONFORMESH_INSTALLED_PLOT_SCRIPT, CONFORMESH_SOURCE_PLOT_SCRIPT}) {
    const auto p = std::filesystem::path(s).parent_path() / "plot_layout.py";
    if (std::filesystem::exists(p)) return p.string();
  }
  throw InputError("layout: scripts/plot_layout.py not found (needed for PNG output; write .svg instead)");
}

void writePng(const LayoutDrawing& d, const std::string& path, int pixels) {
  nlohmann::json tris = nlohmann::json::array(), lines = nlohmann::json::array();
  for (const auto& t : d.triangles)
    tris.push_back({t.corners[0].x(), t.corners[0].y(), t.corners[1].x(), t.corners[1].y(), t.corners[2].x(),
                    t.corners[2].y(), t.layer, t.shade});
  for (const auto& l : d.lines) {
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : l.points) pts.push_back({p.x(), p.y()});
    lines.push_back({{"points", pts}, {"colour", l.colour}, {"closed", l.closed}});
  }
  const std::string jsonPath = path + ".layout.json";
  {
    std::ofstream f(jsonPath);
    if (!f) throw InputError(jsonPath + ": cannot open for writing");
    f << nlohmann::json{{"title", d.title}, {"unit_circle", d.unitCircle}, {"triangles", tris}, {"lines", lines}}
             .dump();
  }
  const std::string python = scriptInterpreter();  // CMake's CONFORMESH_PYTHON (cli_common.h)
  const std::string cmd =
      python + " '" + plotScript() + "' '" + jsonPath + "' '" + path + "' " + std::to_string(pixels) + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::filesystem::remove(jsonPath);
  if (status != 0)
    throw InputError("layout: `" + cmd + "` failed (PNG output needs python3-matplotlib); write .svg instead");
}

// What a layout produces for the output: the picture, the per-corner domain coordinates, the JSON report and the
// human-readable summary lines.
struct LayoutOutcome {
  LayoutDrawing drawing;
  CornerLayout corners;
  nlohmann::json json;
  std::vector<std::string> lines;
};

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
  char buf[256];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

void layOutTorus(const intrinsic::IntrinsicTriangulation& tri, const PictureOptions& po, LayoutOutcome& out) {
  const TorusLayout t = layoutTorus(tri);
  out.drawing = drawTorus(tri, t, po);
  out.corners = cornerLayout(tri, t.domain);
  out.json["omega1"] = complexJson(t.omega1);
  out.json["omega2"] = complexJson(t.omega2);
  out.json["reduced_omega1"] = complexJson(t.reducedOmega1);
  out.json["reduced_omega2"] = complexJson(t.reducedOmega2);
  out.json["tau"] = complexJson(t.tau);
  out.json["relation_residual"] = t.domain.relationResidual;
  out.lines.push_back(format("periods (area 1)   omega1 = %.12g %+.12gi, omega2 = %.12g %+.12gi",
                             t.reducedOmega1.real(), t.reducedOmega1.imag(), t.reducedOmega2.real(),
                             t.reducedOmega2.imag()));
  out.lines.push_back(format("modulus tau        %.12g %+.12gi (|Re| <= 1/2, |tau| >= 1)", t.tau.real(), t.tau.imag()));
}

void layOutHyperbolic(const intrinsic::IntrinsicTriangulation& tri, const PictureOptions& po, LayoutOutcome& out) {
  const HyperbolicLayout h = layoutHyperbolic(tri);
  out.drawing = drawHyperbolic(tri, h, po);
  out.corners = cornerLayout(tri, h.domain);
  nlohmann::json gens = nlohmann::json::array();
  for (const auto& g : h.generators)
    gens.push_back({{"a", complexJson(g.matrix(0, 0))},
                    {"b", complexJson(g.matrix(0, 1))},
                    {"translation_length", g.translationLength}});
  out.json["generators"] = gens;
  out.json["relation"] = h.relation;
  out.json["relation_residual"] = h.relationResidual;
  out.json["max_vertex_residual"] = h.domain.maxVertexResidual;
  for (std::size_t i = 0; i < h.generators.size(); ++i) {
    const Mobius& m = h.generators[i].matrix;
    out.lines.push_back(format("g%-2zu a = %.10g %+.10gi, b = %.10g %+.10gi, length %.8g", i + 1, m(0, 0).real(),
                               m(0, 0).imag(), m(0, 1).real(), m(0, 1).imag(), h.generators[i].translationLength));
  }
  out.lines.push_back("relation           " + h.relation + " = 1");
  out.lines.push_back(format("relation residual  %.3g (max-entry distance from +-I in SU(1,1))", h.relationResidual));
}

void layOutSphere(const intrinsic::Uniformization& u, const intrinsic::IntrinsicTriangulation& input,
                  const LayoutCommandOptions& o, LayoutOutcome& out) {
  SphereLayoutOptions so;
  so.centreVertex = o.centreVertex;
  so.directionVertex = o.directionVertex;
  const SphereLayout s = layoutSphere(u, vertexAreas(input), so);
  out.drawing = drawSphere(u.uniform, s);
  out.corners = cornerLayout(u.uniform, s);
  out.json["centroid_distance"] = s.centroid.norm();
  out.json["balance_iterations"] = s.balanceIterations;
  out.lines.push_back(
      format("centre of mass     |c| = %.3g (area-weighted, after Moebius balancing)", s.centroid.norm()));
}

void layOutDisk(const intrinsic::Uniformization& u, const LayoutCommandOptions& o, LayoutOutcome& out) {
  const DiskLayout d = layoutDisk(u, {o.centreVertex, o.directionVertex});
  out.drawing = drawDisk(u.uniform, d);
  out.corners = cornerLayout(u.uniform, d);
  nlohmann::json circles = nlohmann::json::array();
  for (const auto& c : d.circles) {
    circles.push_back({{"centre", {c.centre.x(), c.centre.y()}}, {"radius", c.radius}, {"deviation", c.deviation}});
    out.lines.push_back(format("circle             centre (%.6g, %.6g), radius %.8g, deviation %.2g", c.centre.x(),
                               c.centre.y(), c.radius, c.deviation));
  }
  out.json["circles"] = circles;
}

// Step 2 (compute): the canonical-domain layout of the uniformization's target; throws InputError for the targets
// that have none here (flat cylinder, genus >= 1 with boundary).
void layOut(const intrinsic::Uniformization& u, const intrinsic::IntrinsicTriangulation& input,
            const LayoutCommandOptions& o, LayoutOutcome& out) {
  PictureOptions po;
  po.tileDepth = o.tiles;
  switch (u.report.target) {
    case intrinsic::UniformizationTarget::FlatTorus:
      return layOutTorus(u.uniform, po, out);
    case intrinsic::UniformizationTarget::Hyperbolic:
      return layOutHyperbolic(u.uniform, po, out);
    case intrinsic::UniformizationTarget::Sphere:
      return layOutSphere(u, input, o, out);
    case intrinsic::UniformizationTarget::CircleDomain:
      return layOutDisk(u, o, out);
    case intrinsic::UniformizationTarget::FlatCylinder: {
      char height[32];
      std::snprintf(height, sizeof height, "%.6g", u.report.cylinderHeight);
      throw InputError("layout: " + o.input + " is an annulus of log(R/r) = " + height +
                       ", uniformized to a flat cylinder (circumference 2 pi, that height): its circle domain's inner "
                       "circle, e^-" +
                       height + " of the outer one, is below what a planar layout resolves");
    }
    default:
      throw InputError("layout: " + o.input + " uniformizes to " + intrinsic::toString(u.report.target) +
                       " (genus >= 1 with boundary), which has no canonical-domain layout here");
  }
}

// Step 3 (write): the picture or the PLY, chosen by the output's extension `ext`.
void writeLayout(const LayoutOutcome& out, const LayoutCommandOptions& o, const std::string& ext) {
  if (ext == ".svg") {
    std::ofstream f(o.output);
    if (!f) throw InputError(o.output + ": cannot open for writing");
    f << toSvg(out.drawing, o.pixels);
    if (!f) throw InputError(o.output + ": write failed");
  } else if (ext == ".png") {
    writePng(out.drawing, o.output, o.pixels);
  } else {
    writeLayoutPly(out.corners, o.output);
  }
}

// parse → uniformize (intrinsic::uniformize) → lay out (embedding/layout) → write → print.
void runLayout(const LayoutCommandOptions& o) {
  const std::string ext = extensionOf(o.output);
  if (ext != ".svg" && ext != ".png" && ext != ".ply")
    throw InputError("layout: output " + o.output + " must end in .svg, .png or .ply, found '" + ext + "'");
  progress("reading " + o.input);
  const intrinsic::IntrinsicTriangulation input = intrinsic::toTriangulation(loadMesh(o.input));
  intrinsic::UniformizationOptions uo;
  uo.flow.tolerance = o.tolerance;
  uo.progress = [](const std::string& line) { progress(line); };
  const intrinsic::Uniformization u = intrinsic::uniformize(input, uo);

  LayoutOutcome out;
  out.json = {{"input", o.input},
              {"output", o.output},
              {"target", intrinsic::toString(u.report.target)},
              {"genus", u.report.genus},
              {"boundary_loops", u.report.boundaryLoops},
              {"flow_residual", u.report.maxResidual}};
  layOut(u, input, o, out);
  writeLayout(out, o, ext);
  if (o.json) {
    printJson(out.json);
    return;
  }
  std::printf("%s -> %s\n  target             %s, genus %d\n", o.input.c_str(), o.output.c_str(),
              intrinsic::toString(u.report.target).c_str(), u.report.genus);
  for (const auto& l : out.lines) std::printf("  %s\n", l.c_str());
}

}  // namespace

void registerLayoutCommand(CLI::App& app) {
  auto o = std::make_shared<LayoutCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "layout", "Lay a surface out in its canonical domain: disk, sphere, flat torus or Poincare disk");
  sub->footer(
      "Example: conformesh layout double-torus.off -o double-torus.svg --tiles 2\n"
      "Details: docs/cli.md#layout (theory: docs/layout.md)");
  sub->add_option("input", o->input, "Input mesh (OFF, OBJ, PLY; positions or edge lengths)")->required();
  sub->add_option("-o,--output", o->output, "Output file: .svg, .png or .ply")->required();
  addRepairOption(sub);
  sub->add_option("--tiles", o->tiles, "Rings of tiles of the universal cover in pictures (0..4)")
      ->capture_default_str()
      ->check(untyped(CLI::Range(0, 4)));
  sub->add_option("--pixels", o->pixels, "Picture size in pixels (64..8000)")
      ->capture_default_str()
      ->check(untyped(CLI::Range(64, 8000)));
  sub->add_option("--centre-vertex", o->centreVertex, "Disk: vertex sent to 0; sphere: to the south pole (-1: none)")
      ->capture_default_str();
  sub->add_option("--direction-vertex", o->directionVertex, "Disk and sphere: vertex rotated onto +x (-1: none)")
      ->capture_default_str();
  sub->add_option("--tolerance", o->tolerance, "Flow tolerance (radians)")->capture_default_str();
  sub->add_flag("--json", o->json, "Print the figures as JSON");
  sub->callback([o] { runLayout(*o); });
}

}  // namespace conformesh::apps
