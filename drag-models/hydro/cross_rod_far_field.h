// The far field of rods solved apart (fix rod/implicit `rod_interaction
// lagged | iterated`, hydro/cross_rod_disturbance.h): the disturbance that
// rods farther than the interaction reach r_c make at a rod's spheres.
//
// Each pair of rods farther apart than r_c couples by less than
// NonlocalRodModel::kInteractionTolerance of a sphere's own obstruction,
// but the Hele-Shaw far field decays only as 1/r^2 while the number of
// rods at distance r grows as r: summed over a suspension the pairs beyond
// r_c are a few per cent of the coupling, which the joint solve of a
// chained cluster keeps. Beyond r_c (>= 10 screening lengths l = H /
// sqrt(12)) the Brinkman Green's function is the potential dipole
// (brinkman_green.h), M = c G = c H (2 rhat rhat - I) / (24 pi mu r^2), or
// in complex notation (z = x + i y, f = P_x + i P_y, u = u_x + i u_y)
//     conj(u(z)) = K sum_k f_k / (z - z_k)^2,   K = c H / (24 pi mu),
// the derivative of a sum of 2-D poles: its multipole expansion about a
// centre z_c,
//     sum_k f_k / (z - z_k)^2 = (z - z_c)^-2 sum_p (p + 1) a_p w^p,
//     a_p = sum_k f_k ((z_k - z_c) / rho)^p,   w = rho / (z - z_c),
// converges for |z - z_c| > rho (rho the largest |z_k - z_c|), and the
// terms p > P left out are bounded by
//     sum_k |f_k| |z - z_c|^-2 T_P(q),  T_P(q) = sum_{p > P} (p + 1) q^p
//       = q^(P+1) ((P + 2) - (P + 1) q) / (1 - q)^2,  q = rho / |z - z_c|
// (Greengard & Rokhlin 1987, J. Comput. Phys. 73: 325, for the pole 1/z;
// here its derivative). The rods' spheres are sorted into a binary tree
// of boxes (halved at the median rod centre along the longer side); a box
// whose spheres are all farther than r_c from the target rod's, whose
// radius is at most kOpening of its distance and which holds no rod coupled
// exactly (excluded: a unit of rods in contact, solved jointly, may reach
// beyond r_c) is summed from its expansion, q <= 1/2, T_20(1/2) = 2.2e-5;
// the rest is opened down to its rods, and each rod not coupled exactly is
// summed sphere by sphere with the dipole. Every rod pair is thus counted
// once: by the exact pair mobilities or the unit's joint solve
// (add_disturbance's `excluded`), or here. Cost per target rod ~ the rods
// near r_c plus ~log N boxes.
//
// What the dipole leaves out of the pair mobility the joint solve uses at
// r > r_c: the Bessel terms of G, ~e^(-r/l), 6e-7 of the dipole at r_c,
// and the tail of the 3-D near-field blend (near_field_coupling.h),
// exponential in r over ~0.6 H, 1.6e-3 of the pair coupling at r_c and
// 2e-5 at 1.5 r_c (beta = 0.15) (test_cross_rod_far_field.cpp measures both).
// The dipoles of a suspension largely cancel over the angles, the blend's
// 3-D tail does not: what it leaves is 0.4-0.7 % of the far field's effect on
// the rods' motion (tests/benchmarks/RESULTS.md).
#pragma once

#include "hydro/cross_rod_disturbance.h"
#include "hydro/hydrodynamic_model.h"

#include <utility>
#include <vector>

namespace hsrod {

class CrossRodFarField {
 public:
  static constexpr int kOrder = 20;          // P: terms p = 0..P of each box's expansion [-]
  static constexpr double kOpening = 0.5;    // largest box radius over its distance from a target sphere [-]
  static constexpr int kLeafRods = 2;        // a box of at most this many rods is not halved further

  // mu [Pa s], H [m], r_c [m]: the pairs beyond r_c are this far field's.
  void set_scene(double viscosity, double gap_height, double reach);
  double reach() const { return reach_; }

  // The rods (ids unique, ascending or not: ties broken by id, so every rank builds
  // the same tree) with their in-plane sphere centres and obstruction
  // forces P^D, P^v; the forces are read now, not kept.
  void build(const std::vector<int>& ids, const std::vector<const RodGeometry*>& rods,
             const std::vector<const RodObstructionForces*>& forces);

  // q^D, q^v of `target` += the far field of every rod whose id is not in
  // `excluded` (ascending: the rods within r_c of the target, coupled
  // exactly, and those of its own unit; the target's own id among them).
  // Returns the bound of the expansion's truncation at every target sphere
  // [m/s]: the larger over the two channels of the sum over the boxes taken
  // whole of K sum|f| D^-2 T_P(rho / D), D the box centre's distance from
  // the target rod's centroid less the rod's radius (<= |z - z_c|).
  double add_disturbance(const RodGeometry& target, const std::vector<int>& excluded,
                         RodObstructionForces& target_forces) const;

  // T_P(q) above, P = kOrder [-].
  static double truncation_factor(double ratio);
  // K = c H / (24 pi mu) [m/(N s) m^2].
  double dipole_strength() const { return dipole_strength_; }

 private:
  struct Box {
    double x_min, x_max, y_min, y_max;  // bounding box of its spheres [m]
    double cx, cy, radius;              // centre and radius about it [m]
    double force_sum[2];                // sum |f| per channel (driving, velocity) [N]
    int first, last;                    // its rods [first, last) in rod order
    int left = -1, right = -1;          // halves (-1: a leaf)
  };
  int build_box(int first, int last);
  void expand(Box& box, int index);

  double dipole_strength_ = 0.0;  // K [m^3/(N s)]
  double reach_ = 0.0;            // r_c [m]
  std::vector<int> rod_order_;    // rod index (into the build's lists) by tree order
  std::vector<std::pair<int, int>> id_positions_;  // (rod id, place in tree order), ascending
  std::vector<int> ids_;          // rod id by rod index
  std::vector<int> sphere_first_; // by rod index: first sphere in the arrays below; size rods + 1
  std::vector<double> x_, y_;     // sphere centres [m]
  std::vector<double> f_[2][2];   // per channel (driving, velocity): real, imaginary parts [N]
  std::vector<double> centre_x_, centre_y_;  // rod centroids [m]
  std::vector<Box> boxes_;
  std::vector<double> terms_;     // per box, channel, p: (p + 1) a_p, real and imaginary [N]
};

}  // namespace hsrod
