// metrics.cpp — conformesh.metrics: families by their CLI names, sampled fields from arrays or files, and the
// Metric's pointwise queries (vectorized over arrays of chart points).
#include "metrics.h"

#include <cmath>
#include <fstream>

#include <pybind11/stl.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"
#include "triangulation.h"

namespace conformesh::python {

namespace {

using intrinsic::SmoothMetric;

Metric family(const std::string& name, const py::kwargs& params) {
  std::map<std::string, double> p;
  for (const auto& [key, value] : params) {
    const std::string k = py::str(key);
    double x = 0;
    try {
      x = value.cast<double>();
    } catch (const py::cast_error&) {
      inputError("metrics.family('" + name + "'): parameter " + k + " = " + py::repr(value).cast<std::string>() +
                 " is not a number");
    }
    if (!std::isfinite(x))
      inputError("metrics.family('" + name + "'): parameter " + k + " = " + formatNumber(x) +
                 " (expected a finite value)");
    p[k] = x;
  }
  return {intrinsic::makeMetric(name, p)};
}

py::list families() {
  py::list out;
  for (const auto& f : intrinsic::metricFamilies()) {
    py::dict params;
    for (const auto& p : f.parameters) params[py::str(p.name)] = py::make_tuple(p.defaultValue, p.meaning);
    py::dict d;
    d["name"] = f.name;
    d["summary"] = f.summary;
    d["parameters"] = params;
    out.append(d);
  }
  return out;
}

intrinsic::SampledField fieldFromArrays(const py::handle& guu, const py::handle& guv, const py::handle& gvv,
                                        const std::array<double, 4>& chart, bool periodicU, bool periodicV,
                                        const std::string& poles) {
  const std::string where = "metrics.sampled";
  intrinsic::SampledField f;
  f.source = where;
  f.domain.u0 = chart[0];
  f.domain.u1 = chart[1];
  f.domain.v0 = chart[2];
  f.domain.v1 = chart[3];
  f.domain.periodicU = periodicU;
  f.domain.periodicV = periodicV;
  if (poles != "none" && poles != "both")
    inputError(where + ": poles = '" + poles + "' (expected 'none' or 'both')");
  const char* names[3] = {"g_uu", "g_uv", "g_vv"};
  std::vector<double>* out[3] = {&f.guu, &f.guv, &f.gvv};
  const py::handle in[3] = {guu, guv, gvv};
  for (int c = 0; c < 3; ++c) {
    py::array a = py::array::ensure(in[c]);
    if (!a || (a.dtype().kind() != 'f' && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
      inputError(where + ": " + names[c] + ": expected a real array of shape (NV, NU)");
    if (a.ndim() != 2) inputError(where + ": " + names[c] + ": expected a 2-D array of shape (NV, NU), got " +
                                  std::to_string(a.ndim()) + " dimensions");
    if (c == 0) {
      f.nv = static_cast<int>(a.shape(0));
      f.nu = static_cast<int>(a.shape(1));
    } else if (a.shape(0) != f.nv || a.shape(1) != f.nu) {
      inputError(where + ": " + names[c] + " has shape (" + std::to_string(a.shape(0)) + ", " +
                 std::to_string(a.shape(1)) + "), g_uu (" + std::to_string(f.nv) + ", " + std::to_string(f.nu) +
                 ")");
    }
    auto d = py::array_t<double, py::array::forcecast>::ensure(a);
    const auto r = d.unchecked<2>();
    out[c]->resize(static_cast<std::size_t>(f.nu) * f.nv);
    for (int j = 0; j < f.nv; ++j)
      for (int i = 0; i < f.nu; ++i) {
        const double x = r(j, i);
        if (!std::isfinite(x))
          inputError(where + ": " + names[c] + "[" + std::to_string(j) + ", " + std::to_string(i) + "] is " +
                     formatNumber(x) + " (expected a finite number)");
        (*out[c])[static_cast<std::size_t>(j) * f.nu + i] = x;  // row j = v-node j, u fastest
      }
  }
  intrinsic::checkChartBounds(f.domain, where);
  if (poles == "both") intrinsic::markPoleToPole(f, where);
  return f;
}

Metric sampled(const py::handle& guu, const py::handle& guv, const py::handle& gvv, const std::array<double, 4>& chart,
               bool periodicU, bool periodicV, const std::string& poles) {
  intrinsic::SampledField f = fieldFromArrays(guu, guv, gvv, chart, periodicU, periodicV, poles);
  py::gil_scoped_release release;
  return {std::make_shared<intrinsic::SampledMetric>(f)};
}

Metric readField(const std::string& path) {
  py::gil_scoped_release release;
  return {std::make_shared<intrinsic::SampledMetric>(intrinsic::readSampledField(path))};
}

void writeField(const std::string& path, const Metric& m, int nu, int nv, const std::string& group) {
  if (nu < 4 || nv < 4) inputError("metrics.write_field: grid (" + std::to_string(nu) + ", " + std::to_string(nv) +
                                   ") (expected at least 4 nodes per axis)");
  py::gil_scoped_release release;
  const intrinsic::SampledField f = intrinsic::sampleMetric(*m.metric, nu, nv);
  std::string lower = path;
  for (auto& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const bool h5 = lower.size() > 3 && (lower.compare(lower.size() - 3, 3, ".h5") == 0 ||
                                      (lower.size() > 5 && lower.compare(lower.size() - 5, 5, ".hdf5") == 0));
  if (h5) {
    intrinsic::writeSampledFieldHdf5(f, path, group);
    return;
  }
  intrinsic::writeFileAtomically(path, intrinsic::formatSampledField(f));
}

// (u, v) broadcast to one shape; values evaluated per point.
template <class F>
py::tuple evaluate(const py::handle& u, const py::handle& v, int outputs, F&& f) {
  auto uu = py::array_t<double, py::array::forcecast>::ensure(u);
  auto vv = py::array_t<double, py::array::forcecast>::ensure(v);
  if (!uu || !vv) inputError("expected real arrays (or numbers) u and v");
  py::module_ np = py::module_::import("numpy");
  py::tuple b = np.attr("broadcast_arrays")(uu, vv);
  auto bu = py::array_t<double, py::array::forcecast | py::array::c_style>::ensure(np.attr("ascontiguousarray")(b[0]));
  auto bv = py::array_t<double, py::array::forcecast | py::array::c_style>::ensure(np.attr("ascontiguousarray")(b[1]));
  std::vector<py::ssize_t> shape(bu.shape(), bu.shape() + bu.ndim());
  const py::ssize_t n = bu.size();
  std::vector<py::array_t<double>> out;
  std::vector<double*> ptr;
  for (int k = 0; k < outputs; ++k) {
    out.emplace_back(shape);
    ptr.push_back(out.back().mutable_data());
  }
  const double* pu = bu.data();
  const double* pv = bv.data();
  {
    py::gil_scoped_release release;
    double buf[8];
    for (py::ssize_t i = 0; i < n; ++i) {
      f(pu[i], pv[i], buf);
      for (int k = 0; k < outputs; ++k) ptr[k][i] = buf[k];
    }
  }
  py::tuple t(outputs);
  for (int k = 0; k < outputs; ++k) t[k] = out[k];
  return t;
}

TriangulationPtr discretize(const Metric& m, int resolution, bool exactGeodesics) {
  intrinsic::DiscretizationOptions o;
  o.resolution = resolution;
  o.exactGeodesics = exactGeodesics;
  py::gil_scoped_release release;
  intrinsic::MeshData d = intrinsic::discretizeMetric(*m.metric, o);
  d.source = m.metric->family() + " T0";
  return fromMeshData(d);
}

std::string polesOf(const intrinsic::ChartDomain& d) {
  if (d.poleAtV0 && d.poleAtV1) return "both";
  if (d.poleAtV0) return "v0";
  if (d.poleAtV1) return "v1";
  return "none";
}

}  // namespace

void bindMetrics(py::module_& m) {
  py::class_<Metric> c(m, "Metric", R"doc(
A smooth Riemannian metric g(u, v) over one chart [u0, u1] x [v0, v1] (optionally periodic, with coordinate poles):
a family (metrics.family), a sampled field (metrics.sampled, metrics.read_field) or a Python function
(metrics.from_function). Immutable; shared by every result built from it.)doc");
  c.def_property_readonly("family", [](const Metric& x) { return x.metric->family(); },
                          "The family name as the CLI knows it ('kerr-newman'), 'field' for sampled fields.");
  c.def_property_readonly("description", [](const Metric& x) { return x.metric->description(); },
                          "One line: the family and its parameter values (the remesh report's 'metric').");
  c.def_property_readonly(
      "chart",
      [](const Metric& x) {
        const auto d = x.metric->domain();
        return py::make_tuple(d.u0, d.u1, d.v0, d.v1);
      },
      "The chart (u0, u1, v0, v1).");
  c.def_property_readonly("periodic_u", [](const Metric& x) { return x.metric->domain().periodicU; },
                          "Whether u is periodic.");
  c.def_property_readonly("periodic_v", [](const Metric& x) { return x.metric->domain().periodicV; },
                          "Whether v is periodic.");
  c.def_property_readonly("poles", [](const Metric& x) { return polesOf(x.metric->domain()); },
                          "Coordinate poles: 'none', 'v0', 'v1' or 'both'.");
  c.def_property_readonly("shape", [](const Metric& x) { return intrinsic::toString(x.metric->domain().shape()); },
                          "What the chart's identifications make: 'rectangle', 'cylinder', 'torus', 'disk', 'sphere'.");
  c.def_property_readonly("genus", [](const Metric& x) { return x.metric->domain().genus(); }, "Genus of the surface.");
  c.def_property_readonly("boundary_loops", [](const Metric& x) { return x.metric->domain().boundaryLoops(); },
                          "Number of boundary loops of the surface.");
  c.def_property_readonly("euler_characteristic",
                          [](const Metric& x) { return x.metric->domain().eulerCharacteristic(); },
                          "Euler characteristic 2 - 2g - b of the surface.");
  c.def_property_readonly("has_embedding", [](const Metric& x) { return x.metric->hasEmbedding(); },
                          "Whether the family has an isometric embedding in R^3 (position()).");
  c.def(
      "g",
      [](const Metric& x, const py::handle& u, const py::handle& v) {
        return evaluate(u, v, 3, [&](double a, double b, double* o) {
          const Eigen::Matrix2d g = x.metric->g(a, b);
          o[0] = g(0, 0), o[1] = g(0, 1), o[2] = g(1, 1);
        });
      },
      py::arg("u"), py::arg("v"), "(g_uu, g_uv, g_vv) at chart points (arrays broadcast together).");
  c.def(
      "gaussian_curvature",
      [](const Metric& x, const py::handle& u, const py::handle& v) {
        return py::object(
            evaluate(u, v, 1, [&](double a, double b, double* o) { o[0] = x.metric->gaussianCurvature(a, b); })[0]);
      },
      py::arg("u"), py::arg("v"), "Gaussian curvature K at chart points (closed form where known, else Brioschi).");
  c.def(
      "area_element",
      [](const Metric& x, const py::handle& u, const py::handle& v) {
        return py::object(
            evaluate(u, v, 1, [&](double a, double b, double* o) { o[0] = x.metric->areaElement(a, b); })[0]);
      },
      py::arg("u"), py::arg("v"), "sqrt(det g) at chart points: the area is its integral over the chart.");
  c.def(
      "position",
      [](const Metric& x, const py::handle& u, const py::handle& v) {
        if (!x.metric->hasEmbedding()) inputError(x.metric->description() + ": the metric has no embedding in R^3");
        return evaluate(u, v, 3, [&](double a, double b, double* o) {
          const Eigen::Vector3d p = x.metric->position(a, b);
          o[0] = p.x(), o[1] = p.y(), o[2] = p.z();
        });
      },
      py::arg("u"), py::arg("v"), "(x, y, z) of the isometric embedding at chart points (InputError without one).");
  c.def("discretize", &discretize, py::arg("resolution") = 8, py::arg("exact_geodesics") = true, R"doc(
T0: a well-shaped triangulation of the chart whose edge lengths are metric lengths (`conformesh discretize`), with
fields 'u' and 'v' (chart coordinates) and positions where the family has an embedding.)doc");
  c.def("__repr__", [](const Metric& x) { return "<conformesh.metrics.Metric " + x.metric->description() + ">"; });

  m.def("family", &family, py::arg("name"), R"doc(
The metric family ``name`` with its parameters as keyword arguments (missing ones take their defaults), e.g.
family("kerr-newman", a=0.95). The names and parameters are the CLI's (`conformesh discretize --list`,
metrics.families()). Raises InputError naming the family and the parameter for an unknown name or parameter or a
value out of range.)doc");
  m.def("families", &families,
        "Every family: a list of dicts {'name', 'summary', 'parameters': {name: (default, meaning)}}.");
  m.def("sampled", &sampled, py::arg("g_uu"), py::arg("g_uv"), py::arg("g_vv"), py::kw_only(), py::arg("chart"),
        py::arg("periodic_u") = false, py::arg("periodic_v") = false, py::arg("poles") = "none", R"doc(
A metric from samples on a regular grid, with exactly the conventions of the field files (docs/metrics.md §4):
arrays of shape (NV, NU), row j the v-node j, u varying along a row; chart = (u0, u1, v0, v1); nodes of a periodic
axis at u0 + i (u1 - u0) / NU, of other axes at u0 + i (u1 - u0) / (NU - 1) (ends included, at least 4);
poles="both" for a pole-to-pole sphere chart (0, 2 pi, 0, pi), u periodic, v-nodes cell-centred at (j + 1/2) pi / NV,
NU even. Interpolated by cubic B-splines. Raises InputError naming the array and index for NaN, a bad shape, or a
sample that is not positive definite.)doc");
  m.def("read_field", &readField, py::arg("path"), R"doc(
A sampled metric field file, as `--field` reads it: the text format, or HDF5 (datasets g_uu, g_uv, g_vv of shape
(NV, NU), attributes chart, periodic_u, periodic_v, poles); 'FILE.h5:/group' names a group.)doc");
  m.def("write_field", &writeField, py::arg("path"), py::arg("metric"), py::arg("nu"), py::arg("nv"),
        py::arg("group") = "/", R"doc(
Samples ``metric`` on an (nv, nu) grid (pole-to-pole for sphere charts) and writes it as a field file that
`--field` and read_field read: HDF5 for .h5/.hdf5 (in ``group``), the text format otherwise.)doc");
}

}  // namespace conformesh::python
