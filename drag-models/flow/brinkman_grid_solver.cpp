// The solve of the MAC grid system (brinkman_grid_assembly.h): its sparse
// LU, cancellable during the factorisation, and the Picard (Oseen)
// iterations of the inertia term.
#include "flow/brinkman_grid_solver.h"
#include "flow/brinkman_grid_assembly.h"

#include <Eigen/SparseCore>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <sstream>
#include <stdexcept>

namespace hsrod {
namespace {

using brinkman_grid::Assembler;
using brinkman_grid::Stencils;
using brinkman_grid::discrete_inlet_profile;

// Eigen preconditioner interface around an existing sparse LU factorisation.
struct FrozenLuPreconditioner {
  const Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>* lu = nullptr;
  template <class M>
  FrozenLuPreconditioner& analyzePattern(const M&) { return *this; }
  template <class M>
  FrozenLuPreconditioner& factorize(const M&) { return *this; }
  template <class M>
  FrozenLuPreconditioner& compute(const M&) { return *this; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return lu->solve(b); }
  Eigen::ComputationInfo info() const { return Eigen::Success; }
};

using SparseLu = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;

// A factorisation that may be abandoned: matrix and LU live in shared state
// so that a worker thread left running after a cancellation never touches
// freed memory (it finishes on its own; the process normally exits).
struct LuJob {
  Eigen::SparseMatrix<double> matrix;
  SparseLu lu;
  std::atomic<bool> done{false};
};

void report(const SolveControl& control, const std::string& what) {
  if (control.progress) control.progress(what);
}

void check_cancel(const SolveControl& control, const char* where) {
  if (control.cancel_requested && control.cancel_requested())
    throw FlowSolveCancelled(std::string("background-flow grid solve interrupted ") + where);
}

// Factorises job->matrix; with a cancel callback the factorisation runs in
// a worker thread while this thread polls the callback every 20 ms, so a
// request is honoured within ~20 ms even inside a long factorisation.
void factorise(const std::shared_ptr<LuJob>& job, const SolveControl& control) {
  if (!control.cancel_requested) {
    job->lu.compute(job->matrix);
    job->done = true;
    return;
  }
  std::thread worker([job] {
    job->lu.compute(job->matrix);
    job->done = true;
  });
  while (!job->done) {
    if (control.cancel_requested()) {
      worker.detach();
      throw FlowSolveCancelled(
          "background-flow grid solve interrupted during the sparse LU factorisation");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  worker.join();
}

}  // namespace

BrinkmanGridSolution solve_brinkman_on_grid(const ChannelGeometry& geo, const MacGrid& grid,
                                            const BrinkmanGridSettings& settings) {
  if (grid.nx < 2 || grid.ny < 2 || !(grid.hx > 0.0) || !(grid.hy > 0.0))
    throw std::invalid_argument("solve_brinkman_on_grid: need at least 2 x 2 cells");
  const SolveControl& control = settings.control;
  check_cancel(control, "before it started");
  BrinkmanGridSolution sol;
  sol.grid = grid;
  sol.masks = classify_mac_nodes(geo, grid);
  const bool fitted = settings.exponential_wall_layer;
  const Stencils stencils(geo, grid, sol.masks, fitted);
  const std::vector<double> inlet =
      discrete_inlet_profile(stencils, grid, sol.masks, geo.width());
  std::vector<double> inlet_by_node(inlet);  // indexed by j = node % ny for column 0
  check_cancel(control, "while classifying the grid");

  const Assembler asm_(geo, grid, sol.masks, inlet_by_node, fitted);
  sol.unknowns = asm_.size();
  Eigen::VectorXd rhs, x;
  // Brinkman-Stokes system: one sparse LU.
  auto stokes = std::make_shared<LuJob>();
  asm_.assemble(Eigen::VectorXd::Zero(asm_.size()), 0.0, stokes->matrix, rhs);
  check_cancel(control, "while assembling");
  {
    std::ostringstream msg;
    msg << "factorising the Brinkman system: " << grid.nx << " x " << grid.ny << " cells, "
        << sol.unknowns << " unknowns";
    report(control, msg.str());
  }
  factorise(stokes, control);
  const SparseLu& lu = stokes->lu;
  if (lu.info() != Eigen::Success)
    throw std::runtime_error("solve_brinkman_on_grid: sparse LU factorisation failed: " +
                             stokes->lu.lastErrorMessage());
  x = lu.solve(rhs);
  Eigen::SparseMatrix<double>& a = stokes->matrix;

  // Inertia: Picard (Oseen) iterations. Each Oseen system is solved by
  // BiCGSTAB preconditioned with the Brinkman-Stokes LU above (the advection
  // is a small perturbation at the cell Reynolds numbers of these scenes), so
  // no further factorisation is needed; a fresh LU is the fallback.
  const double inertia = 1.2 * settings.inertia_reynolds;  // (6/5) Re_H
  if (inertia > 0.0) {
    Eigen::BiCGSTAB<Eigen::SparseMatrix<double>, FrozenLuPreconditioner> krylov;
    krylov.preconditioner().lu = &lu;
    krylov.setTolerance(1e-3 * settings.picard_tolerance);
    krylov.setMaxIterations(200);
    for (int iter = 1; iter <= settings.max_picard_iterations; ++iter) {
      check_cancel(control, "during the Picard iterations");
      asm_.assemble(x, inertia, a, rhs);
      krylov.compute(a);
      Eigen::VectorXd next = krylov.solveWithGuess(rhs, x);
      if (krylov.info() != Eigen::Success) {
        auto oseen = std::make_shared<LuJob>();
        oseen->matrix = a;
        factorise(oseen, control);
        if (oseen->lu.info() != Eigen::Success)
          throw std::runtime_error("solve_brinkman_on_grid: Oseen factorisation failed: " +
                                   oseen->lu.lastErrorMessage());
        next = oseen->lu.solve(rhs);
      }
      sol.picard_iterations = iter;
      sol.picard_change = asm_.velocity_change(next, x);
      x = next;
      {
        std::ostringstream msg;
        msg << "Picard iteration " << iter << ": max velocity change " << sol.picard_change
            << " U (tolerance " << settings.picard_tolerance << ")";
        report(control, msg.str());
      }
      if (sol.picard_change < settings.picard_tolerance) break;
      if (iter == settings.max_picard_iterations) {
        std::ostringstream msg;
        msg << "solve_brinkman_on_grid: Picard iterations for the inertia term did not converge "
               "in "
            << iter << " iterations (last change " << sol.picard_change
            << " U, Re_H = " << settings.inertia_reynolds << ")";
        throw std::runtime_error(msg.str());
      }
    }
  }
  asm_.scatter(x, sol);
  return sol;
}

}  // namespace hsrod
