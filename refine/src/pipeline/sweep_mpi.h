// sweep_mpi.h (private) — the MPI scheduler of runSweep, compiled only when CONFORMESH_WITH_MPI (sweep_mpi.cpp).
#pragma once

#include "conformesh/refine/pipeline/sweep_run.h"

namespace conformesh::refine {

// Initializes MPI, runs the sweep as rank 0 (scheduler) or a worker, finalizes MPI. With one rank, the serial run.
SweepOutcome runSweepMpi(const SweepSpec& spec, const SweepRunOptions& options);

}  // namespace conformesh::refine
