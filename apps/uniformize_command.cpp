// uniformize_command.cpp — `conformesh uniformize IN -o OUT`: the discrete Ricci (Yamabe) flow T0 → T0* of the
// paper's §4.1, written as a PLY with its background geometry, edge lengths, the conformal factor λ per vertex and
// (optionally) the flip log that maps points of T0* back to T0; `--method` selects the circle-packing flows instead.
#include <cstdio>
#include <fstream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/flow/circle_packing.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::apps {

namespace {

struct UniformizeOptions {
  std::string input, output, correspondence;
  std::string method = "yamabe";
  double tolerance = 1e-10;
  int maxSteps = 100;
  bool json = false;
};

nlohmann::json correspondenceJson(const intrinsic::FlowCorrespondence& c) {
  nlohmann::json flips = nlohmann::json::array();
  for (const auto& f : c.flips())
    flips.push_back({f.faceA, f.faceB, f.cornerA, f.cornerB, f.ab, f.bc, f.ca, f.ad, f.db, f.cd});
  return {{"format", "conformesh flow correspondence 1"},
          {"faces", c.nFaces()},
          {"log_scale", c.logScale},
          {"flip_fields", {"faceA", "faceB", "cornerA", "cornerB", "ab", "bc", "ca", "ad", "db", "cd"}},
          {"flips", flips}};
}

// The flow chosen by --method: vertex scaling (uniformization.h) or a circle-packing flow (circle_packing.h, closed
// genus >= 1 only), which returns the same kind of result with no flips.
intrinsic::Uniformization runFlow(const UniformizeOptions& o, const intrinsic::IntrinsicTriangulation& input,
                                  const intrinsic::UniformizationOptions& options) {
  if (o.method == "yamabe") return intrinsic::uniformize(input, options);
  intrinsic::CirclePackingOptions packing;
  packing.scheme = o.method == "circle-packing" ? intrinsic::CirclePackingScheme::Tangential
                                                : intrinsic::CirclePackingScheme::InversiveDistance;
  packing.tolerance = o.tolerance;
  packing.maxNewtonSteps = o.maxSteps;
  packing.progress = options.progress;
  return intrinsic::uniformizeByCirclePacking(input, packing).result;
}

void runUniformize(const UniformizeOptions& o) {
  progress("reading " + o.input);
  const intrinsic::MeshData data = loadMesh(o.input);
  const intrinsic::IntrinsicTriangulation input = intrinsic::toTriangulation(data);
  intrinsic::UniformizationOptions options;
  options.flow.tolerance = o.tolerance;
  options.flow.maxNewtonSteps = o.maxSteps;
  options.progress = [](const std::string& line) { progress(line); };
  const intrinsic::Uniformization u = runFlow(o, input, options);

  intrinsic::MeshData out = intrinsic::fromTriangulation(u.uniform);
  out.source = o.output;
  out.positions = u.positions;
  out.vertexProperties["lambda"] = u.lambda;
  out.comments.push_back("uniformized by conformesh (" + o.method + " flow): target " +
                         intrinsic::toString(u.report.target));
  intrinsic::writeMesh(out, o.output);
  if (!o.correspondence.empty()) {
    std::ofstream file(o.correspondence);
    if (!file) throw InputError(o.correspondence + ": cannot open for writing");
    file << correspondenceJson(u.correspondence).dump() << '\n';
    if (!file) throw InputError(o.correspondence + ": write failed");
  }

  // Figures a reader can check: the worst interior angle-sum error in the written geometry and Gauss–Bonnet.
  const double worst = intrinsic::maxInteriorAngleSumError(u.uniform);
  const intrinsic::CurvatureTotals totals = intrinsic::curvatureTotals(u.uniform);
  const auto& r = u.report;
  nlohmann::json j = {{"input", o.input},
                      {"output", o.output},
                      {"method", o.method},
                      {"target", intrinsic::toString(r.target)},
                      {"background", intrinsic::toString(u.uniform.background)},
                      {"genus", r.genus},
                      {"boundary_loops", r.boundaryLoops},
                      {"newton_steps", r.newtonSteps},
                      {"flips", r.flips},
                      {"max_curvature_residual", r.maxResidual},
                      {"tolerance", r.effectiveTolerance},
                      {"max_interior_angle_sum_error", worst},
                      {"gauss_bonnet_residual", totals.gaussBonnetResidual},
                      {"total_area", intrinsic::totalArea(u.uniform)},
                      {"seconds", r.seconds}};
  if (r.target == intrinsic::UniformizationTarget::Sphere) {
    j["puncture_vertex"] = r.punctureVertex;
    j["puncture_attempts"] = r.punctureAttempts;
    j["centring_iterations"] = r.centringIterations;
  }
  if (r.target == intrinsic::UniformizationTarget::FlatCylinder) j["cylinder_height"] = r.cylinderHeight;
  if (!o.correspondence.empty()) j["correspondence"] = o.correspondence;
  if (o.json) {
    printJson(j);
    return;
  }
  std::printf("%s -> %s\n", o.input.c_str(), o.output.c_str());
  std::printf("  %-30s %s (%s background), genus %d, %d boundary loops\n", "target",
              intrinsic::toString(r.target).c_str(), intrinsic::toString(u.uniform.background).c_str(), r.genus,
              r.boundaryLoops);
  std::printf("  %-30s %d Newton steps, %lld Ptolemy flips, %.2f s\n", "flow", r.newtonSteps, (long long)r.flips,
              r.seconds);
  std::printf("  %-30s %.3g rad (tolerance %.3g)\n", "max |K - K^| at exit", r.maxResidual, r.effectiveTolerance);
  std::printf("  %-30s %.3g rad\n", "max |angle sum - 2pi|", worst);
  std::printf("  %-30s %.3g\n", "Gauss-Bonnet residual", totals.gaussBonnetResidual);
  std::printf("  %-30s %.12g\n", "total area", intrinsic::totalArea(u.uniform));
  if (r.target == intrinsic::UniformizationTarget::FlatCylinder)
    std::printf("  %-30s %.12g (circumference 2 pi; = log(R/r) of the annulus)\n", "cylinder height", r.cylinderHeight);
}

}  // namespace

void registerUniformizeCommand(CLI::App& app) {
  auto o = std::make_shared<UniformizeOptions>();
  CLI::App* sub =
      app.add_subcommand("uniformize", "Uniformize a triangulation to constant curvature (discrete Ricci flow)");
  sub->footer(
      "Computes T0* of the paper's section 4.1 by the discrete Yamabe flow of vertex scaling with Ptolemy (Delaunay)\n"
      "flips (Gu-Luo-Sun-Wu 2018), Newton's method on the convex energy, CHOLMOD Cholesky. The target follows\n"
      "the topology:\n"
      "  closed genus 0      the unit sphere (puncture a vertex, flatten, inverse stereographic projection,\n"
      "                      Moebius centring)              -> PLY with spherical lengths and positions on S^2\n"
      "  closed genus 1      a flat torus of area 1         -> PLY with Euclidean lengths (no positions)\n"
      "  closed genus >= 2   hyperbolic, curvature -1       -> PLY with hyperbolic lengths\n"
      "  genus 0, boundary   a circle domain (the longest loop the unit circle) -> Euclidean lengths, positions\n"
      "                      (an annulus beyond log(R/r) = 17.6: a flat cylinder of circumference 2 pi, both\n"
      "                      loops geodesics, height = log(R/r) -> Euclidean lengths, no positions)\n"
      "  genus >= 1, boundary hyperbolic with geodesic boundary loops\n"
      "The output PLY carries `comment geometry <background>`, the edge element with the lengths, and the vertex\n"
      "property `lambda`: the original metric is ~ e^(2 lambda) times the uniform one. Vertices are not moved by\n"
      "vertex scaling, so vertex i of the output is vertex i of the input; with --correspondence the flip log is\n"
      "written as JSON so that any point (face, barycentric) of T0* can be mapped to T0 (flow_correspondence.h).\n"
      "Printed figures: Newton steps and flips; max |K - K^|, the curvature residual at exit (radians); the worst\n"
      "interior |angle sum - 2pi| recomputed from the output lengths in the output geometry; the Gauss-Bonnet\n"
      "residual (sum of curvature + K_background * area - 2 pi chi). A flow that does not converge is an error\n"
      "naming the residual it reached (exit status 1). docs/ricci_flow.md has the theory and the guarantees.\n"
      "--method circle-packing | inversive-distance: the circle-packing flows of Jin-Kim-Luo-Gu (2008), for\n"
      "comparison; closed surfaces of genus >= 1 only, no flips, so a solution need not exist: tangential\n"
      "packings always exist (Koebe-Andreev-Thurston) but forget the input lengths (the result depends on the\n"
      "connectivity alone); inversive-distance packings keep the input's conformal data but Newton can be blocked\n"
      "by a triangle that ceases to exist, reported as an error naming the face. lambda is then the log ratio of\n"
      "the mean edge lengths at each vertex before and after (an estimate; the correspondence is face-wise affine).\n"
      "Example: conformesh uniformize bunny.off -o bunny-sphere.ply --correspondence bunny-map.json");
  sub->add_option("input", o->input, "Input mesh (OBJ, OFF or PLY; lengths from the PLY edge element if present)")
      ->required();
  sub->add_option("-o,--output", o->output, "Output PLY (T0*)")->required();
  sub->add_option("--method", o->method,
                  "Flow: yamabe (vertex scaling with Ptolemy flips, every topology), circle-packing (tangential\n"
                  "circle packing) or inversive-distance (circle packing keeping the input's inversive distances);\n"
                  "the two circle-packing flows take closed surfaces of genus >= 1 only")
      ->check(CLI::IsMember({"yamabe", "circle-packing", "inversive-distance"}))
      ->capture_default_str();
  sub->add_option("--tolerance", o->tolerance,
                  "Stop when max |K - K^| is below this (radians); raised to 3e-13*sqrt(#vertices) on huge meshes")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub->add_option("--max-steps", o->maxSteps, "Newton step cap per flow solve")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub->add_option("--correspondence", o->correspondence, "Write the T0* -> T0 flip log (JSON) here");
  sub->add_flag("--json", o->json, "Print the report as JSON");
  sub->callback([o] { runUniformize(*o); });
}

}  // namespace conformesh::apps
