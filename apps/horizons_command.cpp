// horizons_command.cpp — `conformesh horizons SERIES -o DIR`: a time series of horizon shape files, each remeshed as
// `remesh --horizon` does, one step per case of the sweep engine (its own process, a record per step, resumable), then
// one table ordered by time (DIR/series.csv, DIR/series.json) and a plot against time (scripts/plot_horizon_series.py).
// Also `conformesh generate horizon-series`, the Kerr–Schild test series. Parsing and printing only: the series is
// refine/pipeline/horizon_series.h. Exit status 0 every step ok, 1 a step failed (the table is written, the error in
// its row), 2 a bad option or SERIES. Details: docs/cli.md#horizons, docs/horizons.md §5c.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/pipeline/horizon_series.h"
#include "conformesh/refine/pipeline/sweep_run.h"
#include "conformesh/refine/pipeline/sweep_state.h"

namespace conformesh::apps {

namespace {

namespace fs = std::filesystem;

struct HorizonsArgs {
  std::string series, dir, spatialMetric;
  std::vector<std::string> params;
  double eps = 0.2, caseTimeout = 0;
  bool noCheck = false, noPlot = false, retryFailed = false, json = false;
};

// scripts/plot_horizon_series.py next to the convergence plot script (installed or the source tree's).
std::string drawPlot(const std::string& dir) {
  const fs::path installed = fs::path(CONFORMESH_INSTALLED_PLOT_SCRIPT).parent_path() / "plot_horizon_series.py";
  const fs::path source = fs::path(CONFORMESH_SOURCE_PLOT_SCRIPT).parent_path() / "plot_horizon_series.py";
  const std::string script = fs::exists(installed) ? installed.string() : source.string();
  const std::string png = (fs::path(dir) / "series.png").string(), tmp = refine::temporaryNameFor(png);
  const std::string cmd = scriptInterpreter() + " '" + script + "' '" + (fs::path(dir) / "series.json").string() +
                          "' '" + tmp + "' >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0 || !fs::exists(tmp) || fs::file_size(tmp) == 0) {
    fs::remove(tmp);
    progress("plot skipped: `" + cmd + "` failed (needs python3-matplotlib); the table is written");
    return "";
  }
  fs::rename(tmp, png);
  return png;
}

void printTable(const nlohmann::json& rows) {
  std::printf("%-5s %-10s %-7s %8s %16s %14s %12s %10s %10s %8s\n", "step", "time", "status", "vertices", "area",
              "M_irr", "spin", "e_G", "GB resid", "min ang");
  auto num = [](const nlohmann::json& v, const char* f) {
    char b[40] = "-";
    if (v.is_number()) std::snprintf(b, sizeof b, f, v.get<double>());
    return std::string(b);
  };
  for (const auto& r : rows) {
    std::printf("%-5d %-10s %-7s %8s %16s %14s %12s %10s %10s %8s\n", r["step"].get<int>(),
                num(r["time"], "%.6g").c_str(), r["status"].get<std::string>().c_str(), num(r["vertices"], "%.0f").c_str(),
                num(r["area"], "%.10f").c_str(), num(r["irreducible_mass"], "%.10f").c_str(),
                num(r["spin"], "%.9f").c_str(), num(r["e_G"], "%.3e").c_str(),
                num(r["gauss_bonnet_residual"], "%.1e").c_str(), num(r["min_angle_deg"], "%.1f").c_str());
    if (r["status"] != "ok") std::printf("      error: %s\n", r["error"].is_string() ? r["error"].get<std::string>().c_str() : "");
  }
}

int run(const HorizonsArgs& a) {
  refine::HorizonSeriesOptions o;
  refine::SweepRunOptions so;
  std::vector<refine::HorizonStep> steps;
  refine::SweepSpec spec;
  try {
    o.series = a.series;
    o.spatialMetric = a.spatialMetric;
    o.params = parseParameters(a.params);
    o.epsilon = a.eps;
    o.check = !a.noCheck;
    if (const std::string e = o.validate(); !e.empty()) throw InputError(e);
    so.dir = a.dir;
    so.caseTimeout = a.caseTimeout;
    so.retryFailed = a.retryFailed;
    if (const std::string e = so.validate(); !e.empty()) throw InputError("horizons" + e.substr(e.find(':')));
    steps = refine::listHorizonSteps(a.series);
    spec = refine::horizonSeriesSpec(steps, o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "conformesh: error: %s\n", e.what());
    return kExitUsage;
  }
  so.producer = {{"command", "horizons"}, {"version", CONFORMESH_VERSION}, {"series", a.series}};
  so.progress = [](const std::string& s) { progress(s); };
  progress("horizons: " + std::to_string(steps.size()) + " steps in " + a.series);
  const refine::SweepOutcome out = refine::runSweepSerial(spec, so);
  const nlohmann::json rows = refine::horizonSeriesRows(steps, spec, a.dir);
  int failed = 0;
  for (const auto& r : rows) failed += r["status"] != "ok";
  const nlohmann::json run = {{"command", "horizons"},  {"version", CONFORMESH_VERSION},
                              {"series", a.series},     {"spatial_metric", a.spatialMetric.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.spatialMetric)},
                              {"params", o.params},     {"eps", a.eps},
                              {"check", o.check},       {"steps", rows.size()},
                              {"failed", failed},       {"ran", out.ran},
                              {"skipped", out.skipped}, {"seconds", out.seconds}};
  std::vector<std::string> written;
  try {
    written = refine::writeHorizonSeriesTable(rows, run, a.dir);
  } catch (const InputError& e) {
    throw OutputRejected(e.what());
  }
  if (!a.noPlot)
    if (const std::string png = drawPlot(a.dir); !png.empty()) written.push_back(png);
  if (a.json) {
    printJson({{"rows", rows}, {"run", run}, {"written", written}});
  } else {
    printTable(rows);
    std::printf("%zu steps: %zu ok, %d failed; this run computed %d (%d kept from an earlier run) in %.1f s\n",
                rows.size(), rows.size() - failed, failed, out.ran, out.skipped, out.seconds);
    for (const auto& w : written) std::printf("written: %s\n", w.c_str());
  }
  if (failed > 0)
    throw InputError("horizons: " + std::to_string(failed) + " of " + std::to_string(rows.size()) +
                     " step(s) failed; their errors are in their rows of " + (fs::path(a.dir) / "series.csv").string());
  return 0;
}

struct HorizonSeriesArgs {
  std::string dir, hdf5;
  bool sampled = false;
  int steps = 10, lMax = 16;
  double a0 = 0.5, a1 = 0.9, mass = 1, dt = 10;
};

void registerGenerateSeries(CLI::App& app) {
  CLI::App* gen = app.get_subcommand("generate");
  auto g = std::make_shared<HorizonSeriesArgs>();
  CLI::App* sub = gen->add_subcommand("horizon-series",
                                      "Kerr-Schild horizon shape files with a slowly changing spin, for `horizons`");
  sub->footer("Writes DIR/t<time>.json: the horizon r = r+ of Kerr-Schild coordinates, the spheroid with semi-axes\n"
              "sqrt(r+^2 + a^2), r+, fitted at --lmax, a rising linearly from --a0 to --a1, time k*--dt, with keys\n"
              "spatial_metric, params and time. Details: docs/cli.md#horizons");
  sub->add_option("-o,--output", g->dir, "Output folder DIR, created if missing (required unless --hdf5)");
  sub->add_option("--hdf5", g->hdf5, "Write one HDF5 file FILE.h5 instead, one group /t<time> per step");
  sub->add_flag("--sampled", g->sampled,
                "With --hdf5: the radius on a 2(lmax+1) x 4(lmax+1) Gauss-Legendre x uniform grid, not coefficients");
  sub->add_option("--steps", g->steps, "Number of shape files (default 10)");
  sub->add_option("--a0", g->a0, "Spin a of the first step (default 0.5)");
  sub->add_option("--a1", g->a1, "Spin a of the last step (default 0.9)");
  sub->add_option("--M", g->mass, "Mass M (default 1)");
  sub->add_option("--dt", g->dt, "Time between steps (default 10)");
  sub->add_option("--lmax", g->lMax, "l_max of the Strahlkorper fit (default 16)");
  sub->callback([g] {
    std::vector<std::string> files;
    try {
      if (g->dir.empty() == g->hdf5.empty())
        throw InputError("generate horizon-series: give one of -o DIR (JSON files) and --hdf5 FILE.h5");
      if (g->sampled && g->hdf5.empty()) throw InputError("generate horizon-series: --sampled needs --hdf5");
      if (!g->hdf5.empty()) {
        files = refine::writeKerrHorizonSeriesHdf5(g->hdf5, g->steps, g->a0, g->a1, g->mass, g->dt, g->lMax,
                                                   g->sampled);
        std::printf("wrote %zu horizon shape groups (%s) in %s (a = %g ... %g, M = %g, l_max = %d)\n", files.size(),
                    g->sampled ? "sampled radius" : "coefficients", g->hdf5.c_str(), g->a0, g->a1, g->mass, g->lMax);
        return;
      }
      files = refine::writeKerrHorizonSeries(g->dir, g->steps, g->a0, g->a1, g->mass, g->dt, g->lMax);
    } catch (const InputError& e) {
      std::fprintf(stderr, "conformesh: error: %s\n", e.what());
      throw CLI::RuntimeError(kExitUsage);
    }
    std::printf("wrote %zu horizon shape files in %s (a = %g ... %g, M = %g, l_max = %d)\n", files.size(),
                g->dir.c_str(), g->a0, g->a1, g->mass, g->lMax);
  });
}

}  // namespace

void registerHorizonsCommand(CLI::App& app) {
  auto a = std::make_shared<HorizonsArgs>();
  CLI::App* sub = app.add_subcommand("horizons", "Remesh a time series of horizon shape files into one table and plot");
  sub->footer(
      "SERIES: a folder of Strahlkorper shape files (*.json, docs/horizons.md §2), or one HDF5 file with a shape\n"
      "group per step. A step's time is its \"time\" key (attribute), else the last number in its file (group) name.\n"
      "Each step runs in its own process with its record in DIR/cases/<id>/;\n"
      "a rerun with the same SERIES and DIR keeps the finished steps. DIR/series.csv, series.json, series.png.\n"
      "Exit status: 0 every step ok, 1 a step failed (its row has the error; the others complete), 2 a bad option.\n"
      "Details: docs/cli.md#horizons");
  sub->add_option("series", a->series, "Folder of horizon shape files (*.json), or FILE.h5 of shape groups")->required();
  sub->add_option("-o,--output", a->dir, "Output folder DIR, created if missing; reused to resume (required)")
      ->required();
  sub->add_option("--spatial-metric", a->spatialMetric,
                  "3-metric of every step: kerr-schild, schwarzschild-isotropic, flat or FILE.h5[:/group] "
                  "(default: each file's \"spatial_metric\", else kerr-schild)");
  sub->add_option("--param", a->params, "k=v of the spatial metric, over each file's \"params\" (repeatable)");
  sub->add_option("--eps", a->eps, "Target edge length of every remesh (default 0.2)");
  sub->add_flag("--no-check", a->noCheck, "Skip the Gaussian curvature measure check (no e_G column values)");
  sub->add_option("--case-timeout", a->caseTimeout, "Wall-clock limit per step in seconds (default 0: none)");
  sub->add_flag("--retry-failed", a->retryFailed, "Redo steps recorded as failed (default: keep their rows)");
  sub->add_flag("--no-plot", a->noPlot, "Do not draw series.png (scripts/plot_horizon_series.py)");
  sub->add_flag("--json", a->json, "Print the rows and the run metadata as JSON");
  sub->callback([a] {
    const int status = run(*a);
    if (status != 0) throw CLI::RuntimeError(status);
  });
  registerGenerateSeries(app);
}

}  // namespace conformesh::apps
