// The implicit step's linear system for a chain with non-local drag (level
// 3, or rods joined by level 4), solved through the Schur complement on the
// translations the drag couples.
//
// The matrix R / dt + K (dynamics/overdamped_rod_step.h) of a chain is
// block-tridiagonal in 6x6 sphere blocks (bonds, contacts, rotational drag)
// plus the non-local resistance, dense between the spheres' in-plane
// translations (x, y; 2n x 2n) and diagonal in z for the depth-averaged
// models (z too when a model couples it: 3n x 3n). Ordering the unknowns
// as a = the coupled translations (p per sphere, p = 2 or 3) and b = the
// rest (6 - p per sphere), A_bb is block-tridiagonal in (6-p)x(6-p) blocks
// and A_ab, A_ba are block-tridiagonal too, so
//     S = A_aa - A_ab A_bb^-1 A_ba            (pn x pn, dense)
//     S a = r_a - A_ab A_bb^-1 r_b,  b = A_bb^-1 (r_b - A_ba a).
// Cost for n spheres: block elimination of A_bb with pn right-hand sides
// (O(n^2) with small blocks) and a dense LU of pn x pn instead of 6n x 6n:
// for the 10-sphere rod (p = 2) ~1/27 of the dense LU's (6n)^3 / 3 flops
// plus ~25 k flops of block work. Golub & Van Loan, "Matrix Computations"
// (4th ed.), sec. 3.2.10 (block LU, Schur complement) and 4.5 (block
// tridiagonal systems). A_bb is eliminated without pivoting across blocks,
// as the banded path (dynamics/overdamped_rod_step.cpp) does for the whole
// matrix: the diagonal holds the drag / dt and the bond stiffness, close to
// symmetric positive definite. S is factorised with partial pivoting.
#pragma once

#include "common/dense_lu.h"
#include "dynamics/small_block_lu.h"
#include "dynamics/wall_contact.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

class CoupledChainSolve {
 public:
  // How many translation components per sphere `resistance` (3n x 3n)
  // couples between spheres: 2 when every z row and column is zero off its
  // diagonal entry (the depth-averaged models), else 3.
  static int coupled_components(const Eigen::MatrixXd& resistance);

  // Factorises the matrix whose 6x6 block-tridiagonal part is (diagonal[k],
  // upper[k] = A(k, k+1), lower[k] = A(k, k-1); k < n) and whose
  // translations carry in addition resistance / dt (resistance: 3n x 3n
  // [N s/m], dt [s]). `components`: coupled_components(resistance).
  void factorise(const std::vector<Matrix6d>& diagonal, const std::vector<Matrix6d>& upper,
                 const std::vector<Matrix6d>& lower, const Eigen::MatrixXd& resistance, double dt, int components);

  // Overwrites b (6n: forces and torques per sphere) with A^-1 b (6n:
  // displacements and rotations per sphere), from the last factorisation.
  void solve_in_place(Eigen::VectorXd& b) const;

 private:
  template <int P>
  struct Factors;
  template <int P>
  void factorise_with(Factors<P>& f, const std::vector<Matrix6d>& diagonal, const std::vector<Matrix6d>& upper,
                      const std::vector<Matrix6d>& lower, const Eigen::MatrixXd& resistance, double dt);
  template <int P>
  void solve_with(const Factors<P>& f, Eigen::VectorXd& b) const;

  template <int P>
  struct Factors {
    static constexpr int B = 6 - P;
    using BandBlock = Eigen::Matrix<double, B, B>;
    using CouplingBlock = Eigen::Matrix<double, P, B>;  // A_ab(k, k + o)
    std::vector<SmallBlockLu<B>> band_lu;        // LU of the eliminated diagonal blocks of A_bb
    std::vector<BandBlock> band_lower;           // A_bb(k, k-1)
    std::vector<BandBlock> band_upper;           // A'_bb(k,k)^-1 A_bb(k, k+1)
    std::vector<CouplingBlock> ab_lower, ab_diagonal, ab_upper;  // A_ab(k, k-1), (k, k), (k, k+1)
    // W = A_bb^-1 A_ba, block row k (B x pn) in columns [pn k, pn (k+1)):
    // each block row contiguous for the sweeps over the chain.
    Eigen::Matrix<double, B, Eigen::Dynamic> w;
  };

  int n_ = 0;
  int components_ = 2;
  Factors<2> planar_;
  Factors<3> spatial_;
  Eigen::MatrixXd schur_;  // S, then its LU factors
  DenseLu schur_lu_;
  mutable Eigen::VectorXd coupled_part_, band_part_;  // a and b of a solve
};

}  // namespace hsrod
