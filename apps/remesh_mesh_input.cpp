// remesh_mesh_input.cpp — `conformesh remesh MESHFILE --eps E [--refine-in input|uniformized] -o OUT.ply`: refine
// the input in its own metric (the default), or uniformize it, refine and pull back through its faces
// (refine/pipeline/mesh_remesh.h); print the quality in the input's metric and the curvature-measure check against the
// input's own angle deficits (meshCurvatureMeasure). Parsing and printing only.
#include "remesh_mesh_input.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "cli_common.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/refine/pipeline/component_remesh.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/output_verification.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::apps {

bool isMeshFilePath(const std::string& input) {
  std::string lower = input;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* ext : {".off", ".obj", ".ply"})
    if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, ext) == 0) return true;
  return false;
}

namespace {

// The library's options from the command's arguments (both routes, one component or several).
refine::MeshRemeshOptions remeshOptions(const MeshRemeshCliArgs& a) {
  refine::MeshRemeshOptions o;
  o.epsilon = a.epsilon;
  o.epsilonRelative = a.epsilonRelative;
  o.maxVertices = a.maxVertices;
  o.ratioBound = a.ratio;
  o.uniform = a.uniform;
  o.refineIn = refine::parseRefineMetric(a.refineIn);
  const bool inInput = o.refineIn == refine::RefineMetric::Input;
  // Smoothing acts in the metric the refinement runs in: on the uniformized route it would improve T1*, not the
  // angles in the input's metric, so that route stays the paper's unsmoothed refinement.
  if (!inInput && a.smoothing != 0)
    throw InputError(
        "remesh: --smoothing applies to a mesh file with --refine-in input; refined uniformized, a mesh "
        "is refined unsmoothed (smoothing would act in the uniformized metric, not the input's)");
  o.refinement.smoothingPasses = a.smoothing;
  o.refinement.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.refinement.segmentRule = refine::parseSegmentRule(a.segmentRule);
  o.progress = [](const std::string& s) { progress(s); };
  return o;
}

// Several components (component_remesh.h): each remeshed alone, one merged file, one report per component.
void runRemeshComponents(const MeshRemeshCliArgs& a, const refine::MeshInput& in, const refine::MeshRemeshOptions& o) {
  const refine::ComponentRemesh r = refine::remeshComponents(in.triangulation, in.positions, o);
  std::vector<intrinsic::MeshData> parts;
  nlohmann::json j = refine::componentRemeshJson(r, in.triangulation, in.source, o);
  for (std::size_t i = 0; i < r.parts.size(); ++i) {
    printNotices(r.parts[i].notices);
    parts.push_back(refine::toMeshData(r.parts[i], in.source, r.epsilon));
    if (a.noCheck) continue;
    progress("component " + std::to_string(i) + ": checking the Gaussian curvature measure");
    intrinsic::CurvatureMeasureOptions co;
    co.progress = countingProgress("curvature measure");
    const intrinsic::CurvatureMeasureResult c =
        refine::meshCurvatureMeasure(r.parts[i], r.components[i].triangulation, co);
    j["components"][i]["gaussian_curvature_measure"] = refine::curvatureMeasureJson(c, co);
    addCurvatureMeasureProperties(parts.back(), c);
  }
  const intrinsic::MeshData data = refine::mergeComponentOutputs(r, parts);
  writeVerifiedMeshOutputs(
      refine::verifyComponentRemesh(r), a.keepFailed, data, a.output, a.ascii, a.vtk,
      [&] { return refine::componentsVtkMesh(data); }, a.json, j);
  if (a.json) {
    printJson(j);
    return;
  }
  const bool inInput = o.refineIn == refine::RefineMetric::Input;
  std::printf("%s (mesh: %d vertices, %d faces, %zu components; %s)\n", in.source.c_str(),
              in.triangulation.mesh.nVertices(), in.triangulation.mesh.nFaces(), r.parts.size(),
              inInput ? "refined in the input metric" : "refined uniformized, each component to its own target");
  std::printf("  %-34s %d vertices, %d triangles\n", "output", j["output_mesh"]["vertices"].get<int>(),
              j["output_mesh"]["faces"].get<int>());
  for (const auto& c : j["components"]) {
    std::printf("  component %-24d %d vertices, %d faces, genus %d, %d boundary loops%s\n", c["component"].get<int>(),
                c["vertices"].get<int>(), c["faces"].get<int>(), c["genus"].get<int>(), c["boundary_loops"].get<int>(),
                inInput ? "" : (", " + c["uniformization"]["target"].get<std::string>()).c_str());
    std::printf("    %-32s %d vertices, smallest angle %.3f deg, Gauss-Bonnet residual %.3e\n", "output",
                c["quality"]["vertices"].get<int>(), c["quality"]["min_angle_deg"].get<double>(),
                c["quality"]["gauss_bonnet_residual"].get<double>());
    std::printf("    %-32s %.10g (input %.10g)\n", "area", c["total_area"].get<double>(),
                c["input_mesh"]["area"].get<double>());
  }
  std::printf("  %-34s %.10g (input %.10g)\n", "total area", j["total_area"].get<double>(),
              j["input_mesh"]["area"].get<double>());
  std::printf("  written to %s%s%s\n", a.output.c_str(), a.vtk.empty() ? "" : " and ", a.vtk.c_str());
}

}  // namespace

void runRemeshMesh(const MeshRemeshCliArgs& a) {
  const refine::MeshInput in = refine::meshInputFromData(loadMesh(a.input));
  const refine::MeshRemeshOptions o = remeshOptions(a);
  const bool inInput = o.refineIn == refine::RefineMetric::Input;
  if (in.triangulation.mesh.components().size() > 1) {
    runRemeshComponents(a, in, o);
    return;
  }
  const refine::MeshRemeshResult r = refine::remeshMesh(in.triangulation, in.positions, o);
  intrinsic::MeshData data = refine::toMeshData(r, in.source, r.epsilon);
  printNotices(r.notices);

  nlohmann::json j = refine::meshRemeshJson(r, in.triangulation, in.source, o);
  if (!a.noCheck) {
    progress("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
    intrinsic::CurvatureMeasureOptions co;
    co.progress = countingProgress("curvature measure");
    const intrinsic::CurvatureMeasureResult c = refine::meshCurvatureMeasure(r, in.triangulation, co);
    j["gaussian_curvature_measure"] = refine::curvatureMeasureJson(c, co);
    addCurvatureMeasureProperties(data, c);
  }
  writeVerifiedMeshOutputs(refine::verifyMeshRemesh(r, in.triangulation), a.keepFailed, data, a.output, a.ascii, a.vtk,
                           [&] { return refine::toVtkMesh(data, r); }, a.json, j);
  if (a.json) {
    printJson(j);
    return;
  }
  const auto& q = r.quality;
  std::printf("%s (mesh: %d vertices, %d faces; %s)\n", in.source.c_str(), r.inputVertices, r.inputFaces,
              inInput ? "refined in the input metric"
                      : ("refined uniformized, " + intrinsic::toString(r.uniformization.target)).c_str());
  std::printf("  %-34s %d vertices, %d triangles\n", "output", q.vertices, q.triangles);
  std::printf("  %-34s %.3f deg (mean per triangle %.3f deg)\n", "smallest angle, input metric", q.minAngleDeg,
              q.meanMinAngleDeg);
  std::printf("  %-34s max %.6g, mean %.6g (eps %.6g)\n", "circumradius, input metric", q.maxCircumradius,
              q.meanCircumradius, r.epsilon);
  std::printf("  %-34s %d of %d checked\n", "inverted triangles on the input", r.invertedTriangles,
              r.orientationChecked);
  std::printf("  %-34s max relative difference %.2e over %d edges\n", "length vs located ends (one face)",
              r.maxSameFaceLengthError, r.sameFaceEdges);
  if (r.loopEdges > 0)
    std::printf("  %-34s %d (geodesic loops around cone vertices below 180 deg)\n", "loop edges", r.loopEdges);
  std::printf("  %-34s %.3e\n", "Gauss-Bonnet residual", q.gaussBonnetResidual);
  std::printf("  %-34s %.10g (input %.10g)\n", "total area", intrinsic::totalArea(r.mesh),
              intrinsic::totalArea(in.triangulation));
  if (j.contains("gaussian_curvature_measure")) {
    const auto& c = j["gaussian_curvature_measure"];
    std::printf("  %-34s e_G %.4e, max %.4e, %.1f %% of vertices within +-%.2f relative\n",
                "curvature measure vs input's", c["mean_abs_error"].get<double>(), c["max_abs_error"].get<double>(),
                100 * c["fraction_within"].get<double>(), c["within_band"].get<double>());
  }
  std::printf("  %-34s uniformize %.2f, refine %.2f, pull back %.2f\n", "seconds", r.seconds.uniformize,
              r.seconds.refine, r.seconds.pullBack);
  std::printf("  written to %s%s%s\n", a.output.c_str(), a.vtk.empty() ? "" : " and ", a.vtk.c_str());
}

}  // namespace conformesh::apps
