// Signal handling of the hsrod executable (installed by its main; in the
// styles' library so that a style stopped by a signal exits as documented).
//   SIGINT / SIGTERM: the run stops at the next step (LIGGGHTS'
//     SignalHandler::request_quit, which the background-flow solve also
//     polls), without writing LIGGGHTS' restart_forced_liggghts_<step>.data
//     into the working directory; a second signal quits at once. The
//     process then ends with an ERROR line and exit code 128 + signal.
//   SIGUSR1: writes a restart file (restart_forced_liggghts_<step>.data) at
//     the next step and runs on (LIGGGHTS' own handler) - on request only.
#pragma once

namespace hsrod {

// Installs the handlers above. Call before MPI_Init.
void install_run_signal_handlers();
// The SIGINT/SIGTERM number received so far, 0 if none.
int quit_signal_received();
// Exit code of a process stopped by that signal, 128 + signal as a shell
// reports it (SIGINT when the handlers are not installed, e.g. in-process).
int quit_exit_code();

}  // namespace hsrod
