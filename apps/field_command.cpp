// field_command.cpp — `conformesh field check FILE`: reads a sampled metric field (text or HDF5), runs the checks of
// intrinsic/metric/field_check.h and prints the surface it implies (topology, area, ∫K dA, smallest det g), as text or
// JSON. Parsing and printing only.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/metric/field_check.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"

namespace conformesh::apps {

namespace {

struct FieldCheckOptions {
  std::string input;
  bool json = false;
};

nlohmann::json orNull(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json toJson(const intrinsic::FieldCheckReport& r) {
  return {{"file", r.source},
          {"grid", {r.nu, r.nv}},
          {"shape", r.shape},
          {"genus", r.genus},
          {"boundary_loops", r.boundaryLoops},
          {"euler_characteristic", r.eulerCharacteristic},
          {"area", r.area},
          {"area_error_estimate", r.areaError},
          {"total_curvature", r.totalCurvature},
          {"total_curvature_error_estimate", r.totalCurvatureError},
          {"gauss_bonnet_2pi_chi", orNull(r.gaussBonnet)},
          {"min_det_g", r.minDetG},
          {"min_det_g_node", {r.minDetNodeU, r.minDetNodeV}},
          {"min_det_g_line", r.minDetLine},
          {"min_det_regular_form", orNull(r.minDetRegular)}};
}

void printText(const intrinsic::FieldCheckReport& r) {
  auto line = [](const char* name, const std::string& value) { std::printf("  %-28s %s\n", name, value.c_str()); };
  auto num = [](double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return std::string(buf);
  };
  std::printf("%s\n", r.source.c_str());
  line("grid", std::to_string(r.nu) + " x " + std::to_string(r.nv));
  line("implied surface", r.shape + " (genus " + std::to_string(r.genus) + ", " + std::to_string(r.boundaryLoops) +
                              " boundary loops, Euler characteristic " + std::to_string(r.eulerCharacteristic) + ")");
  line("area", num(r.area) + "  (quadrature error estimate " + num(r.areaError) + ")");
  std::string k = num(r.totalCurvature) + "  (error estimate " + num(r.totalCurvatureError) + ")";
  if (std::isfinite(r.gaussBonnet)) k += "; 2 pi chi = " + num(r.gaussBonnet);
  line("integral of K dA", k);
  line("smallest det g", num(r.minDetG) + " at grid node (" + std::to_string(r.minDetNodeU) + ", " +
                             std::to_string(r.minDetNodeV) + ")" +
                             (r.minDetLine > 0 ? ", line " + std::to_string(r.minDetLine) : ""));
  if (std::isfinite(r.minDetRegular)) line("smallest det g / sin^2 v", num(r.minDetRegular));
}

void runFieldCheck(const FieldCheckOptions& o) {
  progress("reading metric field " + o.input);
  const intrinsic::FieldCheckReport r = intrinsic::checkField(intrinsic::readSampledField(o.input));
  if (o.json)
    printJson(toJson(r));
  else
    printText(r);
}

}  // namespace

void registerFieldCommand(CLI::App& app) {
  CLI::App* field = app.add_subcommand("field", "Sampled metric fields: check what a field file describes");
  field->footer("Details: docs/cli.md#field-check");
  field->require_subcommand(1);
  auto o = std::make_shared<FieldCheckOptions>();
  CLI::App* check = field->add_subcommand(
      "check", "Check a sampled metric field and print its topology, area, integral of K dA and smallest det g");
  check->footer("Example: conformesh field check kerr095.txt --json\nDetails: docs/cli.md#field-check");
  check->add_option("file", o->input, "Field file: text or HDF5 (FILE.h5:/group)")->required();
  check->add_flag("--json", o->json, "Print the report as JSON (default: text)");
  check->callback([o] { runFieldCheck(*o); });
}

}  // namespace conformesh::apps
