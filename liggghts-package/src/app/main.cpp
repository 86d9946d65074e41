// hsrod: LIGGGHTS 3.8 (Debian's libliggghts) with this package's styles.
// Same command line as liggghts (-in, -var, -log, -echo, -screen, ...),
// serial or under mpirun. Mirrors LIGGGHTS' own main(), plus the style
// registration between creating the instance and reading the input.

#include "input.h"
#include "lammps.h"
#include "update.h"

#include "run_signals.h"
#include "screen_mode.h"
#include "style_registration.h"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <string>
#include <typeinfo>

using namespace LAMMPS_NS;

int main(int argc, char **argv) {
  // Ctrl-C / SIGTERM end the run cleanly at the next step, as in liggghts,
  // but without a restart file in the working directory (run_signals.h).
  hsrod::install_run_signal_handlers();

  // Line-buffered screen output: an ERROR printed just before MPI_Abort
  // must reach a pipe or a log collector, not die in a buffer.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  MPI_Init(&argc, &argv);
  // The one exception guard at the glue boundary: the styles turn the
  // physics' exceptions into error->all() messages; anything that still
  // escapes (std::bad_alloc, a bug) ends the run with an ERROR line and a
  // non-zero exit code on every rank, never an abort with a core dump.
  int rc = 0;
  try {
    LAMMPS *lammps = new LAMMPS(argc, argv, MPI_COMM_WORLD);
    hsrod::register_styles(lammps);
    // -var hsrod_screen FILE: screen a resolved CFD-DEM script (screen/screen_mode.h).
    const std::string screen_scene = hsrod::screen::requested_scene(argc, argv);
    if (!screen_scene.empty() && !hsrod::screen::begin(lammps, screen_scene)) {
      rc = 1;
    } else {
      lammps->input->file();
      if (!screen_scene.empty()) hsrod::screen::report(lammps);
    }
    // A run cut short by a signal is not a success: a sweep or a script
    // must see it (output files are complete up to the step it stopped at).
    if (const int signum = hsrod::quit_signal_received()) {
      int me = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &me);
      if (me == 0)
        std::fprintf(stdout, "ERROR: hsrod: stopped by signal %d (%s) at step %lld; the input script was not finished\n",
                     signum, signum == 2 ? "SIGINT" : "SIGTERM", static_cast<long long>(lammps->update->ntimestep));
      rc = 128 + signum;
    }
    delete lammps;
  } catch (const std::exception &e) {
    std::fprintf(stdout, "ERROR: hsrod: unexpected exception (%s): %s\n", typeid(e).name(), e.what());
    std::fprintf(stderr, "ERROR: hsrod: unexpected exception (%s): %s\n", typeid(e).name(), e.what());
    std::fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, 1);
  } catch (...) {
    std::fprintf(stdout, "ERROR: hsrod: unexpected non-standard exception\n");
    std::fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return rc;
}
