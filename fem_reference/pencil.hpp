// Internal to fem_reference/: the dense eigen step of a pencil on the geometrically exact
// beam's reduced unknowns (RingModel or the Reissner TimoshenkoModel) and its refinement, shared by linear buckling
// (buckling.cpp) and the frequencies under load (preload.cpp). Both pencils have the form
//
//   (P + lambda Q) x = 0,   P = K_0 + E symmetric positive definite,
//
// K_0 the linear model's stiffness (the beam's tangent at rest, T(0, 0)), E a dense
// correction (buckling: none, P = K_0, Q = K_1; under load: E = T(q*, 1) - K_0 + s M, so
// that P = T(q*, 1) + s M, and Q = -M, lambda = omega^2 + s), and the lowest positive
// lambda are wanted. The raw pairs come from modal/ (buckling: raw_pairs(), i.e.
// modal::critical_factors; under load: modal::loaded_modes, the chains' step), both a
// Cholesky of P, O(N^3); refine() then improves them in extended precision.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "fem_reference/ring_model.hpp"

namespace fem::detail {

/// The reduced sparse matrix as a dense one. O(N^2) memory, O(nnz) fill.
Eigen::MatrixXd dense(const SparseMatrix<double>& A);

/// The dense step's size rule (fem::kDenseBucklingLimit reduced unknowns): above it a
/// user's discretization is a std::invalid_argument naming fem.elements and fem.degree, a
/// step of a reference refinement (`refining`) a ring::NumericalError. `analysis` names
/// the analysis in the message ("buckling", "modes under load"). O(1).
void check_dense_size(const Setup& setup, unsigned int unknowns, bool refining, const std::string& analysis);

/// Lowest positive factors of a pencil and their vectors (columns), ascending; the
/// columns beyond the wanted ones are guards for the refinement.
struct Pairs {
  std::vector<double> factors;
  Eigen::MatrixXd vectors;
  /// refine(): each wanted pair's relative residual sqrt(r^T P^-1 r / x^T P x),
  /// r = (P + lambda Q) x, and the worst of them.
  std::vector<double> residuals;
  double residual = 0.0;
};

/// The dense eigen step (modal::critical_factors) for `count` + kGuardModes pairs, or,
/// when the pencil has fewer positive factors, for `count` alone (which then throws
/// std::invalid_argument naming buckling.count if even those are not there; and when P is
/// not positive definite). O(N^3).
Pairs raw_pairs(const Eigen::MatrixXd& P, const Eigen::MatrixXd& Q, int count, unsigned int N);

/// Improves the dense step's pairs as the modes' refine() does theirs (ring_model.hpp):
/// the thin ring's membrane stiffness makes a double-precision dense step lose 3e-9
/// (extensible) to 1e-7 (inextensible, beta = 2e6) of the bending factors (measured on the
/// paper's ring, N = 130..570; refined: ~2e-11), because the P it factors holds the
/// bending energy only as a cancellation of stiff terms.
/// Rayleigh-Ritz on the span of the pairs with X^T K_0 X accumulated in extended precision
/// from the strain fields (LinearModel::stiffness_product; E and Q are applied in double:
/// they hold no stiff part of their own, only the assembly's rounding of the stiff
/// entries, see preload.hpp), then the corrections x -= P^-1 r of the wanted pairs,
/// r = P x + lambda Q x (one step of inverse iteration in the form that keeps the digits),
/// the guards x <- P^-1 Q x (subspace iteration), each round followed by Ritz, until the
/// wanted residuals ||r||_* / ||P x||_* (dual norm of P: ||r||_*^2 = r^T P^-1 r) are
/// below kRefinedResidual or stop halving, at most kMaxRefinementRounds. A wanted pair
/// whose residual stays above kAcceptedResidual is a ring::NumericalError naming `who`.
/// `E` may be empty (0 x 0: none). `P_inverse` factors the sparse P.
/// O(rounds (m N p + N^2 m)) for m pairs.
Pairs refine(const LinearModel& model, const SparseDirectUMFPACK& P_inverse, const Eigen::MatrixXd& E,
             const Eigen::MatrixXd& Q, Pairs p, int count, const std::string& who);

}  // namespace fem::detail
