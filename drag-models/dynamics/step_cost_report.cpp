#include "dynamics/step_cost_report.h"

#include <algorithm>
#include <cstdio>

namespace hsrod {

double StepCost::other_seconds() const {
  return std::max(0.0, total_seconds - drag_seconds - solver.bond_seconds - solver.contact_seconds -
                           solver.solve_seconds);
}

std::string StepCost::report() const {
  const double per_step = steps > 0 ? total_seconds / static_cast<double>(steps) : 0.0;
  const double per_sphere_step = sphere_steps > 0 ? total_seconds / static_cast<double>(sphere_steps) : 0.0;
  const auto share = [this](double seconds) { return total_seconds > 0.0 ? 100.0 * seconds / total_seconds : 0.0; };
  char line[512];
  std::snprintf(line, sizeof(line),
                "%ld steps, %.3g us per step, %.3g us per sphere-step: drag model %.0f %%, bonds %.0f %%, "
                "contacts %.0f %%, solve %.0f %%, other (gather, guard, scatter) %.0f %%; %ld solves "
                "(%ld block-tridiagonal, %ld sparse, %ld dense)",
                steps, 1e6 * per_step, 1e6 * per_sphere_step, share(drag_seconds), share(solver.bond_seconds),
                share(solver.contact_seconds), share(solver.solve_seconds), share(other_seconds()), solver.steps,
                solver.banded_steps, solver.sparse_steps, solver.dense_steps);
  return line;
}

void accumulate(OverdampedSolverStatistics& a, const OverdampedSolverStatistics& b) {
  a.steps += b.steps;
  a.sphere_steps += b.sphere_steps;
  a.bond_seconds += b.bond_seconds;
  a.contact_seconds += b.contact_seconds;
  a.solve_seconds += b.solve_seconds;
  a.banded_steps += b.banded_steps;
  a.sparse_steps += b.sparse_steps;
  a.dense_steps += b.dense_steps;
  a.capacitance_steps += b.capacitance_steps;
  a.capacitance_fallbacks += b.capacitance_fallbacks;
  a.capacitance_handovers += b.capacitance_handovers;
  a.sparse_capacitance_steps += b.sparse_capacitance_steps;
}

OverdampedSolverStatistics difference(const OverdampedSolverStatistics& a, const OverdampedSolverStatistics& b) {
  OverdampedSolverStatistics d;
  d.steps = a.steps - b.steps;
  d.sphere_steps = a.sphere_steps - b.sphere_steps;
  d.bond_seconds = a.bond_seconds - b.bond_seconds;
  d.contact_seconds = a.contact_seconds - b.contact_seconds;
  d.solve_seconds = a.solve_seconds - b.solve_seconds;
  d.banded_steps = a.banded_steps - b.banded_steps;
  d.sparse_steps = a.sparse_steps - b.sparse_steps;
  d.dense_steps = a.dense_steps - b.dense_steps;
  d.capacitance_steps = a.capacitance_steps - b.capacitance_steps;
  d.capacitance_fallbacks = a.capacitance_fallbacks - b.capacitance_fallbacks;
  d.capacitance_handovers = a.capacitance_handovers - b.capacitance_handovers;
  d.sparse_capacitance_steps = a.sparse_capacitance_steps - b.sparse_capacitance_steps;
  return d;
}

}  // namespace hsrod
