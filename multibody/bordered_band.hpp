// Internal to multibody/: the one factorization of the O(n) Newton matrices, a band
// with a small border. SparseSaddle (dynamics_sparse.hpp, segment angles) and
// natural::BandedKkt (natural.hpp, hinge positions) order their unknowns so that
//
//   A = [P  B]   P: the core, order m, banded (lower width kl, upper ku);
//       [C  D]   B: m x b, C: b x m, D: b x b, the border of b unknowns (b small),
//
// and factor it as P = L U (LAPACK's band LU with partial pivoting, BandLU) and the Schur
// complement S = D - C P^-1 B (dense LU with partial pivoting); A z = f is then
//   P u = f_P,   S w = f_D - C u,   z_P = u - (P^-1 B) w,   z_D = w.
// Only the b' border columns with entries in the band are solved for (P^-1 B by rows: one
// pass of BandLU::solve_rows over the factors for all), and C keeps only the band columns
// that border rows reach: the structure, fixed at construction from the pattern.
// Singular (the one test): a non-finite entry, an exactly zero pivot of the band, or a
// Schur complement that is not finite or has an exactly zero pivot. An ill-conditioned
// matrix factors; the caller's Newton iteration or refinement judges the solution.
// Cost: factor O(m kl (kl + ku) + m b' (2 kl + ku) + b^3); solve O(m (2 kl + ku + b') k)
// for k right-hand sides; memory O(m (2 kl + ku + 1 + b')).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <vector>

namespace multibody::detail {

/// Banded LU with partial pivoting by LAPACK (dgbtrf/dgbtrs) in LAPACK's band storage:
/// lower bandwidth kl, upper ku. O(N kl (kl + ku)) to factor, O(N (2 kl + ku)) to solve.
class BandLU {
 public:
  void resize(Eigen::Index N, int kl, int ku);  ///< zero matrix of order N
  /// Entry (i, j), |i - j| within the band (before factor()).
  double& at(Eigen::Index i, Eigen::Index j) { return ab_[size_t(j) * ldab_ + kl_ + ku_ + i - j]; }
  bool factor();  ///< false on a non-finite entry or an exactly zero pivot
  /// k right-hand sides, column q at b + q ld, in place.
  void solve_many(double* b, Eigen::Index ld, Eigen::Index k) const;
  /// k right-hand sides stored by rows (row i at b + i k), in place: dgbtrs's operations
  /// in its order (the same result bit for bit) in one pass over the factors for all k,
  /// where dgbtrs streams them from memory once per right-hand side.
  void solve_rows(double* b, int k) const;
  long stored() const { return static_cast<long>(ab_.size()); }

 private:
  Eigen::Index N_ = 0;
  int kl_ = 0, ku_ = 0, ldab_ = 1;
  std::vector<double> ab_;
  std::vector<int> ipiv_;  ///< LAPACK's 1-based row interchanges
};

/// The bordered band matrix A = [P B; C D] and its factorization (file comment).
/// Unknowns 0 .. core - 1 are the band's, core .. core + border - 1 the border's.
/// Usage, per Newton iteration: clear(); add(i, j, v) ...; if (factor()) solve(z);
class BorderedBand {
 public:
  BorderedBand() = default;
  /// The structure of a matrix with `core` band unknowns and `border` border unknowns:
  /// visit(mark) calls mark(i, j) for every entry (i, j) the matrix may hold (repeats
  /// allowed). It fixes the band's widths, the border columns with entries in the band
  /// and the band columns that border rows reach. A zero matrix. O(entries + storage).
  template <class Visit>
  BorderedBand(Eigen::Index core, Eigen::Index border, Visit visit)
      : core_(core), border_(border), solved_(border, -1), reached_(core, -1) {
    visit([&](Eigen::Index i, Eigen::Index j) {
      ++entries_;
      if (i < core && j < core) {
        kl_ = std::max(kl_, static_cast<int>(i - j));
        ku_ = std::max(ku_, static_cast<int>(j - i));
      } else if (i < core) {
        solved_[j - core] = 0;
      } else if (j < core) {
        reached_[j] = 0;
      }
    });
    number();
    clear();
  }

  Eigen::Index order() const { return core_ + border_; }
  /// Zero matrix (before assembly). O(storage).
  void clear();
  /// A(i, j) += v; (i, j) must be in the pattern. O(1).
  void add(Eigen::Index i, Eigen::Index j, double v) {
    if (i < core_ && j < core_) {
      assert(j - i <= ku_ && i - j <= kl_);
      band_.at(i, j) += v;
    } else if (i < core_) {
      assert(solved_[j - core_] >= 0);
      X_(i, solved_[j - core_]) += v;
    } else if (j < core_) {
      assert(reached_[j] >= 0);
      C_(i - core_, reached_[j]) += v;
    } else {
      D_(i - core_, j - core_) += v;
    }
  }
  /// Factors the assembled matrix in place; false when it is singular by the test of the
  /// file comment.
  bool factor();
  /// z = A^-1 z in place for k right-hand sides stored by rows (row i at z + i k), with
  /// the last successful factorization.
  void solve(double* z, int k = 1) const;
  /// Entries of the pattern (with repeats) and doubles stored (bench counters).
  long entries() const { return entries_; }
  long stored() const;

 private:
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  void number();  ///< columns of X_ and C_ from the marks in solved_ and reached_

  Eigen::Index core_ = 0, border_ = 0;
  int kl_ = 0, ku_ = 0;
  long entries_ = 0;
  std::vector<int> solved_;     ///< per border unknown: its column in X_, or -1 (no entries in the band)
  std::vector<int> border_of_;  ///< per column of X_: its border unknown
  std::vector<int> reached_;    ///< per band unknown: its column in C_, or -1 (no border row reaches it)
  std::vector<int> band_of_;    ///< per column of C_: its band unknown
  BandLU band_;
  RowMatrix X_;                 ///< B's solved columns, then P^-1 B (by rows, for BandLU::solve_rows)
  Eigen::MatrixXd C_, D_;       ///< C on the reached columns; D, then S = D - C P^-1 B
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_;
};

}  // namespace multibody::detail
