// hsrod-sweep: the MPI task farm. Rank 0 is the scheduler: it holds the
// queue of unfinished case IDs, hands the next one to whichever worker asks
// (dynamic scheduling: a slow, clogging case occupies one worker while the
// others keep taking cases), and is the only writer of the result file. The
// other ranks are workers: ask, run the case (CaseProcess), send the row,
// ask again. Messages carry only a case ID one way and a finished row the
// other: every rank derives a case's variables from its ID (CaseGrid).
//
// Rank 0 runs no cases when there are workers: a case's child process
// inherits its parent's MPI shared-memory segments, and its own progress
// engine (LIGGGHTS creates communicators) would take messages addressed to
// the parent out of them (measured: a worker's request vanished and the
// sweep hung). A worker is only ever sent a message in answer to its own
// request, i.e. while it has no child. The scheduler sleeps between polls
// (2 ms), so it costs no core: run N workers as `mpirun -np N+1`
// (`--oversubscribe` if N+1 exceeds Open MPI's slots). A single process
// (no mpirun, or -np 1) runs the cases itself, one after the other.
#pragma once

#include "case_process.h"
#include "sweep_csv.h"
#include "sweep_grid.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace hsrod::sweep {

struct FarmReport {
  std::size_t run = 0;     // cases run by this invocation
  std::size_t failed = 0;  // of which failed
  // This rank's accounting (load-independent parallel efficiency: a rank
  // is busy while a case of its own runs; idle time is scheduling, waiting
  // for work or for the last cases of other ranks).
  double busy_seconds = 0.0;      // summed wall time of the cases it ran [s]
  double case_cpu_seconds = 0.0;  // summed CPU time of those cases [s]
  double own_cpu_seconds = 0.0;   // CPU time of this process itself, children excluded [s]
  double elapsed_seconds = 0.0;   // wall time of run_task_farm on this rank [s]
};

// Called on rank 0 for every finished case, in the order they finish.
using OnFinished = std::function<void(std::size_t id, const CaseOutcome &outcome)>;

// Runs `pending` (on rank 0; ignored elsewhere) on all ranks of MPI_COMM_WORLD.
FarmReport run_task_farm(const CaseGrid &grid, const CaseSetup &setup, const std::vector<std::size_t> &pending,
                         const OnFinished &on_finished);

}  // namespace hsrod::sweep
