// Level 4 of the fidelity ladder: two-way gap-averaged Brinkman.
// The rod is a moving obstacle in the planform flow, solved on a window
// around it that includes the scene's walls and obstacles (the pore), so the
// interaction of the spheres with each other and with the walls comes from
// the same depth-averaged Brinkman equations as the background flow
// (Nagel et al., J. Fluid Mech. 835, 2018, treat a confined fibre as a
// region of the gap-averaged flow in the same spirit).
//
// Each sphere keeps level 3's split of its confined friction zeta(beta)
// into film friction zeta_f (with the gap walls, its own velocity only) and
// obstruction friction zeta_o (nonlocal_model.h). The obstruction force
// P_i is exerted on the window flow spread over the sphere's footprint (the
// 4-point kernel of Peskin, Acta Numerica 11, 2002, on the window lattice:
// its weights sum to one and its self-interaction barely depends on where
// the sphere sits relative to the nodes), and the sphere sees the
// footprint average <u> of the total flow:
//     P_i = zeta_o (c <u>_i - v_i),   <u> = <u_bg> - M P,
// where M [m/(N s)] is the window's mobility between footprints (one sparse
// factorisation of the window operator; per update two forward
// substitutions over the footprints' reaches, BrinkmanWindow::weighted_response) and c = 3/2
// the mid-plane factor. The footprint's self-mobility on the grid is not a
// sphere's: it is replaced by the sphere's own (1/zeta_o), removing the
// self term m_free of an isolated footprint in free space, measured at
// construction on the same lattice. Hence
//     R_o = (I / zeta_o + c (M - m_free I))^-1,   F = c R_o <u_bg> - (zeta_f + R_o) v,
// which reduces to level 1 for an isolated sphere far from walls and to
// level 3 (with the point Green's function) for distant spheres, while near
// neighbours interact through finite footprints and the walls reflect the
// disturbance. Out-of-plane (z) motion keeps the isolated friction zeta.
//
// State: the model is immutable; each rod's window, factorisation and
// stored resistance live in a TwoWayWindowState that the caller owns
// (make_state(); RodHydrodynamics keeps one for the fix's rods).
//
// Window: cells of size h (the footprints' lattice) over a fine zone that
// reaches fine_margin_for beyond the rod, then cells growing by the ratio
// `grading` out to margin_for beyond the rod (cut at the side walls). The
// rod's Hele-Shaw far field decays only as 1/r^2, so a window that cuts it
// off at a few screening lengths (u' = 0 on its edges) overestimates the
// friction by ~10 %; the graded ring carries the far field to where it no
// longer matters (friction within 1 % of a 4x larger window, tested) at a
// fraction of the cells of a uniform window of that size.
//
// Two scales (default; options.reflection_cells_per_diameter): the window
// is solved on coarser cells (d/2) and the footprint mobility is corrected
// between footprints closer than kNearReach d to that of the fine lattice:
//     M = M_window + psi(r) (G_fine - G_window),
// with G_* the free-space lattice mobilities from tables built once
// (hydro/twoway_lattice_green.h) and psi a smooth taper from 1 (r < 4 d) to
// 0 (r = 8 d). The window then supplies what the walls, the window's edges
// and the far field add, all smooth on the scale of the coarse cells; the
// rod's friction stays within 0.8 % of one scale (tested) at ~1/6 of the
// cost (4x fewer window cells, cells growing by 1.7 instead of 1.2).
//
// Cost control ("solved every k steps"): the resistance R_o is recomputed
// when a sphere has moved more than `update_distance` relative to the rod's
// centroid since the last solve, when the centroid has moved more than
// max(update_distance, s/8) with s the distance to the nearest wall (along
// a straight channel: across it only), when the rod leaves the inner part
// of the fine zone, or after `update_every` evaluations; the window is
// re-placed only in the second-last case, and re-factorised unless no pore
// cylinder reaches it (then it is an earlier window moved along the channel).
// Between updates the driving uses the current background flow with the
// stored R_o.
#pragma once

#include "flow/brinkman_window.h"
#include "hydro/local_models.h"
#include "hydro/twoway_lattice_green.h"
#include "hydro/twoway_window_options.h"

#include <algorithm>
#include <map>
#include <memory>

namespace hsrod {


// Counters of the work a level-4 model did (tests and benchmarks read them).
struct TwoWayWindowStatistics {
  long evaluations = 0;      // evaluate() calls
  long updates = 0;          // resistance re-solves (the footprint mobility of 2n columns each)
  long placements = 0;       // window placements
  long factorisations = 0;   // sparse LU factorisations (wall-free placements reuse one)
  int last_window_cells = 0;
  double factorisation_seconds = 0.0;  // wall time in window factorisations [s]
  double solve_seconds = 0.0;          // wall time in the footprint mobilities of the updates [s]
};

// Per-rod state of level 4 (owned by the caller, see ModelState): each
// rod's window, the resistance solved at its last update, and the wall-free
// windows by size shared between the rods of one state (any wall-free
// placement of that size is the same system, translated: no new
// factorisation), with the work counters.
struct TwoWayWindowState : ModelState {
  struct Rod {
    std::unique_ptr<BrinkmanWindow> window;
    WindowLattice placed;    // the lattice asked for at the last placement
    bool translated = false; // window = the cached wall-free one of that size, translated
    std::vector<Eigen::Vector3d> solved_positions;  // at the last update [m]
    Eigen::MatrixXd obstruction;                    // R_o, in-plane (2n x 2n) [N s/m]
    int evaluations_since_update = 0;
    std::vector<int> members;  // rods evaluated together in this window (by RodGeometry::id; empty: one rod,
                               // or restored from a restart), evaluate_rods
  };
  std::map<int, Rod> rods;  // by RodGeometry::id
  std::map<std::pair<int, int>, std::shared_ptr<const BrinkmanWindow>> free_windows;  // by (nx, ny)
  TwoWayWindowStatistics statistics;
  double spacing = 0.0;  // window lattice spacing of the model [m], for the summary
  std::string work_summary() const override;
  // The window of rod `rod_id` (RodGeometry::id) at its last update, null if none.
  const BrinkmanWindow* window_of(int rod_id) const {
    const auto it = rods.find(rod_id);
    return it == rods.end() ? nullptr : it->second.window.get();
  }
};

class TwoWayWindowModel : public LocalDragBase {
 public:
  TwoWayWindowModel(const HydrodynamicParameters& parameters, const ConfinementTable& table,
                    const TwoWayWindowOptions& options = {});
  std::string name() const override { return "twoway"; }
  int level() const override { return 4; }
  std::unique_ptr<ModelState> make_state() const override;
  // Restart data: the rods' window placements, stored resistances and
  // positions at their last update, and the shared wall-free windows' lattices;
  // restoring re-factorises the same windows, so a restarted run continues
  // the one it came from to round-off.
  std::vector<double> save_state(const ModelState& state) const override;
  void restore_state(ModelState& state, const std::vector<double>& data, const BackgroundFlow& flow) const override;
  using HydrodynamicModel::evaluate;
  // `state`: a TwoWayWindowState (null: a fresh one for this call).
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState* state) const override;
  // Several rods: one window around all of them, its fine zone
  // spanning every rod, so that each rod's obstruction disturbs the flow
  // the others see (the mobility M between all their footprints, walls
  // included), exactly as the spheres of one rod interact; the near field
  // (twoway_near_field.h) acts between spheres of different rods too. As at
  // level 3, the rods are one rod without bonds between them. The joint
  // window is kept in the state under key joint_key(rods) and re-solved when
  // the set of rods changes.
  void evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                     ModelState* state) const override;
  // State key of rods evaluated together: -(1 + smallest id), negative so
  // that it never names a rod alone (ids >= 0).
  static int joint_key(const std::vector<RodGeometry>& rods);
  // Sphere-centre distance beyond which rods are evaluated apart [m]: the
  // window's flow is level 3's depth-averaged Brinkman flow, whose far field
  // is the Hele-Shaw dipole, so the same reach as level 3
  // (NonlocalRodModel::interaction_reach: coupling below 1e-3 of a sphere's
  // own obstruction).
  double interaction_reach() const override;
  // Cells of the window the model would place for `rod` in `flow` now, and
  // the limit above which it refuses it (options.max_window_cells): for a
  // check before the run, so that a run never starts on unbounded work.
  long window_cells_for(const RodGeometry& rod, const BackgroundFlow& flow) const;
  long max_window_cells() const { return options_.max_window_cells; }
  // The window against max_window_cells (twoway_window_resources.cpp).
  std::string resource_problem(const RodGeometry& rod, const BackgroundFlow& flow,
                               const ResourceLimits& limits) const override;

  double film_friction() const { return film_friction_; }  // zeta_f [N s/m]
  double free_self_mobility() const { return free_self_mobility_; }  // m_free [m/(N s)]
  double lattice_spacing() const { return spacing_; }                // h [m]
  // Cell size of the window (its fine zone) [m]: h with one scale, d /
  // reflection_cells_per_diameter with two.
  double window_spacing() const { return window_spacing_; }
  bool two_scales() const { return window_spacing_ > spacing_ * (1.0 + 1e-12); }
  // Width w of the 4-point kernel [m]: d/4, so that the footprint (support
  // +-2w) is the sphere's own disc, but never below the cell size h (the
  // kernel must span several nodes); below 4 cells per diameter the
  // footprint is therefore wider than the sphere.
  double kernel_width() const { return std::max(spacing_, 0.25 * parameters_.sphere_diameter); }
  // Half-width of the square over which a sphere's force is spread [m].
  double footprint_radius() const { return 2.0 * kernel_width(); }
  // The same on the window's lattice (= the above with one scale).
  double window_kernel_width() const { return std::max(window_spacing_, 0.25 * parameters_.sphere_diameter); }
  double window_footprint_radius() const { return 2.0 * window_kernel_width(); }
  // Window reach beyond the rod's footprints [m] for a rod of planform
  // extent `rod_extent` [m]: options.margin if set, else
  // max(kOuterScreenings l, kOuterExtents extent, 2 d) with l = H / sqrt(12):
  // the screened near field has long decayed there, and the rod's
  // Hele-Shaw dipole far field (~ 1/r^2) that the window's edges cut off
  // changes the rod's friction by < 1 % (tests/drag-models/hydro,
  // WindowConverged...).
  double margin_for(double rod_extent) const;
  static constexpr double kOuterScreenings = 16.0;
  static constexpr double kOuterExtents = 4.0;
  // A rigid shift of the rod by this fraction of its distance to the nearest
  // wall calls for a new solve (see needs_update).
  static constexpr double kWallShiftFraction = 0.125;
  // Largest in-plane turn of the rod [rad] between solves: the stored
  // resistance is turned with the rod (exact for the continuous problem
  // away from walls), which leaves the lattice's sub-percent anisotropy.
  // (For rods of more than ~10 spheres the update distance binds first.)
  static constexpr double kMaxTurn = 0.1;
  // Two scales (default): the window is solved on d / 2 cells (the walls'
  // reflection and the far field), the fine lattice's free-space Green's
  // table corrects the mobility between footprints closer than kNearReach d.
  static constexpr double kReflectionCellsPerDiameter = 2.0;
  static constexpr double kNearReach = 8.0;
  // Default growth ratios of the graded cells: one scale 1.2 (the window's
  // convergence was measured with it); two scales 1.7 (the window carries
  // only the walls' reflection and the far field, both smooth; 1.4 was
  // within 1e-4 d, 6e-4 deg and 4e-6 W of 1.2 on the pore passage and 30 %
  // cheaper; 1.7 is within 0.002 d, 0.004 deg and 3e-5 W of 1.4 on the main
  // example's passage, ~20 % cheaper again, and passes the same window and
  // two-scale tests).
  static constexpr double kOneScaleGrading = 1.2;
  static constexpr double kTwoScaleGrading = 1.7;
  // Reach of the window's fine (uniform) zone beyond the footprints [m]:
  // options.fine_margin if set, else max(2 l, 2 d), at most margin_for
  // (measured on a 10-sphere rod at beta = 0.15 in the channel, at a side
  // wall and in the pore: friction within 0.03 % of a fine zone of 8 l with
  // cells growing by 1.1, 0.13 % with a fine zone of 1 l). Downstream the
  // zone reaches one fine margin further; the rod is re-windowed when it
  // comes within half a fine margin of the zone's edge.
  double fine_margin_for(double rod_extent) const;
  // Forces [N] on the window's fluid nodes (rows as window.nodes()) for the
  // in-plane forces `sphere_forces` [N] (x, y per sphere: 2n entries) that
  // the fluid exerts on the spheres at `positions` [m]: their reaction,
  // spread over each sphere's footprint as the model does (the source of
  // the rod's disturbance flow, window.solve of it). Read-only; for output.
  Eigen::VectorXd fluid_node_forces(const BrinkmanWindow& window, const std::vector<Eigen::Vector3d>& positions,
                                    const Eigen::VectorXd& sphere_forces) const;

 private:
  struct Footprint {
    std::vector<int> nodes[2];       // window unknowns per component (x, y)
    std::vector<double> weights[2];  // normalised to sum 1
  };
  using RodState = TwoWayWindowState::Rod;

  void evaluate_with(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, TwoWayWindowState& state) const;
  // Whether the rod's stored resistance is stale (see "Cost control" above);
  // if not, `turn` is the rod's in-plane turn since its last solve [rad].
  bool needs_update(const RodGeometry& rod, const ChannelGeometry& geometry, const RodState& rod_state,
                    double& turn) const;
  // The background flow averaged over each sphere's footprint (2n entries) [m/s].
  Eigen::VectorXd footprint_background(const RodGeometry& rod, const BackgroundFlow& flow,
                                       const BrinkmanWindow& window) const;
  Footprint footprint(const BrinkmanWindow& window, const Eigen::Vector3d& centre) const;
  // The window lattice for the rod as it is now (its span, the way the flow carries it).
  WindowLattice lattice_for(const RodGeometry& rod, const BackgroundFlow& flow) const;
  void place_window(const RodGeometry& rod, const BackgroundFlow& flow, RodState& rod_state,
                    TwoWayWindowState& state) const;
  bool window_holds(const RodGeometry& rod, const ChannelGeometry& geometry, const BrinkmanWindow& window) const;
  static bool window_clear_of_cylinders(const WindowLattice& lattice, const ChannelGeometry& geometry);
  static bool near_side_walls(const WindowLattice& lattice, const ChannelGeometry& geometry);
  static bool same_cells(const WindowLattice& a, const WindowLattice& b);
  static void fine_zone(const WindowLattice& lattice, Eigen::Vector2d& lo, Eigen::Vector2d& hi);
  // The window for a rod whose sphere centres span [lo, hi] [m]: the fine
  // zone (cells of size h) reaching fine_margin_for beyond the footprints,
  // graded cells (ratio options.grading) out to margin_for, cut at the side walls.
  // `travel`: the direction per axis (-1, 0, 1) in which the fine zone
  // reaches one fine margin further (the way the flow carries the rod).
  WindowLattice window_lattice(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const ChannelGeometry& geometry,
                               const Eigen::Vector2i& travel) const;
  // The square wall-free lattice of a free-lattice Green's table: 2 `cells`
  // of size h [m] about the origin, graded out to `margin` [m] beyond them.
  WindowLattice free_lattice(double h, int cells, double margin) const;
  void update_resistance(const RodGeometry& rod, const ChannelGeometry& geometry, RodState& rod_state,
                         TwoWayWindowStatistics& statistics) const;
  // In-plane footprint mobility M (2n x 2n) [m/(N s)] of the rod: the
  // window's, plus with two scales the fine lattice's free-space mobility
  // minus the window lattice's (the window then supplies only what the
  // walls and the window's extent change).
  Eigen::MatrixXd footprint_mobility(const RodGeometry& rod, const ChannelGeometry& geometry,
                                     const BrinkmanWindow& window) const;
  std::shared_ptr<const LatticeGreenTable> free_lattice_table(double h, double kernel_width) const;
  // Two scales: the near reach, both free-lattice tables and the fine self-mobility.
  void build_two_scale_tables();
  // Weight of the fine-lattice correction for two spheres `distance` [m]
  // apart: 1 within near_reach_ / 2, smoothly 0 at near_reach_.
  double near_weight(double distance) const;
  double measure_free_self_mobility() const;

  TwoWayWindowOptions options_;
  double spacing_;             // h [m]
  double window_spacing_;      // cell size of the window's fine zone [m]
  double near_reach_ = 0.0;    // two scales: pair distance up to which the fine lattice corrects the window [m]
  std::shared_ptr<const LatticeGreenTable> fine_table_, window_table_;  // two scales: free-lattice Green's tables
  double film_friction_;       // zeta_f [N s/m]
  double obstruction_;         // zeta_o [N s/m]
  double free_self_mobility_;  // m_free [m/(N s)]
  double fine_self_mobility_ = 0.0;  // two scales: a footprint's own fine-lattice mobility, mean over sub-cell places [m/(N s)]
};

// Level 4 with a state of its own, for a caller that holds one model and
// evaluates its rods through it over time (tests, tools); fix hele_shaw/drag
// keeps the state in RodHydrodynamics instead.
class TwoWayWindowSession : public TwoWayWindowModel {
 public:
  using TwoWayWindowModel::TwoWayWindowModel;
  using TwoWayWindowModel::evaluate;
  // Evaluates with this session's state (not const: the state advances).
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) {
    TwoWayWindowModel::evaluate(rod, flow, out, &state_);
  }
  const TwoWayWindowStatistics& statistics() const { return state_.statistics; }
  std::string work_summary() const { return state_.work_summary(); }

 private:
  TwoWayWindowState state_;
};

}  // namespace hsrod
