// The one eigen step of linear buckling (ring/analysis.hpp, BucklingOptions) that every
// solver shares: the lowest positive load factors of the pencil (K_0 + lambda K_1), given
// the two matrices on the solver's admissible space (constraints eliminated). Each
// solver builds K_0 and K_1 in its own coordinates; this layer knows no solver.
//
// Method: K_0 = L L^T (Cholesky; K_0 must be positive definite: a held ring at rest), then
// the symmetric C = L^-1 K_1 L^-T, whose eigenvalues mu = -1 / lambda (LAPACK-style dense
// tridiagonal QR, Eigen's SelfAdjointEigenSolver); the positive lambda are the negative mu,
// the lowest lambda the most negative mu. x = L^-T y. Cost: O(N^3) time, O(N^2) memory.
#pragma once

#include <Eigen/Dense>
#include <string>

namespace modal {

struct CriticalFactors {
  Eigen::VectorXd factors;  ///< lambda_1 <= lambda_2 <= ..., positive
  Eigen::MatrixXd vectors;  ///< [N x count], column i the mode of factors[i]
};

/// The `count` lowest positive lambda of (K_0 + lambda K_1) x = 0, K_0 symmetric positive
/// definite, K_1 symmetric (both read from their lower triangles). A mu within 1e-12 of
/// the largest |mu| of zero is no buckling (lambda beyond 1e12 times the lowest). Throws
/// std::invalid_argument naming `who` when K_0 is not positive definite (a rigid mode the
/// supports leave free), or naming buckling.count when the pencil has fewer than `count`
/// positive factors (the others buckle under the loads reversed, or never).
CriticalFactors critical_factors(const Eigen::MatrixXd& K0, const Eigen::MatrixXd& K1, int count,
                                 const std::string& who);

/// The modes of a loaded equilibrium (modes.preload = "static"): the `count` lowest omega^2 of
/// T x = omega^2 M x, T the tangent stiffness there (symmetric, read as (T + T^T) / 2; the
/// prestress and the loads' own stiffness in it) and M the mass, both on the constraints'
/// tangent space. Method: the shifted inverse, S = T + shift M = L L^T (Cholesky), the largest
/// mu of L^-1 M L^-T (a symmetric eigensolve), omega^2 = 1/mu - shift, x = L^-T y; `shift`
/// (the solver's bending scale) lifts the near-singular T of a ring close to a critical load
/// so that S stays definite while the ring is stable. Throws std::invalid_argument naming
/// modes.count when count exceeds the space, and ring::NumericalError ("`who`: ...") when S
/// is not positive definite or an omega^2 <= 0: the ring is at or past a critical load.
/// max_residual: the largest ||T x - w^2 M x|| / (||T x|| + w^2 ||M x||). O(N^3).
struct LoadedModes {
  Eigen::VectorXd omega2;   ///< ascending, positive
  Eigen::MatrixXd vectors;  ///< [N x count], column i the mode of omega2[i]
  double max_residual = 0.0;
};
LoadedModes loaded_modes(const Eigen::MatrixXd& T, const Eigen::MatrixXd& M, double shift, int count,
                         const std::string& who);

/// An orthonormal basis of ker G (N x (N - rank G); the identity without rows): the
/// trailing columns of Q in the column-pivoted Householder QR G^T = Q R. O(N^2 C).
Eigen::MatrixXd kernel_basis(const Eigen::MatrixXd& G, Eigen::Index N);

/// How many independent directions the equilibrium with tangent stiffness T (N x N) under
/// constraints with Jacobian G (C x N) is unstable in: the negative eigenvalues of Z^T T Z,
/// Z an orthonormal basis of ker G (Householder QR of G^T; rank-revealing), below -1e-12
/// of the largest |eigenvalue| (rounding is ~1e-16 of it; a crossing eigenvalue moves with
/// the load at ~(l/R)^4 of it, so a count is late by ~1e-12 (R/l)^4 in the load factor:
/// 3e-7 at n = 160). For the continuation driver's bifurcation test
/// (paths/continuation.hpp). Dense: O(N^3).
int unstable_directions(const Eigen::MatrixXd& T, const Eigen::MatrixXd& G);

/// The same tangent's least stable direction: Z y, y the unit eigenvector of the least
/// eigenvalue of Z^T T Z (for branch switching, paths/continuation.hpp), and that
/// eigenvalue. O(N^3).
struct LeastStable {
  Eigen::VectorXd direction;  ///< N values, in ker G
  double eigenvalue = 0.0;
};
LeastStable least_stable(const Eigen::MatrixXd& T, const Eigen::MatrixXd& G);

}  // namespace modal
