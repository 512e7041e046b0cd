// Internal to multibody/dynamics.cpp: the O(n) large-n path of the forced response.
// Same equations, same coordinates (segment angles) and the same
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
// (dq, y_t, s_t, dlambda) of order n (1 + 4 terms) + c. Interleaved segment by segment
// it is banded (bandwidths ~2 stride and stride) except for the springs' two cyclic
// corner entries and the c constraint rows and columns; those form a border of 2 + c
// unknowns: a BorderedBand (bordered_band.hpp). Solves can be refined against the exact
// O(n) product T x; Newton corrections are not (the iteration itself refines them), the
// consistent initial accelerations are (twice).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "multibody/bordered_band.hpp"
#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"

namespace multibody::detail {

/// One term c U^T (I_2 (x) A) W of a structured matrix; column j of `left`/`right` is
/// the 2-vector of segment j.
struct LowRankTerm {
  double coef = 0.0;
  Eigen::Matrix2Xd left, right;
};

/// T = diag(d) + cyclic * (2,-1,-1 cyclic) + sum_k hinge_k grad r_k grad r_k^T + sum of
/// terms, r_k = q_k - q_{k-1} (cyclic) the hinge rotations: the hinges' own tangents (a plastic
/// law's, bending.hpp; empty: none); n x n, never formed. O(n) memory.
struct StructuredMatrix {
  Vector diag;
  double cyclic = 0.0;
  Vector hinge;  ///< per-hinge tangent stiffness on r_k (n entries) or empty
  std::vector<LowRankTerm> terms;
  /// hinge_k, 0 when there are none (k cyclic).
  double hinge_at(Eigen::Index k) const {
    const Eigen::Index n = diag.size();
    return hinge.size() ? hinge[(k % n + n) % n] : 0.0;
  }
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

/// The factorized saddle-point matrix [T sc G^T; sc G 0] of a structured T as a
/// BorderedBand: the banded core (dq, y, s), and the springs' two cyclic corner entries
/// and the c constraint rows as a border of 2 + c unknowns. O(n) time and memory.
class SparseSaddle {
 public:
  /// Factors; false when the matrix is singular by BorderedBand's test.
  bool factor(const StructuredMatrix& T, const Matrix& G, double sc);
  /// Solves [T sc G^T; sc G 0] [x; y] = [b; d] with `refinements` steps of iterative
  /// refinement against the exact product. False on a non-finite result.
  bool solve(const Vector& b, const Vector& d, Vector& x, Vector& y, int refinements = 0) const;
  /// The same for the k columns of [B; D] at once (one pass over the band's factors),
  /// without refinement. False on a non-finite result.
  bool solve_columns(const Matrix& B, const Matrix& D, Matrix& X, Matrix& Y) const;
  Eigen::Index constraints() const { return G_.rows(); }  ///< c
  /// Entries of the bordered matrix's pattern and doubles stored (bench counters).
  long nonzeros() const { return band_.entries(); }
  long factor_nonzeros() const { return band_.stored(); }

 private:
  StructuredMatrix T_;
  Matrix G_;
  double sc_ = 1.0;
  BorderedBand band_;  ///< its structure depends on n, the number of terms and c only
};

/// closest_nonadjacent (dynamics_model.hpp) with a uniform grid of cell size l + reach
/// over the segment midpoints: only segments in neighbouring cells can be closer than
/// `reach`, so the same pairs are measured in O(n) expected time; same result
/// (smallest distance, ties to the lexicographically first pair). `l` is the segment
/// length (all segments are rigid and equally long).
ClosestPair closest_nonadjacent_grid(const Eigen::Matrix2Xd& hinges, double l, int min_gap,
                                     double reach);

/// The contact test of every response step: closest_nonadjacent below kGridContact
/// segments (the O(n^2) box loop is as fast there, both well under a step's cost), the
/// grid above (same pairs, same result, O(n)). `closed` = false: an arch's open chain
/// (closest_nonadjacent's box loop at every n: the arch runs on the dense paths only).
constexpr int kGridContact = 128;
ClosestPair closest_contact(const Eigen::Matrix2Xd& hinges, double l, int min_gap, double reach, bool closed = true);

}  // namespace multibody::detail
