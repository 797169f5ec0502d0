// layout_command.cpp — `conformesh layout IN -o OUT.svg|.png|.ply`: uniformizes a triangulation and lays it out in its
// canonical domain (disk or circle domain, sphere, flat torus with its periods and modulus, Poincaré disk with its
// deck group), as a picture (SVG; PNG through scripts/plot_layout.py and matplotlib) or as a PLY with per-corner
// domain coordinates. The geometry is in conformesh_embedding (docs/layout.md); this file parses and prints.
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
  // Debian's interpreter, which python3-matplotlib belongs to, ahead of any other python3 on the PATH.
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd =
      python + " '" + plotScript() + "' '" + jsonPath + "' '" + path + "' " + std::to_string(pixels) + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::filesystem::remove(jsonPath);
  if (status != 0)
    throw InputError("layout: `" + cmd + "` failed (PNG output needs python3-matplotlib); write .svg instead");
}

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
  const intrinsic::IntrinsicTriangulation& tri = u.uniform;
  PictureOptions po;
  po.tileDepth = o.tiles;

  nlohmann::json j = {{"input", o.input},
                      {"output", o.output},
                      {"target", intrinsic::toString(u.report.target)},
                      {"genus", u.report.genus},
                      {"boundary_loops", u.report.boundaryLoops},
                      {"flow_residual", u.report.maxResidual}};
  LayoutDrawing drawing;
  CornerLayout corners;
  std::vector<std::string> lines;  // human-readable summary
  char buf[256];
  switch (u.report.target) {
    case intrinsic::UniformizationTarget::FlatTorus: {
      const TorusLayout t = layoutTorus(tri);
      drawing = drawTorus(tri, t, po);
      corners = cornerLayout(tri, t.domain);
      j["omega1"] = complexJson(t.omega1);
      j["omega2"] = complexJson(t.omega2);
      j["reduced_omega1"] = complexJson(t.reducedOmega1);
      j["reduced_omega2"] = complexJson(t.reducedOmega2);
      j["tau"] = complexJson(t.tau);
      j["relation_residual"] = t.domain.relationResidual;
      std::snprintf(buf, sizeof buf, "periods (area 1)   omega1 = %.12g %+.12gi, omega2 = %.12g %+.12gi",
                    t.reducedOmega1.real(), t.reducedOmega1.imag(), t.reducedOmega2.real(), t.reducedOmega2.imag());
      lines.push_back(buf);
      std::snprintf(buf, sizeof buf, "modulus tau        %.12g %+.12gi (|Re| <= 1/2, |tau| >= 1)", t.tau.real(),
                    t.tau.imag());
      lines.push_back(buf);
      break;
    }
    case intrinsic::UniformizationTarget::Hyperbolic: {
      const HyperbolicLayout h = layoutHyperbolic(tri);
      drawing = drawHyperbolic(tri, h, po);
      corners = cornerLayout(tri, h.domain);
      nlohmann::json gens = nlohmann::json::array();
      for (const auto& g : h.generators)
        gens.push_back({{"a", complexJson(g.matrix(0, 0))},
                        {"b", complexJson(g.matrix(0, 1))},
                        {"translation_length", g.translationLength}});
      j["generators"] = gens;
      j["relation"] = h.relation;
      j["relation_residual"] = h.relationResidual;
      j["max_vertex_residual"] = h.domain.maxVertexResidual;
      for (std::size_t i = 0; i < h.generators.size(); ++i) {
        const Mobius& m = h.generators[i].matrix;
        std::snprintf(buf, sizeof buf, "g%-2zu a = %.10g %+.10gi, b = %.10g %+.10gi, length %.8g", i + 1,
                      m(0, 0).real(), m(0, 0).imag(), m(0, 1).real(), m(0, 1).imag(),
                      h.generators[i].translationLength);
        lines.push_back(buf);
      }
      lines.push_back("relation           " + h.relation + " = 1");
      std::snprintf(buf, sizeof buf, "relation residual  %.3g (max-entry distance from +-I in SU(1,1))",
                    h.relationResidual);
      lines.push_back(buf);
      break;
    }
    case intrinsic::UniformizationTarget::Sphere: {
      SphereLayoutOptions so;
      so.centreVertex = o.centreVertex;
      so.directionVertex = o.directionVertex;
      const SphereLayout s = layoutSphere(u, vertexAreas(input), so);
      drawing = drawSphere(tri, s);
      corners = cornerLayout(tri, s);
      j["centroid_distance"] = s.centroid.norm();
      j["balance_iterations"] = s.balanceIterations;
      std::snprintf(buf, sizeof buf, "centre of mass     |c| = %.3g (area-weighted, after Moebius balancing)",
                    s.centroid.norm());
      lines.push_back(buf);
      break;
    }
    case intrinsic::UniformizationTarget::CircleDomain: {
      const DiskLayout d = layoutDisk(u, {o.centreVertex, o.directionVertex});
      drawing = drawDisk(tri, d);
      corners = cornerLayout(tri, d);
      nlohmann::json circles = nlohmann::json::array();
      for (const auto& c : d.circles) {
        circles.push_back({{"centre", {c.centre.x(), c.centre.y()}}, {"radius", c.radius}, {"deviation", c.deviation}});
        std::snprintf(buf, sizeof buf, "circle             centre (%.6g, %.6g), radius %.8g, deviation %.2g",
                      c.centre.x(), c.centre.y(), c.radius, c.deviation);
        lines.push_back(buf);
      }
      j["circles"] = circles;
      break;
    }
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
  if (ext == ".svg") {
    std::ofstream f(o.output);
    if (!f) throw InputError(o.output + ": cannot open for writing");
    f << toSvg(drawing, o.pixels);
    if (!f) throw InputError(o.output + ": write failed");
  } else if (ext == ".png") {
    writePng(drawing, o.output, o.pixels);
  } else {
    writeLayoutPly(corners, o.output);
  }
  if (o.json) {
    printJson(j);
    return;
  }
  std::printf("%s -> %s\n  target             %s, genus %d\n", o.input.c_str(), o.output.c_str(),
              intrinsic::toString(u.report.target).c_str(), u.report.genus);
  for (const auto& l : lines) std::printf("  %s\n", l.c_str());
}

}  // namespace

void registerLayoutCommand(CLI::App& app) {
  auto o = std::make_shared<LayoutCommandOptions>();
  CLI::App* sub = app.add_subcommand("layout", "Lay a surface out in its canonical domain (picture or PLY)");
  sub->footer(
      "Uniformizes IN (as `conformesh uniformize`) and lays the result out where the uniformization theorem puts it:\n"
      "  genus 0, boundary   the unit disk / a circle domain, normalized by --centre-vertex (to 0) and\n"
      "                      --direction-vertex (onto +x)\n"
      "  closed genus 0      the unit sphere, Moebius-balanced (area-weighted centre of mass at the origin);\n"
      "                      the picture is an orthographic view, the PLY's texcoords the stereographic plane\n"
      "  closed genus 1      a flat torus: the surface is cut along a tree-cotree basis into a fundamental domain D;\n"
      "                      the periods omega1, omega2 are the translations carrying D to its neighbours across\n"
      "                      the two generator loops; tau = omega2/omega1 is reduced into |Re tau| <= 1/2,\n"
      "                      |tau| >= 1 (the modular group's fundamental domain), so equal tau = same conformal torus\n"
      "  closed genus >= 2   D in the Poincare disk; the 2g deck transformations z -> (az + b)/(conj(b)z + conj(a))\n"
      "                      in SU(1,1) (|a|^2 - |b|^2 = 1); 'length' is the length of the closed geodesic of each\n"
      "                      generator, 2 acosh|Re a|; the relation read off the cut (each generator once with each\n"
      "                      sign) and how far its product is from the identity\n"
      "Output by extension: .svg (D, plus --tiles rings of tiles of the universal cover, and the generator loops in\n"
      "colour), .png (the same drawn by scripts/plot_layout.py, needs python3-matplotlib), .ply (the uniformized\n"
      "triangulation with per-corner domain coordinates as `texcoord`, like texture coordinates).\n"
      "docs/layout.md has the theory; --json prints every figure machine-readably.");
  sub->add_option("input", o->input, "Input mesh (OFF, OBJ, PLY; positions or edge lengths)")->required();
  sub->add_option("-o,--output", o->output, "Output file: .svg, .png or .ply")->required();
  sub->add_option("--tiles", o->tiles,
                  "Rings of tiles of the universal cover in pictures (tori: (2n+1)^2 tiles; "
                  "hyperbolic: words of length <= n)")
      ->capture_default_str()
      ->check(CLI::Range(0, 4));
  sub->add_option("--pixels", o->pixels, "Picture size in pixels")->capture_default_str()->check(CLI::Range(64, 8000));
  sub->add_option("--centre-vertex", o->centreVertex, "Disk: vertex sent to 0; sphere: vertex sent to the south pole")
      ->capture_default_str();
  sub->add_option("--direction-vertex", o->directionVertex, "Disk and sphere: vertex rotated onto the +x direction")
      ->capture_default_str();
  sub->add_option("--tolerance", o->tolerance,
                  "Flow tolerance (radians); the deck relation's residual is about this times the generators' norms")
      ->capture_default_str();
  sub->add_flag("--json", o->json, "Print the figures as JSON");
  sub->callback([o] { runLayout(*o); });
}

}  // namespace conformesh::apps
