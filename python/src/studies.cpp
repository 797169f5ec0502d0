// studies.cpp — conformesh.convergence (the paper's §6 study) and conformesh.layout (canonical domains).
#include <cmath>
#include <fstream>

#include <pybind11/stl.h>

#include "conformesh/embedding/layout/layout_picture.h"
#include "conformesh/embedding/layout/layout_ply.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/refine/pipeline/convergence_study.h"
#include "metrics.h"
#include "pipelines.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "triangulation.h"

namespace conformesh::python {

namespace {

using namespace conformesh::embedding;

// ---- convergence --------------------------------------------------------------------------------------------------

struct ConvergenceResult {
  py::object rows, orders, report;
};

ConvergenceResult convergence(const Metric& metric, const std::vector<int>& vertices, double ratio, int t0Resolution,
                              const std::string& diskTarget, const py::object& smoothing,
                              const std::string& smoothingRule, bool extrinsic, const py::object& progress) {
  refine::ConvergenceOptions o;
  if (!vertices.empty()) o.targetVertices = vertices;
  o.remesh.ratioBound = ratio;
  o.remesh.t0Resolution = t0Resolution;
  o.remesh.diskTarget = refine::parseDiskTarget(diskTarget);
  if (!smoothing.is_none()) o.remesh.refinement.smoothingPasses = smoothing.cast<int>();
  o.remesh.refinement.smoothingRule = refine::parseSmoothingRule(smoothingRule);
  o.extrinsic = extrinsic;
  const std::string invalid = o.validate();
  if (!invalid.empty())  // validate() names the study itself in most of its messages
    inputError(invalid.rfind("convergence: ", 0) == 0 ? invalid : "convergence: " + invalid);
  CallGuard guard(progress);
  o.progress = guard.lineCallback();
  o.measure.progress = guard.countCallback("curvature measure");
  o.remesh.refinement.progressEvery = 2000;
  o.remesh.refinement.progress = [&guard](const refine::RefineProgress& p) {
    guard.step("refining: " + std::to_string(p.vertices) + " vertices");
  };
  refine::ConvergenceStudy s;
  {
    py::gil_scoped_release release;
    s = refine::runConvergenceStudy(*metric.metric, o);
  }
  // Rows: the columns of the CLI's CSV; the report: its JSON (refine/pipeline/remesh_json.h).
  py::list rows;
  for (const auto& L : s.levels) {
    nlohmann::json row = {{"target_vertices", L.targetVertices},
                          {"vertices", L.vertices},
                          {"triangles", L.triangles},
                          {"eps", L.epsilon},
                          {"max_circumradius", L.quality.maxCircumradius},
                          {"mean_circumradius", L.quality.meanCircumradius},
                          {"min_angle_deg", L.quality.minAngleDeg},
                          {"mean_min_angle_deg", L.quality.meanMinAngleDeg},
                          {"e_G", L.measure.meanAbsoluteError},
                          {"max_error", L.measure.maxAbsoluteError},
                          {"fraction_within", L.measure.fractionWithinBand},
                          {"inverted_triangles", L.invertedTriangles},
                          {"total_area", L.totalArea},
                          {"gauss_bonnet_residual", L.quality.gaussBonnetResidual},
                          {"seconds", L.seconds}};
    if (s.extrinsic) {
      row["e_H"] = L.meanCurvature.meanAbsoluteError;
      row["hausdorff"] = L.deviation.hausdorffClosest;
      row["normal_deviation"] = L.deviation.normalDeviation;
    }
    rows.append(toPython(row));
  }
  const nlohmann::json j = refine::convergenceStudyJson(s, o);
  const nlohmann::json& orders = j["orders"];
  return {rows, toPython(orders), toPython(j)};
}

// ---- layout -------------------------------------------------------------------------------------------------------

struct LayoutResult {
  TriangulationPtr triangulation;
  py::object corners, target, report;
  std::shared_ptr<LayoutDrawing> drawing;
  std::shared_ptr<CornerLayout> cornerLayout;
};

py::list complexPair(Complex z) {
  py::list l;
  l.append(z.real());
  l.append(z.imag());
  return l;
}

nlohmann::json cj(Complex z) { return {z.real(), z.imag()}; }

LayoutResult layout(const TriangulationPtr& in, double tolerance, int tiles, int centreVertex, int directionVertex,
                    const py::object& progress) {
  CallGuard guard(progress);
  auto drawing = std::make_shared<LayoutDrawing>();
  auto corners = std::make_shared<CornerLayout>();
  nlohmann::json j;
  intrinsic::Uniformization u;
  {
    py::gil_scoped_release release;
    intrinsic::UniformizationOptions uo;
    uo.flow.tolerance = tolerance;
    uo.progress = guard.lineCallback();
    u = intrinsic::uniformize(in->tri, uo);
    const intrinsic::IntrinsicTriangulation& tri = u.uniform;
    PictureOptions po;
    po.tileDepth = tiles;
    // The keys of `conformesh layout --json` (apps/layout_command.cpp), without the file names.
    j = {{"input", in->source},
         {"target", intrinsic::toString(u.report.target)},
         {"genus", u.report.genus},
         {"boundary_loops", u.report.boundaryLoops},
         {"flow_residual", u.report.maxResidual}};
    switch (u.report.target) {
      case intrinsic::UniformizationTarget::FlatTorus: {
        const TorusLayout t = layoutTorus(tri);
        *drawing = drawTorus(tri, t, po);
        *corners = cornerLayout(tri, t.domain);
        j["omega1"] = cj(t.omega1);
        j["omega2"] = cj(t.omega2);
        j["reduced_omega1"] = cj(t.reducedOmega1);
        j["reduced_omega2"] = cj(t.reducedOmega2);
        j["tau"] = cj(t.tau);
        j["relation_residual"] = t.domain.relationResidual;
        break;
      }
      case intrinsic::UniformizationTarget::Hyperbolic: {
        const HyperbolicLayout h = layoutHyperbolic(tri);
        *drawing = drawHyperbolic(tri, h, po);
        *corners = cornerLayout(tri, h.domain);
        nlohmann::json gens = nlohmann::json::array();
        for (const auto& g : h.generators)
          gens.push_back(
              {{"a", cj(g.matrix(0, 0))}, {"b", cj(g.matrix(0, 1))}, {"translation_length", g.translationLength}});
        j["generators"] = gens;
        j["relation"] = h.relation;
        j["relation_residual"] = h.relationResidual;
        j["max_vertex_residual"] = h.domain.maxVertexResidual;
        break;
      }
      case intrinsic::UniformizationTarget::Sphere: {
        SphereLayoutOptions so;
        so.centreVertex = centreVertex;
        so.directionVertex = directionVertex;
        const SphereLayout s = layoutSphere(u, vertexAreas(in->tri), so);
        *drawing = drawSphere(tri, s);
        *corners = cornerLayout(tri, s);
        j["centroid_distance"] = s.centroid.norm();
        j["balance_iterations"] = s.balanceIterations;
        break;
      }
      case intrinsic::UniformizationTarget::CircleDomain: {
        const DiskLayout d = layoutDisk(u, {centreVertex, directionVertex});
        *drawing = drawDisk(tri, d);
        *corners = cornerLayout(tri, d);
        nlohmann::json circles = nlohmann::json::array();
        for (const auto& c : d.circles)
          circles.push_back(
              {{"centre", {c.centre.x(), c.centre.y()}}, {"radius", c.radius}, {"deviation", c.deviation}});
        j["circles"] = circles;
        break;
      }
      case intrinsic::UniformizationTarget::FlatCylinder:
        throw InputError("layout: " + in->source + " is an annulus uniformized to a flat cylinder (height " +
                         formatNumber(u.report.cylinderHeight) +
                         "): its circle domain's inner circle is below what a planar layout resolves");
      default:
        throw InputError("layout: " + in->source + " uniformizes to " + intrinsic::toString(u.report.target) +
                         " (genus >= 1 with boundary), which has no canonical-domain layout here");
    }
  }
  LayoutResult out;
  auto t = fromIntrinsic(u.uniform, in->source + " uniformized");
  t->positions = corners->positions;
  t->fields["lambda"] = u.lambda;
  out.triangulation = t;
  std::vector<double> c(6 * corners->corners.size());
  for (std::size_t f = 0; f < corners->corners.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      c[6 * f + 2 * k] = corners->corners[f][k].x();
      c[6 * f + 2 * k + 1] = corners->corners[f][k].y();
    }
  out.corners = toArray(std::move(c), 6).attr("reshape")(-1, 3, 2);
  out.target = py::str(intrinsic::toString(u.report.target));
  out.report = toPython(j);
  out.drawing = drawing;
  out.cornerLayout = corners;
  return out;
}

void writeLayout(const LayoutResult& r, const std::string& path, int pixels) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  py::gil_scoped_release release;
  if (ext == ".ply") {
    writeLayoutPly(*r.cornerLayout, path);
  } else if (ext == ".svg") {
    std::ofstream f(path);
    if (!f) throw InputError(path + ": cannot open for writing");
    f << toSvg(*r.drawing, pixels);
    if (!f) throw InputError(path + ": write failed");
  } else {
    throw InputError("LayoutResult.write: " + path + " must end in .svg or .ply (PNG: use svg() with matplotlib, "
                     "or `conformesh layout`)");
  }
}

}  // namespace

void bindStudies(py::module_& m) {
  py::class_<ConvergenceResult>(m, "ConvergenceResult", "What conformesh.convergence returns.")
      .def_readonly("rows", &ConvergenceResult::rows,
                    "One dict per level, the columns of the CLI's CSV (vertices, eps, mean_circumradius, e_G, ...).")
      .def_readonly("orders", &ConvergenceResult::orders,
                    "The fitted log-log slopes: e_G_vs_mean_circumradius (Theorem 3.4: >= 1), "
                    "mean_circumradius_vs_vertices (-1/2), area_error_vs_mean_circumradius (2), and with "
                    "extrinsic=True e_H, hausdorff, normal_deviation against the mean circumradius.")
      .def_readonly("report", &ConvergenceResult::report, "The study as the CLI's JSON (levels, orders, ...).");
  m.def("convergence", &convergence, py::arg("metric"), py::kw_only(), py::arg("vertices") = std::vector<int>{},
        py::arg("ratio") = 1.4142135623730951, py::arg("t0_resolution") = 10, py::arg("disk_target") = "auto",
        py::arg("smoothing") = py::none(), py::arg("smoothing_rule") = "odt", py::arg("extrinsic") = false,
        py::arg("progress") = py::none(), R"doc(
The paper's §6 experiment (`conformesh convergence`) on ``metric``: one uniformization, remeshed at eps calibrated to
the target ``vertices`` counts (default: the paper's Table 2), each level's quality and Gaussian-curvature-measure
error e_G, and the fitted orders. extrinsic=True adds the mean-curvature, Hausdorff and normal checks (metrics with
an embedding). Releases the GIL; ``progress(str)`` and Ctrl-C between steps.)doc");

  py::class_<LayoutResult>(m, "LayoutResult", "What conformesh.layout returns.")
      .def_readonly("triangulation", &LayoutResult::triangulation,
                    "The uniformized triangulation laid out (positions: the layout's points, zeros where unknown).")
      .def_readonly("corners", &LayoutResult::corners,
                    "Domain coordinates per face corner, float64 (num_faces, 3, 2): the developed fundamental domain "
                    "(tori: the plane; hyperbolic: the Poincare disk), the circle domain, or the sphere's "
                    "stereographic plane.")
      .def_readonly("target", &LayoutResult::target, "The uniformization target ('sphere', 'flat-torus', ...).")
      .def_readonly("report", &LayoutResult::report,
                    "The report of `conformesh layout --json`: periods and modulus tau (tori), deck generators and "
                    "the relation (genus >= 2), circles (circle domains), balancing (spheres).")
      .def(
          "svg", [](const LayoutResult& r, int pixels) { return toSvg(*r.drawing, pixels); },
          py::arg("pixels") = 900, "The layout picture as SVG text.")
      .def("write", &writeLayout, py::arg("path"), py::arg("pixels") = 900,
           "Writes the picture (.svg) or the PLY with per-corner domain coordinates (.ply), as `conformesh layout`.");
  m.def("layout", &layout, py::arg("tri"), py::kw_only(), py::arg("tolerance") = 1e-12, py::arg("tiles") = 1,
        py::arg("centre_vertex") = -1, py::arg("direction_vertex") = -1, py::arg("progress") = py::none(), R"doc(
Uniformizes ``tri`` and lays it out in its canonical domain (`conformesh layout`): a disk or circle domain
(normalized by centre_vertex -> 0 and direction_vertex onto +x), the Moebius-balanced unit sphere, a flat torus
with its periods and modulus, or the Poincare disk with its deck group (``tiles`` rings of the universal cover in
the picture). Raises InputError for targets without a layout (flat cylinders, genus >= 1 with boundary).)doc");
}

}  // namespace conformesh::python
