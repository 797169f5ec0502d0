// remesh_command.cpp — `conformesh remesh FAMILY --eps E -o OUT.ply`: the whole pipeline on a smooth metric
// (discretize → uniformize → refine → pull back), the output's quality in the original metric, and the intrinsic
// Gaussian-curvature-measure check (paper eq. 5); PLY with lengths always, VTK for ParaView on request.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "remesh_mesh_input.h"
#include "report_json.h"

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
  int smoothing = refine::RemeshOptions{}.refinement.smoothingPasses;
  std::string smoothingRule = "odt";
  std::string refineIn = "uniformized";
  std::string segmentRule = "ruppert";
};

void run(const RemeshArgs& a) {
  if (isMeshFilePath(a.family))  // a mesh file: pull back through its faces, or refine in its metric (remesh_mesh.h)
    return runRemeshMesh({a.family, a.epsilon, a.ratio, a.uniform, a.output, a.vtk, a.json, a.noCheck, a.ascii,
                          a.refineIn, a.smoothing, a.smoothingRule, a.segmentRule});
  if (a.refineIn != "uniformized")
    throw InputError("remesh: --refine-in " + a.refineIn +
                     " applies to mesh files; a smooth metric is refined uniformized");
  const std::unique_ptr<intrinsic::SmoothMetric> metric = loadMetric("remesh", a.family, a.params, a.field);
  refine::RemeshOptions o;
  o.epsilon = a.epsilon;
  o.ratioBound = a.ratio;
  o.uniform = a.uniform;
  o.t0Resolution = a.t0Resolution;
  o.diskTarget = refine::parseDiskTarget(a.diskTarget);
  o.refinement.smoothingPasses = a.smoothing;
  o.refinement.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.refinement.segmentRule = refine::parseSegmentRule(a.segmentRule);
  o.progress = [](const std::string& s) { progress(s); };
  const refine::RemeshResult r = refine::remeshMetric(*metric, o);
  intrinsic::MeshData data = refine::toMeshData(r, *metric, a.epsilon);

  nlohmann::json j = {{"metric", metric->description()},
                      {"eps", a.epsilon},
                      {"ratio_bound", a.ratio},
                      {"smoothing_passes", a.smoothing},
                      {"segment_rule", a.segmentRule},
                      {"t0", {{"vertices", r.t0Vertices}, {"faces", r.t0Faces}}},
                      {"uniformization", uniformizationJson(r.uniformization)},
                      {"disk_target", refine::toString(r.diskTarget)},
                      {"refinement", refineStatisticsJson(r.refinement)},
                      {"quality_uniformized", qualityJson(r.uniformQuality)},
                      {"quality", qualityJson(r.quality)},
                      {"inverted_triangles", r.invertedTriangles},
                      {"total_area", intrinsic::totalArea(r.mesh)},
                      {"seconds",
                       {{"discretize", r.seconds.discretize},
                        {"uniformize", r.seconds.uniformize},
                        {"refine", r.seconds.refine},
                        {"pull_back", r.seconds.pullBack}}}};
  if (!a.noCheck) {
    progress("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
    intrinsic::CurvatureMeasureOptions co;
    co.progress = countingProgress("curvature measure");
    co.region = a.region == "union" ? intrinsic::MeasureRegion::TriangleUnion : intrinsic::MeasureRegion::GeodesicBall;
    const intrinsic::CurvatureMeasureResult c = intrinsic::gaussianCurvatureMeasure(r.mesh, r.reference, *metric, co);
    j["gaussian_curvature_measure"] = curvatureMeasureJson(c, co);
    addCurvatureMeasureProperties(data, c);
  }
  writeMeshOutputs(
      data, a.output, a.ascii, a.vtk, [&] { return refine::toVtkMesh(data, r); }, j);
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
              q.meanCircumradius, a.epsilon);
  std::printf("  %-34s %d\n", "inverted triangles in the map back", r.invertedTriangles);
  std::printf("  %-34s %.3e\n", "Gauss-Bonnet residual", q.gaussBonnetResidual);
  if (j.contains("gaussian_curvature_measure")) {
    const auto& c = j["gaussian_curvature_measure"];
    std::printf("  %-34s e_G %.4e, max %.4e, %.1f %% of vertices within +-%.2f relative\n",
                "Gaussian curvature measure", c["mean_abs_error"].get<double>(), c["max_abs_error"].get<double>(),
                100 * c["fraction_within"].get<double>(), c["within_band"].get<double>());
  }
  std::printf("  %-34s discretize %.2f, uniformize %.2f, refine %.2f, pull back %.2f\n", "seconds",
              r.seconds.discretize, r.seconds.uniformize, r.seconds.refine, r.seconds.pullBack);
  std::printf("  written to %s%s%s\n", a.output.c_str(), a.vtk.empty() ? "" : " and ", a.vtk.c_str());
}

}  // namespace

void registerRemeshCommand(CLI::App& app) {
  auto a = std::make_shared<RemeshArgs>();
  CLI::App* sub = app.add_subcommand("remesh", "Mesh a surface given by a smooth metric, with curvature convergence");
  sub->footer(
      "Pipeline (docs/cli.md, docs/theory.md): discretize the metric's chart into T0 -> uniformize T0 by discrete\n"
      "Ricci flow to curvature +1 / 0 / -1 (conformal factor lambda) -> Delaunay refinement of the uniformized\n"
      "surface until every circumradius is below eps*exp(-lambda) and every circumradius/shortest edge below B ->\n"
      "pull the new vertices back to the surface; each output edge gets its length in the ORIGINAL metric.\n"
      "Reported: smallest angle and circumradii measured with the output's own lengths; inverted triangles of the\n"
      "map back (0 for a homeomorphism); and, unless --no-check, the Gaussian curvature measure check: for each\n"
      "vertex v, the sum of angle deficits in the geodesic ball B(v, r), r = 0.05*sqrt(area), against the integral\n"
      "of the metric's K over the same region (paper eq. 5); e_G is their mean absolute difference.\n"
      "Families and their parameters: conformesh discretize --list.\n"
      "A mesh file (.off/.obj/.ply) as INPUT: uniformize it, refine, pull back through its faces; output lengths\n"
      "are the developed lengths of the edges' image paths on the input, and the check compares the output's\n"
      "deficits with the input's own over the same balls (docs/cli.md, remesh). With --refine-in input the input\n"
      "itself is refined in its own metric (no Ricci flow), and the angle bound holds in that metric.\n"
      "Example: conformesh remesh kerr-newman --param a=0.99 --eps 0.05 -o kerr.ply --vtk kerr.vtk");
  sub->add_option("family", a->family,
                  "Metric family (see `conformesh discretize --list`), or a mesh file (.off/.obj/.ply)");
  addFieldOption(sub, a->field);
  sub->add_option("--param", a->params, "Family parameter key=value (repeatable)");
  sub->add_option("--eps", a->epsilon, "Circumradius bound in the original metric (required)")->required();
  sub->add_option("--ratio", a->ratio, "Shape bound B = circumradius / shortest edge (default sqrt(2): 20.7 deg)");
  sub->add_flag("--uniform", a->uniform, "Ignore the conformal factor (uniform in the uniformized domain)");
  sub->add_option("--t0-resolution", a->t0Resolution,
                  "Resolution of the initial triangulation T0 (default: automatic from eps, 8..32)");
  sub->add_option("--disk-target", a->diskTarget,
                  "Disk charts: 'circle' maps to the unit disk; 'keep-boundary' flattens keeping the boundary lengths "
                  "(corners keep their angles, lambda = 0 on the boundary); 'auto' (default) keeps the boundary of "
                  "rectangle charts, which have corners")
      ->check(CLI::IsMember({"auto", "circle", "keep-boundary"}));
  sub->add_option(
         "--segment-rule", a->segmentRule,
         "Boundary segments: 'ruppert' (default; split when encroached, conforming Delaunay, termination proved for "
         "B >= sqrt 2) or 'chew' (Chew's second algorithm: constrained Delaunay, a segment is split only for "
         "a circumcentre beyond it, deleting the inserted interior vertices in its diametral disk first; "
         "proved in the plane for B >= sqrt(5)/2 = 1.118, 26.57 deg; docs/refinement.md §6)")
      ->check(CLI::IsMember({"ruppert", "chew"}));
  sub->add_option("-o,--output", a->output, "Output PLY (edge lengths, vertex fields)")->required();
  sub->add_option("--vtk", a->vtk, "Also write legacy VTK for ParaView");
  sub->add_flag("--json", a->json, "Print the report as JSON");
  sub->add_flag("--no-check", a->noCheck, "Skip the curvature-measure check");
  sub->add_option("--region", a->region, "Regions of the check: ball (default) or union (Theorem 3.4's unions)")
      ->check(CLI::IsMember({"ball", "union"}));
  addSmoothingOptions(sub, a->smoothing, a->smoothingRule,
                      "Raises the mean smallest angle (`convergence` uses 1), at ~3.5x the refinement time. 0 = the "
                      "paper's unsmoothed refinement. Metric families, fields and mesh files with --refine-in input (a "
                      "mesh refined uniformized is refined unsmoothed; --smoothing is then an error)");
  sub->add_option("--refine-in", a->refineIn,
                  "Mesh files: the metric the Delaunay refinement runs in. 'uniformized' (default, the paper's): the "
                  "Ricci-flow uniformization, graded by exp(-lambda), pulled back through the input faces; 'input': "
                  "the input's own flat cone metric, size bound eps uniform on the input, so the angle bound holds in "
                  "the input's metric")
      ->check(CLI::IsMember({"uniformized", "input"}));
  sub->add_flag("--ascii", a->ascii, "Write ASCII PLY instead of binary");
  sub->callback([a] { run(*a); });
}

}  // namespace conformesh::apps
