// Chains with pair contacts off the band: rods of a contact cluster (merged
// into one rod, each rod's spheres consecutive) and a chain folded onto
// itself. The step's matrix is A = T + E M E^T: T block-tridiagonal (drag,
// bonds, wall contacts, the pair contacts' diagonal blocks and those between
// neighbouring spheres), M (6p x 6p) the contact blocks coupling spheres
// further apart in the numbering, E the unit columns of those p spheres.
// With x = T^-1 (b - E M y) and y = E^T x (the p spheres' unknowns),
//     (I + G M) y = E^T T^-1 b,   G = E^T T^-1 E   (6p x 6p),
// the capacitance form of the Sherman-Morrison-Woodbury identity (Hager,
// "Updating the inverse of a matrix", SIAM Review 31 (1989) 221, eq. 1.2),
// written without M^-1 (a contact block has no inverse). T^-1 E is cheap: T
// is block diagonal over the chain segments (a rod's spheres), so the
// column of sphere s fills only its own segment. Cost per step: one band
// elimination, 6 columns per coupled sphere over its segment, and a dense
// LU of 6p x 6p, against a sparse LU whose fill spans the cluster.
#include "dynamics/overdamped_rod_step_internal.h"

namespace hsrod {

namespace {

// A pair contact's 6x6 blocks of the step's matrix: (i, i), (j, j), (i, j),
// (j, i): Hertz stiffness on the translations and friction C / dt.
struct PairContactBlocks {
  Matrix6d ii, jj, ij, ji;
};

PairContactBlocks pair_contact_blocks(const SpherePairContact& c, double dt) {
  PairContactBlocks b;
  b.ii.setZero();
  b.ii.block<3, 3>(0, 0) = c.stiffness;
  b.jj = b.ii;
  b.ij = -b.ii;
  b.ji = -b.ii;
  if (c.rubbing) {
    b.ii += c.friction.block<6, 6>(0, 0) / dt;
    b.jj += c.friction.block<6, 6>(6, 6) / dt;
    b.ij += c.friction.block<6, 6>(0, 6) / dt;
    b.ji += c.friction.block<6, 6>(6, 0) / dt;
  }
  return b;
}

}  // namespace

// The blocks assembled (fused) and the wall contacts added: adds the pair
// contacts, factorises and solves; `rhs` holds the right-hand side.
const Eigen::VectorXd& OverdampedRodSolver::Workspace::solve_chain_with_contacts(double dt, int n) {
  band_linked.assign(n, 0);
  for (int k = 0; k + 1 < n; ++k) band_linked[k] = bonded(k, k + 1) ? 1 : 0;
  coupled_index.assign(n, -1);
  coupled_spheres.clear();
  off_band.clear();
  for (const SpherePairContact& c : pair_contacts) {
    const PairContactBlocks b = pair_contact_blocks(c, dt);
    diagonal[c.i] += b.ii;
    diagonal[c.j] += b.jj;
    if (c.j == c.i + 1 || c.i == c.j + 1) {
      const bool ascending = c.j == c.i + 1;
      const int first = ascending ? c.i : c.j;
      upper[first] += ascending ? b.ij : b.ji;
      lower[first + 1] += ascending ? b.ji : b.ij;
      band_linked[first] = 1;
      continue;
    }
    off_band.push_back({c.i, c.j, b.ij, b.ji});
    coupled_spheres.push_back(c.i);
    coupled_spheres.push_back(c.j);
  }
  solve_banded(n);  // rhs <- T^-1 b; factors of T kept
  kept = Kept::banded;
  ++statistics.banded_steps;
  if (off_band.empty()) return rhs;

  std::sort(coupled_spheres.begin(), coupled_spheres.end());
  coupled_spheres.erase(std::unique(coupled_spheres.begin(), coupled_spheres.end()), coupled_spheres.end());
  const int p = static_cast<int>(coupled_spheres.size());
  for (int a = 0; a < p; ++a) coupled_index[coupled_spheres[a]] = a;
  coupling.setZero(6 * p, 6 * p);
  for (const OffBandContact& c : off_band) {
    coupling.block<6, 6>(6 * coupled_index[c.i], 6 * coupled_index[c.j]) += c.ij;
    coupling.block<6, 6>(6 * coupled_index[c.j], 6 * coupled_index[c.i]) += c.ji;
  }
  // Columns T^-1 E_s over each coupled sphere's segment: forward elimination
  // from s (the entries before s stay zero), back substitution over the segment.
  coupled_segment.resize(p);
  coupled_column_start.resize(p + 1);
  coupled_column_start[0] = 0;
  for (int a = 0; a < p; ++a) {
    const int s = coupled_spheres[a];
    int first = s, last = s;
    while (first > 0 && band_linked[first - 1]) --first;
    while (last + 1 < n && band_linked[last]) ++last;
    coupled_segment[a] = {first, last};
    coupled_column_start[a + 1] = coupled_column_start[a] + (last - first + 1);
  }
  coupled_columns.resize(coupled_column_start[p]);
  for (int a = 0; a < p; ++a) {
    const int s = coupled_spheres[a], first = coupled_segment[a].first, last = coupled_segment[a].second;
    Matrix6d* y = coupled_columns.data() + coupled_column_start[a] - first;  // y[k]: sphere k's rows
    for (int k = first; k < s; ++k) y[k].setZero();
    y[s].setIdentity();
    block_lus[s].solve_block_in_place(y[s]);
    for (int k = s + 1; k <= last; ++k) {
      y[k].noalias() = -lower[k] * y[k - 1];
      block_lus[k].solve_block_in_place(y[k]);
    }
    for (int k = last - 1; k >= first; --k) y[k].noalias() -= upper[k] * y[k + 1];
  }
  // I + G M, G(t, s) = (T^-1 E_s) at sphere t when t is in s's segment.
  capacitance.setIdentity(6 * p, 6 * p);
  for (int a = 0; a < p; ++a)
    for (int t = 0; t < p; ++t) {
      const int sphere = coupled_spheres[t];
      if (sphere < coupled_segment[a].first || sphere > coupled_segment[a].second) continue;
      const Matrix6d& g = coupled_columns[coupled_column_start[a] + sphere - coupled_segment[a].first];
      for (int b = 0; b < p; ++b)
        if (!coupling.block<6, 6>(6 * a, 6 * b).isZero(0.0))
          capacitance.block<6, 6>(6 * t, 6 * b).noalias() += g * coupling.block<6, 6>(6 * a, 6 * b);
    }
  capacitance_lu.compute_in_place(capacitance);
  kept = Kept::chain_contacts;
  apply_off_band_correction(rhs);
  return rhs;
}

// x <- x - T^-1 E M y with (I + G M) y = E^T x, for x = T^-1 b.
void OverdampedRodSolver::Workspace::apply_off_band_correction(Eigen::VectorXd& x) const {
  const int p = static_cast<int>(coupled_spheres.size());
  coupled_work.resize(6 * p);
  for (int a = 0; a < p; ++a) coupled_work.segment<6>(6 * a) = x.segment<6>(6 * coupled_spheres[a]);
  capacitance_lu.solve_in_place(coupled_work);
  coupled_load.noalias() = coupling * coupled_work;
  for (int a = 0; a < p; ++a) {
    const int first = coupled_segment[a].first, last = coupled_segment[a].second;
    const Vector6d u = coupled_load.segment<6>(6 * a);
    if (u.isZero(0.0)) continue;
    for (int k = first; k <= last; ++k)
      x.segment<6>(6 * k).noalias() -= coupled_columns[coupled_column_start[a] + k - first] * u;
  }
}

}  // namespace hsrod
