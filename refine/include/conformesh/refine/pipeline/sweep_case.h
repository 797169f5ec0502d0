// sweep_case.h — running one case of a sweep: the remesh and its curvature check through the library (remeshMetric or
// remeshMesh, exactly as `conformesh remesh` runs them), its mesh written into DIR/cases/<id>/, and its record. The
// case runs in a child process (fork): a case that throws, crashes or exceeds the time limit is recorded as such and
// the caller goes on. Writes only inside DIR/cases/<id>/.
#pragma once

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/refine/pipeline/sweep_spec.h"
#include "conformesh/refine/pipeline/sweep_state.h"

namespace conformesh::refine {

struct SweepRunOptions {
  std::string dir;           // DIR
  double caseTimeout = 0;    // seconds of wall-clock time per case; 0 = no limit
  int threads = 0;           // OpenMP threads inside each case; 0 = the library's default
  bool retryFailed = false;  // redo cases whose record says failed or timeout (ok cases are always kept)
  int shardIndex = 0, shardCount = 1;  // this job runs the cases whose index % shardCount == shardIndex
  double progressInterval = 5;         // seconds between progress lines (rank 0 / the serial process)
  nlohmann::json producer;             // what made the records: binary, version, command line (copied into each)
  std::function<void(const std::string&)> progress;  // progress lines; nullptr = silent

  // What is wrong with these options ("" when valid).
  std::string validate() const;
};

// Runs case `c` in this process and returns its record: {"id", "status": "ok" | "failed", "error", "error_kind":
// "input" | "convergence" | "internal", "where" (the last pipeline stage reached), "case" (SweepCase::inputsJson),
// "producer", "wall_seconds"} plus every key of `remesh --json` (and "smooth_area" for metrics, "output"). Stage
// messages go to `stage`. Writes the mesh files, not the record. Never throws for the case's own errors.
nlohmann::json computeSweepCase(const SweepCase& c, const SweepRunOptions& options,
                                const std::function<void(const std::string&)>& stage);

// Runs case `c` in a child process under options.caseTimeout: logs the attempt, cleans the case's folder, and writes
// DIR/cases/<id>/record.json (atomically) — from the child when it finishes, else from here with status "timeout"
// (the child is killed with SIGKILL) or "failed" (the child ended by a signal or without a record). `tick` is called
// about ten times a second while the case runs. Returns the record.
nlohmann::json runSweepCase(const SweepCase& c, const SweepRunOptions& options, int rank,
                            const std::function<void()>& tick);

}  // namespace conformesh::refine
