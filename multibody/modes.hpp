// Linear natural frequencies of the rigid-segment chain (the paper's section 4).
//
// The problem (K0 x = omega^2 M0 x, the constraint-reduced pencil about the n-gon) and
// the dependent coordinates: linear_model.hpp.
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
// ## Sparse path (the banded backend of backend.hpp: method = sparse, or auto from n = 257)
// Same pencil, never formed: K and M(q0) only as O(n) operators in chain coordinates,
// and S = K + s M solved in O(n) on the null space of J by a Riccati sweep with a border
// of <= 6 unknowns (shifted_solve.hpp). The eigenpairs come either from the eigen layer
// (modal/lanczos.hpp: Spectra's shift-invert Lanczos with that solve as the operator and
// M as B) or from the hand-written Lanczos of lanczos.hpp; kDefaultSparseEigensolver says
// which one runs by default and multibody/README.md why (measured side by side in
// docs/measured.md, "Time and memory, 23 modes"). The
// orthonormal basis D (Householder of J^T) is never applied: the residuals' norms are
// those of the projections onto the null space of J (modes.cpp), and the result is the
// chain-coordinate shapes dq. Cost: O(n) per Lanczos step, ~50 steps for 23 modes at every n, plus
// O(n k) per step for the reorthogonalization; memory N x (steps + 1) doubles plus the
// outputs. Robust dependent coordinates only; n >= 10 (forcing it below is an input
// error: at n = 8 every mode is wanted and the Krylov space degenerates).
//
// ## Sparse path with the terms beyond the paper's ring (method = sparse, or auto from n = 257)
// The foundation, springs, a clamp, further pins and point masses without rotary inertia
// (backend.hpp, banded_modes_lacks) are taken in hinge positions (position_modes.hpp): K the
// O(n) statics' tangent at rest, M the constant bar mass plus the point masses, the links
// and pins as constraint rows; the eigen layer's shift-invert Lanczos runs on one refined
// bordered-band KKT solve per step, and its vectors are converted to chain coordinates
// (dphi_k = e_k x (du_{k+1} - du_k) / l), where the residuals below are those of the dense
// path's pencil (the chain's K and M with the terms', the constraint rows with the further
// pins'), as O(n) products. Cost O(n) per step; memory 2n x ncv doubles for the basis plus the
// band's factors.
//
// ## Residuals: why max_residual grows like n^2 on either path and what to read instead
// For a smooth low mode x, K0 x is a second difference of a smooth vector: it is computed
// with an absolute error ~eps ||K0|| ||x|| while its size is ~omega^2 ||M0 x||, so the
// relative residual ||K0 x - w^2 M0 x|| / (||K0 x|| + w^2 ||M0 x||) of even the exact
// eigenvector has a floor that grows like n^2, while the frequencies stay within 1e-11 of
// the oracles. ModalSolution::backward_error (normwise,
// ||r|| / ((||K0|| + w^2 ||M0||) ||x||)) is the measure that says whether the eigensolver
// did its job; the tests bound it. Measured values of both, per path and n:
// docs/measured.md, "Residuals".
//
// ## Rigid modes
// The eigen layer's rule (modal/modes.hpp): omega^2 < modal::kRigidThreshold * s is a
// rigid (zero) mode, counted in ModalResult::rigid_modes, never numbered, never returned.
// The chain is inextensible, so omega^2 / s depends on n and the supports only: the
// lowest elastic omega^2 is 0.79 s (n = 4, pinned) and >= 1.1 s from n = 5 (2.5 s
// pinned, 7.2 s free at large n), while the robust path's rigid modes come out at
// |omega^2| <= 2e-12 s up to n = 2000. (The paper's coordinates at n = 2000 without
// rotary inertia push the rigid mode to 1.5e-5 s and miss it; see MultibodyStress.)
// Expected: 1 (pin), 0 (pin + roller), 3 (free).
//
// ## Outputs
// ModalResult: solver "multibody"; model {n, rotary_inertia, dependent, method};
// omega = the `count` lowest elastic modes in rad/s ascending; shapes = hinge
// displacements sampled with ring::sample_polygon (anchor = hinge 0's angle, the pin's or
// 0 deg for a free ring); unknowns = r; seconds = solver wall time (assembly, reduction,
// factorizations, eigensolver, eigenvectors; not the sampling at the 360 stations by
// ring::sample_polygon);
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

#include "multibody/backend.hpp"
#include "multibody/chain.hpp"
#include "multibody/linear_model.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// The eigensolver of the sparse path (file comment): the eigen layer's Spectra
/// Lanczos, or the hand-written one of lanczos.hpp.
enum class SparseEigensolver { library, hand_written };
/// The one solve_modes(spec, options, count) and compute_modes use: the hand-written
/// Lanczos, measured faster at large n with frequencies that agree with the library's to
/// ~1e-12 (docs/measured.md, "Time and memory, 23 modes").
constexpr SparseEigensolver kDefaultSparseEigensolver = SparseEigensolver::hand_written;
/// Spectra's relative Ritz-residual bound on the library path (modal::LanczosOptions::tol).
constexpr double kLibraryLanczosTol = 1e-10;

/// Full modal solution, with the coordinates behind ModalResult.
struct ModalSolution {
  ring::ModalResult result;
  /// r x count reduced eigenvectors, M0-orthonormal; dense path only (the sparse path never
  /// forms the null-space basis D, and x = D^T dq is needed by nothing it returns: empty).
  Matrix x;
  Matrix dq;            ///< dofs x count chain-coordinate shapes delta q = D x
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
/// Throws std::invalid_argument for an invalid chain (see Chain), method = sparse with
/// dependent = paper or a spinning ring (its modes: compute_modes), ring::NumericalError
/// if M0 or K0 + s M0 is not positive definite or the eigensolver does not converge.
/// The rigid modes found are reported as found (result.rigid_modes), not forced to the
/// supports' count.
ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          int count);
/// The same with the sparse path's eigensolver chosen (tests and benchmarks; the dense
/// path ignores it).
ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count,
                          SparseEigensolver eigensolver);

/// The project-wide entry point: solve_modes(...).result at rest; for a spinning ring
/// (spec.rotation.spinning()) the gyroscopic modes of spin.hpp (compute_spinning_modes).
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                int count);

}  // namespace multibody
