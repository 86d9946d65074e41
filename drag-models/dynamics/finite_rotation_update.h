// Position update of the linearly implicit rod step with finite bond
// rotations (an update linear in the rotation loses a stiff rod's rotation).
//
// The step (overdamped_rod_step.h) solves for displacements dx_i and
// rotation vectors dphi_i. The orientations are updated exactly,
// q -> Exp(dphi) q, but x -> x + dx moves the spheres along the tangent of
// the rotation: a bond turned by phi is stretched by L0 phi^2 / 2 and
// sheared by L0 phi^3 / 6. For a stiff rod that spurious strain is far from
// harmless: the next step linearises about it, and the geometric stiffness
// of the spurious tension k_n phi^2 / 2 (transverse, resisting the bond's
// rotation) dwarfs the drag R / dt when k_n dt / zeta * phi^2 / 2 >> 1.
// The rotation is then blocked on every other step: a 10-sphere rod of
// E = 1.5e12 Pa turned by a couple lagged the rigid rotation by 45 % at any
// step from 4e-7 to 4e-6 s (tests/drag-models/dynamics/test_guarded_step.cpp).
// A rod in the overdamped limit cannot hold spurious strain of more than
// ~zeta / (k_n dt) (2e-9 there) without this happening.
//
// The update here takes the rotational part of each bond's relative
// displacement as a finite rotation: with r_b = x_j - x_i before the step
// and the bond's rotation phi_b = r_b x (dx_j - dx_i) / |r_b|^2 (from its own
// end displacements, not from the spheres' rotations: spheres rolling on a
// wall turn without turning the bond, and their spin, sensitive to the
// friction law near stick, would amplify round-off), the bond vector
// should become
//     r_b' = r_b + (dx_j - dx_i) + delta_b,  delta_b = (Exp(phi_b) - 1 - [phi_b]x) r_b,
// which turns a rigidly rotating bond without stretching it (delta_b is
// second order in phi: the step stays a consistent linearised backward-Euler
// step; only its error in the stiff modes changes). A rigid rotation Omega is
// reproduced exactly for bonds across Omega or along it (a rod turning in the
// plane: Omega along z); a component of Omega along a bond that also turns
// (a rod spinning about its own axis while turning) enters only through the
// linear part, a shear of |Omega_par| |Omega_perp| |r_b| / 2. The sphere corrections
// z_i (x' = x + dx + z) that meet these bond vectors in the least-squares
// sense, with zero mean (the rod's centroid moves by the mean dx), solve the
// bond graph's Laplacian system L z = B^T delta (B the bond-sphere incidence);
// for a chain this is exact (z is the running sum of delta_b). L depends on
// the bonds only and is factorised once per bond set.
#pragma once

#include "dynamics/overdamped_rod_step.h"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <utility>
#include <vector>

namespace hsrod {

class FiniteRotationUpdate {
 public:
  // Moves rod.positions by the step's displacements and the finite-rotation
  // correction. `dy`: 6n (dx_i [m], dphi_i [rad]) of the step; the
  // positions are those before the step (orientations are not touched).
  void apply(OverdampedRod& rod, const Eigen::VectorXd& dy);

 private:
  void analyse(const OverdampedRod& rod);

  int spheres_ = -1;
  std::vector<std::pair<int, int>> bonds_;  // the bond set the factorisation belongs to
  bool chain_ = false;                       // bonds (k, k+1) for k = 0 .. n-2, in order
  std::vector<int> component_;               // connected component of each sphere
  std::vector<int> component_size_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> laplacian_;  // L + one pinned sphere per component
  Eigen::MatrixXd incidence_rhs_, correction_;  // n x 3 work arrays: B^T delta, then z [m]
  std::vector<Eigen::RowVector3d> component_mean_;  // mean correction per component [m] (work array)
};

}  // namespace hsrod
