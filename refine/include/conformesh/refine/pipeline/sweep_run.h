// sweep_run.h — running a whole sweep: the cases of this job's shard that have no record yet (or failed ones with
// retryFailed), each in a child process with its time limit (sweep_case.h), then the table (sweep_table.h). Without
// MPI, or with one rank, the cases run in spec order in this process. Launched under MPI (mpirun, srun) in a build
// with CONFORMESH_WITH_MPI, rank 0 hands the cases out one at a time, largest first, to ranks 1..N−1, prints the
// progress, gathers their records and writes the table; it computes none itself (sweep_mpi.cpp). Progress lines on
// rank 0 at most every options.progressInterval seconds: done / running / failed, elapsed, estimated remaining time.
#pragma once

#include <chrono>
#include <string>

#include "conformesh/refine/pipeline/sweep_case.h"
#include "conformesh/refine/pipeline/sweep_spec.h"
#include "conformesh/refine/pipeline/sweep_table.h"

namespace conformesh::refine {

struct SweepOutcome {
  bool root = true;    // false on the worker ranks: they return after the last case, without a table
  int ranks = 1;       // MPI world size (1 without MPI)
  int skipped = 0;     // cases of this shard that already had a record
  int ran = 0;         // cases computed by this run
  double seconds = 0;  // wall-clock time of the run
  SweepTable table;    // rank 0 only
};

// Runs the sweep (see above). Throws InputError for invalid options, or when launched on several MPI ranks by a
// build without MPI (every rank would run every case).
SweepOutcome runSweep(const SweepSpec& spec, const SweepRunOptions& options);
// The serial sweep alone (one process, spec order), whatever the launcher.
SweepOutcome runSweepSerial(const SweepSpec& spec, const SweepRunOptions& options);

// True when this process was started by an MPI launcher (mpirun / mpiexec / srun set their rank variables), and its
// rank from those variables (0 otherwise), read before MPI is initialized.
bool launchedUnderMpi();
int launcherRank();
// True when this build has the MPI scheduler (CMake option CONFORMESH_WITH_MPI).
bool sweepHasMpi();

// The progress lines: "sweep: 7/12 done (6 ok, 1 failed, 0 timeout), 2 running, elapsed 0:41, ETA 0:30".
class SweepProgress {
 public:
  SweepProgress(int toRun, int skipped, const SweepRunOptions& options);
  void finished(const std::string& status);
  void tick(int running, bool force = false);

 private:
  int toRun_, skipped_, done_ = 0, ok_ = 0, failed_ = 0, timeout_ = 0;
  double interval_;
  std::function<void(const std::string&)> say_;
  std::chrono::steady_clock::time_point start_, last_;
};

// The cases of options' shard whose record is missing (or failed / timeout with retryFailed), in spec order; `skipped`
// counts the others of the shard.
std::vector<const SweepCase*> casesToRun(const SweepSpec& spec, const SweepRunOptions& options, int& skipped);

}  // namespace conformesh::refine
