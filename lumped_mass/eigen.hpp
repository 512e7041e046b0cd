// The constrained generalized eigenproblem of a lumped::Model:
//   K x = lambda M x,  C x = 0,  S x = 0,  lambda = omega^2,
// with the massless DOFs condensed statically. Two paths that share only the model:
//
// dense (O(N^3) time, O(N^2) memory; for small n): supports eliminated by an
//   orthonormal selection T (S T = 0), link constraints by an orthonormal null-space
//   basis Z of C T (Householder QR of (C T)^T), massless DOFs by Guyan condensation
//   Kd = Kaa - Kab Kbb^-1 Kba; then Eigen's GeneralizedSelfAdjointEigenSolver
//   (Cholesky of the reduced mass, which is positive definite).
// sparse (O(n) time per operator application and O(n) memory): shift-invert Lanczos
//   (Spectra::SymGEigsShiftSolver) in the space of the inertial DOFs. The operator
//   (A - sigma B)^-1 x solves the sparse system
//       [ Kt - sigma Mt   Ct^T ] [y]   [E x]
//       [ Ct              0    ] [z] = [ 0 ]
//   and returns the inertial part E^T y: this is exactly the constrained inverse
//   Z (Z^T (Kt - sigma Mt) Z)^-1 Z^T of the link constraints and the Schur complement
//   of the massless DOFs, without forming either. Factorization: SparseLU (COLAMD) for
//   the indefinite saddle-point matrix of the chain, SimplicialLDLT (AMD) for the
//   frames, which is positive definite because sigma < 0. The chain's midpoint mass
//   matrix is singular on the whole space (the zig-zag u_k = (-1)^k v moves no
//   midpoint), so the Lanczos inner product uses B = Mt + m Ct^T Ct, positive definite,
//   and equal to Mt on the admissible vectors the operator produces.
//   Shift sigma = -EI/(rho A R^4): below every eigenvalue, so a free ring's singular K
//   is no problem and rigid modes come out as the largest 1/(lambda - sigma).
//
// Rigid modes: an eigenvalue lambda < kRigidThreshold * EI/(rho A R^4) counts as rigid.
// The lowest elastic omega^2 of any supported or free ring is >= ~2 EI/(rho A R^4)
// (free ring k = 2: 7.2; pinned ring: 2.5 in these units), while a rigid mode's
// lambda is roundoff; the count must equal Supports::rigid_modes(), or NumericalError.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "lumped_mass/model.hpp"

namespace lumped {

/// omega^2 below this fraction of EI/(rho A R^4) is a rigid (zero) mode.
constexpr double kRigidThreshold = 1e-6;

enum class Method { automatic, dense, sparse };

/// Eigenpairs in the model's own DOFs (model.hpp), supports and constraints satisfied.
struct Eigenpairs {
  std::vector<double> lambda;  ///< omega^2, ascending: `rigid` rigid modes first, then elastic
  Eigen::MatrixXd X;           ///< N x lambda.size(), columns M-orthonormal (x^T M x = 1),
                               ///< massless DOFs filled with their condensed values
  int rigid = 0;               ///< rigid modes found (== model.expected_rigid)
  Method method = Method::dense;  ///< the path that ran (dense or sparse)
  long long unknowns = 0;      ///< size of the eigenproblem (dense: reduced size; sparse:
                               ///< order of the factorized sparse system)
  long long factor_nonzeros = 0;  ///< sparse path: nonzeros of the factors (0 for dense)
  double max_residual = 0.0;   ///< largest relative residual of the elastic pairs, see residuals()
};

/// Elastic modes available: admissible DOFs minus rigid modes.
int elastic_dofs(const Model& model);

/// The `count` lowest elastic modes and all rigid ones. automatic picks dense for
/// n <= 96 or when count is too close to elastic_dofs() for Lanczos, else sparse.
/// Throws std::invalid_argument for count outside [1, elastic_dofs()] (or too large for
/// the sparse path when Method::sparse is forced), ring::NumericalError if the
/// factorization or the iteration fails or the rigid count disagrees with the supports.
Eigenpairs solve(const Model& model, int count, Method method = Method::automatic);

/// Relative residual of each pair, ||P (K x - lambda M x)|| / (||K x|| + lambda ||M x||),
/// P the orthogonal projector onto the admissible DOFs (null space of C and S; the
/// constraint forces are removed), maxed with ||[C; S] x|| / ||x||. O(n) per pair.
std::vector<double> residuals(const Model& model, const Eigenpairs& pairs);

}  // namespace lumped
