// sweep_mpi.cpp — the MPI scheduler of a sweep (compiled only when CONFORMESH_WITH_MPI). Rank 0 computes nothing: it
// sorts the cases to run largest first (SweepCase::cost) and answers each worker's message — "ready", or the record
// of the case it just finished — with the index of the next case, or −1 when none is left. Each worker runs its case
// in a child process (sweep_case.cpp), which writes the record to DIR before the worker reports it, so the records
// of finished cases survive the death of any rank; a rerun redoes only the cases without a record. One message per
// case each way: rank 0's load is a probe, a receive of one record (a few kB) and a send of one integer per case.
#include "pipeline/sweep_mpi.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "conformesh/refine/pipeline/sweep_state.h"

namespace conformesh::refine {

namespace fs = std::filesystem;

namespace {

constexpr int kTagRecord = 1, kTagWork = 2;

SweepOutcome runScheduler(const SweepSpec& spec, const SweepRunOptions& options, int ranks) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepOutcome out;
  out.ranks = ranks;
  std::vector<const SweepCase*> todo = casesToRun(spec, options, out.skipped);
  std::stable_sort(todo.begin(), todo.end(), [](const SweepCase* a, const SweepCase* b) { return a->cost > b->cost; });
  SweepProgress progress(static_cast<int>(todo.size()), out.skipped, options);
  size_t next = 0;
  int active = ranks - 1, running = 0;
  std::string buffer;
  while (active > 0) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagRecord, MPI_COMM_WORLD, &flag, &st);
    if (!flag) {
      progress.tick(running);
      ::usleep(20000);
      continue;
    }
    int count = 0;
    MPI_Get_count(&st, MPI_CHAR, &count);
    buffer.resize(static_cast<size_t>(count));
    MPI_Recv(buffer.data(), count, MPI_CHAR, st.MPI_SOURCE, kTagRecord, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (count > 0) {  // a finished case's record (already in DIR)
      const nlohmann::json record = nlohmann::json::parse(buffer);
      progress.finished(record["status"]);
      --running;
      ++out.ran;
    }
    int index = -1;
    if (next < todo.size()) {
      index = todo[next++]->index;
      ++running;
    } else {
      --active;
    }
    MPI_Send(&index, 1, MPI_INT, st.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
  }
  progress.tick(0, true);
  out.table = writeSweepTable(spec, options.dir);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

void runWorker(const SweepSpec& spec, const SweepRunOptions& options, int rank) {
  std::string message;  // empty: ready for the first case
  for (;;) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kTagRecord, MPI_COMM_WORLD);
    int index = -1;
    MPI_Recv(&index, 1, MPI_INT, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) return;
    message = runSweepCase(spec.cases.at(static_cast<size_t>(index)), options, rank, nullptr).dump();
  }
}

}  // namespace

SweepOutcome runSweepMpi(const SweepSpec& spec, const SweepRunOptions& options) {
  int provided = 0, rank = 0, ranks = 1;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  SweepOutcome out;
  if (ranks == 1) {
    MPI_Finalize();
    // One rank: the serial sweep (runSweep does not take the MPI branch again once MPI is finalized).
    SweepRunOptions serial = options;
    out = runSweepSerial(spec, serial);
    return out;
  }
  if (rank == 0) {
    fs::create_directories(fs::path(options.dir) / "cases");
    writeFileAtomically((fs::path(options.dir) / "spec.json").string(), spec.document.dump(1) + "\n");
  }
  MPI_Barrier(MPI_COMM_WORLD);  // DIR exists before any worker writes into it
  if (rank == 0) {
    out = runScheduler(spec, options, ranks);
  } else {
    // Under MPI the ranks share the node's cores: one OpenMP thread per case unless asked otherwise.
    SweepRunOptions worker = options;
    if (worker.threads == 0) worker.threads = 1;
    runWorker(spec, worker, rank);
    out.root = false;
    out.ranks = ranks;
  }
  MPI_Finalize();
  return out;
}

}  // namespace conformesh::refine
