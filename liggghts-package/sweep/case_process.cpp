#include "case_process.h"

#include "input.h"
#include "lammps.h"
#include "variable.h"

#include "style_registration.h"

#include <mpi.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace hsrod::sweep {
namespace {

bool case_child = false;

// Exit codes of a child (the parent reports how a case died).
constexpr int child_ok = 0;
constexpr int child_setup_failed = 90;  // could not redirect output

void write_text(int fd, const std::string &text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

// The child: run the script, evaluate the measures, report them on the pipe.
[[noreturn]] void run_child(const CaseSetup &setup, std::size_t id,
                            const std::vector<std::pair<std::string, std::string>> &variables,
                            const std::string &log_path, int pipe_fd) {
  case_child = true;
  // Die with the worker (a killed sweep leaves no orphans running cases).
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  const int log_fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (log_fd < 0 || ::dup2(log_fd, STDOUT_FILENO) < 0 || ::dup2(log_fd, STDERR_FILENO) < 0)
    ::_exit(child_setup_failed);
  ::close(log_fd);

  std::vector<std::string> words = {"hsrod-sweep", "-in", setup.script_path, "-log", "none"};
  for (const auto &[name, value] : variables) words.insert(words.end(), {"-var", name, value});
  words.insert(words.end(), {"-var", "hsrod_sweep", "1", "-var", "hsrod_case", std::to_string(id)});
  std::vector<char *> argv;
  for (std::string &w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  auto *lmp = new LAMMPS_NS::LAMMPS(static_cast<int>(words.size()), argv.data(), MPI_COMM_SELF);
  hsrod::register_styles(lmp);
  lmp->input->file();
  // Measures: equal-style formulas after the script (an error here, e.g. a
  // compute that is not current, fails the case with LIGGGHTS' message).
  std::string reply = "ok\n";
  for (std::size_t k = 0; k < setup.measures.size(); ++k) {
    std::string name = "hsrod_sweep_measure_" + std::to_string(k);
    std::string command = "variable " + name + " equal \"" + setup.measures[k].expression + "\"";
    lmp->input->one(command.c_str());
    const double value = lmp->input->variable->compute_equal(lmp->input->variable->find(name.data()));
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    reply += std::string(text) + "\n";
  }
  std::fflush(nullptr);
  write_text(pipe_fd, reply);
  ::close(pipe_fd);
  ::_exit(child_ok);  // no MPI_Finalize, no destructors: the parent owns MPI
}

std::string last_error_line(const std::string &log_path) {
  std::ifstream log(log_path);
  std::string line, error, last;
  while (std::getline(log, line)) {
    if (line.rfind("ERROR", 0) == 0) error = line;
    if (!line.empty()) last = line;
  }
  return error.empty() ? last : error;
}

}  // namespace

bool in_case_child() { return case_child; }

CaseProcess::CaseProcess(const CaseSetup &setup, std::size_t id,
                         const std::vector<std::pair<std::string, std::string>> &variables)
    : setup_(setup), id_(id), log_path_(setup.log_dir + "/case" + std::to_string(id) + ".log") {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
  std::fflush(nullptr);  // the child must not inherit and re-print buffered output
  start_ = std::chrono::steady_clock::now();
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid_ == 0) {
    ::close(fds[0]);
    run_child(setup, id, variables, log_path_, fds[1]);
  }
  ::close(fds[1]);
  pipe_fd_ = fds[0];
}

CaseProcess::~CaseProcess() {
  if (!finished_ && pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  if (pipe_fd_ >= 0) ::close(pipe_fd_);
}

bool CaseProcess::wait(int timeout_ms) {
  if (finished_) return true;
  const auto deadline_reached = [&] {
    if (setup_.timeout_seconds <= 0.0) return false;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > setup_.timeout_seconds;
  };
  const auto call_start = std::chrono::steady_clock::now();
  while (true) {
    // Wake at the case's deadline (to the millisecond), at the latest every
    // 0.2 s; timeouts below the old fixed 0.2 s slice were not enforced.
    int slice = -1;
    if (setup_.timeout_seconds > 0.0) {
      const double left_s =
          setup_.timeout_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      slice = std::clamp(static_cast<int>(std::ceil(left_s * 1000.0)), 1, 200);
    }
    if (timeout_ms >= 0) {
      const int left = timeout_ms - static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                                         std::chrono::steady_clock::now() - call_start)
                                                         .count());
      if (left <= 0) return false;
      slice = slice < 0 ? left : std::min(slice, left);
    }
    pollfd request{pipe_fd_, POLLIN, 0};
    const int ready = ::poll(&request, 1, slice);
    if (ready < 0 && errno != EINTR) throw std::runtime_error(std::string("poll failed: ") + std::strerror(errno));
    if (ready > 0) {
      char buffer[4096];
      const ssize_t n = ::read(pipe_fd_, buffer, sizeof buffer);
      if (n > 0) {
        reply_.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0 || errno != EINTR) {  // end of file: the child has ended (or closed the pipe)
        reap(false);
        return true;
      }
    }
    if (deadline_reached()) {
      ::kill(pid_, SIGKILL);
      reap(true);
      return true;
    }
  }
}

void CaseProcess::reap(bool timed_out) {
  rusage usage{};
  while (::wait4(pid_, &wait_status_, 0, &usage) < 0 && errno == EINTR) {
  }
  cpu_seconds_ = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                 1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  finished_ = true;
  timed_out_ = timed_out;
  wall_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const bool ok = !timed_out && WIFEXITED(wait_status_) && WEXITSTATUS(wait_status_) == child_ok &&
                  reply_.rfind("ok\n", 0) == 0;
  if (ok && !setup_.keep_logs) ::unlink(log_path_.c_str());
}

CaseOutcome CaseProcess::outcome() const {
  CaseOutcome outcome;
  outcome.wall_seconds = wall_seconds_;
  outcome.cpu_seconds = cpu_seconds_;
  outcome.rank = setup_.rank;
  outcome.ok = !timed_out_ && WIFEXITED(wait_status_) && WEXITSTATUS(wait_status_) == child_ok &&
               reply_.rfind("ok\n", 0) == 0;
  if (outcome.ok) {
    std::size_t begin = 3;
    for (std::size_t k = 0; k < setup_.measures.size(); ++k) {
      const std::size_t end = reply_.find('\n', begin);
      outcome.measures.push_back(reply_.substr(begin, end - begin));
      begin = end + 1;
    }
    return outcome;
  }
  outcome.measures.assign(setup_.measures.size(), "");
  const std::string log_line = last_error_line(log_path_);
  if (timed_out_) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", setup_.timeout_seconds);
    outcome.error = std::string("timed out after --case-timeout ") + limit + " s";
  } else if (WIFSIGNALED(wait_status_)) {
    outcome.error = "killed by signal " + std::to_string(WTERMSIG(wait_status_)) + " (" +
                    strsignal(WTERMSIG(wait_status_)) + ")";
    if (!log_line.empty()) outcome.error += "; last output: " + log_line;
  } else if (WIFEXITED(wait_status_) && WEXITSTATUS(wait_status_) == child_setup_failed) {
    outcome.error = "cannot write the case log " + log_path_;
  } else {
    outcome.error = log_line.empty() ? "exit status " + std::to_string(WEXITSTATUS(wait_status_)) : log_line;
  }
  outcome.error += " (log: " + log_path_ + ")";
  return outcome;
}

}  // namespace hsrod::sweep
