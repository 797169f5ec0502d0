// sweep_command.cpp — `conformesh sweep SPEC.json -o DIR`: every case of a sweep specification (surfaces × parameters
// × options × ε or vertex counts) remeshed and checked, one record per case in DIR, one table, per-group convergence
// orders and plots; resumable, with a per-case time limit; on MPI when launched by mpirun / srun (docs/sweeps.md).
// Parsing and printing only: the sweep engine is refine/pipeline/sweep_*. Exit status 0 when every case is ok, 1 (an
// error line) when a case failed or timed out, 2 for a bad spec or option (the message printed by rank 0 only).
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/pipeline/sweep_run.h"
#include "conformesh/refine/pipeline/sweep_state.h"

namespace conformesh::apps {

namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  std::string spec, dir;
  double caseTimeout = 0;
  int threads = 0;
  std::string shard = "0/1";
  double progressInterval = 5;
  bool retryFailed = false, tableOnly = false, list = false, noPlot = false, json = false;
};

std::string selfPath() {
  char buf[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  return n > 0 ? std::string(buf, static_cast<size_t>(n)) : "conformesh";
}

void parseShard(const std::string& s, refine::SweepRunOptions& o) {
  int k = -1, n = 0;
  char tail = 0;
  if (std::sscanf(s.c_str(), "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 0 || k >= n)
    throw InputError("sweep: --shard: expected K/N with 0 <= K < N (e.g. 0/4), found '" + s + "'");
  o.shardIndex = k;
  o.shardCount = n;
}

// Draws each group's plots with scripts/plot_convergence.py, as `convergence` does, through temporary names.
std::vector<std::string> drawPlots(const refine::SweepTable& t) {
  const std::string script = fs::exists(CONFORMESH_INSTALLED_PLOT_SCRIPT) ? CONFORMESH_INSTALLED_PLOT_SCRIPT
                                                                          : CONFORMESH_SOURCE_PLOT_SCRIPT;
  const std::string python = scriptInterpreter();  // CMake's CONFORMESH_PYTHON (cli_common.h)
  std::vector<std::string> written;
  for (const std::string& file : t.groupFiles) {
    const std::string prefix = (fs::path(file).parent_path() / fs::path(file).stem()).string();
    const std::string tmp = refine::temporaryNameFor(prefix);
    const std::string cmd = python + " '" + script + "' '" + file + "' '" + tmp + "' >/dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) {
      progress("plots skipped: `" + cmd + "` failed (needs python3-matplotlib); the tables are written");
      return written;
    }
    for (const char* s : {"_fig10.png", "_fig11.png", "_fig12.png"})
      if (fs::exists(tmp + s)) {
        fs::rename(tmp + s, prefix + s);
        written.push_back(prefix + s);
      }
  }
  return written;
}

int run(const SweepArgs& a) {
  const bool root = refine::launcherRank() == 0;
  refine::SweepSpec spec;
  refine::SweepRunOptions o;
  try {
    spec = refine::readSweepSpec(a.spec);
    o.dir = a.dir;
    o.caseTimeout = a.caseTimeout;
    o.threads = a.threads;
    o.retryFailed = a.retryFailed;
    o.progressInterval = a.progressInterval;
    parseShard(a.shard, o);
    if (const std::string e = o.validate(); !e.empty()) throw InputError(e);
  } catch (const InputError& e) {
    if (root) std::fprintf(stderr, "conformesh: error: %s\n", e.what());
    return kExitUsage;
  }
  if (a.list) {
    if (!root) return 0;
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& c : spec.cases) {
      nlohmann::json j = c.inputsJson();
      j["id"] = c.id;
      j["index"] = c.index;
      cases.push_back(j);
    }
    printJson(cases);
    return 0;
  }
  o.producer = {{"binary", selfPath()},
                {"version", CONFORMESH_VERSION},
                {"mpi_build", refine::sweepHasMpi()},
                {"case_timeout", a.caseTimeout},
                {"spec", fs::path(a.spec).filename().string()}};
  o.progress = [](const std::string& s) { progress(s); };
  refine::SweepOutcome out;
  if (a.tableOnly) {
    if (!root) return 0;
    out.table = refine::writeSweepTable(spec, a.dir);
  } else {
    out = refine::runSweep(spec, o);
    if (!out.root) return 0;
  }
  const refine::SweepTable& t = out.table;
  std::vector<std::string> written = t.written;
  if (!a.noPlot)
    for (const std::string& p : drawPlots(t)) written.push_back(p);
  if (a.json) {
    printJson({{"cases", t.total},
               {"ok", t.ok},
               {"failed", t.failed},
               {"timeout", t.timeout},
               {"missing", t.missing},
               {"skipped", out.skipped},
               {"ran", out.ran},
               {"ranks", out.ranks},
               {"seconds", out.seconds},
               {"orders", t.orders},
               {"written", written}});
  } else {
    std::printf("%s: %d cases: %d ok, %d failed, %d timeout, %d without a record; this run computed %d (%d skipped as "
                "finished) on %d rank%s in %.1f s\n",
                a.spec.c_str(), t.total, t.ok, t.failed, t.timeout, t.missing, out.ran, out.skipped, out.ranks,
                out.ranks == 1 ? "" : "s", out.seconds);
    auto order = [](const nlohmann::json& x) {
      char b[32] = "-";  // fewer than two distinct points
      if (x.is_number()) std::snprintf(b, sizeof b, "%.3f", x.get<double>());
      return std::string(b);
    };
    for (const auto& g : t.orders)
      if (!g["orders"].is_null())
        std::printf("  %-28s %zu levels: e_G ~ R^%s, mean R ~ V^%s, |area error| ~ R^%s\n",
                    g["group"].get<std::string>().c_str(), g["ok_levels"].get<size_t>(),
                    order(g["orders"]["e_G_vs_mean_circumradius"]).c_str(),
                    order(g["orders"]["mean_circumradius_vs_vertices"]).c_str(),
                    order(g["orders"]["area_error_vs_mean_circumradius"]).c_str());
    for (const auto& w : written) std::printf("written: %s\n", w.c_str());
  }
  if (t.failed + t.timeout > 0)
    throw InputError("sweep: " + std::to_string(t.failed) + " failed and " + std::to_string(t.timeout) +
                     " timed-out case(s); their errors are in " + (fs::path(a.dir) / "table.csv").string());
  return 0;
}

}  // namespace

void registerSweepCommand(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* sub = app.add_subcommand("sweep", "Run a study of many remeshes from a JSON spec, resumable, on MPI");
  sub->footer(
      "SPEC.json: {\"studies\": [{\"input\": FAMILY | FILE | GLOB, \"params\": {\"a\": [0.5, 0.9]}, \"eps\": [0.1,\n"
      "0.05] (or \"vertices\": [1000, 2000]), \"options\": {\"smoothing\": 1}}]}; lists span a grid. Each case gets a\n"
      "stable id from what it means; DIR/cases/<id>/ holds its record.json and mesh.ply; DIR/table.csv, table.json,\n"
      "orders.json and groups/ gather them. A rerun with the same SPEC and DIR skips finished cases.\n"
      "Under MPI (mpirun -n N / srun) rank 0 hands out cases, largest first, to ranks 1..N-1.\n"
      "Exit status: 0 every case ok, 1 a case failed or timed out (the table is written), 2 a bad spec or option.\n"
      "Spec format, resumption, faults, Slurm: docs/sweeps.md.");
  sub->add_option("spec", a->spec, "The sweep specification (JSON; docs/sweeps.md)")->required();
  sub->add_option("-o,--output", a->dir, "Output folder DIR, created if missing; reused to resume (required)")
      ->required();
  sub->add_option("--case-timeout", a->caseTimeout,
                  "Wall-clock limit per case in seconds; the case's process is killed and recorded as timeout "
                  "(default 0: no limit)");
  sub->add_option("--threads", a->threads,
                  "OpenMP threads inside each case (default 0: the library's default serially, 1 per MPI worker)");
  sub->add_option("--shard", a->shard, "Run only the cases whose index % N == K, as K/N, for several jobs sharing DIR "
                                       "(default 0/1: all)");
  sub->add_flag("--retry-failed", a->retryFailed, "Also redo cases recorded as failed or timeout (default: keep them)");
  sub->add_flag("--table-only", a->tableOnly, "Only gather DIR's records into the table, orders and plots");
  sub->add_flag("--list", a->list, "Print the expanded cases with their ids as JSON and stop");
  sub->add_option("--progress-interval", a->progressInterval,
                  "Seconds between progress lines on stderr (rank 0; default 5)");
  sub->add_flag("--no-plot", a->noPlot, "Do not draw the per-group plots (scripts/plot_convergence.py)");
  sub->add_flag("--json", a->json, "Print the summary (counts, orders, files written) as JSON");
  sub->callback([a] {
    const int status = run(*a);
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace conformesh::apps
