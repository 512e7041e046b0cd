// The constrained generalized eigenproblem of a lumped::Model:
//   K x = lambda M x,  C x = 0,  S x = 0,  lambda = omega^2,
// with the massless DOFs condensed statically. Two paths that share only the model:
//
// Both paths use the stiffness only in factored form, K = B^T diag(D) B (model.hpp).
// In Cartesian node coordinates the assembled K is a fourth difference: its entries are
// ~(R/l)^4 times what a smooth mode's K x is, so any solver that factors or reduces the
// assembled K loses eps (R/l)^4 relative accuracy in the low modes (1e-3 at n = 1e4,
// everything at n = 1e5). Through B (a second difference) the loss is eps (R/l)^2.
//
// dense (O(N^3) time, O(N^2) memory; for small n): supports eliminated by an
//   orthonormal selection T (S T = 0), link constraints by an orthonormal null-space
//   basis Z of C T (Householder QR of (C T)^T), massless DOFs by static (Guyan)
//   condensation done as a least-squares projection of D^1/2 B; with Y the resulting
//   basis and Y^T M Y = L L^T (after Jacobi scaling), lambda = sigma^2 for the singular
//   values sigma of F = D^1/2 B Y L^-T (Eigen::BDCSVD): small singular values carry
//   absolute error eps ||F||, i.e. relative error eps sqrt(lambda_max / lambda) in lambda.
// sparse (O(n) memory, O(n) per operator application): shift-invert Lanczos of the
//   eigen layer (modal/lanczos.hpp: Spectra's SymGEigsShiftSolver, the layer's subspace
//   rule and start vector) in the space of the inertial DOFs. The operator
//   (A - sigma B)^-1 x solves the sparse mixed (stress) system
//       [ -sigma Mt   Bt^T    Ct^T ] [y ]   [E x]
//       [ Bt         -D^-1    0    ] [s ] = [ 0 ]     (s = D Bt y: strain resultants)
//       [ Ct          0       0    ] [mu]   [ 0 ]
//   (rows and columns scaled for pivoting) and returns the inertial part E^T y. Its
//   Schur complement on y is Kt - sigma Mt restricted to C y = 0 with the massless DOFs
//   condensed: the constrained inverse Z (Z^T (Kt - sigma Mt) Z)^-1 Z^T and the Guyan
//   condensation without forming either. Factorization: SparseLU with COLAMD (the
//   system is indefinite); fill O(n) for the ring's cyclic-banded pattern (measured
//   15-20 factor nonzeros per unknown for n = 1e3..1e5). The chain's midpoint mass matrix
//   is singular on the whole space (the zig-zag u_k = (-1)^k v moves no midpoint), so the
//   Lanczos inner product uses B = Mt + m Ct^T Ct, positive definite, and equal to Mt on
//   the admissible vectors the operator produces; the start vector is op(B r).
//   Shift sigma = -EI/(rho A R^4): below every eigenvalue, so a free ring's singular K
//   is no problem and rigid modes come out as the largest 1/(lambda - sigma).
//
// Rigid modes: the eigen layer's rule (modal/modes.hpp), an eigenvalue
// lambda < modal::kRigidThreshold * EI/(rho A R^4) counts as rigid.
// The lowest elastic omega^2 of the paper's rings is >= ~2 EI/(rho A R^4)
// (free ring k = 2: 7.2; pinned ring: 2.5 in these units), while a rigid mode's
// lambda is roundoff; the count must equal RingSpec::rigid_modes(), or NumericalError.
// Springs, masses and a foundation can bring a mode below the threshold only when their
// stiffness is below ~1e-6 of the ring's own (e.g. k_t < 1e-6 EI/R^4 holding the rotation).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "lumped_mass/model.hpp"
#include "modal/modes.hpp"

namespace lumped {

enum class Method { automatic, dense, sparse };

/// Eigenpairs in the model's own DOFs (model.hpp), supports and constraints satisfied.
struct Eigenpairs {
  std::vector<double> lambda;  ///< omega^2, ascending: `rigid` rigid modes first, then elastic
  Eigen::MatrixXd X;           ///< N x lambda.size(), columns M-orthonormal (x^T M x = 1),
                               ///< massless DOFs filled with their condensed values
  int rigid = 0;               ///< rigid modes found (== model.expected_rigid)
  Method method = Method::dense;  ///< the path that ran (dense or sparse)
  long long unknowns = 0;      ///< dimension of the eigenproblem: admissible DOFs after supports,
                               ///< constraints and condensation (elastic_dofs() + rigid), both paths
  long long system_order = 0;  ///< sparse path: order of the factorized mixed system (0 for dense)
  long long factor_nonzeros = 0;  ///< sparse path: nonzeros of the factors (0 for dense)
  double max_residual = 0.0;   ///< largest relative residual of the elastic pairs (residuals())
};

/// Elastic modes available: admissible DOFs minus rigid modes.
int elastic_dofs(const Model& model);

/// The `count` lowest elastic modes and all rigid ones. automatic picks dense for
/// n <= 24 (sparse is already faster at n = 40: bench/lumped_mass) or when count + rigid > elastic_dofs() / 3 (Lanczos would need nearly the
/// whole space), else sparse.
/// Throws std::invalid_argument for count outside [1, elastic_dofs()] (or too large for
/// the sparse path when Method::sparse is forced), ring::NumericalError if the
/// factorization or the iteration fails or the rigid count disagrees with the supports.
Eigenpairs solve(const Model& model, int count, Method method = Method::automatic);

/// Relative residual of each pair, ||P (K x - lambda M x)|| / (||K x|| + lambda ||M x||),
/// P the orthogonal projector onto the admissible DOFs (null space of C and S; the
/// constraint forces are removed): ModalResult::max_residual's definition (ring/results.hpp).
/// How well the pairs satisfy C x = 0 and S x = 0 is not part of it (the solver builds them
/// in the admissible space; tests/lumped_mass/solver_test.cpp bounds the drift). O(n) per pair.
std::vector<double> residuals(const Model& model, const Eigenpairs& pairs);

}  // namespace lumped
