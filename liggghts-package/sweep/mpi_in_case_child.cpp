// hsrod-sweep: MPI_Finalize and MPI_Abort as seen by LIGGGHTS, through the
// MPI profiling interface (MPI standard, "Profiling Interface": a program may
// define MPI_X and reach the library's through PMPI_X). Open MPI's libmpi
// exports both names, and libliggghts' calls bind to the executable's
// definitions. In a case's child process (case_process.h) LIGGGHTS' error
// path (Error::all: MPI_Finalize + exit(1); Error::one: MPI_Abort) ends only
// that child, with a distinct exit status; the ERROR line is already in its
// log. Everywhere else the calls pass straight through.

#include "case_process.h"

#include <mpi.h>

#include <cstdio>
#include <unistd.h>

namespace {
constexpr int child_error_all = 91;   // Error::all -> MPI_Finalize
constexpr int child_error_one = 92;   // Error::one -> MPI_Abort
}  // namespace

extern "C" int MPI_Finalize(void) {
  if (hsrod::sweep::in_case_child()) {
    std::fflush(nullptr);
    ::_exit(child_error_all);
  }
  return PMPI_Finalize();
}

extern "C" int MPI_Abort(MPI_Comm comm, int errorcode) {
  if (hsrod::sweep::in_case_child()) {
    std::fflush(nullptr);
    ::_exit(child_error_one);
  }
  return PMPI_Abort(comm, errorcode);
}
