// refine_command.cpp — `conformesh refine IN --eps E [--ratio B] [--uniform] -o OUT [--json]`: Delaunay refinement of
// a constant-curvature intrinsic triangulation (a uniformized T0*), graded by its conformal factor, with the quality
// report of paper §6.1 / Fig. 10. Parsing and printing only; the algorithm is conformesh/refine/delaunay_refinement.h.
#include <chrono>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/refine/pipeline/refinement_output.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/trace/input_location.h"
#include "conformesh/refine/pipeline/output_verification.h"

namespace conformesh::apps {

namespace {

struct RefineArgs {
  std::string input, output;
  double epsilon = 0;
  double ratio = 1.4142135623730951;
  bool uniform = false, json = false, ascii = false, offCenters = false;
  std::string boundary = "auto";
  std::string segmentRule = "ruppert";
  std::int64_t maxInsertions = 50'000'000;
  int smoothing = refine::RefineOptions{}.smoothingPasses;
  std::string smoothingRule = "odt";
  bool keepFailed = false;
};

void run(const RefineArgs& args) {
  intrinsic::MeshData data = loadMesh(args.input);
  intrinsic::ConversionReport conv;
  const intrinsic::IntrinsicTriangulation tri = intrinsic::toTriangulation(data, &conv);

  refine::RefineOptions opt;
  opt.epsilon = args.epsilon;
  opt.ratioBound = args.ratio;
  opt.maxInsertions = args.maxInsertions;
  opt.offCenters = args.offCenters;
  opt.segmentRule = refine::parseSegmentRule(args.segmentRule);
  opt.smoothingPasses = args.smoothing;
  opt.smoothingRule = refine::parseSmoothingRule(args.smoothingRule);
  opt.boundarySplit = args.boundary == "circle"     ? refine::BoundarySplit::Circle
                      : args.boundary == "geodesic" ? refine::BoundarySplit::Geodesic
                                                    : refine::BoundarySplit::Auto;
  bool graded = false;
  const auto lam = data.vertexProperties.find("lambda");
  if (!args.uniform && lam != data.vertexProperties.end()) {
    if (static_cast<int>(lam->second.size()) != tri.mesh.nVertices())
      throw InputError(args.input + ": vertex property 'lambda' has " + std::to_string(lam->second.size()) +
                       " values but the mesh has " + std::to_string(tri.mesh.nVertices()) + " vertices in faces");
    opt.lambda = lam->second;
    graded = true;
  }
  opt.progress = [](const refine::RefineProgress& p) {
    progress("refine: " + std::to_string(p.insertions) + " insertions, " + std::to_string(p.vertices) + " vertices, " +
             std::to_string(p.queuedTriangles) + " triangles queued");
  };
  progress("refining " + args.input + " (" + intrinsic::toString(tri.background) + ", " +
           std::to_string(tri.mesh.nVertices()) + " vertices), eps " + std::to_string(args.epsilon) + ", B " +
           std::to_string(args.ratio) + (graded ? ", graded by lambda" : ", uniform"));
  const auto t0 = std::chrono::steady_clock::now();
  const refine::RefineResult r = refine::refineDelaunay(tri, opt);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const refine::QualityReport q = refine::measureQuality(r.triangulation);

  // Output: same background, lengths, each vertex's place on the input, positions where the input has them (a file
  // whose unreferenced vertices were dropped has positions indexed by the file, not the triangulation: none then).
  const bool positionsFit = conv.unreferencedVerticesRemoved == 0;
  intrinsic::MeshData out =
      refine::refinementMeshData(r, tri, positionsFit ? data.positions : std::vector<Eigen::Vector3d>{}, graded);
  out.source = args.output;
  intrinsic::WriteOptions wo;
  if (args.ascii) wo.plyEncoding = intrinsic::PlyEncoding::Ascii;
  nlohmann::json j = refine::refineJson(r, tri, opt, q, seconds);
  j["input"] = args.input;
  j["output"] = args.output;
  const refine::OutputVerification check = refine::verifyRefinement(tri, r);
  const std::string written = verifiedOutputPath(check, args.keepFailed, args.output, j);
  if (!written.empty()) {
    progress("writing " + written);
    intrinsic::writeMesh(out, written, wo);
  }
  rejectIfFailed(check, args.output, written, args.json, j);

  const refine::RefineStatistics& s = r.statistics;
  if (args.json) {
    printJson(j);
    return;
  }
  std::cout << args.input << " -> " << args.output << " (" << intrinsic::toString(tri.background) << ", " << seconds
            << " s)\n"
            << "  vertices " << q.vertices << " (input " << s.inputVertices << "), triangles " << q.triangles << '\n'
            << "  inserted: " << s.circumcenterInsertions << " circumcentres, " << s.offCenterInsertions
            << " off-centres, " << s.centroidInsertions << " centroids, " << s.boundarySplits << " boundary splits ("
            << s.circleLoops << " of " << s.boundaryLoops << " boundary loops on their circle); " << s.flips
            << " flips\n";
  if (opt.segmentRule == refine::SegmentRule::Chew)
    std::cout << "  Chew's rule: " << s.deletedVertices << " free vertices deleted from diametral disks ("
              << s.refusedDeletions << " refused)\n";
  if (args.smoothing > 0)
    std::cout << "  smoothing: " << args.smoothing << " passes, " << s.smoothingMoves << " vertex moves ("
              << s.smoothingRefused << " refused), " << s.insertionsAfterSmoothing << " insertions after smoothing\n";
  std::cout << "  smallest angle " << q.minAngleDeg << "°, mean per-triangle smallest angle " << q.meanMinAngleDeg
            << "°, " << 100 * q.fractionBelow30 << "% of triangles under 30°\n"
            << "  circumradius: max " << q.maxCircumradius << ", mean " << q.meanCircumradius
            << " (background metric); max circumradius/shortest edge " << q.maxRadiusEdgeRatio << '\n'
            << "  Delaunay: " << q.nonDelaunayEdges << " non-Delaunay edges; Gauss-Bonnet residual "
            << q.gaussBonnetResidual << '\n'
            << "  angle histogram (" << q.histogramBinDeg << "° bins):";
  for (int c : q.angleHistogram) std::cout << ' ' << c;
  std::cout << '\n';
}

}  // namespace

void registerRefineCommand(CLI::App& app) {
  auto args = std::make_shared<RefineArgs>();
  CLI::App* sub = app.add_subcommand(
      "refine", "Refine a constant-curvature triangulation (Delaunay, graded by lambda; paper §4.2)");
  sub->footer("Example: conformesh refine torus.ply --eps 0.02 -o torus_refined.ply\nDetails: docs/cli.md#refine");
  sub->add_option("input", args->input, "Input mesh (.ply with edge lengths, or .obj/.off/.ply with positions)")
      ->required();
  addRepairOption(sub);
  sub->add_option("--eps", args->epsilon, "Size bound: largest circumradius (times exp(-lambda)), > 0")->required();
  sub->add_option("--ratio", args->ratio, "Shape bound B = circumradius / shortest edge, >= 1 (sqrt 2: 20.7 deg)")
      ->capture_default_str();
  sub->add_flag("--uniform", args->uniform, "Ignore the input's 'lambda' property: uniform refinement (lambda = 0)");
  sub->add_option("--boundary", args->boundary, "Boundary edges split: auto, circle (on the circle) or geodesic")
      ->check(oneOf({"auto", "circle", "geodesic"}))
      ->capture_default_str();
  sub->add_option("--segment-rule", args->segmentRule, "Boundary segments: ruppert (conforming) or chew (constrained)")
      ->check(oneOf({"ruppert", "chew"}))
      ->capture_default_str();
  sub->add_flag("--off-centers", args->offCenters, "Split bad-shaped triangles at Üngör's off-centre when nearer");
  addSmoothingOptions(sub, args->smoothing, args->smoothingRule, "");
  sub->add_option("--max-insertions", args->maxInsertions, "Stop with an error after this many insertions")
      ->capture_default_str();
  sub->add_option("-o,--output", args->output, "Output .ply (edge lengths, background, input locations)")->required();
  addKeepFailedOption(sub, args->keepFailed);
  sub->add_flag("--json", args->json, "Print the statistics and quality report as JSON on stdout");
  sub->add_flag("--ascii", args->ascii, "Write ASCII PLY instead of binary little-endian PLY");
  sub->callback([args] { run(*args); });
}

}  // namespace conformesh::apps
