#include "run_signals.h"

#include "signal_handling.h"

#include <csignal>
#include <cstdlib>
#include <cstring>

#include <unistd.h>

namespace hsrod {
namespace {

volatile std::sig_atomic_t g_quit_signal = 0;

void write_message(int fd, const char *text) {
  // Async-signal-safe output; a failed write has nowhere to be reported.
  ssize_t ignored = ::write(fd, text, std::strlen(text));
  (void)ignored;
}

// LIGGGHTS' int_handler would also request a restart file on every Ctrl-C
// (SignalHandler::enable_restart_writing): only the quit request is set here.
void quit_handler(int signum) {
  if (g_quit_signal != 0) {
    write_message(STDERR_FILENO, "\nSecond SIGINT/SIGTERM caught: quitting now.\n");
    std::_Exit(128 + signum);
  }
  g_quit_signal = signum;
  LAMMPS_NS::SignalHandler::request_quit = true;
  write_message(STDOUT_FILENO, "\nSIGINT/SIGTERM caught: stopping at the next step (no restart file written).\n");
}

void install(int signum, void (*handler)(int)) {
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = handler;
  sigaction(signum, &action, nullptr);
}

}  // namespace

void install_run_signal_handlers() {
  install(SIGINT, quit_handler);
  install(SIGTERM, quit_handler);
  install(SIGUSR1, LAMMPS_NS::SignalHandler::usr1_handler);
}

int quit_signal_received() { return g_quit_signal; }

int quit_exit_code() { return 128 + (g_quit_signal != 0 ? static_cast<int>(g_quit_signal) : SIGINT); }

}  // namespace hsrod
