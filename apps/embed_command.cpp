// embed_command.cpp — `conformesh embed IN -o OUT.ply`: fit vertex positions in R³ to a mesh's edge lengths (Ceres,
// embedding/fit/isometric_embedding.h) and say whether the fit is isometric. Parsing and printing only; a fit that is
// not isometric still writes the best positions (nothing is lost) and then exits with status 1 naming the residual.
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::apps {

namespace {

struct EmbedOptions {
  std::string input, output, init;
  double tolerance = embedding::EmbeddingOptions{}.tolerance;
  double regularizer = embedding::EmbeddingOptions{}.regularizerWeight;
  int landmarks = embedding::EmbeddingOptions{}.landmarks;
  int maxIterations = embedding::EmbeddingOptions{}.maxIterations;
  bool json = false;
};

void runEmbed(const EmbedOptions& o) {
  progress("reading " + o.input);
  const intrinsic::MeshData data = loadMesh(o.input);
  intrinsic::ConversionReport conv;
  const intrinsic::IntrinsicTriangulation tri = intrinsic::toTriangulation(data, &conv);

  embedding::EmbeddingOptions eo;
  eo.tolerance = o.tolerance;
  eo.regularizerWeight = o.regularizer;
  eo.landmarks = o.landmarks;
  eo.maxIterations = o.maxIterations;
  eo.progress = [](const std::string& line) { progress(line); };
  if (!o.init.empty()) {
    // The start's vertices are the input file's vertices, in the input's order (before unreferenced ones are dropped).
    progress("reading initial positions from " + o.init);
    const intrinsic::MeshData init = loadMesh(o.init);
    if (init.positions.empty()) throw InputError(o.init + ": --init needs a file with vertex positions, found none");
    if (init.nVertices != data.nVertices)
      throw InputError(o.init + ": --init has " + std::to_string(init.nVertices) + " vertices, " + o.input + " has " +
                       std::to_string(data.nVertices));
    eo.initialPositions.resize(tri.mesh.nVertices());
    for (int v = 0; v < data.nVertices; ++v)
      if (conv.vertexMap[v] >= 0) eo.initialPositions[conv.vertexMap[v]] = init.positions[v];
  }
  progress("fitting " + std::to_string(tri.mesh.nVertices()) + " vertices to " + std::to_string(tri.mesh.nEdges()) +
           " edge lengths");
  const embedding::EmbeddingResult fit = embedding::fitIsometricEmbedding(tri, eo);

  if (!o.output.empty()) {
    intrinsic::MeshData out = intrinsic::fromTriangulation(tri);
    out.positions = fit.positions;
    for (const auto& [name, values] : data.vertexProperties) {
      std::vector<double> carried(tri.mesh.nVertices());
      for (int v = 0; v < data.nVertices; ++v)
        if (conv.vertexMap[v] >= 0) carried[conv.vertexMap[v]] = values[v];
      out.vertexProperties[name] = carried;
    }
    // fromTriangulation lists edges by edge index: the residuals line up.
    out.edgeProperties["relative_residual"] = embedding::relativeEdgeResiduals(tri, fit.positions);
    out.comments = data.comments;
    out.comments.push_back("conformesh embed: " + fit.verdict);
    progress("writing " + o.output);
    intrinsic::writeMesh(out, o.output);
  }

  if (o.json) {
    nlohmann::json j = refine::embeddingJson(fit, tri);
    j["file"] = o.input;
    j["output"] = o.output;
    printJson(j);
  } else {
    auto line = [](const char* name, const std::string& value) { std::printf("  %-28s %s\n", name, value.c_str()); };
    auto num = [](double x) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.3e", x);
      return std::string(buf);
    };
    std::printf("%s\n", o.input.c_str());
    line("vertices / edges", std::to_string(tri.mesh.nVertices()) + " / " + std::to_string(tri.mesh.nEdges()));
    line("start", fit.start);
    line("LM iterations",
         std::to_string(fit.regularizedIterations) + " regularized + " + std::to_string(fit.iterations) + " final");
    line("max relative residual", num(fit.maxRelativeResidual) + " (edge " + std::to_string(fit.worstEdge) + ")");
    line("RMS relative residual", num(fit.rmsRelativeResidual));
    line("time", num(fit.startSeconds) + " s start, " + num(fit.fitSeconds) + " s fit");
    line("verdict", fit.verdict);
    if (!o.output.empty()) line("written", o.output);
  }
  if (!fit.isometric)
    throw ConvergenceError("embed: " + o.input + " is " + fit.verdict +
                           (o.output.empty() ? "" : "; the best fit was written to " + o.output));
}

}  // namespace

void registerEmbedCommand(CLI::App& app) {
  auto o = std::make_shared<EmbedOptions>();
  CLI::App* sub = app.add_subcommand(
      "embed", "Fit vertex positions in R^3 to a mesh's edge lengths; say whether the fit is isometric");
  sub->footer(
      "Example: conformesh remesh ellipsoid --eps 0.1 -o e.ply && conformesh embed e.ply -o fit.ply\n"
      "Details: docs/cli.md#embed");
  sub->add_option("input", o->input, "Mesh with edge lengths (.ply with an edge element, or positions)")->required();
  addRepairOption(sub);
  sub->add_option("-o,--output", o->output, "Write the fitted mesh here (.ply keeps lengths and residuals)");
  sub->add_option("--init", o->init, "Start from the vertex positions of this file (same vertices as the input)");
  sub->add_option("--tolerance", o->tolerance, "Largest relative edge residual accepted as isometric (> 0)")
      ->capture_default_str()
      ->check(untyped(CLI::PositiveNumber));
  sub->add_option("--regularizer", o->regularizer,
                  "Weight of the dihedral regularizer in the first solve (>= 0; 0: skip)")
      ->capture_default_str()
      ->check(untyped(CLI::NonNegativeNumber));
  sub->add_option("--landmarks", o->landmarks, "Landmarks of the MDS start (4..100000)")
      ->capture_default_str()
      ->check(untyped(CLI::Range(4, 100000)));
  sub->add_option("--max-iterations", o->maxIterations, "LM iterations of the final solve (1..100000)")
      ->capture_default_str()
      ->check(untyped(CLI::Range(1, 100000)));
  sub->add_flag("--json", o->json, "Print the report as JSON");
  sub->callback([o] { runEmbed(*o); });
}

}  // namespace conformesh::apps
