// sweep_run.cpp — the serial sweep, the progress lines and the choice of scheduler (see sweep_run.h).
#include "conformesh/refine/pipeline/sweep_run.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/pipeline/sweep_state.h"
#ifdef CONFORMESH_WITH_MPI
#include "pipeline/sweep_mpi.h"
#endif

namespace conformesh::refine {

namespace fs = std::filesystem;

namespace {
const char* envOf(std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (const char* v = std::getenv(n)) return v;
  return nullptr;
}
std::string clock(double s) {
  const long t = static_cast<long>(s + 0.5);
  char b[32];
  if (t >= 3600)
    std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  else
    std::snprintf(b, sizeof b, "%ld:%02ld", t / 60, t % 60);
  return b;
}
}  // namespace

bool launchedUnderMpi() {
  return envOf({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"}) != nullptr;
}

int launcherRank() {
  const char* r = envOf({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"});
  return r ? std::atoi(r) : 0;
}

bool sweepHasMpi() {
#ifdef CONFORMESH_WITH_MPI
  return true;
#else
  return false;
#endif
}

SweepProgress::SweepProgress(int toRun, int skipped, const SweepRunOptions& options)
    : toRun_(toRun), skipped_(skipped), interval_(options.progressInterval), say_(options.progress),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void SweepProgress::finished(const std::string& status) {
  ++done_;
  (status == "ok" ? ok_ : status == "timeout" ? timeout_ : failed_)++;
}

void SweepProgress::tick(int running, bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!say_ || (!force && std::chrono::duration<double>(now - last_).count() < interval_)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string eta = "?";
  if (done_ > 0) eta = clock(elapsed / done_ * (toRun_ - done_));
  say_("sweep: " + std::to_string(done_) + "/" + std::to_string(toRun_) + " done (" + std::to_string(ok_) + " ok, " +
       std::to_string(failed_) + " failed, " + std::to_string(timeout_) + " timeout), " + std::to_string(running) +
       " running, " + std::to_string(skipped_) + " skipped as finished; elapsed " + clock(elapsed) + ", ETA " + eta);
}

std::vector<const SweepCase*> casesToRun(const SweepSpec& spec, const SweepRunOptions& options, int& skipped) {
  std::vector<const SweepCase*> out;
  skipped = 0;
  const SweepDir dir{options.dir};
  for (const SweepCase& c : spec.cases) {
    if (c.index % options.shardCount != options.shardIndex) continue;
    const auto record = readRecord(dir, c.id);
    if (record && (!options.retryFailed || (*record)["status"] == "ok")) {
      ++skipped;
      continue;
    }
    out.push_back(&c);
  }
  return out;
}

SweepOutcome runSweep(const SweepSpec& spec, const SweepRunOptions& options) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError(e);
#ifdef CONFORMESH_WITH_MPI
  if (launchedUnderMpi()) return runSweepMpi(spec, options);
#else
  if (const char* n = envOf({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}); n && std::atoi(n) > 1)
    throw InputError("sweep: launched on " + std::string(n) +
                     " MPI ranks, but this conformesh was built without MPI (CONFORMESH_WITH_MPI=OFF); every rank "
                     "would run every case. Rebuild with libopenmpi-dev installed, or run one process");
#endif
  return runSweepSerial(spec, options);
}

SweepOutcome runSweepSerial(const SweepSpec& spec, const SweepRunOptions& options) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError(e);
  const auto t0 = std::chrono::steady_clock::now();
  fs::create_directories(fs::path(options.dir) / "cases");
  writeFileAtomically((fs::path(options.dir) / "spec.json").string(), spec.document.dump(1) + "\n");
  SweepOutcome out;
  const std::vector<const SweepCase*> todo = casesToRun(spec, options, out.skipped);
  SweepProgress progress(static_cast<int>(todo.size()), out.skipped, options);
  for (const SweepCase* c : todo) {
    const nlohmann::json record = runSweepCase(*c, options, 0, [&] { progress.tick(1); });
    progress.finished(record["status"]);
    ++out.ran;
  }
  progress.tick(0, true);
  out.table = writeSweepTable(spec, options.dir);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace conformesh::refine
