// Internal to multibody/dynamics.cpp: the O(n) large-n path of the forced response
// (issue 8, point 2). Same equations, same coordinates (segment angles) and the same
// saddle-point Newton system as the dense path; only the linear algebra differs.
//
// Structure used. With midpoint_i = P_0 + l sum_j L_ij e(phi_j), L_ij = 1 (j < i),
// 1/2 (j = i), 0 (j > i), every n x n matrix of the Newton tangent is
//   T = diag(d) + k (cyclic 2,-1,-1) + sum_t c_t U_t^T (I_2 (x) A) W_t,   A = L^T L,
// where U_t, W_t are "2-vector per column" matrices (column j has its two entries in
// the x and y rows of segment j): the inertia part m l^2 U^T A W with U_j = e'(phi_j)
// (derivation in dynamics_sparse.cpp), and, with mass-proportional damping, the
// constant M(phi0) = m l^2 U0^T A U0 + Jr I. L = (I - Z)^{-1} (I + Z) / 2 with Z the
// down-shift, so y = L w and s = L^T y are the sparse bidiagonal relations
//   y_j - y_{j-1} = (w_j + w_{j-1}) / 2,   s_j - s_{j+1} = (y_j + y_{j+1}) / 2,
// and the saddle-point system [T G^T; G 0] becomes a sparse system in
// (dq, y_t, s_t, dlambda) of order n (1 + 4 terms) + c with O(n) non-zeros, factored
// by Eigen's SparseLU (COLAMD ordering; fill measured O(n), see the bench). Each solve
// is refined against the exact O(n) product T x, so it is accurate to round-off of the
// dense LU's size.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <memory>
#include <vector>

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"

namespace multibody::detail {

/// One term c U^T (I_2 (x) A) W of a structured matrix; column j of `left`/`right` is
/// the 2-vector of segment j.
struct LowRankTerm {
  double coef = 0.0;
  Eigen::Matrix2Xd left, right;
};

/// T = diag(d) + cyclic * (2,-1,-1 cyclic) + sum of terms; n x n, never formed. O(n) memory.
struct StructuredMatrix {
  Vector diag;
  double cyclic = 0.0;
  std::vector<LowRankTerm> terms;
  Eigen::Index size() const { return diag.size(); }
  /// T x. O(n).
  Vector times(const Vector& x) const;
  /// The diagonal of T. O(n).
  Vector diagonal() const;
  /// Dense copy (tests only). O(n^2).
  Matrix dense() const;
};

/// (I_2 (x) A) w per component, A = L^T L (two cumulative sums). O(n).
Eigen::Matrix2Xd apply_A(const Eigen::Matrix2Xd& w);

/// Inertia force r = M(q) qdd + xi(q, v) and, if T is given, its tangent
/// cm M + cv d xi/dv + d(M qdd + xi)/dq added to *T (the same quantity as
/// inertia_terms of dynamics_model.hpp, in O(n)).
void inertia_terms_structured(const Chain& chain, const Vector& q, const Vector& v,
                              const Vector& qdd, double cm, double cv, Vector& r,
                              StructuredMatrix* T);

/// M(q) as a structured matrix (m l^2 U^T A U + Jr I). O(n).
StructuredMatrix mass_structured(const Chain& chain, const Vector& q);

/// The factorized saddle-point matrix [T sc G^T; sc G 0] of a structured T. O(n) fill.
class SparseSaddle {
 public:
  /// Factors; false if SparseLU reports a singular matrix.
  bool factor(const StructuredMatrix& T, const Matrix& G, double sc);
  /// Solves [T sc G^T; sc G 0] [x; y] = [b; d] with `refinements` steps of iterative
  /// refinement against the exact product. False on a non-finite result.
  bool solve(const Vector& b, const Vector& d, Vector& x, Vector& y, int refinements = 2) const;
  /// Non-zeros of the assembled matrix and of the L and U factors (bench counters).
  long nonzeros() const { return nnz_; }
  long factor_nonzeros() const;

 private:
  StructuredMatrix T_;
  Matrix G_;
  double sc_ = 1.0;
  int stride_ = 1;
  long nnz_ = 0;
  Eigen::Index order_ = 0;
  std::shared_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>> lu_;
};

/// closest_nonadjacent (dynamics_model.hpp) with a uniform grid of cell size l + reach
/// over the segment midpoints: only segments in neighbouring cells can be closer than
/// `reach`, so the same pairs are measured in O(n) expected time; same result
/// (smallest distance, ties to the lexicographically first pair). `l` is the segment
/// length (all segments are rigid and equally long).
ClosestPair closest_nonadjacent_grid(const Eigen::Matrix2Xd& hinges, double l, int min_gap,
                                     double reach);

}  // namespace multibody::detail
