// hsrod-sweep: one case of a sweep, run by a fresh LIGGGHTS instance in a
// forked child process of the calling (worker) process.
//
// Why a child: LIGGGHTS 3.8 has no recoverable error path. Error::all
// prints "ERROR: ..." to the screen and log, closes them and calls
// MPI_Finalize() and exit(1) (or MPI_Abort); Error::one calls MPI_Abort.
// Inside a worker of an MPI job either call would end or hang the whole
// sweep. The child runs the case on MPI_COMM_SELF (its own communicator:
// every communication of the instance stays inside the process) with its
// screen redirected to a log file; hsrod-sweep interposes MPI_Finalize and
// MPI_Abort through the MPI profiling interface (mpi_in_case_child.cpp), so
// in a child they end only the child. The parent reads the measures from a
// pipe, or, if the child died, the ERROR line from its log. A crash, a
// hang beyond --case-timeout or a memory blow-up of one case thus costs
// only that case. fork() is cheap (no new MPI process start).
#pragma once

#include "sweep_csv.h"

#include <chrono>
#include <memory>
#include <string>
#include <sys/types.h>
#include <utility>
#include <vector>

namespace hsrod::sweep {

struct Measure {
  std::string name;        // CSV column
  std::string expression;  // LIGGGHTS equal-style formula, evaluated after the script ends
};

// What every case of a sweep shares.
struct CaseSetup {
  std::string script_path;  // the prepared script (absolute path)
  std::string log_dir;      // case logs (absolute path); kept for failed cases
  bool keep_logs = false;   // keep the logs of successful cases too
  double timeout_seconds = 0.0;  // 0: no limit
  std::vector<Measure> measures;
  int rank = 0;             // the MPI rank running the cases (recorded in the CSV)
};

class CaseProcess {
 public:
  // Forks the child that runs case `id` with `-var name value` for each
  // swept variable (plus hsrod_sweep 1 and hsrod_case <id>).
  CaseProcess(const CaseSetup &setup, std::size_t id, const std::vector<std::pair<std::string, std::string>> &variables);
  ~CaseProcess();
  CaseProcess(const CaseProcess &) = delete;
  CaseProcess &operator=(const CaseProcess &) = delete;

  std::size_t id() const { return id_; }
  // Waits up to timeout_ms (-1: until it ends) for the case to end; true once it has.
  bool wait(int timeout_ms);
  // The case's outcome; only after wait() returned true.
  CaseOutcome outcome() const;

 private:
  void reap(bool timed_out);

  const CaseSetup &setup_;
  std::size_t id_;
  std::string log_path_;
  pid_t pid_ = -1;
  int pipe_fd_ = -1;
  std::string reply_;  // what the child wrote to the pipe
  bool finished_ = false;
  bool timed_out_ = false;
  int wait_status_ = 0;
  std::chrono::steady_clock::time_point start_;
  double wall_seconds_ = 0.0;
  double cpu_seconds_ = 0.0;  // user + system time of the child
};

// True inside a case's child process (read by the MPI interposition).
bool in_case_child();

}  // namespace hsrod::sweep
