#include "dynamics/coupled_chain_solve.h"

#include <algorithm>

namespace hsrod {

int CoupledChainSolve::coupled_components(const Eigen::MatrixXd& resistance) {
  const int rows = static_cast<int>(resistance.rows());
  for (int z = 2; z < rows; z += 3) {
    for (int r = 0; r < rows; ++r)
      if (r != z && (resistance(r, z) != 0.0 || resistance(z, r) != 0.0)) return 3;
  }
  return 2;
}

void CoupledChainSolve::factorise(const std::vector<Matrix6d>& diagonal, const std::vector<Matrix6d>& upper,
                                  const std::vector<Matrix6d>& lower, const Eigen::MatrixXd& resistance, double dt,
                                  int components) {
  components_ = components;
  if (components == 2)
    factorise_with(planar_, diagonal, upper, lower, resistance, dt);
  else
    factorise_with(spatial_, diagonal, upper, lower, resistance, dt);
}

void CoupledChainSolve::solve_in_place(Eigen::VectorXd& b) const {
  if (components_ == 2)
    solve_with(planar_, b);
  else
    solve_with(spatial_, b);
}

// The coupled translations are each sphere's first P unknowns, the band
// its last B = 6 - P (z when P = 2, and the rotation): the blocks' corners.
template <int P>
void CoupledChainSolve::factorise_with(Factors<P>& f, const std::vector<Matrix6d>& diagonal,
                                       const std::vector<Matrix6d>& upper, const std::vector<Matrix6d>& lower,
                                       const Eigen::MatrixXd& resistance, double dt) {
  constexpr int B = Factors<P>::B;
  using BandBlock = typename Factors<P>::BandBlock;
  const int n = static_cast<int>(diagonal.size());
  const int m = P * n;  // coupled unknowns
  n_ = n;
  f.band_lu.resize(n);
  f.band_lower.resize(n);
  f.band_upper.resize(n);
  f.ab_lower.resize(n);
  f.ab_diagonal.resize(n);
  f.ab_upper.resize(n);

  // S starts as A_aa: the non-local resistance / dt, then the chain's
  // (block-tridiagonal) part.
  schur_.resize(m, m);
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < P; ++c)
      for (int i = 0; i < n; ++i)
        for (int r = 0; r < P; ++r) schur_(P * i + r, P * k + c) = resistance(3 * i + r, 3 * k + c) / dt;
  for (int k = 0; k < n; ++k) {
    schur_.template block<P, P>(P * k, P * k) += diagonal[k].template topLeftCorner<P, P>();
    if (k + 1 < n) schur_.template block<P, P>(P * k, P * (k + 1)) += upper[k].template topLeftCorner<P, P>();
    if (k > 0) schur_.template block<P, P>(P * k, P * (k - 1)) += lower[k].template topLeftCorner<P, P>();
    f.ab_diagonal[k] = diagonal[k].template topRightCorner<P, B>();
    f.ab_upper[k] = upper[k].template topRightCorner<P, B>();
    f.ab_lower[k] = lower[k].template topRightCorner<P, B>();
  }

  // (Products of a small fixed block with a row of blocks are lazy,
  // coefficient-based: Eigen's general product would pack them for GEMM.)
  // W = A_bb^-1 A_ba by block elimination with the pn columns of A_ba as
  // right-hand sides. A_ba's column block of sphere j lives in block rows
  // j-1..j+1, so after the forward sweep block row k has non-zero columns
  // for spheres 0..k+1 only ("live"), which the sweep keeps to.
  f.w.setZero(B, static_cast<Eigen::Index>(m) * n);
  const auto live = [n](int k) { return P * std::min(n, k + 2); };
  for (int k = 0; k < n; ++k) {
    auto wk = f.w.middleCols(static_cast<Eigen::Index>(m) * k, m);
    wk.template middleCols<P>(P * k) = diagonal[k].template bottomLeftCorner<B, P>();
    if (k + 1 < n) wk.template middleCols<P>(P * (k + 1)) = upper[k].template bottomLeftCorner<B, P>();
    if (k > 0) wk.template middleCols<P>(P * (k - 1)) = lower[k].template bottomLeftCorner<B, P>();
  }
  for (int k = 0; k < n; ++k) {
    BandBlock d = diagonal[k].template bottomRightCorner<B, B>();
    if (P == 2) d(0, 0) += resistance(3 * k + 2, 3 * k + 2) / dt;  // z: uncoupled, on the band
    auto wk = f.w.middleCols(static_cast<Eigen::Index>(m) * k, m);
    if (k > 0) {
      f.band_lower[k] = lower[k].template bottomRightCorner<B, B>();
      d.noalias() -= f.band_lower[k] * f.band_upper[k - 1];
      const int previous = live(k - 1);
      wk.leftCols(previous) -=
          f.band_lower[k].lazyProduct(f.w.middleCols(static_cast<Eigen::Index>(m) * (k - 1), previous));
    }
    f.band_lu[k].compute(d);
    auto live_columns = wk.leftCols(live(k));
    f.band_lu[k].solve_in_place(live_columns);
    if (k + 1 < n) {
      f.band_upper[k] = upper[k].template bottomRightCorner<B, B>();
      f.band_lu[k].solve_in_place(f.band_upper[k]);
    }
  }
  for (int k = n - 2; k >= 0; --k)
    f.w.middleCols(static_cast<Eigen::Index>(m) * k, m) -=
        f.band_upper[k].lazyProduct(f.w.middleCols(static_cast<Eigen::Index>(m) * (k + 1), m));

  // S = A_aa - A_ab W (A_ab block-tridiagonal).
  for (int i = 0; i < n; ++i) {
    auto rows = schur_.template middleRows<P>(P * i);
    rows -= f.ab_diagonal[i].lazyProduct(f.w.middleCols(static_cast<Eigen::Index>(m) * i, m));
    if (i > 0) rows -= f.ab_lower[i].lazyProduct(f.w.middleCols(static_cast<Eigen::Index>(m) * (i - 1), m));
    if (i + 1 < n) rows -= f.ab_upper[i].lazyProduct(f.w.middleCols(static_cast<Eigen::Index>(m) * (i + 1), m));
  }
  schur_lu_.compute_in_place(schur_);
}

template <int P>
void CoupledChainSolve::solve_with(const Factors<P>& f, Eigen::VectorXd& b) const {
  constexpr int B = Factors<P>::B;
  const int n = n_;
  const int m = P * n;
  Eigen::VectorXd& a = coupled_part_;
  Eigen::VectorXd& z = band_part_;
  a.resize(m);
  z.resize(B * n);
  for (int k = 0; k < n; ++k) {
    a.template segment<P>(P * k) = b.template segment<P>(6 * k);
    z.template segment<B>(B * k) = b.template segment<B>(6 * k + P);
  }
  // z = A_bb^-1 r_b.
  for (int k = 0; k < n; ++k) {
    auto y = z.template segment<B>(B * k);
    if (k > 0) y.noalias() -= f.band_lower[k] * z.template segment<B>(B * (k - 1));
    f.band_lu[k].solve_in_place(y);
  }
  for (int k = n - 2; k >= 0; --k)
    z.template segment<B>(B * k).noalias() -= f.band_upper[k] * z.template segment<B>(B * (k + 1));
  // S a = r_a - A_ab z.
  for (int i = 0; i < n; ++i) {
    auto y = a.template segment<P>(P * i);
    y.noalias() -= f.ab_diagonal[i] * z.template segment<B>(B * i);
    if (i > 0) y.noalias() -= f.ab_lower[i] * z.template segment<B>(B * (i - 1));
    if (i + 1 < n) y.noalias() -= f.ab_upper[i] * z.template segment<B>(B * (i + 1));
  }
  schur_lu_.solve_in_place(a);
  // b = A_bb^-1 (r_b - A_ba a) = z - W a.
  for (int k = 0; k < n; ++k)
    z.template segment<B>(B * k).noalias() -= f.w.middleCols(static_cast<Eigen::Index>(m) * k, m) * a;
  for (int k = 0; k < n; ++k) {
    b.template segment<P>(6 * k) = a.template segment<P>(P * k);
    b.template segment<B>(6 * k + P) = z.template segment<B>(B * k);
  }
}

}  // namespace hsrod
