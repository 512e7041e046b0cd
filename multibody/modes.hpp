// Linear natural frequencies of the rigid-segment chain (the paper's section 4).
//
// ## Problem
// Linearized about the undeformed n-gon q0 (no preload, so neither the constraint
// forces nor the quadratic-velocity terms contribute), with a basis D of the null space
// of the constraint Jacobian J = Chain::constraint_jacobian(q0) (delta q = D x):
//   \f$ K_0 x = \omega^2 M_0 x,\quad K_0 = D^T K D,\quad M_0 = D^T M(q_0) D \f$
// (the paper's equations 24-26). Unknowns r = dofs - constraints: n - 2 (pin),
// n - 3 (pin + roller), n (free ring).
//
// ## Dependent coordinates (MultibodyOptions::dependent)
// - `paper`: the last two angles are dependent, D = [I; -J_2^{-1} J_1] (equation 17),
//   J_2 = the 2x2 block of the last two columns, det J_2 = l^2 sin(2 pi / n): its
//   condition number grows like n. With a roller the third dependent angle is that of
//   segment r-1 (r = roller hinge; segment n-3 if r-1 >= n-2), whose roller-row entry is
//   the only one among the three dependent columns.
// - `robust` (default): D = the last r columns of the orthogonal factor Q of a
//   Householder QR of J^T (an orthonormal null-space basis, condition number 1 for any
//   n and any configuration), applied implicitly (O(n^2) for Q^T A Q).
//
// ## Solution method (dense path)
// In angle coordinates M_0 is ill-conditioned (its spectrum spans ~n^2 and the pencil's
// ~n^4), so the usual Cholesky of M_0 loses the lowest eigenvalues (1e-5 .. 1e-3
// relative at n = 640 without rotary inertia). We solve the inverse problem instead:
// with the shift s = EI / (rho A R^4) (the ring's bending scale squared, a few tenths of
// the lowest elastic omega^2), S = K_0 + s M_0 is positive definite and well conditioned
// for the modes that matter; the LARGEST eigenvalues mu of S^{-1} M_0 give
// omega^2 = 1/mu - s. Their rounding error is ~eps ||M_0|| / lambda_min(S) ~ eps mu_max,
// i.e. relative accuracy ~1e-14 for the lowest mode (the requested ones lose at most the
// ratio mu_1 / mu_k). Small problems (r <= 300, or more than r/3 modes) use a full
// symmetric eigensolver of G^{-1} M_0 G^{-T} (S = G G^T); larger ones use Spectra's
// Lanczos (SymEigsSolver) on the same operator and compute only the modes requested.
// Cost: O(r^3) for the Cholesky factorizations (S and the M_0 check), O(r^2) per Lanczos
// step; O(r^3) eigenvectors on the small path.
//
// ## Sparse path (MultibodyOptions::method = sparse, or automatic above kSparseThreshold)
// Same pencil, never formed: K and M(q0) only as O(n) operators in chain coordinates
// (M through the midpoint kinematics). The constrained solve with S = K + s M is
// O(n): S = A + (cyclic spring at hinge 0) + (translation coupling, free ring), where A
// (the open chain held at hinge 0) is solved by a discrete Riccati sweep over the state
// (hinge displacement, previous angle) with scalar pivots (Cholesky-stable, ~60 flops per
// segment), and the constraints J dq = 0 and the two couplings form a border of <= 6
// unknowns (Schur complement of prefactored solves); one step of iterative refinement.
// Eigenvalues: a Lanczos of our own for T = S_c M in the S inner product on the null
// space of J (full reorthogonalization, DGKS second pass, no restart), Ritz values from
// the exact Rayleigh quotient V^T M V so solve errors only slow convergence; a closed
// Krylov space (multiple eigenvalues: the free ring's rigid modes and cos/sin pairs)
// continues with a fresh random direction. The orthonormal basis D (Householder of J^T)
// is applied only to the final vectors (x = D^T dq). Cost: ~45-50 Lanczos steps for 23
// modes at every n, each O(n) plus 4 k n for the reorthogonalization (k = step); memory
// N x (steps + 1) doubles plus the outputs. Measured curve: multibody/README.md. Robust
// dependent coordinates only; n >= 10 (forcing it below is an input error: at n = 8 every mode is wanted and the
// Krylov space degenerates).
//
// ## Residuals: why max_residual grows like n^2 on either path and what to read instead
// For a smooth low mode x, K0 x is a second difference of a smooth vector: it is computed
// with an absolute error ~eps ||K0|| ||x|| while its size is ~omega^2 ||M0 x||, so the
// relative residual ||K0 x - w^2 M0 x|| / (||K0 x|| + w^2 ||M0 x||) of even the EXACT
// eigenvector is floored at ~eps ||K0|| / (omega^2 ||M0||) ~ eps (n / k)^2-ish: measured
// 2.7e-10 (n = 10^3), 1.7e-8 (10^4), 1.8e-6 (10^5), 2e-4 (10^6) while the frequencies stay
// within 1e-11 of the oracles. ModalSolution::backward_error (normwise,
// ||r|| / ((||K0|| + w^2 ||M0||) ||x||)) is the meaningful measure: ~1e-12 at every n up
// to 10^6 on the sparse path, ~1e-15 on the dense one: the growth of max_residual is
// this floor, not a loss of accuracy.
//
// ## Rigid modes
// A computed omega^2 < kRigidThreshold * s (s as above) is a rigid (zero) mode: counted
// in ModalResult::rigid_modes, never numbered, never returned. The chain is inextensible,
// so omega^2 / s depends on n and the supports only: the lowest elastic omega^2 is
// 0.79 s (n = 4, pinned) and >= 1.1 s from n = 5 (2.5 s pinned, 7.2 s free at large n),
// while the robust path's rigid modes come out at |omega^2| <= 2e-12 s up to n = 2000:
// the threshold 1e-6 s sits more than five orders from both. (The paper's coordinates
// at n = 2000 without rotary inertia push the rigid mode to 1.5e-5 s and miss it; see
// MultibodyStress.) Expected: 1 (pin), 0 (pin + roller), 3 (free).
//
// ## Outputs
// ModalResult: solver "multibody"; model {n, rotary_inertia, dependent, method};
// omega = the `count` lowest elastic modes in rad/s ascending; shapes = hinge
// displacements sampled with ring::sample_polygon (anchor = hinge 0's angle, the pin's or
// 0 deg for a free ring); unknowns = r; seconds = solver wall time (assembly, reduction,
// factorizations, eigensolver, eigenvectors; not the sampling at the 360 stations, which
// costs ~10 us per mode in ring::sample_polygon);
// max_residual = max over the returned modes of
// ||K_0 x - w^2 M_0 x|| / (||K_0 x|| + w^2 ||M_0 x||).
//
// Usage:
//   ring::RingSpec spec;  spec.section.diameter = 0.12;  spec.supports.pin = 180.0;
//   ring::MultibodyOptions opt;  opt.n = 40;
//   ring::ModalResult r = multibody::compute_modes(spec, opt, 23);
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "multibody/chain.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// omega^2 < kRigidThreshold * EI / (rho A R^4) counts as a rigid mode.
constexpr double kRigidThreshold = 1e-6;

/// MultibodyOptions::Method::automatic takes the sparse path above this n (robust only).
/// Measured (23 modes, pinned, rotary inertia, minimum of 3 runs, loaded 2-core machine):
/// dense 8 ms / sparse 14 ms at n = 160, dense 35 ms / sparse 16 ms at n = 320, dense
/// 207 ms / sparse 14 ms at n = 640. Both are within 1e-12 of the independent oracles on
/// either side (tests/multibody/test_modes_sparse.cpp), so the switch costs no accuracy.
constexpr int kSparseThreshold = 256;
/// True when solve_modes may take the sparse large-n path for these options (automatic:
/// n > kSparseThreshold, robust; solve_modes then also requires count + rigid + 2 <= r / 3,
/// else dense).
bool uses_sparse_path(const ring::MultibodyOptions& options);

/// The linearized, constraint-reduced problem about the n-gon (for tests and studies).
struct LinearModel {
  Matrix K0;           ///< r x r, D^T K D
  Matrix M0;           ///< r x r, D^T M(q0) D
  double j2_condition = 0.0;  ///< 2-norm condition of the paper's block J_2 (the last two
                              ///< angle columns of the closure Jacobian), for reporting
  /// delta q = D x for the columns of x (r x k): O(n k). Chain coordinates of reduced vectors.
  Matrix expand(const Matrix& x) const;
  /// D itself, dofs x r (dense, O(n^2)).
  Matrix basis() const;

  // D is kept implicit: paper: rows `independent` = identity, rows `dependent` = X;
  // robust: the last r columns of the Householder factor Q of J^T.
  ring::MultibodyOptions::Dependent kind = ring::MultibodyOptions::Dependent::robust;
  std::vector<int> independent, dependent;
  Matrix X;                           ///< paper: -J_P^{-1} J_I, c x r
  Eigen::HouseholderQR<Matrix> qr;    ///< robust: QR of J^T
};

/// Assembles K0 and M0 (and the implicit D) for `chain` with the given dependent-coordinate
/// choice. Cost O(n^2 c) time, O(n^2) memory (c = constraints, 2 or 3).
LinearModel linearize(const Chain& chain, ring::MultibodyOptions::Dependent dependent);

/// Full modal solution, with the coordinates behind ModalResult.
struct ModalSolution {
  ring::ModalResult result;
  Matrix x;             ///< r x count reduced eigenvectors, M0-orthonormal
  Matrix dq;            ///< dofs x count chain-coordinate shapes delta q = D x
  /// n x count hinge displacements (m per unit modal amplitude, ring-centred frame):
  /// row k = hinge k at rest angle anchor + 360 k / n; the linearized kinematics of dq.
  Matrix hinge_ux, hinge_uy;
  Eigen::VectorXd rigid_omega2;  ///< computed omega^2 of the modes counted as rigid
  /// Normwise backward error, max over the returned modes of
  /// ||K0 x - w^2 M0 x|| / ((||K0|| + w^2 ||M0||) ||x||) (2-norms estimated by power
  /// iteration; on the sparse path those of the unreduced K and M). Unlike
  /// result.max_residual it is not floored by the rounding of K0 x (see the file comment).
  double backward_error = 0.0;
  LinearModel model;    ///< K0, M0 and D used
};

/// Solves for the `count` lowest elastic modes (see the file comment).
/// \param count 1 <= count <= r - rigid modes of the supports; otherwise
///        std::invalid_argument naming the range.
/// Throws std::invalid_argument for an invalid chain (see Chain) or method = sparse with
/// dependent = paper, ring::NumericalError
/// if M0 or K0 + s M0 is not positive definite or the eigensolver does not converge.
/// The rigid modes found are reported as found (result.rigid_modes), not forced to the
/// supports' count.
ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          int count);

/// The project-wide entry point: solve_modes(...).result.
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                int count);

}  // namespace multibody
