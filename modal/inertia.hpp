// The inertia (negative, zero, positive eigenvalue counts) of a large sparse symmetric
// matrix whose pattern is a band in a known ordering plus a small border, without its
// eigenvalues: Sylvester's law of inertia on a block LDL^T. For the continuation driver's
// bifurcation test (paths/continuation.hpp) at sizes where the dense count
// (modal::unstable_directions, O(N^3)) is out of reach.
//
// ## Method
// A frontal block elimination (the idea of Duff & Reid's multifrontal codes, on one
// front): the unknowns are eliminated in `groups`, in order; the front is a dense matrix
// holding the border (never eliminated until the end), the groups waiting to be
// eliminated, and every group coupled to them (entered when the group they couple to is
// about to go). A group's pivot block D = F[P, P] (P: the group and any groups delayed
// before it) is decomposed by a symmetric eigen-solve; it is accepted when it is regular
// and its multipliers L = F[R, P] D^-1 onto the rows R of the front that will be pivots
// later (not the border's) are at most 1 / u in size (threshold pivoting, u = `threshold`,
// MA57's rule on blocks; the border's rows only accumulate their Schur complement, which
// feeds no pivot but the final dense count, so their growth is left free: a constraint
// row coupled to every unknown grows along the band however the band is pivoted), and then
//   inertia(K) = inertia(D) + inertia(F[R, R] - L D L^T)
// (Haynsworth's inertia additivity of the Schur complement). A rejected pivot is delayed:
// it joins the next group's pivot. The front that is left at the end (border and any
// delayed groups) is counted by a dense eigen-solve.
// Exact in exact arithmetic for any accepted sequence; in floating point the count is that
// of K + E with E of the order of eps times the size of the entries multiplied by the
// growth, which the threshold bounds by (1 + 1/u) per elimination that touches an entry.
//
// Cost: O(N f^2) time and O(f^2) extra memory, f the front size (the band's width in
// unknowns plus the border plus delayed unknowns); nullopt when the front would exceed
// `max_front` (a pattern that is not band plus border in this ordering, or too many delays).
#pragma once

#include <Eigen/SparseCore>
#include <optional>
#include <vector>

namespace modal {

struct Inertia {
  long negative = 0, zero = 0, positive = 0;
};

/// The inertia of the symmetric K (both triangles stored), eliminated group by group in the
/// order of `groups` and then `border` (file comment). Every index 0..K.rows()-1 must be in
/// exactly one group or in the border (std::invalid_argument otherwise). An eigenvalue of
/// a pivot or of the final front within 1e-15 of the largest |entry| of K counts as zero.
/// nullopt when the front would grow beyond `max_front` unknowns.
std::optional<Inertia> frontal_inertia(const Eigen::SparseMatrix<double>& K, const std::vector<std::vector<int>>& groups,
                                       const std::vector<int>& border, int max_front = 200, double threshold = 0.01);

}  // namespace modal
