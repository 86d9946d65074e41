// The discretisation behind solve_brinkman_on_grid (brinkman_grid_solver.h
// describes the scheme): MAC-grid wall stencils, the developed inlet profile
// and the assembly of the saddle-point system. Internal to the grid solver.
#pragma once

#include "flow/brinkman_grid_solver.h"
#include "flow/line_stencils.h"

#include <Eigen/SparseCore>

#include <vector>

namespace hsrod {
namespace brinkman_grid {

enum class Component { kU, kV };

// Neighbour of a node along one grid direction: another node of the same
// component at distance `dist`, or the wall (node < 0, value 0) at `dist`.
struct Neighbour {
  double dist;
  int node;
};

class Stencils {
 public:
  Stencils(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m,
           bool exponential_wall_layer)
      : geo_(geo), g_(g), m_(m), fitted_(exponential_wall_layer) {}

  bool fitted() const { return fitted_; }

  // Decay rate [1/H] of the Brinkman wall layer along the unit direction
  // `line` at p: the layer decays as exp(-sqrt(12) n) in the wall distance n
  // (units of H; flow/README.md), i.e. at sqrt(12) |n_wall . line| along the
  // line. 0 without the exponential wall layer and beyond ten layer
  // thicknesses (exp(-10) = 5e-5), where the standard stencil is used.
  double layer_rate(const Eigen::Vector2d& p, const Eigen::Vector2d& line) const;

  Eigen::Vector2d position(Component c, int i, int j) const {
    return c == Component::kU ? g_.u_position(i, j) : g_.v_position(i, j);
  }
  int index(Component c, int i, int j) const {
    return c == Component::kU ? g_.u_index(i, j) : g_.v_index(i, j);
  }
  NodeKind kind(Component c, int node) const {
    return c == Component::kU ? m_.u[node] : m_.v[node];
  }

  // Neighbour of node (i, j) of component c in direction (di, dj), one of
  // (+-1, 0), (0, +-1). Handles the outlet (zero normal derivative: mirror
  // node), the inlet for v (v = 0 on x = 0) and walls crossed by the grid line
  // (exact distance from a ray cast).
  Neighbour neighbour(Component c, int i, int j, int di, int dj) const;

  // Flux through the face of node (i, j) as a combination of node values,
  // divided by the face length h. Where the face line crosses a wall within
  // h, the velocity along the line is taken linear in the distance from the
  // wall (the no-slip profile; exact for a linear near-wall profile), and
  // the fluid part of a neighbouring face whose centre lies in the wall is
  // carried by this face:
  //   no wall within h:       F/h = u_g                            (midpoint rule)
  //   wall at h/2 <= d < h:   F/h = [1 + (d - h/2)^2 / (2 d h)] u_g (neighbour sliver)
  //   wall at d < h/2:        F/h = (d + h/2)^2 / (2 h) * [w u_g / d + (1 - w) u_f / (d + h)]
  // In the last case the slope of the profile is taken from the node itself
  // and from the next node f along the line (distance d + h from the wall),
  // blended with w = 2d/h so that the weight of u_g stays bounded as d -> 0
  // (u_g is then a tiny value with an O(h^2) absolute error).
  struct FaceFlux {
    double self = 1.0;  // weight of the node's own value
    int other = -1;     // node f (same component), or -1
    double other_weight = 0.0;
  };
  FaceFlux face_flux(Component c, int i, int j) const;

  // face_flux with the exponential wall layer: the velocity along the face
  // line at distance s from the wall is taken as A phi(s), phi the layer
  // shape of line_stencils.h (decay rate layer_rate; linear for rate 0), A
  // fitted to the node value at distance d. The face [d - h/2, d + h/2]
  // plus the fluid sliver [0, d - h/2] of a neighbouring face whose centre
  // is in the wall carry F/h = Phi(d + h/2) / (h phi(d)); a face whose line
  // meets a wall within [h, 2h) carries [Phi(d + h/2) - Phi(d - h/2)] / (h
  // phi(d)). Close to the wall (d < h/2) A is blended with the next node's
  // estimate, as in face_flux.
  FaceFlux fitted_face_flux(Component c, int i, int j) const;

  // Second difference along `axis` (0: x, 1: y) at node (i, j) with
  // neighbours at distances a, b: Shortley-Weller, exponentially fitted to
  // the wall layer when that is on (line_stencils.h).
  LineWeights second(Component c, int i, int j, int axis, double a, double b) const;

 private:
  const ChannelGeometry& geo_;
  const MacGrid& g_;
  const MacMasks& m_;
  bool fitted_;
};

// Developed inlet profile of the discrete operator: -u'' + 12 u = 1 along the
// inlet column with the same wall stencil, scaled to mean 1 over the width.
std::vector<double> discrete_inlet_profile(const Stencils& st, const MacGrid& g,
                                           const MacMasks& m, double width);

// The system's unknowns (the unknown u, then v, then pressure values) and
// its rows: momentum per velocity unknown, continuity per pressure cell.
class Assembler {
 public:
  Assembler(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m,
            const std::vector<double>& inlet, bool exponential_wall_layer);

  int size() const { return n_; }

  // Assembles the (Oseen-linearised) system; `advect` holds the previous
  // iterate (unknown vector) and `inertia` = (6/5) Re_H (0: Brinkman-Stokes).
  void assemble(const Eigen::VectorXd& advect, double inertia, Eigen::SparseMatrix<double>& a,
                Eigen::VectorXd& rhs) const;

  // Scatters an unknown vector into per-node arrays.
  void scatter(const Eigen::VectorXd& x, BrinkmanGridSolution& s) const;

  // Largest change of the velocity unknowns (the pressure block is last).
  double velocity_change(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;

 private:
  double u_value(const Eigen::VectorXd& x, int node) const;
  double v_value(const Eigen::VectorXd& x, int node) const;
  // v interpolated to u node (i, j): mean of the four surrounding v nodes
  // (at the outlet the two inner ones, mirrored).
  double v_around_u(const Eigen::VectorXd& x, int i, int j) const;
  double u_around_v(const Eigen::VectorXd& x, int i, int j) const;

  void add_u(int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
             Eigen::VectorXd& rhs) const;
  void add_v(int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
             Eigen::VectorXd& rhs) const;
  void add(Component c, int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
           Eigen::VectorXd& rhs) const;

  // Flux of face `node` (weight w) into a continuity row; inlet values are
  // known, wall faces carry none.
  void add_flux(Component c, int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
                Eigen::VectorXd& rhs) const;

  // -lap(u) + 12 u + (advection velocity) . grad u for one velocity node.
  void momentum_row(Component c, int i, int j, int row, const Eigen::Vector2d& advection,
                    std::vector<Eigen::Triplet<double>>& t, Eigen::VectorXd& rhs) const;

  const MacGrid& g_;
  const MacMasks& m_;
  Stencils st_;
  const std::vector<double>& inlet_;  // inlet profile per row j [U]
  std::vector<int> uid_, vid_, pid_;
  std::vector<Stencils::FaceFlux> flux_u_, flux_v_;  // per fluid node (Stencils::face_flux)
  int n_ = 0;
};

}  // namespace brinkman_grid
}  // namespace hsrod
