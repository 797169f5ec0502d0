// remesh_command.cpp — `conformesh remesh FAMILY --eps E -o OUT.ply`: the whole pipeline on a smooth metric
// (discretize → uniformize → refine → pull back), the output's quality in the original metric, and the intrinsic
// Gaussian-curvature-measure check (paper eq. 5); PLY with lengths always, VTK for ParaView on request.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "usage_errors.h"
#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "horizon_input.h"
#include "conformesh/refine/pipeline/output_verification.h"
#include "remesh_mesh_input.h"

namespace conformesh::apps {

namespace {

struct RemeshArgs {
  std::string family;
  std::vector<std::string> params;
  std::string field;
  double epsilon = 0;
  double ratio = 1.4142135623730951;
  bool uniform = false;
  int t0Resolution = 0;
  std::string diskTarget = "auto";
  std::string output, vtk;
  bool json = false, noCheck = false, ascii = false;
  std::string region = "ball";
  int checkSample = 0;
  int smoothing = refine::RemeshOptions{}.refinement.smoothingPasses;
  std::string smoothingRule = "odt";
  std::string refineIn;  // "": per input kind (mesh files: input; smooth metrics: uniformized, the only one)
  std::string segmentRule = "ruppert";
  HorizonInput horizon;
  bool keepFailed = false;
  double epsilonRelative = 0;
  std::int64_t maxVertices = refine::MeshRemeshOptions{}.maxVertices;
  bool embed = false;      // --embed: fit positions where the metric has no known embedding
  bool epsGiven = false;  // --eps or --eps-rel on the command line
};

// " +- E (quadrature stopped above its tolerance)" when the reference's error estimate is above its tolerance (a metric
// that is only C¹, e.g. an interpolated gamma), else "": the figure then says how far it can be trusted.
std::string quadratureCaveat(double value, double estimate, double tolerance) {
  if (!(estimate > tolerance * std::max(1.0, std::abs(value)))) return "";
  char buf[96];
  std::snprintf(buf, sizeof buf, " +- %.1e, quadrature stopped above its tolerance", estimate);
  return buf;
}

// Total area and ∫K dA of the mesh beside the metric's quadratures (the JSON's smooth_reference).
void printSmoothReference(const nlohmann::json& s) {
  const double area = s["smooth_area"].get<double>(), curvature = s["smooth_total_curvature"].get<double>();
  std::printf("  %-34s %.10g (smooth %.10g%s, relative %+.2e)\n", "total area", s["mesh_area"].get<double>(), area,
              quadratureCaveat(area, s["smooth_area_error_estimate"].get<double>(), 1e-12).c_str(),
              s["area_relative_difference"].get<double>());
  // Closed: both are 2πχ. With boundary the deficits leave out the boundary strip, an O(eps) difference.
  char closed[64] = ", interior vertices: O(eps) short";
  if (!s["gauss_bonnet"].is_null()) std::snprintf(closed, sizeof closed, ", 2 pi chi %.10g", s["gauss_bonnet"].get<double>());
  std::printf("  %-34s %.10g (smooth %.10g%s%s, difference %+.2e)\n", "integral of K dA",
              s["mesh_total_curvature"].get<double>(), curvature,
              quadratureCaveat(curvature, s["smooth_total_curvature_error_estimate"].get<double>(), 1e-10).c_str(),
              closed, s["total_curvature_difference"].get<double>());
}

// What the "within" share measures and what to expect as eps falls (docs/cli.md#remesh; measured there).
void printWithinBandNote(const nlohmann::json& c, double epsilon) {
  std::printf("  %-34s (balls of radius r = %.1f eps; share with |error| < %.2f of the ball's int|K|dA: ~0 %% at r "
              "= 3 eps, > 85 %% at 9 eps)\n",
              "", c["radius"].get<double>() / epsilon, c["within_band"].get<double>());
}

// --embed: fits R^3 positions to the output's edge lengths (embedding/fit/isometric_embedding.h) where the metric has
// no known embedding. Criterion: max relative edge residual <= EmbeddingOptions::tolerance (1e-8; docs/cli.md#remesh).
// Isometric: the positions go into `data` and `r` (PLY, VTK). Otherwise the outputs keep the canonical-domain points.
// A fit that is not isometric, or that throws, is reported ("embedding") and is not an error of remesh.
void fitOutputEmbedding(refine::RemeshResult& r, intrinsic::MeshData& data, nlohmann::json& report) {
  if (!r.positions.empty()) {
    report["embedding"] = refine::remeshKnownEmbeddingJson();
    return;
  }
  embedding::EmbeddingOptions eo;
  eo.progress = [](const std::string& line) { progress(line); };
  progress("embed: fitting " + std::to_string(r.mesh.mesh.nVertices()) + " vertices to the output's edge lengths");
  try {
    const embedding::EmbeddingResult fit = embedding::fitIsometricEmbedding(r.mesh, eo);
    report["embedding"] = refine::remeshEmbeddingJson(fit, r.mesh);
    if (!fit.isometric) return;
    r.positions = fit.positions;
    data.positions = fit.positions;
    data.comments.push_back("positions: fitted isometric embedding (conformesh remesh --embed: " + fit.verdict + ")");
  } catch (const std::exception& e) {
    progress(std::string("embed: the fit failed: ") + e.what());
    report["embedding"] = refine::remeshEmbeddingErrorJson(e.what());
  }
}

// One line of the text report on --embed.
void printEmbedding(const nlohmann::json& e) {
  std::string line;
  if (e.value("known_embedding", false))
    line = "known embedding (no fit needed)";
  else if (e.contains("error"))
    line = "fit failed: " + e["error"].get<std::string>() + "; drawn in the canonical domain";
  else {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s (max rel. length error %.3e, tolerance %.1e)",
                  e["isometric"].get<bool>() ? "isometric" : "NOT isometric",
                  e["max_relative_residual"].get<double>(), e["tolerance"].get<double>());
    line = buf;
    line += e["isometric"].get<bool>() ? "; fitted positions written"
                                       : "; outputs keep the canonical-domain (sphere) points";
  }
  std::printf("  %-34s %s\n", "embedded", line.c_str());
}

void run(const RemeshArgs& a) {
  if (!a.epsGiven) throw UsageError("--eps E or --eps-rel F is required");
  if (a.embed && isMeshFilePath(a.family))
    throw InputError("remesh: --embed applies to smooth metrics; for a mesh file run `conformesh embed` on the output");
  // A mesh file: refine in its own metric (the default: it keeps the angle bound there), or uniformize, refine and
  // pull back through its faces (remesh_mesh_input.h).
  if (isMeshFilePath(a.family))
    return runRemeshMesh({a.family, a.epsilon, a.ratio, a.uniform, a.output, a.vtk, a.json, a.noCheck, a.ascii,
                          a.refineIn.empty() ? "input" : a.refineIn, a.smoothing, a.smoothingRule, a.segmentRule,
                          a.keepFailed, a.epsilonRelative, a.maxVertices});
  if (!a.refineIn.empty() && a.refineIn != "uniformized")
    throw InputError("remesh: --refine-in " + a.refineIn +
                     " applies to mesh files; a smooth metric is refined uniformized");
  const std::unique_ptr<intrinsic::SmoothMetric> metric = loadMetricOrHorizon("remesh", a.family, a.params, a.field, a.horizon);
  refine::RemeshOptions o;
  o.epsilon = a.epsilon;
  o.epsilonRelative = a.epsilonRelative;
  o.maxVertices = a.maxVertices;
  o.ratioBound = a.ratio;
  o.uniform = a.uniform;
  o.t0Resolution = a.t0Resolution;
  o.diskTarget = refine::parseDiskTarget(a.diskTarget);
  o.refinement.smoothingPasses = a.smoothing;
  o.refinement.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.refinement.segmentRule = refine::parseSegmentRule(a.segmentRule);
  o.progress = [](const std::string& s) { progress(s); };
  refine::RemeshResult r = refine::remeshMetric(*metric, o);
  intrinsic::MeshData data = refine::toMeshData(r, *metric, r.epsilon);
  printNotices(r.notices);

  nlohmann::json j = refine::metricRemeshJson(r, *metric, o);
  if (a.horizon.given()) {
    j["horizon"] = horizonReportJson(*metric, intrinsic::totalArea(r.mesh));
    j["horizon"]["shape"] = horizonShapeReportJson(a.horizon);
    progress("approximate Killing vector on the output mesh (axis, orbits)");
    j["horizon"]["killing"] = refine::killingJson(r.mesh, r.reference, metric->domain());
  }
  if (!a.noCheck) {
    progress("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
    intrinsic::CurvatureMeasureOptions co;
    co.progress = countingProgress("curvature measure");
    co.region = a.region == "union" ? intrinsic::MeasureRegion::TriangleUnion : intrinsic::MeasureRegion::GeodesicBall;
    co.sampleCentres = a.checkSample;
    const intrinsic::CurvatureMeasureResult c = intrinsic::gaussianCurvatureMeasure(r.mesh, r.reference, *metric, co);
    j["gaussian_curvature_measure"] = refine::curvatureMeasureJson(c, co);
    addCurvatureMeasureProperties(data, c);
  }
  if (a.embed) fitOutputEmbedding(r, data, j);
  writeVerifiedMeshOutputs(refine::verifyMetricRemesh(r), a.keepFailed, data, a.output, a.ascii, a.vtk,
                           [&] { return refine::toVtkMesh(data, r); }, a.json, j);
  if (a.json) {
    printJson(j);
    return;
  }
  const auto& q = r.quality;
  std::printf("%s\n", metric->description().c_str());
  std::printf("  %-34s %d vertices, %d triangles\n", "output", q.vertices, q.triangles);
  std::printf("  %-34s %.3f deg (mean per triangle %.3f deg)\n", "smallest angle, original metric", q.minAngleDeg,
              q.meanMinAngleDeg);
  std::printf("  %-34s max %.6g, mean %.6g (eps %.6g)\n", "circumradius, original metric", q.maxCircumradius,
              q.meanCircumradius, r.epsilon);
  std::printf("  %-34s %d\n", "inverted triangles in the map back", r.invertedTriangles);
  std::printf("  %-34s %.3e\n", "Gauss-Bonnet residual", q.gaussBonnetResidual);
  printSmoothReference(j["smooth_reference"]);
  if (j.contains("gaussian_curvature_measure")) {
    const auto& c = j["gaussian_curvature_measure"];
    std::printf("  %-34s e_G %.4e, max %.4e, %.1f %% of vertices within +-%.2f relative\n",
                "Gaussian curvature measure", c["mean_abs_error"].get<double>(), c["max_abs_error"].get<double>(),
                100 * c["fraction_within"].get<double>(), c["within_band"].get<double>());
    if (c.value("sampled_centres", 0) > 0)
      std::printf("  %-34s %d centres: e_G in [%.4e, %.4e] (95 %%)\n", "  sampled", c["sampled_centres"].get<int>(),
                  c["mean_abs_error"].get<double>() - c["mean_abs_error_half_width_95"].get<double>(),
                  c["mean_abs_error"].get<double>() + c["mean_abs_error_half_width_95"].get<double>());
    printWithinBandNote(c, r.epsilon);
  }
  if (j.contains("horizon")) printHorizonReport(j["horizon"]);
  if (j.contains("embedding")) printEmbedding(j["embedding"]);
  std::printf("  %-34s discretize %.2f, uniformize %.2f, refine %.2f, pull back %.2f\n", "seconds",
              r.seconds.discretize, r.seconds.uniformize, r.seconds.refine, r.seconds.pullBack);
  std::printf("  written to %s%s%s\n", a.output.c_str(), a.vtk.empty() ? "" : " and ", a.vtk.c_str());
}

}  // namespace

void registerRemeshCommand(CLI::App& app) {
  auto a = std::make_shared<RemeshArgs>();
  CLI::App* sub = app.add_subcommand(
      "remesh", "Mesh a smooth metric or a mesh file: uniformize, refine, pull back, check curvature");
  sub->footer(
      "Example: conformesh remesh kerr-newman --param a=0.99 --eps 0.05 -o kerr.ply --vtk kerr.vtk\n"
      "Details: docs/cli.md#remesh (mesh files: docs/cli.md#remesh-meshfile)");
  sub->add_option("family", a->family,
                  "Metric family (`conformesh discretize --list`) or a mesh file (.off/.obj/.ply)");
  addFieldOption(sub, a->field);
  addHorizonOptions(sub, a->horizon);
  sub->add_option("--param", a->params, "Family parameter key=value (repeatable)");
  auto* eps = sub->add_option("--eps", a->epsilon, "Circumradius bound in the original metric");
  auto* epsRel = sub->add_option("--eps-rel", a->epsilonRelative,
                                 "Circumradius bound as a fraction of sqrt(area) (instead of --eps)");
  epsRel->excludes(eps);
  sub->add_option("--max-vertices", a->maxVertices, "Refuse an eps whose expected vertex count exceeds this")
      ->capture_default_str();
  sub->add_option("--ratio", a->ratio, "Shape bound B = circumradius / shortest edge (sqrt 2: 20.7 deg)")
      ->capture_default_str();
  sub->add_flag("--uniform", a->uniform, "Ignore the conformal factor (uniform in the uniformized domain)");
  sub->add_option("--t0-resolution", a->t0Resolution, "Resolution of T0 (0: from eps, 8..32)")->capture_default_str();
  sub->add_option("--disk-target", a->diskTarget, "Disk charts: auto, circle (unit disk) or keep-boundary")
      ->check(oneOf({"auto", "circle", "keep-boundary"}))
      ->capture_default_str();
  sub->add_option("--segment-rule", a->segmentRule, "Boundary segments: ruppert (conforming) or chew (constrained)")
      ->check(oneOf({"ruppert", "chew"}))
      ->capture_default_str();
  sub->add_option("-o,--output", a->output, "Output PLY (edge lengths, vertex fields)")->required();
  addRepairOption(sub);
  sub->add_option("--vtk", a->vtk, "Also write legacy VTK for ParaView");
  sub->add_flag("--json", a->json, "Print the report as JSON");
  sub->add_flag("--no-check", a->noCheck, "Skip the curvature-measure check");
  sub->add_option("--region", a->region, "Regions of the check: ball or union (Theorem 3.4's unions)")
      ->check(oneOf({"ball", "union"}))
      ->capture_default_str();
  sub->add_option("--check-sample", a->checkSample,
                  "Smooth metrics: check N random centres (seed 1), e_G with its 95 % interval; 0 = every vertex")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  addSmoothingOptions(sub, a->smoothing, a->smoothingRule, "; mesh files: input route only");
  sub->add_option("--refine-in", a->refineIn,
                  "Refine in: input (mesh files' default, keeps the angles) or uniformized (smooth metrics' only)")
      ->check(oneOf({"uniformized", "input"}));
  sub->add_flag("--embed", a->embed,
                "Smooth metrics without a known embedding: fit R^3 positions, written when isometric (off)");
  sub->add_flag("--ascii", a->ascii, "Write ASCII PLY instead of binary");
  addKeepFailedOption(sub, a->keepFailed);
  sub->callback([a, eps, epsRel] {
    a->epsGiven = eps->count() + epsRel->count() > 0;
    run(*a);
  });
}

}  // namespace conformesh::apps
