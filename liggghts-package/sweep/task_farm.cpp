#include "task_farm.h"

#include <mpi.h>

#include <chrono>
#include <deque>
#include <memory>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

namespace hsrod::sweep {
namespace {

constexpr int tag_result = 1;  // worker -> scheduler: "" (first request) or a finished case
constexpr int tag_task = 2;    // scheduler -> worker: case ID, or -1 = stop
constexpr int poll_ms = 2;     // rank 0's reaction time to a worker's message

std::vector<std::pair<std::string, std::string>> case_variables(const CaseGrid &grid, std::size_t id) {
  std::vector<std::pair<std::string, std::string>> variables;
  const std::vector<std::string> values = grid.values_of(id);
  for (std::size_t i = 0; i < values.size(); ++i) variables.emplace_back(grid.variables()[i].name, values[i]);
  return variables;
}

// Finished case as a message: "id|ok|wall|cpu|rank|error\x1f" + measures joined by '\x1f'.
std::string pack(std::size_t id, const CaseOutcome &o) {
  std::string text = std::to_string(id) + "\x1f" + (o.ok ? "1" : "0") + "\x1f" + std::to_string(o.wall_seconds) +
                     "\x1f" + std::to_string(o.cpu_seconds) + "\x1f" + std::to_string(o.rank) + "\x1f" + o.error;
  for (const std::string &m : o.measures) text += "\x1f" + m;
  return text;
}

std::size_t unpack(const std::string &text, std::size_t measures, CaseOutcome &o) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find('\x1f', begin);
    parts.push_back(text.substr(begin, end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  parts.resize(6 + measures);
  o.ok = parts[1] == "1";
  o.wall_seconds = std::stod(parts[2]);
  o.cpu_seconds = std::stod(parts[3]);
  o.rank = std::stoi(parts[4]);
  o.error = parts[5];
  o.measures.assign(parts.begin() + 6, parts.end());
  return std::stoul(parts[0]);
}

void send_task(int worker, long id) { MPI_Send(&id, 1, MPI_LONG, worker, tag_task, MPI_COMM_WORLD); }

void worker_loop(const CaseGrid &grid, const CaseSetup &setup, FarmReport &report) {
  std::string message;  // empty: first request
  while (true) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, tag_result, MPI_COMM_WORLD);
    long id = -1;
    MPI_Recv(&id, 1, MPI_LONG, 0, tag_task, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (id < 0) return;
    CaseProcess process(setup, static_cast<std::size_t>(id), case_variables(grid, static_cast<std::size_t>(id)));
    process.wait(-1);
    const CaseOutcome outcome = process.outcome();
    ++report.run;
    report.busy_seconds += outcome.wall_seconds;
    report.case_cpu_seconds += outcome.cpu_seconds;
    if (!outcome.ok) ++report.failed;
    message = pack(static_cast<std::size_t>(id), outcome);
  }
}

void scheduler_loop(const CaseGrid &grid, const CaseSetup &setup, const std::vector<std::size_t> &pending_ids,
                    const OnFinished &on_finished, FarmReport &report) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const bool runs_cases = ranks == 1;  // see task_farm.h: never with workers
  std::deque<std::size_t> pending(pending_ids.begin(), pending_ids.end());
  int active_workers = ranks - 1;
  std::unique_ptr<CaseProcess> local;  // rank 0's own case
  const auto finished = [&](std::size_t id, const CaseOutcome &outcome) {
    ++report.run;
    if (!outcome.ok) ++report.failed;
    on_finished(id, outcome);
  };
  while (active_workers > 0 || local || (runs_cases && !pending.empty())) {
    // Serve every worker that is waiting.
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, &waiting, &status);
    while (waiting) {
      int length = 0;
      MPI_Get_count(&status, MPI_CHAR, &length);
      std::string message(static_cast<std::size_t>(length), '\0');
      MPI_Recv(message.data(), length, MPI_CHAR, status.MPI_SOURCE, tag_result, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (!message.empty()) {
        CaseOutcome outcome;
        const std::size_t id = unpack(message, setup.measures.size(), outcome);
        finished(id, outcome);
      }
      if (!pending.empty()) {
        send_task(status.MPI_SOURCE, static_cast<long>(pending.front()));
        pending.pop_front();
      } else {
        send_task(status.MPI_SOURCE, -1);
        --active_workers;
      }
      MPI_Iprobe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, &waiting, &status);
    }
    // A single process runs the cases itself; waiting on its child is also the poll interval.
    if (runs_cases && !local && !pending.empty()) {
      const std::size_t id = pending.front();
      pending.pop_front();
      local = std::make_unique<CaseProcess>(setup, id, case_variables(grid, id));
    }
    if (local) {
      if (local->wait(active_workers > 0 ? poll_ms : -1)) {  // nobody to serve: just wait for the case
        const CaseOutcome outcome = local->outcome();
        report.busy_seconds += outcome.wall_seconds;
        report.case_cpu_seconds += outcome.cpu_seconds;
        finished(local->id(), outcome);
        local.reset();
      }
    } else {
      ::usleep(poll_ms * 1000);
    }
  }
}

}  // namespace

FarmReport run_task_farm(const CaseGrid &grid, const CaseSetup &setup, const std::vector<std::size_t> &pending,
                         const OnFinished &on_finished) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  FarmReport report;
  const auto own_cpu = [] {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  };
  const double cpu_start = own_cpu();
  const auto start = std::chrono::steady_clock::now();
  if (rank == 0)
    scheduler_loop(grid, setup, pending, on_finished, report);
  else
    worker_loop(grid, setup, report);
  report.own_cpu_seconds = own_cpu() - cpu_start;
  report.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace hsrod::sweep
