// hsrod-sweep: regime maps and parameter studies of any hsrod input script
// on an MPI task farm. Doc: liggghts-package/doc/hsrod_sweep.txt.
//
//   hsrod-sweep --in in.pore --var E 15e3:15e6:*10 --var alpha 0,45,90
//               --measure outcome=c_shape[14] --measure x=c_shape[2] --output map.csv
//   mpirun -np 2 hsrod-sweep ...   (same command, cases shared by the ranks)

#include "sweep_csv.h"
#include "sweep_grid.h"
#include "sweep_script.h"
#include "task_farm.h"

#include <CLI/CLI.hpp>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace hsrod::sweep;

namespace {

struct Options {
  std::string script;
  std::vector<std::pair<std::string, std::string>> variables;  // name, specification
  std::vector<std::string> measures;                           // name=expression
  std::string output = "sweep.csv";
  std::string workdir;
  double case_timeout = 0.0;
  bool fresh = false;
  bool keep_logs = false;
  bool list = false;
};

std::vector<Measure> parse_measures(const std::vector<std::string> &specs) {
  std::vector<Measure> measures;
  for (const std::string &spec : specs) {
    const std::size_t eq = spec.find('=');
    Measure m{spec.substr(0, eq), eq == std::string::npos ? "" : spec.substr(eq + 1)};
    if (eq == std::string::npos || m.name.empty() || m.expression.empty() ||
        m.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      throw std::runtime_error("--measure '" + spec + "' must be name=formula (name: letters, digits, '_')");
    if (m.expression.find('"') != std::string::npos)
      throw std::runtime_error("--measure " + m.name + ": the formula must not contain '\"'");
    measures.push_back(m);
  }
  return measures;
}

std::string read_file(const std::string &path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read input script '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string format_seconds(double s) {
  char text[32];
  if (s < 120)
    std::snprintf(text, sizeof text, "%.1f s", s);
  else if (s < 7200)
    std::snprintf(text, sizeof text, "%.1f min", s / 60);
  else
    std::snprintf(text, sizeof text, "%.1f h", s / 3600);
  return text;
}

// Everything rank 0 checks and prepares before any case runs.
struct Prepared {
  std::string script_path, log_dir;
  std::vector<std::size_t> pending;
  std::size_t already_finished = 0;
};

Prepared prepare(const Options &options, const CaseGrid &grid, const std::vector<Measure> &measures,
                 std::unique_ptr<ResultFile> &results) {
  Prepared p;
  const fs::path output = fs::absolute(options.output);
  fs::path logs = output;
  logs.replace_extension();
  logs += "_logs";
  fs::create_directories(logs);
  p.log_dir = logs.string();
  std::vector<std::string> names;
  for (const SweptVariable &v : grid.variables()) names.push_back(v.name);
  const PreparedScript script = prepare_script(read_file(options.script), names);
  for (const std::string &name : script.not_defined)
    std::printf("hsrod-sweep: note: %s is not defined in %s; it is passed as -var %s (index style)\n", name.c_str(),
                options.script.c_str(), name.c_str());
  p.script_path = (logs / "sweep_script.in").string();
  const std::string tmp = p.script_path + ".tmp";
  {
    std::ofstream out(tmp);
    out << script.text;
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  fs::rename(tmp, p.script_path);
  // One sweep per result file at a time (exactly-once even if a killed job
  // left processes behind): an exclusive lock, released when the process ends.
  const std::string lock_path = output.string() + ".lock";
  const int lock_fd = ::open(lock_path.c_str(), O_WRONLY | O_CREAT, 0644);
  if (lock_fd < 0 || ::flock(lock_fd, LOCK_EX | LOCK_NB) != 0)
    throw std::runtime_error("another hsrod-sweep is writing " + output.string() + " (lock " + lock_path + ")");
  if (options.fresh) fs::remove(output);
  std::vector<std::string> measure_names;
  for (const Measure &m : measures) measure_names.push_back(m.name);
  results = std::make_unique<ResultFile>(output.string(), grid, measure_names);
  p.already_finished = results->finished().size();
  for (std::size_t id = 0; id < grid.size(); ++id)
    if (!results->finished().count(id)) p.pending.push_back(id);
  return p;
}

// Every rank's six accounting numbers on rank 0, sent point to point. Not
// MPI_Gather: its binomial tree makes some workers receive from others, and
// a worker still waiting on its last case's forked child shares its MPI
// shared-memory segments with that child, which can take the fragment meant
// for the parent (with 4 workers the sweep then hung in the gather about one
// run in four). Rank 0 runs no case when there are workers, so it is the one
// safe receiver.
std::vector<double> accounting_at_scheduler(const double (&mine)[6], int rank, int ranks) {
  constexpr int tag_accounting = 7;
  if (rank != 0) {
    MPI_Send(mine, 6, MPI_DOUBLE, 0, tag_accounting, MPI_COMM_WORLD);
    return {};
  }
  std::vector<double> all(6 * static_cast<std::size_t>(ranks));
  std::copy(mine, mine + 6, all.begin());
  for (int r = 1; r < ranks; ++r)
    MPI_Recv(&all[6 * static_cast<std::size_t>(r)], 6, MPI_DOUBLE, r, tag_accounting, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return all;
}

void broadcast(std::string &text) {
  long length = static_cast<long>(text.size());
  MPI_Bcast(&length, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
}

// Per rank: cases, busy wall, case CPU, own CPU; then the load-independent
// efficiency of the farm: summed busy time over (case-running ranks x the
// sweep's makespan), 1 when every worker had a case running from the first
// to the last moment (machine load slows busy time and makespan alike; a
// worker idle at the end, waiting for the others' last cases, counts).
void print_rank_accounting(const std::vector<double> &all, int ranks) {
  double makespan = 0.0, busy = 0.0, case_cpu = 0.0;
  for (int r = 0; r < ranks; ++r) makespan = std::max(makespan, all[6 * static_cast<std::size_t>(r) + 2]);
  int runners = 0;
  for (int r = 0; r < ranks; ++r) {
    const double *a = &all[6 * static_cast<std::size_t>(r)];
    const bool runs_cases = ranks == 1 || r > 0;
    if (!runs_cases) {
      std::printf("hsrod-sweep: rank %d (scheduler): %.0f row(s) written, own CPU %.3g s in the %.4g s sweep\n", r, a[0],
                  a[4], makespan);
      continue;
    }
    std::printf("hsrod-sweep: rank %d: %.0f case(s), busy %.4g s of the %.4g s sweep (%.1f %%), case CPU %.4g s, own "
                "CPU %.3g s\n", r, a[0], a[1], makespan, makespan > 0 ? 100.0 * a[1] / makespan : 0.0, a[3], a[4]);
    ++runners;
    busy += a[1];
    case_cpu += a[3];
  }
  std::printf("hsrod-sweep: busy fraction %.2f %% (summed case wall %.4g s / (%d case-running rank(s) x %.4g s)); "
              "summed case CPU %.4g s\n", makespan > 0 ? 100.0 * busy / (runners * makespan) : 0.0, busy, runners,
              makespan, case_cpu);
}

// --case-timeout: finite seconds >= 0 (CLI::NonNegativeNumber lets nan
// through, which then meant no limit). "" when valid, else the message.
std::string check_case_timeout(std::string &text) {
  const std::string expected = "--case-timeout must be a finite number of seconds >= 0 (0: none), got " + text;
  try {
    std::size_t used = 0;
    const double seconds = std::stod(text, &used);
    return used == text.size() && std::isfinite(seconds) && seconds >= 0.0 ? std::string() : expected;
  } catch (const std::exception &) {
    return expected;
  }
}

// The command line's options, with their help texts.
void add_options(CLI::App &app, Options &options) {
  app.add_option("-i,--in", options.script, "LIGGGHTS input script")->required();
  app.add_option("--var", options.variables,
                 "NAME VALUES: sweep variable NAME over VALUES = comma-separated items, each a value, "
                 "start:stop:step or start:stop:*factor (inclusive); repeat for a grid (last varies fastest)")
      ->required();
  app.add_option("--measure", options.measures,
                 "NAME=FORMULA: a CSV column, the LIGGGHTS equal-style FORMULA (e.g. c_shape[14], v_x) "
                 "evaluated after the script ends; repeatable");
  app.add_option("-o,--output", options.output, "result CSV (resumed if it holds rows of the same sweep)")
      ->capture_default_str();
  app.add_option("--workdir", options.workdir, "working directory of the cases (default: the current one)");
  app.add_option("--case-timeout", options.case_timeout, "wall seconds after which a case is killed and failed (0: none)")
      ->check(CLI::Validator(check_case_timeout, "SECONDS >= 0"));
  app.add_flag("--fresh", options.fresh, "delete an existing result file and start over");
  app.add_flag("--keep-logs", options.keep_logs, "keep the screen log of every case (failed cases always keep theirs)");
  app.add_flag("--list", options.list, "print the cases and exit");
}

// One CSV column per name: a measure must not shadow another column.
void check_columns(const std::vector<SweptVariable> &swept, const std::vector<Measure> &measures) {
  std::set<std::string> columns = {"case", "status", "error", "wall_s", "cpu_s", "rank"};
  for (const SweptVariable &v : swept)
    if (!columns.insert(v.name).second) throw std::runtime_error("--var " + v.name + " is given twice");
  for (const Measure &m : measures)
    if (!columns.insert(m.name).second)
      throw std::runtime_error("--measure " + m.name + ": a column of that name exists (a swept variable, another "
                               "measure, or one of case, status, error, wall_s, cpu_s, rank); rename the measure");
}

// --list: the cases, one line each (rank 0).
void print_cases(const CaseGrid &grid) {
  std::printf("case");
  for (const SweptVariable &v : grid.variables()) std::printf(",%s", v.name.c_str());
  std::printf("\n");
  for (std::size_t id = 0; id < grid.size(); ++id) {
    std::printf("%zu", id);
    for (const std::string &value : grid.values_of(id)) std::printf(",%s", value.c_str());
    std::printf("\n");
  }
}

// The pending cases on the task farm: rank 0 appends each finished case's
// row and prints its progress, then every rank's accounting and the totals.
void run_cases(const Options &options, const CaseGrid &grid, const std::vector<Measure> &measures,
               const Prepared &prepared, ResultFile *results, int rank, int ranks) {
  CaseSetup setup;
  setup.script_path = prepared.script_path;
  setup.log_dir = prepared.log_dir;
  setup.keep_logs = options.keep_logs;
  setup.timeout_seconds = options.case_timeout;
  setup.measures = measures;
  setup.rank = rank;

  const std::size_t total = grid.size();
  const int workers = ranks > 1 ? ranks - 1 : 1;  // rank 0 only schedules when there are workers
  if (rank == 0)
    std::printf("hsrod-sweep: %zu cases, %zu already in %s, %zu to run on %d worker(s) (%d MPI rank(s))\n", total,
                prepared.already_finished, options.output.c_str(), prepared.pending.size(), workers, ranks);
  const auto start = std::chrono::steady_clock::now();
  std::size_t done_now = 0, failed_now = 0;
  double case_seconds = 0.0, case_cpu_seconds = 0.0;
  double record_seconds = 0.0;  // rank 0's time per finished case: row append, progress line, fsync share
  auto last_sync = std::chrono::steady_clock::now();
  const auto on_finished = [&](std::size_t id, const CaseOutcome &outcome) {
    const auto record_start = std::chrono::steady_clock::now();
    results->append(csv_row(grid, id, outcome));
    ++done_now;
    if (!outcome.ok) ++failed_now;
    case_seconds += outcome.wall_seconds;
    case_cpu_seconds += outcome.cpu_seconds;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t remaining = prepared.pending.size() - done_now;
    const double eta = elapsed / static_cast<double>(done_now) * static_cast<double>(remaining);
    std::printf("[%zu/%zu] case %zu %s in %.3g s (%.3g s CPU, rank %d)%s%s | elapsed %s, ETA %s\n",
                prepared.already_finished + done_now, total, id, outcome.ok ? "ok" : "FAILED", outcome.wall_seconds,
                outcome.cpu_seconds, outcome.rank, outcome.ok ? "" : ": ", outcome.ok ? "" : outcome.error.c_str(),
                format_seconds(elapsed).c_str(), format_seconds(eta).c_str());
    const auto now = std::chrono::steady_clock::now();
    if (now - last_sync > std::chrono::seconds(1) || done_now == prepared.pending.size()) {
      results->sync();  // group fsync: see sweep_csv.h
      last_sync = now;
    }
    record_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - record_start).count();
  };
  const FarmReport farm = run_task_farm(grid, setup, prepared.pending, on_finished);
  // Per-rank accounting on rank 0: cases, busy and elapsed wall, case CPU, own CPU.
  const double mine[6] = {static_cast<double>(farm.run), farm.busy_seconds, farm.elapsed_seconds,
                          farm.case_cpu_seconds, farm.own_cpu_seconds, 0.0};
  const std::vector<double> all = accounting_at_scheduler(mine, rank, ranks);
  if (rank == 0) {
    print_rank_accounting(all, ranks);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double n = done_now ? static_cast<double>(done_now) : 1.0;
    std::printf("hsrod-sweep: finished %zu case(s) (%zu failed) in %s wall; per case: %.3g s wall and %.3g s CPU "
                "in its process, %.3g s of sweep wall time; all %zu cases in %s\n",
                done_now, failed_now, format_seconds(elapsed).c_str(), case_seconds / n, case_cpu_seconds / n,
                elapsed / n, total, options.output.c_str());
    std::printf("hsrod-sweep: scheduler: %.3g ms per finished case to write its row, print progress and fsync "
                "(at most once a second)\n",
                1e3 * record_seconds / n);
  }
}

}  // namespace

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  Options options;
  CLI::App app{"hsrod-sweep: runs an hsrod input script over a grid of variable values as an MPI task farm, "
               "one CSV row per finished case (resumable). See liggghts-package/doc/hsrod_sweep.txt."};
  add_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    const int code = rank == 0 ? app.exit(e) : (e.get_exit_code() ? 1 : 0);
    MPI_Finalize();
    return code;
  }

  int status = 0;
  std::string error;
  std::vector<SweptVariable> swept;
  std::vector<Measure> measures;
  std::unique_ptr<CaseGrid> grid;
  std::unique_ptr<ResultFile> results;
  Prepared prepared;
  try {
    for (const auto &[name, spec] : options.variables) swept.push_back({name, parse_values(name, spec)});
    grid = std::make_unique<CaseGrid>(swept);
    measures = parse_measures(options.measures);
    check_columns(swept, measures);
    if (rank == 0 && !options.list) prepared = prepare(options, *grid, measures, results);
  } catch (const std::exception &e) {
    status = 1;
    error = e.what();
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (status != 0) {
    if (rank == 0) std::fprintf(stderr, "hsrod-sweep: ERROR: %s\n", error.c_str());
    MPI_Finalize();
    return 1;
  }
  if (options.list) {
    if (rank == 0) print_cases(*grid);
    MPI_Finalize();
    return 0;
  }
  broadcast(prepared.script_path);
  broadcast(prepared.log_dir);
  if (!options.workdir.empty() && chdir(options.workdir.c_str()) != 0) {
    std::fprintf(stderr, "hsrod-sweep: ERROR: rank %d cannot enter --workdir '%s'\n", rank, options.workdir.c_str());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  run_cases(options, *grid, measures, prepared, results.get(), rank, ranks);
  MPI_Finalize();
  return 0;
}
