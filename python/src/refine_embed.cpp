// refine_embed.cpp — conformesh.refine (Delaunay refinement of a constant-curvature triangulation, `conformesh
// refine`) and conformesh.embed (positions in R³ fitted to the edge lengths by Ceres, `conformesh embed`): results as
// NumPy arrays, reports with the keys of the commands' --json.
#include <chrono>
#include <cmath>
#include <optional>

#include <pybind11/stl.h>

#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/pipeline/output_verification.h"
#include "conformesh/refine/pipeline/refinement_output.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "conformesh/refine/trace/input_location.h"
#include "pipelines.h"
#include "triangulation.h"

namespace conformesh::python {

namespace {

// ---- refine -------------------------------------------------------------------------------------------------------

struct RefineArgs {
  double eps = 0, ratio = 1.4142135623730951;
  bool uniform = false, offCenters = false, frontal = false;
  py::object conformalFactor = py::none();
  std::string boundary = "auto", segmentRule = "ruppert", smoothingRule = "odt";
  int smoothing = 0;
  std::int64_t maxInsertions = 50'000'000;
  bool keepFailed = false;
};

struct RefineResult {
  TriangulationPtr triangulation;
  py::object inputFaces, inputBarycentric, conformalFactor = py::none(), positions = py::none(), report;
  std::shared_ptr<intrinsic::MeshData> data;  // what the CLI writes with -o
};

refine::BoundarySplit parseBoundary(const std::string& s) {
  if (s == "auto") return refine::BoundarySplit::Auto;
  if (s == "circle") return refine::BoundarySplit::Circle;
  if (s == "geodesic") return refine::BoundarySplit::Geodesic;
  inputError("refine: boundary '" + s + "' (expected 'auto', 'circle' or 'geodesic')");
}

// The options of `conformesh refine`; lambda from `conformal_factor`, else the input's field 'lambda' (the CLI's
// vertex property), unless uniform. Returns whether the refinement is graded.
bool refineOptions(const Triangulation& in, const RefineArgs& a, refine::RefineOptions& o) {
  o.epsilon = a.eps;
  o.ratioBound = a.ratio;
  o.maxInsertions = a.maxInsertions;
  o.offCenters = a.offCenters;
  o.frontal = a.frontal;
  o.segmentRule = refine::parseSegmentRule(a.segmentRule);
  o.smoothingPasses = a.smoothing;
  o.smoothingRule = refine::parseSmoothingRule(a.smoothingRule);
  o.boundarySplit = parseBoundary(a.boundary);
  const int n = in.tri.mesh.nVertices();
  if (!a.conformalFactor.is_none()) {
    if (a.uniform) inputError("refine: conformal_factor and uniform=True exclude each other");
    o.lambda = vectorFromArray(a.conformalFactor, "refine: conformal_factor", n);
  } else if (!a.uniform) {
    const auto lam = in.fields.find("lambda");
    if (lam != in.fields.end()) {
      if (static_cast<int>(lam->second.size()) != n)
        inputError("refine: " + in.source + ": field 'lambda' has " + std::to_string(lam->second.size()) +
                   " values but the triangulation has " + std::to_string(n) + " vertices");
      o.lambda = lam->second;
    }
  }
  const std::string invalid = o.validate();
  if (!invalid.empty()) inputError("refine: " + invalid);
  return !o.lambda.empty();
}

RefineResult refineTriangulation(const TriangulationPtr& in, double eps, const RefineArgs& args,
                                 const py::object& progress) {
  RefineArgs a = args;
  a.eps = eps;
  refine::RefineOptions o;
  const bool graded = refineOptions(*in, a, o);
  CallGuard guard(progress);
  o.progressEvery = 2000;  // each check costs one GIL round trip
  o.progress = [&guard](const refine::RefineProgress& p) {
    guard.step("refine: " + std::to_string(p.insertions) + " insertions, " + std::to_string(p.vertices) +
               " vertices, " + std::to_string(p.queuedTriangles) + " triangles queued");
  };
  refine::RefineResult r;
  refine::QualityReport q;
  double seconds = 0;
  {
    py::gil_scoped_release release;
    const auto t0 = std::chrono::steady_clock::now();
    r = refine::refineDelaunay(in->tri, o);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    q = refine::measureQuality(r.triangulation);
  }
  RefineResult out;
  // Positions as the CLI writes them: none when reading dropped unreferenced vertices (refine_command.cpp).
  const bool positionsFit = in->reading.unreferencedVerticesRemoved == 0;
  out.data = std::make_shared<intrinsic::MeshData>(
      refine::refinementMeshData(r, in->tri, positionsFit ? in->positions : std::vector<Eigen::Vector3d>{}, graded));
  nlohmann::json j = refine::refineJson(r, in->tri, o, q, seconds);  // the keys of `conformesh refine --json`
  j["input"] = in->source;
  verifyOrRaise(refine::verifyRefinement(in->tri, r), a.keepFailed, j);
  out.report = toPython(j);
  auto t = fromIntrinsic(r.triangulation, in->source + " refined");
  t->positions = out.data->positions;
  t->fields = out.data->vertexProperties;
  out.triangulation = t;
  std::vector<int> face(r.locations.size());
  std::vector<double> bary(3 * r.locations.size());
  for (std::size_t v = 0; v < r.locations.size(); ++v) {
    face[v] = r.locations[v].face;
    for (int k = 0; k < 3; ++k) bary[3 * v + k] = r.locations[v].bary[k];
  }
  out.inputFaces = toArray(std::move(face));
  out.inputBarycentric = toArray(std::move(bary), 3);
  if (graded) out.conformalFactor = toArray(std::move(r.lambda));
  if (!out.data->positions.empty()) out.positions = toArray(std::vector<Eigen::Vector3d>(out.data->positions));
  return out;
}

RefineResult refineBinding(const TriangulationPtr& in, double eps, double ratio, bool uniform,
                           const py::object& conformalFactor, const std::string& boundary,
                           const std::string& segmentRule, bool offCenters, bool frontal, int smoothing,
                           const std::string& smoothingRule, std::int64_t maxInsertions, bool keepFailed,
                           const py::object& progress) {
  RefineArgs a;
  a.ratio = ratio;
  a.uniform = uniform;
  a.conformalFactor = conformalFactor;
  a.boundary = boundary;
  a.segmentRule = segmentRule;
  a.offCenters = offCenters;
  a.frontal = frontal;
  a.smoothing = smoothing;
  a.smoothingRule = smoothingRule;
  a.maxInsertions = maxInsertions;
  a.keepFailed = keepFailed;
  return refineTriangulation(in, eps, a, progress);
}

void writeRefine(const RefineResult& r, const std::string& path, bool ascii) {
  py::gil_scoped_release release;
  intrinsic::MeshData d = *r.data;
  d.source = path;
  intrinsic::WriteOptions w;
  if (ascii) w.plyEncoding = intrinsic::PlyEncoding::Ascii;
  intrinsic::writeMesh(d, path, w);
}

// ---- embed --------------------------------------------------------------------------------------------------------

struct EmbedResult {
  TriangulationPtr triangulation;
  py::object positions, edgeResiduals, report;
  bool isometric = false;
  std::string verdict;
};

EmbedResult embed(const TriangulationPtr& in, const py::object& init, double tolerance, double regularizer,
                  int landmarks, int maxIterations, bool strict, const py::object& progress) {
  embedding::EmbeddingOptions eo;
  eo.tolerance = tolerance;
  eo.regularizerWeight = regularizer;
  eo.landmarks = landmarks;
  eo.maxIterations = maxIterations;
  if (landmarks < 4 || landmarks > 100000) inputError("embed: landmarks = " + std::to_string(landmarks) +
                                                      " (expected 4..100000)");
  if (maxIterations < 1 || maxIterations > 100000)
    inputError("embed: max_iterations = " + std::to_string(maxIterations) + " (expected 1..100000)");
  const std::string invalid = eo.validate();
  if (!invalid.empty()) inputError("embed: " + invalid);
  if (!init.is_none()) {
    eo.initialPositions = pointsFromArray(init, "embed: init");
    if (static_cast<int>(eo.initialPositions.size()) != in->tri.mesh.nVertices())
      inputError("embed: init has " + std::to_string(eo.initialPositions.size()) + " rows, the triangulation has " +
                 std::to_string(in->tri.mesh.nVertices()) + " vertices");
  }
  // The library reports from inside Ceres' IterationCallback, which cannot be told to stop, and unwinding through
  // Ceres' minimizer is not something it promises to survive: a Python error (Ctrl-C, a raising progress) is held
  // until the fit returns, later lines are dropped, and then it is raised.
  CallGuard guard(progress);
  std::optional<py::error_already_set> pending;
  eo.progress = [&guard, &pending](const std::string& line) {
    if (pending) return;
    try {
      guard.step(line);
    } catch (py::error_already_set& e) {
      pending.emplace(std::move(e));
    }
  };
  embedding::EmbeddingResult fit;
  {
    py::gil_scoped_release release;
    fit = embedding::fitIsometricEmbedding(in->tri, eo);
  }
  if (pending) throw std::move(*pending);
  if (strict && !fit.isometric) throw ConvergenceError("embed: " + in->source + " is " + fit.verdict);
  EmbedResult out;
  nlohmann::json j = refine::embeddingJson(fit, in->tri);  // the keys of `conformesh embed --json`
  j["file"] = in->source;
  out.report = toPython(j);
  out.isometric = fit.isometric;
  out.verdict = fit.verdict;
  auto t = std::make_shared<Triangulation>(*in);
  t->source = in->source + " embedded";
  t->positions = fit.positions;
  out.triangulation = t;
  out.edgeResiduals = toArray(embedding::relativeEdgeResiduals(in->tri, fit.positions));
  out.positions = toArray(std::move(fit.positions));
  return out;
}

}  // namespace

void bindRefineAndEmbed(py::module_& m) {
  py::class_<RefineResult>(m, "RefineResult", "What conformesh.refine returns.")
      .def_readonly("triangulation", &RefineResult::triangulation,
                    "The refined triangulation: the input's background, its vertices 0..n-1 the input's; fields "
                    "input_face, input_b0..2 and (graded) lambda; positions when the CLI writes them.")
      .def_readonly("input_faces", &RefineResult::inputFaces,
                    "The input face each output vertex lies on, int32 (num_vertices,).")
      .def_readonly("input_barycentric", &RefineResult::inputBarycentric,
                    "Barycentric coordinates in that face, float64 (num_vertices, 3).")
      .def_property_readonly(
          "input_locations", [](const RefineResult& r) { return py::make_tuple(r.inputFaces, r.inputBarycentric); },
          "(input_faces, input_barycentric).")
      .def_readonly("conformal_factor", &RefineResult::conformalFactor,
                    "Graded refinement: lambda interpolated at every output vertex, float64 (num_vertices,); else "
                    "None.")
      .def_readonly("positions", &RefineResult::positions,
                    "Euclidean input with positions: each output vertex's point on the input's flat faces; else None.")
      .def_readonly("report", &RefineResult::report, "The report of `conformesh refine --json` as a dict.")
      .def("write", &writeRefine, py::arg("path"), py::arg("ascii") = false,
           "Writes the PLY `conformesh refine -o PATH` writes (binary, or ASCII).")
      .def("__repr__", [](const RefineResult& r) {
        return "<conformesh.RefineResult " + std::to_string(r.triangulation->tri.mesh.nVertices()) + " vertices>";
      });
  m.def("refine", &refineBinding, py::arg("tri"), py::arg("eps"), py::kw_only(),
        py::arg("ratio") = 1.4142135623730951, py::arg("uniform") = false, py::arg("conformal_factor") = py::none(),
        py::arg("boundary") = "auto", py::arg("segment_rule") = "ruppert", py::arg("off_centers") = false,
        py::arg("frontal") = false, py::arg("smoothing") = 0, py::arg("smoothing_rule") = "odt",
        py::arg("max_insertions") = 50'000'000, py::arg("keep_failed") = false, py::arg("progress") = py::none(), R"doc(
Delaunay refinement of a constant-curvature triangulation (`conformesh refine`; paper §4.2): a uniformized T0*
(uniformize(...).triangulation) or any spherical, Euclidean or hyperbolic triangulation. Triangles are split until
every circumradius r <= eps * exp(-lambda(c)) (lambda interpolated at the circumcentre c; background metric) and
r / shortest edge <= ratio (smallest angle >= arcsin(1 / (2 ratio))). lambda: ``conformal_factor`` (per input
vertex), else the field 'lambda' of ``tri`` (what uniformize and the CLI's files carry), else 0; uniform=True
ignores the field. Options as the CLI's: boundary ('auto', 'circle', 'geodesic'), segment_rule ('ruppert',
'chew'), off_centers (Üngör's off-centres), frontal (Rebay's frontal points; not in the CLI), smoothing (passes),
smoothing_rule ('odt', 'centroid'), max_insertions (a ConvergenceError beyond). ``progress(str)`` is called every
2000 insertions; the GIL is released and Ctrl-C raises KeyboardInterrupt there. The output is verified as the CLI
verifies it (report['verification']): a failure raises VerificationError unless keep_failed=True. Raises InputError
(bad options, lambda of the wrong length, a loop 'circle' cannot split) or ConvergenceError (a cap hit).)doc");

  py::class_<EmbedResult>(m, "EmbedResult", "What conformesh.embed returns.")
      .def_readonly("triangulation", &EmbedResult::triangulation,
                    "The input triangulation (same lengths and fields) with the fitted positions.")
      .def_readonly("positions", &EmbedResult::positions, "The fitted positions, float64 (num_vertices, 3).")
      .def_readonly("edge_residuals", &EmbedResult::edgeResiduals,
                    "(|x_i - x_j| - l_e) / l_e per edge (Triangulation.edges order), float64 (num_edges,).")
      .def_readonly("isometric", &EmbedResult::isometric, "Whether max |edge_residuals| <= tolerance.")
      .def_readonly("verdict", &EmbedResult::verdict, "The library's one-line verdict.")
      .def_readonly("report", &EmbedResult::report, "The report of `conformesh embed --json` as a dict.")
      .def("__repr__", [](const EmbedResult& r) { return "<conformesh.EmbedResult " + r.verdict + ">"; });
  m.def("embed", &embed, py::arg("tri"), py::kw_only(), py::arg("init") = py::none(),
        py::arg("tolerance") = embedding::EmbeddingOptions{}.tolerance,
        py::arg("regularizer") = embedding::EmbeddingOptions{}.regularizerWeight,
        py::arg("landmarks") = embedding::EmbeddingOptions{}.landmarks,
        py::arg("max_iterations") = embedding::EmbeddingOptions{}.maxIterations, py::arg("strict") = false,
        py::arg("progress") = py::none(), R"doc(
Fits positions in R^3 to the edge lengths of ``tri`` (`conformesh embed`; Ceres Levenberg-Marquardt on the residuals
(|x_i - x_j| - l_e) / l_e, docs/embedding.md): from ``init`` ((num_vertices, 3), the triangulation's vertex order)
or a landmark-MDS start with ``landmarks`` landmarks; a first solve with the dihedral regularizer of weight
``regularizer`` (0 skips it), then the pure fit of at most ``max_iterations`` LM iterations. The fit is isometric
when the largest relative residual is <= ``tolerance``. A fit that is not isometric is returned (isometric=False,
the best positions) unless strict=True, which raises ConvergenceError with the CLI's message. ``progress(str)``
receives one line per LM iteration; the GIL is released. Ctrl-C (or an exception in progress) is raised only when
the fit returns (docs/python.md, Limits). Raises InputError (non-Euclidean background, several components, a
self-loop edge, bad init).)doc");
}

}  // namespace conformesh::python
