// uniformize_command.cpp — `conformesh uniformize IN -o OUT`: the discrete Ricci (Yamabe) flow T0 → T0* of the
// paper's §4.1, written as a PLY with its background geometry, edge lengths, the conformal factor λ per vertex and
// (optionally) the flip log that maps points of T0* back to T0; `--method` selects the circle-packing flows instead.
#include <cstdio>
#include <fstream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/circle_packing.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/mesh_components.h"
#include "conformesh/refine/pipeline/output_verification.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::apps {

namespace {

struct UniformizeOptions {
  std::string input, output, correspondence;
  std::string method = "yamabe";
  double tolerance = 1e-10;
  int maxSteps = 100;
  bool json = false, keepFailed = false;
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

// --correspondence of a circle domain with inserted vertices (the half of the double): its flip log is empty, so it is
// refused before anything is written rather than written as a map that cannot be read back.
void refuseCorrespondence(const intrinsic::Uniformization& u, int component) {
  const std::string gap = intrinsic::correspondenceUnavailable(u);
  if (gap.empty()) return;
  throw ConvergenceError("uniformize: " + (component >= 0 ? "component " + std::to_string(component) + ": " : "") +
                         gap + "; the flip log cannot carry them, so --correspondence cannot be written");
}

void writeCorrespondence(const std::string& path, const nlohmann::json& j) {
  std::ofstream file(path);
  if (!file) throw InputError(path + ": cannot open for writing");
  file << j.dump() << '\n';
  if (!file) throw InputError(path + ": write failed");
}

// The file of several components: each component's T0* in its own geometry (the header's is component 0's, each
// component's in a comment when they differ: docs/formats.md), per-vertex lambda and component.
intrinsic::MeshData mergedOutput(const UniformizeOptions& o, const intrinsic::ComponentUniformization& cu) {
  std::vector<intrinsic::MeshData> parts;
  bool positions = true, mixed = false;
  for (const auto& u : cu.parts) {
    positions = positions && !u.positions.empty();
    mixed = mixed || u.uniform.background != cu.parts[0].uniform.background;
  }
  for (const auto& u : cu.parts) {
    parts.push_back(intrinsic::fromTriangulation(u.uniform));
    if (positions) parts.back().positions = u.positions;
    parts.back().vertexProperties["lambda"] = u.lambda;
  }
  intrinsic::MeshData out = intrinsic::concatenateMeshData(parts);
  out.source = o.output;
  out.comments.push_back("uniformized by conformesh (" + o.method + " flow): " + std::to_string(cu.parts.size()) +
                         " components, each to its own target (vertex property component)");
  for (std::size_t i = 0; i < cu.parts.size(); ++i)
    out.comments.push_back("component " + std::to_string(i) + " target " +
                           intrinsic::toString(cu.parts[i].report.target) +
                           (mixed ? " geometry " + intrinsic::toString(cu.parts[i].uniform.background) : ""));
  return out;
}

// Several components (uniformizeComponents): one merged file, one report per component.
void runUniformizeComponents(const UniformizeOptions& o, const intrinsic::IntrinsicTriangulation& input,
                             const intrinsic::UniformizationOptions& options) {
  const intrinsic::ComponentUniformization cu = intrinsic::uniformizeComponents(
      input, options, [&o](const intrinsic::IntrinsicTriangulation& t, const intrinsic::UniformizationOptions& uo) {
        return runFlow(o, t, uo);
      });
  nlohmann::json j = refine::componentUniformizationJson(cu);
  j["input"] = o.input;
  j["output"] = o.output;
  j["method"] = o.method;
  if (!o.correspondence.empty()) {
    j["correspondence"] = o.correspondence;
    for (std::size_t i = 0; i < cu.parts.size(); ++i) refuseCorrespondence(cu.parts[i], static_cast<int>(i));
  }
  refine::OutputVerification check;
  const int n = static_cast<int>(cu.parts.size());
  for (int i = 0; i < n; ++i)
    for (const std::string& f : refine::verifyUniformization(cu.parts[i]).failures)
      check.failures.push_back(intrinsic::describeComponent(i, n, cu.components[i].topology) + ": " + f);
  const std::string written = verifiedOutputPath(check, o.keepFailed, o.output, j);
  if (!written.empty()) intrinsic::writeMesh(mergedOutput(o, cu), written);
  rejectIfFailed(check, o.output, written, o.json, j);
  if (!o.correspondence.empty()) {
    nlohmann::json maps = nlohmann::json::array();
    for (const auto& u : cu.parts) maps.push_back(correspondenceJson(u.correspondence));
    writeCorrespondence(o.correspondence,
                        {{"format", "conformesh flow correspondence components 1"}, {"components", maps}});
  }
  if (o.json) {
    printJson(j);
    return;
  }
  std::printf("%s -> %s\n", o.input.c_str(), o.output.c_str());
  std::printf("  %-30s %d, each uniformized to its own target, %.2f s\n", "components", n, cu.seconds);
  for (const auto& c : j["components"]) {
    std::printf("  component %-20d %d vertices, %d faces, genus %d, %d boundary loops\n", c["component"].get<int>(),
                c["vertices"].get<int>(), c["faces"].get<int>(), c["genus"].get<int>(), c["boundary_loops"].get<int>());
    std::printf("    %-28s %s (curvature %g), %d Newton steps, %lld flips\n", "target",
                c["target"].get<std::string>().c_str(), c["target_curvature"].get<double>(),
                c["newton_steps"].get<int>(), c["flips"].get<long long>());
    std::printf("    %-28s max |K - K^| %.3g rad, Gauss-Bonnet residual %.3g\n", "residuals",
                c["max_curvature_residual"].get<double>(), c["gauss_bonnet_residual"].get<double>());
    std::printf("    %-28s %.12g\n", "area", c["total_area"].get<double>());
  }
  std::printf("  %-30s %.12g (sum over components)\n", "total area", j["total_area"].get<double>());
}

void runUniformize(const UniformizeOptions& o) {
  progress("reading " + o.input);
  const intrinsic::MeshData data = loadMesh(o.input);
  const intrinsic::IntrinsicTriangulation input = intrinsic::toTriangulation(data);
  intrinsic::UniformizationOptions options;
  options.flow.tolerance = o.tolerance;
  options.flow.maxNewtonSteps = o.maxSteps;
  options.progress = [](const std::string& line) { progress(line); };
  if (input.mesh.components().size() > 1) {
    runUniformizeComponents(o, input, options);
    return;
  }
  const intrinsic::Uniformization u = runFlow(o, input, options);

  intrinsic::MeshData out = intrinsic::fromTriangulation(u.uniform);
  out.source = o.output;
  out.positions = u.positions;
  out.vertexProperties["lambda"] = u.lambda;
  out.comments.push_back("uniformized by conformesh (" + o.method + " flow): target " +
                         intrinsic::toString(u.report.target));
  // Figures a reader can check: the worst interior angle-sum error in the written geometry and Gauss–Bonnet.
  nlohmann::json j = refine::uniformizedJson(u);
  j["input"] = o.input;
  j["output"] = o.output;
  j["method"] = o.method;
  if (!o.correspondence.empty()) {
    j["correspondence"] = o.correspondence;
    refuseCorrespondence(u, -1);
  }
  const refine::OutputVerification check = refine::verifyUniformization(u);
  const std::string written = verifiedOutputPath(check, o.keepFailed, o.output, j);
  if (!written.empty()) intrinsic::writeMesh(out, written);
  rejectIfFailed(check, o.output, written, o.json, j);
  if (!o.correspondence.empty()) writeCorrespondence(o.correspondence, correspondenceJson(u.correspondence));

  if (o.json) {
    printJson(j);
    return;
  }
  const auto& r = u.report;
  std::printf("%s -> %s\n", o.input.c_str(), o.output.c_str());
  std::printf("  %-30s %s (%s background), genus %d, %d boundary loops\n", "target",
              intrinsic::toString(r.target).c_str(), intrinsic::toString(u.uniform.background).c_str(), r.genus,
              r.boundaryLoops);
  std::printf("  %-30s %d Newton steps, %lld Ptolemy flips, %.2f s\n", "flow", r.newtonSteps, (long long)r.flips,
              r.seconds);
  std::printf("  %-30s %.3g rad (tolerance %.3g)\n", "max |K - K^| at exit", r.maxResidual, r.effectiveTolerance);
  std::printf("  %-30s %.3g rad\n", "max |angle sum - 2pi|", j["max_interior_angle_sum_error"].get<double>());
  std::printf("  %-30s %.3g\n", "Gauss-Bonnet residual", j["gauss_bonnet_residual"].get<double>());
  std::printf("  %-30s %.12g\n", "total area", j["total_area"].get<double>());
  if (r.target == intrinsic::UniformizationTarget::FlatCylinder)
    std::printf("  %-30s %.12g (circumference 2 pi; = log(R/r) of the annulus)\n", "cylinder height", r.cylinderHeight);
  if (!u.insertedVertices.empty())
    std::printf("  %-30s %d (vertices %d..%d, %s)\n", "inserted boundary vertices",
                static_cast<int>(u.insertedVertices.size()), u.insertedVertices.front().vertex,
                u.insertedVertices.back().vertex, intrinsic::insertionReason(u).c_str());
}

}  // namespace

void registerUniformizeCommand(CLI::App& app) {
  auto o = std::make_shared<UniformizeOptions>();
  CLI::App* sub =
      app.add_subcommand("uniformize", "Uniformize a triangulation to constant curvature by discrete Ricci flow");
  sub->footer(
      "Example: conformesh uniformize bunny.off -o bunny-sphere.ply --correspondence bunny-map.json\n"
      "Details: docs/cli.md#uniformize");
  sub->add_option("input", o->input, "Input mesh (OBJ, OFF or PLY; lengths from the PLY edge element if present)")
      ->required();
  sub->add_option("-o,--output", o->output, "Output PLY (T0*)")->required();
  addRepairOption(sub);
  sub->add_option("--method", o->method, "Flow: yamabe, circle-packing or inversive-distance (closed genus >= 1)")
      ->check(oneOf({"yamabe", "circle-packing", "inversive-distance"}))
      ->capture_default_str();
  sub->add_option("--tolerance", o->tolerance, "Stop when max |K - K^| is below this (radians, > 0)")
      ->check(untyped(CLI::PositiveNumber))
      ->capture_default_str();
  sub->add_option("--max-steps", o->maxSteps, "Newton step cap per flow solve (> 0)")
      ->check(untyped(CLI::PositiveNumber))
      ->capture_default_str();
  sub->add_option("--correspondence", o->correspondence, "Write the T0* -> T0 flip log (JSON) here");
  sub->add_flag("--json", o->json, "Print the report as JSON");
  addKeepFailedOption(sub, o->keepFailed);
  sub->callback([o] { runUniformize(*o); });
}

}  // namespace conformesh::apps
