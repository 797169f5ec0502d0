// discretize_command.cpp — `conformesh discretize FAMILY [--param k=v ...] --resolution N -o t0.ply`, `--list`, and
// `--field FILE` for sampled metrics: builds T0 of a smooth metric (metric_discretization.h) and writes it as a PLY
// with edge lengths, chart coordinates u, v per vertex, and positions when the family has an embedding.
//
// Parsing and printing only: the metric comes from makeMetric() or SampledMetric, T0 from discretizeMetric(), the
// reference figures (smooth area, ∫K dA) from metric_quadrature.h.
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"

namespace conformesh::apps {

namespace {

struct DiscretizeArgs {
  std::string family, field, output;
  std::vector<std::string> params;
  int resolution = 8;
  bool list = false, chartLengths = false, json = false, ascii = false;
};

void printList(bool json) {
  nlohmann::json j = nlohmann::json::array();
  std::ostringstream s;
  for (const intrinsic::FamilyInfo& f : intrinsic::metricFamilies()) {
    nlohmann::json params = nlohmann::json::array();
    s << f.name << "\n  " << f.summary << "\n";
    for (const intrinsic::FamilyParameter& p : f.parameters) {
      s << "    " << p.name << " = " << p.defaultValue << "  (" << p.meaning << ")\n";
      params.push_back({{"name", p.name}, {"default", p.defaultValue}, {"meaning", p.meaning}});
    }
    j.push_back({{"name", f.name}, {"summary", f.summary}, {"parameters", params}});
  }
  if (json)
    printJson(j);
  else
    std::cout << s.str();
}

void run(const DiscretizeArgs& a) {
  if (a.list) {
    printList(a.json);
    return;
  }
  if (a.output.empty()) throw InputError("discretize: -o/--output is required (a .ply file)");
  const std::unique_ptr<intrinsic::SmoothMetric> metric = loadMetric("discretize", a.family, a.params, a.field);
  progress("discretizing " + metric->description() + " at resolution " + std::to_string(a.resolution));
  intrinsic::DiscretizationOptions opt;
  opt.resolution = a.resolution;
  opt.exactGeodesics = !a.chartLengths;
  intrinsic::DiscretizationReport rep;
  const intrinsic::MeshData data = intrinsic::discretizeMetric(*metric, opt, &rep);
  const intrinsic::IntrinsicTriangulation tri = intrinsic::toTriangulation(data);
  const intrinsic::CurvatureTotals ct = intrinsic::curvatureTotals(tri);
  progress("integrating the smooth area and total curvature for comparison");
  intrinsic::QuadratureOptions q;
  q.throwOnFailure = false;  // reference figures only: report their error estimates instead of failing
  const intrinsic::QuadratureResult area = intrinsic::metricArea(*metric, q);
  const intrinsic::QuadratureResult curv = intrinsic::metricTotalCurvature(*metric, q);
  intrinsic::WriteOptions w;
  if (a.ascii) w.plyEncoding = intrinsic::PlyEncoding::Ascii;
  intrinsic::writeMesh(data, a.output, w);
  progress("wrote " + a.output);

  const double t0Area = intrinsic::totalArea(tri);
  nlohmann::json j = {{"metric", metric->description()},
                      {"chart", intrinsic::toString(rep.shape)},
                      {"resolution", a.resolution},
                      {"vertices", rep.vertices},
                      {"edges", rep.edges},
                      {"faces", rep.faces},
                      {"euler_characteristic", tri.mesh.eulerCharacteristic()},
                      {"exact_geodesic_edges", rep.exactLengths},
                      {"min_angle_deg", rep.minAngle * 180 / M_PI},
                      {"max_angle_deg", rep.maxAngle * 180 / M_PI},
                      {"t0_area", t0Area},
                      {"smooth_area", area.value},
                      {"smooth_area_error_estimate", area.errorEstimate},
                      {"smooth_total_curvature", curv.value},
                      {"t0_total_curvature", ct.interiorDeficit + ct.boundaryTurning},
                      {"gauss_bonnet_residual", ct.gaussBonnetResidual},
                      {"positions", !data.positions.empty()},
                      {"output", a.output}};
  if (a.json) {
    printJson(j);
    return;
  }
  std::cout << "metric        " << metric->description() << "\n"
            << "chart         " << intrinsic::toString(rep.shape) << ", resolution " << a.resolution << "\n"
            << "T0            V=" << rep.vertices << " E=" << rep.edges << " F=" << rep.faces
            << "  chi=" << tri.mesh.eulerCharacteristic() << "\n"
            << "edge lengths  " << rep.exactLengths << " exact geodesic distances, " << rep.edges - rep.exactLengths
            << " chart-curve lengths\n"
            << "angles        " << rep.minAngle * 180 / M_PI << " .. " << rep.maxAngle * 180 / M_PI << " deg\n"
            << "area          T0 " << t0Area << "  smooth " << area.value << "  (rel. diff "
            << (t0Area - area.value) / area.value << ", O(h^2))\n"
            << "curvature     T0 deficits + boundary turning " << ct.interiorDeficit + ct.boundaryTurning
            << " = 2 pi chi (residual " << ct.gaussBonnetResidual << ")\n"
            << "              smooth int K dA " << curv.value
            << (rep.shape == intrinsic::ChartShape::Sphere || rep.shape == intrinsic::ChartShape::Torus
                    ? " (closed: = 2 pi chi)\n"
                    : " (with boundary: 2 pi chi minus the boundary's total geodesic curvature)\n")
            << "wrote         " << a.output << (data.positions.empty() ? " (edge lengths only, no embedding)" : "")
            << "\n";
}

}  // namespace

void registerDiscretizeCommand(CLI::App& app) {
  auto args = std::make_shared<DiscretizeArgs>();
  CLI::App* sub = app.add_subcommand("discretize", "Discretize a smooth metric into T0, the initial triangulation");
  sub->footer(
      "Example: conformesh discretize kerr-newman --param a=1 --resolution 16 -o kerr.ply\n"
      "Details: docs/cli.md#discretize");
  sub->add_option("family", args->family, "Metric family name (see --list)");
  sub->add_option("--param", args->params, "Family parameter KEY=VALUE (repeatable), e.g. --param a=0.9");
  addFieldOption(sub, args->field);
  sub->add_option("-r,--resolution", args->resolution,
                  "Sphere: frequency N (10N^2+2 vertices); disk: rings; grid: cells")
      ->capture_default_str();
  sub->add_option("-o,--output", args->output, "Output PLY file");
  sub->add_flag("--list", args->list, "List the families, their parameters, defaults and meaning");
  sub->add_flag("--chart-lengths", args->chartLengths, "Chart-curve lengths even where exact geodesics are known");
  sub->add_flag("--ascii", args->ascii, "Write ASCII PLY (default binary little-endian)");
  sub->add_flag("--json", args->json, "Print the summary (or the --list) as JSON");
  sub->callback([args] { run(*args); });
}

}  // namespace conformesh::apps
