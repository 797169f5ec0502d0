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
#include "conformesh/refine/pipeline/remesh_json.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/output_verification.h"

namespace conformesh::apps {

bool isMeshFilePath(const std::string& input) {
  std::string lower = input;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* ext : {".off", ".obj", ".ply"})
    if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, ext) == 0) return true;
  return false;
}

void runRemeshMesh(const MeshRemeshCliArgs& a) {
  const refine::MeshInput in = refine::meshInputFromData(loadMesh(a.input));
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
