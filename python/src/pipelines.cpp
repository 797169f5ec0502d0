// pipelines.cpp — the long calls: each releases the GIL, wires the library's progress callbacks into a CallGuard
// (user progress + Ctrl-C between steps) and returns its results as NumPy arrays and the CLI's --json dicts.
#include "pipelines.h"

#include <cmath>

#include <pybind11/stl.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/circle_packing.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/pipeline/convergence_study.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "metrics.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "triangulation.h"

namespace conformesh::python {

namespace {

// Interrupt checks inside the refinement loop: every this many insertions (each check costs one GIL round trip).
constexpr std::int64_t kRefineCheckEvery = 2000;

std::string geometryName(intrinsic::Background b) {
  return intrinsic::toString(b);  // "spherical", "euclidean", "hyperbolic"
}

// ---- uniformize ---------------------------------------------------------------------------------------------------

struct UniformizeResult {
  TriangulationPtr triangulation;
  py::object conformalFactor, geometry, positions, report;
};

// The module takes one connected surface per call: several components are refused up front with what to do (the
// CLI remeshes and uniformizes each component to its own target, docs/cli.md).
void rejectSeveralComponents(const std::string& what, const intrinsic::IntrinsicTriangulation& tri) {
  const std::size_t n = tri.mesh.components().size();
  if (n > 1)
    inputError(what + ": the triangulation has " + std::to_string(n) +
               " connected components; the Python module takes one at a time (the command line's `conformesh " + what +
               "` handles several, each to its own target: docs/cli.md)");
}

UniformizeResult uniformize(const TriangulationPtr& in, double tolerance, int maxSteps, const std::string& method,
                            bool keepFailed, const py::object& progress) {
  if (!(tolerance > 0)) inputError("uniformize: tolerance must be > 0");
  if (maxSteps < 1) inputError("uniformize: max_steps must be >= 1");
  if (method != "yamabe" && method != "circle-packing" && method != "inversive-distance")
    inputError("uniformize: method '" + method + "' (expected 'yamabe', 'circle-packing' or 'inversive-distance')");
  rejectSeveralComponents("uniformize", in->tri);
  CallGuard guard(progress);
  intrinsic::Uniformization u;
  {
    py::gil_scoped_release release;
    intrinsic::UniformizationOptions options;
    options.flow.tolerance = tolerance;
    options.flow.maxNewtonSteps = maxSteps;
    options.progress = guard.lineCallback();
    if (method == "yamabe") {
      u = intrinsic::uniformize(in->tri, options);
    } else {
      intrinsic::CirclePackingOptions packing;
      packing.scheme = method == "circle-packing" ? intrinsic::CirclePackingScheme::Tangential
                                                  : intrinsic::CirclePackingScheme::InversiveDistance;
      packing.tolerance = tolerance;
      packing.maxNewtonSteps = maxSteps;
      packing.progress = options.progress;
      u = intrinsic::uniformizeByCirclePacking(in->tri, packing).result;
    }
  }
  // The report of `conformesh uniformize --json`, without the output file name.
  nlohmann::json j = refine::uniformizedJson(u);
  j["input"] = in->source;
  j["method"] = method;
  verifyOrRaise(refine::verifyUniformization(u), keepFailed, j);
  UniformizeResult out;
  out.geometry = py::str(geometryName(u.uniform.background));
  auto t = fromIntrinsic(std::move(u.uniform), in->source + " uniformized");
  t->positions = u.positions;
  t->fields["lambda"] = u.lambda;
  out.triangulation = t;
  out.conformalFactor = toArray(std::move(u.lambda));
  out.positions = u.positions.empty() ? py::none() : py::object(toArray(std::move(u.positions)));
  out.report = toPython(j);
  return out;
}

// ---- remesh -------------------------------------------------------------------------------------------------------

struct RemeshResult {
  TriangulationPtr triangulation;
  py::object chartCoordinates = py::none(), inputFaces = py::none(), inputBarycentric = py::none();
  py::object positions = py::none(), fields, report;
  // What the CLI writes: the PLY's content and, where it can be built, the VTK.
  std::shared_ptr<intrinsic::MeshData> data;
  std::function<intrinsic::VtkMesh()> vtk;
};

struct RemeshArgs {
  double eps = 0;
  bool check = true;
  double ratio = 1.4142135623730951;
  bool uniform = false;
  int t0Resolution = 0;
  std::string diskTarget = "auto";
  py::object smoothing = py::none();
  std::string smoothingRule = "odt", segmentRule = "ruppert", region = "ball";
  std::string refineIn;  // "" (refine_in=None): 'input' for a triangulation, 'uniformized' for a metric
  bool keepFailed = false;
};


void wireRefinementChecks(refine::RefineOptions& ref, CallGuard& guard) {
  ref.progressEvery = kRefineCheckEvery;
  ref.progress = [&guard](const refine::RefineProgress& p) {
    guard.step("refining: " + std::to_string(p.vertices) + " vertices, " + std::to_string(p.insertions) +
               " insertions");
  };
}

py::dict fieldsDict(const intrinsic::MeshData& d) {
  py::dict f;
  for (const auto& [name, values] : d.vertexProperties) f[py::str(name)] = toArray(std::vector<double>(values));
  return f;
}

RemeshResult remeshMetric(const Metric& metric, const RemeshArgs& a, CallGuard& guard) {
  if (!a.refineIn.empty() && a.refineIn != "uniformized")
    inputError("remesh: refine_in='" + a.refineIn + "' applies to triangulations; a smooth metric is refined "
               "uniformized");
  refine::RemeshOptions o;
  o.epsilon = a.eps;
  o.ratioBound = a.ratio;
  o.uniform = a.uniform;
  o.t0Resolution = a.t0Resolution;
  o.diskTarget = refine::parseDiskTarget(a.diskTarget);
  const int smoothing = a.smoothing.is_none() ? refine::RemeshOptions{}.refinement.smoothingPasses
                                              : a.smoothing.cast<int>();
  o.refinement.smoothingPasses = smoothing;
  o.refinement.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.refinement.segmentRule = refine::parseSegmentRule(a.segmentRule);
  if (a.region != "ball" && a.region != "union") inputError("remesh: region '" + a.region + "' (expected ball or union)");
  o.progress = guard.lineCallback();
  wireRefinementChecks(o.refinement, guard);
  auto shared = std::make_shared<refine::RemeshResult>();
  auto data = std::make_shared<intrinsic::MeshData>();
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    *shared = refine::remeshMetric(*metric.metric, o);
    const refine::RemeshResult& r = *shared;
    *data = refine::toMeshData(r, *metric.metric, r.epsilon);
    j = refine::metricRemeshJson(r, *metric.metric, o);  // the keys of `conformesh remesh FAMILY --json`
    if (a.check) {
      guard.step("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
      intrinsic::CurvatureMeasureOptions co;
      co.progress = guard.countCallback("curvature measure");
      co.region = a.region == "union" ? intrinsic::MeasureRegion::TriangleUnion : intrinsic::MeasureRegion::GeodesicBall;
      const intrinsic::CurvatureMeasureResult c =
          intrinsic::gaussianCurvatureMeasure(r.mesh, r.reference, *metric.metric, co);
      j["gaussian_curvature_measure"] = refine::curvatureMeasureJson(c, co);
      std::vector<double> error(c.discrete.size());
      for (std::size_t v = 0; v < error.size(); ++v) error[v] = c.discrete[v] - c.smooth[v];
      data->vertexProperties["error"] = std::move(error);
      data->vertexProperties["relative_error"] = c.relativeError;
    }
  }
  verifyOrRaise(refine::verifyMetricRemesh(*shared), a.keepFailed, j);
  RemeshResult out;
  const refine::RemeshResult& r = *shared;
  out.data = data;
  out.vtk = [shared, data] { return refine::toVtkMesh(*data, *shared); };
  auto t = fromIntrinsic(r.mesh, metric.metric->description() + " remeshed");
  t->positions = r.positions;
  t->fields = data->vertexProperties;
  out.triangulation = t;
  out.chartCoordinates = toArray(std::vector<Eigen::Vector2d>(r.chart));
  if (!r.positions.empty()) out.positions = toArray(std::vector<Eigen::Vector3d>(r.positions));
  out.fields = fieldsDict(*data);
  out.report = toPython(j);
  return out;
}

RemeshResult remeshTriangulation(const Triangulation& in, const RemeshArgs& a, CallGuard& guard) {
  if (in.tri.background != intrinsic::Background::Euclidean)
    inputError("remesh: " + in.source + ": the input must have a Euclidean background, not " +
               intrinsic::toString(in.tri.background));
  refine::MeshRemeshOptions o;
  o.epsilon = a.eps;
  o.ratioBound = a.ratio;
  o.uniform = a.uniform;
  // The default keeps the angle bound in the input's metric, as the CLI's (docs/cli.md#remesh-meshfile).
  o.refineIn = refine::parseRefineMetric(a.refineIn.empty() ? "input" : a.refineIn);
  const bool inInput = o.refineIn == refine::RefineMetric::Input;
  const int smoothing = a.smoothing.is_none() ? 0 : a.smoothing.cast<int>();
  if (!inInput && smoothing != 0)
    inputError("remesh: smoothing applies to a triangulation with refine_in='input'; refined uniformized, a mesh "
               "is refined unsmoothed (smoothing would act in the uniformized metric, not the input's)");
  if (a.region != "ball") inputError("remesh: region applies to metrics; a mesh's check uses graph balls");
  if (a.t0Resolution != 0 || a.diskTarget != "auto") inputError("remesh: t0_resolution and disk_target apply to metrics");
  o.refinement.smoothingPasses = smoothing;
  o.refinement.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.refinement.segmentRule = refine::parseSegmentRule(a.segmentRule);
  o.progress = guard.lineCallback();
  wireRefinementChecks(o.refinement, guard);
  rejectSeveralComponents("remesh", in.tri);
  auto shared = std::make_shared<refine::MeshRemeshResult>();
  auto data = std::make_shared<intrinsic::MeshData>();
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    *shared = refine::remeshMesh(in.tri, in.positions, o);
    const refine::MeshRemeshResult& r = *shared;
    *data = refine::toMeshData(r, in.source, r.epsilon);
    j = refine::meshRemeshJson(r, in.tri, in.source, o);  // the keys of `conformesh remesh MESHFILE --json`
    if (a.check) {
      guard.step("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
      intrinsic::CurvatureMeasureOptions co;
      co.progress = guard.countCallback("curvature measure");
      const intrinsic::CurvatureMeasureResult c = refine::meshCurvatureMeasure(r, in.tri, co);
      j["gaussian_curvature_measure"] = refine::curvatureMeasureJson(c, co);
      std::vector<double> error(c.discrete.size());
      for (std::size_t v = 0; v < error.size(); ++v) error[v] = c.discrete[v] - c.smooth[v];
      data->vertexProperties["error"] = std::move(error);
      data->vertexProperties["relative_error"] = c.relativeError;
    }
  }
  verifyOrRaise(refine::verifyMeshRemesh(*shared, in.tri), a.keepFailed, j);
  RemeshResult out;
  const refine::MeshRemeshResult& r = *shared;
  out.data = data;
  out.vtk = [shared, data] { return refine::toVtkMesh(*data, *shared); };
  auto t = fromIntrinsic(r.mesh, in.source + " remeshed");
  t->positions = r.positions;
  t->fields = data->vertexProperties;
  out.triangulation = t;
  std::vector<int> face(r.location.size());
  std::vector<double> bary(3 * r.location.size());
  for (std::size_t v = 0; v < r.location.size(); ++v) {
    face[v] = r.location[v].face;
    for (int k = 0; k < 3; ++k) bary[3 * v + k] = r.location[v].bary[k];
  }
  out.inputFaces = toArray(std::move(face));
  out.inputBarycentric = toArray(std::move(bary), 3);
  if (!r.positions.empty()) out.positions = toArray(std::vector<Eigen::Vector3d>(r.positions));
  out.fields = fieldsDict(*data);
  out.report = toPython(j);
  return out;
}

RemeshResult remesh(const py::object& source, double eps, bool check, double ratio, bool uniform, int t0Resolution,
                    const std::string& diskTarget, const py::object& smoothing, const std::string& smoothingRule,
                    const std::string& segmentRule, const py::object& refineIn, const std::string& region,
                    bool keepFailed, const py::object& progress) {
  if (!(eps > 0) || !std::isfinite(eps)) inputError("remesh: eps = " + formatNumber(eps) + " (expected a finite eps > 0)");
  if (!smoothing.is_none() && !py::isinstance<py::int_>(smoothing))
    inputError("remesh: smoothing must be an int or None");
  if (!refineIn.is_none() && !py::isinstance<py::str>(refineIn))
    inputError("remesh: refine_in must be 'input', 'uniformized' or None");
  RemeshArgs a{eps,       check,         ratio,       uniform, t0Resolution, diskTarget,
               smoothing, smoothingRule, segmentRule, region,  "",           keepFailed};
  if (!refineIn.is_none()) a.refineIn = refineIn.cast<std::string>();
  CallGuard guard(progress);
  if (py::isinstance<Metric>(source)) return remeshMetric(source.cast<const Metric&>(), a, guard);
  if (py::isinstance<Triangulation>(source)) return remeshTriangulation(source.cast<const Triangulation&>(), a, guard);
  inputError("remesh: expected a conformesh.metrics.Metric or a conformesh.Triangulation, got " +
             py::str(py::type::of(source).attr("__name__")).cast<std::string>());
}

void writeRemesh(const RemeshResult& r, const std::string& path, const py::object& vtk, bool ascii) {
  py::gil_scoped_release release;
  intrinsic::WriteOptions w;
  if (ascii) w.plyEncoding = intrinsic::PlyEncoding::Ascii;
  intrinsic::writeMesh(*r.data, path, w);
  if (!vtk.is_none()) {
    py::gil_scoped_acquire gil;
    const std::string v = vtk.cast<std::string>();
    py::gil_scoped_release again;
    intrinsic::writeVtk(r.vtk(), v);
  }
}

}  // namespace

void verifyOrRaise(const refine::OutputVerification& check, bool keepFailed, nlohmann::json& report) {
  report["verification"] = refine::verificationJson(check);
  if (!check.passed() && !keepFailed) throw VerificationFailed(check.message() + " (keep_failed=True returns it)");
}

void bindPipelines(py::module_& m) {
  py::class_<UniformizeResult>(m, "UniformizeResult", "What conformesh.uniformize returns.")
      .def_readonly("triangulation", &UniformizeResult::triangulation,
                    "T0*: the uniformized triangulation (constant curvature +1, 0 or -1; field 'lambda').")
      .def_readonly("conformal_factor", &UniformizeResult::conformalFactor,
                    "lambda per vertex, float64 (num_vertices,): the input metric is about e^(2 lambda) times T0*'s.")
      .def_readonly("geometry", &UniformizeResult::geometry, "'spherical', 'euclidean' or 'hyperbolic'.")
      .def_readonly("positions", &UniformizeResult::positions,
                    "Points of T0* on the unit sphere (genus 0) or the plane (circle domains), else None.")
      .def_readonly("report", &UniformizeResult::report, "The report of `conformesh uniformize --json` as a dict.")
      .def("__repr__", [](const UniformizeResult& r) {
        return "<conformesh.UniformizeResult " + py::str(r.geometry).cast<std::string>() + ">";
      });
  m.def("uniformize", &uniformize, py::arg("tri"), py::kw_only(), py::arg("tolerance") = 1e-10,
        py::arg("max_steps") = 100, py::arg("method") = "yamabe", py::arg("keep_failed") = false, py::arg("progress") = py::none(), R"doc(
Uniformizes ``tri`` by the discrete Ricci (Yamabe) flow of vertex scaling (paper §4.1; `conformesh uniformize`):
closed genus 0 to the unit sphere, genus 1 to a flat torus of area 1, genus >= 2 hyperbolic, genus 0 with boundary
to a circle domain, genus >= 1 with boundary hyperbolic with geodesic boundary. ``tolerance`` bounds the angle-sum
residual (radians); method 'circle-packing' or 'inversive-distance' selects the circle-packing flows (closed genus
>= 1). ``progress(str)`` is called after every Newton step; the GIL is released and Ctrl-C raises KeyboardInterrupt
at the next step. T0* is verified as the CLI verifies it (report['verification']): a failure raises VerificationError
unless keep_failed=True. Raises InputError (more than one component, bad lengths) or ConvergenceError.)doc");

  py::class_<RemeshResult>(m, "RemeshResult", "What conformesh.remesh returns.")
      .def_readonly("triangulation", &RemeshResult::triangulation,
                    "T1: the output, Euclidean, lengths in the ORIGINAL metric (fields as in `fields`).")
      .def_readonly("chart_coordinates", &RemeshResult::chartCoordinates,
                    "Metric input: (u, v) per output vertex, float64 (num_vertices, 2); None for a triangulation.")
      .def_readonly("input_faces", &RemeshResult::inputFaces,
                    "Triangulation input: the input face of each output vertex, int32 (num_vertices,); else None.")
      .def_readonly("input_barycentric", &RemeshResult::inputBarycentric,
                    "Triangulation input: barycentric coordinates in that face, float64 (num_vertices, 3); else None.")
      .def_property_readonly(
          "input_locations",
          [](const RemeshResult& r) -> py::object {
            if (r.inputFaces.is_none()) return py::none();
            return py::make_tuple(r.inputFaces, r.inputBarycentric);
          },
          "Triangulation input: (input_faces, input_barycentric); None for a metric.")
      .def_readonly("positions", &RemeshResult::positions,
                    "Positions in R^3 per output vertex where the metric has an embedding or the input has "
                    "positions (interpolated), else None.")
      .def_readonly("fields", &RemeshResult::fields,
                    "Per-vertex fields, float64 arrays: those of the CLI's PLY output (u, v, lambda, curvature, "
                    "smooth_curvature, input_face, input_b0..2; error and relative_error with check=True).")
      .def_readonly("report", &RemeshResult::report, "The report of `conformesh remesh --json` as a dict.")
      .def("write", &writeRemesh, py::arg("path"), py::arg("vtk") = py::none(), py::arg("ascii") = false,
           "Writes the PLY the CLI writes with -o (binary, or ASCII) and, with vtk=PATH, its VTK (--vtk).")
      .def("__repr__", [](const RemeshResult& r) {
        return "<conformesh.RemeshResult " + std::to_string(r.triangulation->tri.mesh.nVertices()) + " vertices>";
      });
  m.def("remesh", &remesh, py::arg("source"), py::arg("eps"), py::arg("check") = true, py::kw_only(),
        py::arg("ratio") = 1.4142135623730951, py::arg("uniform") = false, py::arg("t0_resolution") = 0,
        py::arg("disk_target") = "auto", py::arg("smoothing") = py::none(), py::arg("smoothing_rule") = "odt",
        py::arg("segment_rule") = "ruppert", py::arg("refine_in") = py::none(), py::arg("region") = "ball",
        py::arg("keep_failed") = false, py::arg("progress") = py::none(), R"doc(
The whole pipeline (`conformesh remesh`): on a metrics.Metric, discretize -> uniformize -> Delaunay-refine with
circumradii <= eps (in the original metric) and circumradius/shortest edge <= ratio -> pull back, every output edge
with its length in the original metric; on a Triangulation (Euclidean, one component), refine it in its own metric
(refine_in='input', the default for triangulations: it keeps the angle bound there) or uniformize it, refine and pull
back through its faces (refine_in='uniformized', the paper's). refine_in=None: 'input' for a Triangulation,
'uniformized' (the only route) for a Metric.
With check=True the Gaussian curvature measure check runs (report['gaussian_curvature_measure'], fields 'error' and
'relative_error'). Options as the CLI's: t0_resolution (0 = automatic), disk_target ('auto', 'circle',
'keep-boundary'), smoothing (passes; None = the CLI's default), smoothing_rule ('odt', 'centroid'), segment_rule
('ruppert', 'chew'), region ('ball', 'union'). ``progress(str)`` receives the stage lines; the GIL is released and
Ctrl-C raises KeyboardInterrupt between steps (nothing is written). The output is verified as the CLI verifies it
(report['verification']): a failure raises VerificationError unless keep_failed=True. Raises InputError or
ConvergenceError.)doc");
}

}  // namespace conformesh::python
