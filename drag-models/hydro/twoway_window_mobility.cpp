// Level 4's footprint mobility: the 4-point footprints on the window, the
// window's response between them, the two-scale correction from the free
// lattices' Green's tables, and the obstruction resistance R_o it gives.
#include "hydro/twoway_window_model.h"
#include "common/math_constants.h"
#include "hydro/peskin_kernel.h"

#include <Eigen/Cholesky>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace hsrod {

namespace {

// Mean self-mobility of a footprint on a free lattice table of cells h [m]
// over sub-cell places and the two in-plane directions [m/(N s)].
double mean_lattice_self_mobility(const LatticeGreenTable& table, double h) {
  double sum = 0.0;
  int samples = 0;
  for (double ox : {0.0, 0.125, 0.25, 0.375, 0.5})
    for (double oy : {0.0, 0.125, 0.25, 0.375, 0.5}) {
      const LatticeFootprint f = table.footprint(Eigen::Vector3d(ox * h, oy * h, 0.0), Eigen::Vector2d::Zero());
      const Eigen::Matrix2d m = table.pair(f, f);
      sum += m(0, 0) + m(1, 1);
      samples += 2;
    }
  return sum / samples;
}

// Mean free-lattice mobility [m/(N s)] between the footprints of two
// spheres at x_i and x_j on a table of cells h [m], over sub-cell places of
// the pair (both shifted alike across one cell): a function of x_j - x_i
// alone, as the continuous Green's function is.
Eigen::Matrix2d mean_lattice_pair_mobility(const LatticeGreenTable& table, const Eigen::Vector3d& x_i,
                                           const Eigen::Vector3d& x_j, const Eigen::Vector2d& anchor, double h) {
  // Places per direction (the midpoint rule over one period of the lattice):
  // the pair term's sub-cell variation is its first harmonic, so 2 x 2
  // places remove it as 4 x 4 do (the dumbbell test's turn: the same to
  // 1e-3 deg per 200 um), at a quarter of the cost.
  constexpr int kPlaces = 2;
  Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
  for (int a = 0; a < kPlaces; ++a)
    for (int b = 0; b < kPlaces; ++b) {
      const Eigen::Vector3d shift((a + 0.5) / kPlaces * h, (b + 0.5) / kPlaces * h, 0.0);
      sum += table.pair(table.footprint(x_i + shift, anchor), table.footprint(x_j + shift, anchor));
    }
  return sum / (kPlaces * kPlaces);
}
}  // namespace

void TwoWayWindowModel::build_two_scale_tables() {
  near_reach_ = kNearReach * parameters_.sphere_diameter;
  fine_table_ = free_lattice_table(spacing_, kernel_width());
  window_table_ = free_lattice_table(window_spacing_, window_kernel_width());
  fine_self_mobility_ = mean_lattice_self_mobility(*fine_table_, spacing_);
}

// Self-mobility of one footprint on the lattice in free space (a planform
// far wider than the window), on the window the model places around a lone
// sphere, averaged over sub-cell positions and the two in-plane directions.
double TwoWayWindowModel::measure_free_self_mobility() const {
  const double h = window_spacing_, r = window_footprint_radius();
  const double half = margin_for(2.0 * r) + r;
  const double side = 2.0 * h * std::ceil(200.0 * half / h);  // planform corner on the lattice
  const ChannelGeometry open(side, side, parameters_.gap_height, -0.5 * side, -0.5 * side);
  const WindowLattice lattice =
      window_lattice(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), open, Eigen::Vector2i::Zero());
  const BrinkmanWindow window(open, lattice, parameters_.viscosity);
  double sum = 0.0;
  int samples = 0;
  for (double ox : {0.0, 0.25, 0.5})
    for (double oy : {0.0, 0.25, 0.5}) {
      RodGeometry sphere;
      sphere.sphere_diameter = parameters_.sphere_diameter;
      sphere.positions.push_back(Eigen::Vector3d(ox * spacing_, oy * spacing_, 0.0));
      const Eigen::MatrixXd m = footprint_mobility(sphere, open, window);
      sum += m(0, 0) + m(1, 1);
      samples += 2;
    }
  return sum / samples;
}

// Green's table of a free lattice of cells h [m] for footprints of kernel
// width w [m]: a wall-free window, uniform over the pairs' reach plus a
// footprint on each side and graded out to the model's margin beyond it.
std::shared_ptr<const LatticeGreenTable> TwoWayWindowModel::free_lattice_table(double h, double w) const {
  const double reach = near_reach_ + 4.0 * std::sqrt(2.0) * w + h;
  const int cells = static_cast<int>(std::ceil(reach / h)) + 2;
  const double margin = margin_for(2.0 * reach);
  const double side = 4.0 * (cells * h + margin);
  const ChannelGeometry open(side, side, parameters_.gap_height, -0.5 * side, -0.5 * side);
  const BrinkmanWindow window(open, free_lattice(h, cells, margin), parameters_.viscosity);
  return std::make_shared<const LatticeGreenTable>(window, w, reach);
}

double TwoWayWindowModel::near_weight(double distance) const {
  const double t = (distance - 0.5 * near_reach_) / (0.5 * near_reach_);
  if (t <= 0.0) return 1.0;
  if (t >= 1.0) return 0.0;
  return 1.0 - t * t * (3.0 - 2.0 * t);  // smoothstep
}

TwoWayWindowModel::Footprint TwoWayWindowModel::footprint(const BrinkmanWindow& window,
                                                          const Eigen::Vector3d& centre) const {
  Footprint f;
  const double w = window_kernel_width();
  const Eigen::Vector2d c = centre.head<2>();
  for (int a = 0; a < 2; ++a) {
    double total = 0.0;
    for (int k : window.nodes_near(c, 2.0 * std::sqrt(2.0) * w, a)) {
      const Eigen::Vector2d r = (window.nodes()[k].position - c) / w;
      const double weight = peskin_kernel(r.x()) * peskin_kernel(r.y());
      if (weight <= 0.0) continue;
      f.nodes[a].push_back(k);
      f.weights[a].push_back(weight);
      total += weight;
    }
    // Near a wall some nodes are missing: the force stays on the fluid ones.
    for (double& weight : f.weights[a]) weight /= total;
  }
  return f;
}

Eigen::VectorXd TwoWayWindowModel::fluid_node_forces(const BrinkmanWindow& window,
                                                     const std::vector<Eigen::Vector3d>& positions,
                                                     const Eigen::VectorXd& sphere_forces) const {
  if (sphere_forces.size() != 2 * static_cast<Eigen::Index>(positions.size()))
    throw std::invalid_argument("twoway: fluid_node_forces needs 2 force components per sphere");
  Eigen::VectorXd nodes = Eigen::VectorXd::Zero(window.unknowns());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Footprint f = footprint(window, positions[i]);
    for (int a = 0; a < 2; ++a)
      for (std::size_t k = 0; k < f.nodes[a].size(); ++k)
        nodes[f.nodes[a][k]] -= f.weights[a][k] * sphere_forces[2 * static_cast<Eigen::Index>(i) + a];
  }
  return nodes;
}

Eigen::MatrixXd TwoWayWindowModel::footprint_mobility(const RodGeometry& rod, const ChannelGeometry& geometry,
                                                      const BrinkmanWindow& window) const {
  const int n = rod.size();
  std::vector<Footprint> prints;
  prints.reserve(n);
  for (const auto& x : rod.positions) prints.push_back(footprint(window, x));
  // Unit forces spread over each footprint, the response averaged over the
  // footprints with the same weights (BrinkmanWindow::weighted_response).
  std::vector<BrinkmanWindow::NodeForces> forces(2 * n);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 2; ++a) {
      forces[2 * i + a].reserve(prints[i].nodes[a].size());
      for (std::size_t k = 0; k < prints[i].nodes[a].size(); ++k)
        forces[2 * i + a].emplace_back(prints[i].nodes[a][k], prints[i].weights[a][k]);
    }
  Eigen::MatrixXd mobility = window.weighted_response(forces, forces);
  if (two_scales()) {
    // The fine lattice's free-space mobility replaces the window lattice's
    // between nearby footprints (each footprint with itself and with its
    // neighbours within the near reach); what the window adds to its own
    // free-space mobility (the walls' reflection, the window's edges, the
    // far field) is kept.
    const Eigen::Vector2d anchor(geometry.x_lo(), geometry.y_lo());
    std::vector<LatticeFootprint> coarse;
    for (const auto& x : rod.positions) coarse.push_back(window_table_->footprint(x, anchor));
    // The fine pair terms, each pair once (reciprocity: M_ji = M_ij^T).
    std::vector<Eigen::Matrix2d> fine_pairs(static_cast<std::size_t>(n) * n);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (near_weight((rod.positions[i] - rod.positions[j]).head<2>().norm()) > 0.0) {
          fine_pairs[i * n + j] =
              mean_lattice_pair_mobility(*fine_table_, rod.positions[i], rod.positions[j], anchor, spacing_);
          fine_pairs[j * n + i] = fine_pairs[i * n + j].transpose();
        }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double weight = near_weight((rod.positions[i] - rod.positions[j]).head<2>().norm());
        if (weight <= 0.0) continue;
        // A footprint's fine-lattice mobility, with itself or with a
        // neighbour, varies by a fraction of a percent with its place
        // between the nodes; a rod's spheres sit at different places, so
        // that noise would make the two ends of a short rod unequal and turn
        // it (a 2-sphere rod ~3 deg over 200 um of travel by the self term,
        // up to 2.7 deg by the pair term at beta 0.85): both terms take
        // their mean over sub-cell places instead.
        const Eigen::Matrix2d fine_pair =
            i == j ? Eigen::Matrix2d(fine_self_mobility_ * Eigen::Matrix2d::Identity()) : fine_pairs[i * n + j];
        mobility.block<2, 2>(2 * i, 2 * j) += weight * (fine_pair - window_table_->pair(coarse[i], coarse[j]));
      }
  }
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 2; ++a)
      if (prints[i].nodes[a].empty()) {  // footprint off the grid: isolated sphere
        const int row = 2 * i + a;
        mobility.row(row).setZero();
        mobility(row, row) = free_self_mobility_;
      }
  return mobility;
}

// R_o = (I / zeta_o + c (M - m_free I))^-1 from the footprint mobility M.
void TwoWayWindowModel::update_resistance(const RodGeometry& rod, const ChannelGeometry& geometry, RodState& state,
                                          TwoWayWindowStatistics& stats) const {
  const int n = rod.size();
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd mobility = footprint_mobility(rod, geometry, *state.window);
  stats.solve_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Reciprocity holds for the continuous problem; the wall stencils make the
  // discrete M slightly non-symmetric.
  mobility = 0.5 * (mobility + mobility.transpose()).eval();
  Eigen::MatrixXd a = kMidplaneFactor * mobility;
  a.diagonal().array() += 1.0 / obstruction_ - kMidplaneFactor * free_self_mobility_;
  Eigen::LLT<Eigen::MatrixXd> llt(a);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("twoway: the rod's obstruction matrix is not positive definite: level 4's window "
                             "model does not describe this rod here (seen for a sphere too close to a wall for "
                             "the window grid, and for long rods at beta >= 0.85 at any window_cells); "
                             "refine window_cells, or use model nonlocal (level 3) or local (level 2)");
  state.obstruction = llt.solve(Eigen::MatrixXd::Identity(2 * n, 2 * n));
  state.solved_positions = rod.positions;
  state.evaluations_since_update = 0;
  ++stats.updates;
}

}  // namespace hsrod
