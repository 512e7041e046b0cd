// What every solver does with computed eigenpairs: the rigid-mode rule, the residual
// and normwise backward error, and the ModalResult assembly (sorting, rigid count,
// omega = sqrt(omega^2)). The eigenpairs themselves come from lanczos.hpp (operators)
// or from a dense factorization of the solver's own.
//
// ## Rigid modes
// omega^2 < kRigidThreshold * EI / (rho A R^4) is a rigid (zero) mode: counted in
// ModalResult::rigid_modes, never numbered, never returned. In those units the lowest
// elastic omega^2 of the models here is >= 0.79 (the 4-segment pinned chain), 2.5 for a
// pinned and 7.2 for a free ring at large n, while computed rigid modes come out at
// |omega^2| <= 1e-11 (round-off): 1e-6 sits more than five orders from both
// (multibody/README.md, lumped_mass/README.md). multibody/ and lumped_mass/ use this rule
// and no other. The FE reference cannot: on the exact circle its polar fields only
// approximate the rigid translations, whose omega^2 is then the discretization's error
// (up to 0.1 of the scale on 4 cells of degree 2, 1e-3 on 40 of degree 2: far above
// round-off), so it takes the supports' count of lowest pairs as rigid and refuses a mesh
// that does not separate them from the elastic ones (fem_reference/ring_model.hpp,
// kRigidSeparation).
//
// ## Residuals
// For a pair (lambda, x) of A x = lambda B x with r = A x - lambda B x (projected onto
// the admissible space by the caller where there are constraints):
//   relative = ||r|| / (||A x|| + |lambda| ||B x||)   (ModalResult::max_residual),
//   backward = ||r|| / ((||A|| + |lambda| ||B||) ||x||)   (normwise backward error).
// For a smooth low mode of a discretized ring the relative residual is floored by the
// rounding of A x at ~eps ||A|| / (lambda ||B||), which grows like n^2 (n^4 for an
// assembled fourth difference) even for the exact eigenvector; the backward error is the
// measure that says whether the solver did its job (~1e-12 or below here).
// Cost: O(1) per pair given the products; norm_estimate O(iterations) operator products.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace modal {

/// omega^2 < kRigidThreshold * bending_scale(spec) counts as a rigid mode.
constexpr double kRigidThreshold = 1e-6;

/// The ring's bending scale EI / (rho A R^4) in rad^2/s^2: the unit of kRigidThreshold,
/// and the magnitude of the shift the solvers use (a few tenths of the lowest elastic
/// omega^2 of any supported or free ring).
double bending_scale(const ring::RingSpec& spec);

/// True when omega2 is a rigid mode for this bending scale (see the file comment).
bool is_rigid(double omega2, double scale);

/// Indices into a list of computed omega^2 (any order): the rigid ones (ascending) and
/// the `count` lowest elastic ones (ascending).
struct Selection {
  std::vector<int> rigid;
  std::vector<int> elastic;
  std::vector<double> rigid_omega2;  ///< omega2 of the rigid ones, ascending
};

/// Sorts and classifies omega2 (O(k log k)). Throws ring::NumericalError (naming
/// `solver`) for a non-finite value or when fewer than `count` elastic modes are there;
/// std::invalid_argument for count < 1 or scale <= 0.
Selection select_modes(const std::string& solver, const Eigen::VectorXd& omega2, double scale, int count);

/// ||r|| / (||A x|| + |lambda| ||B x||), the relative residual of one pair (file comment).
double relative_residual(double r_norm, double ax_norm, double bx_norm, double lambda);

/// Relative residual and normwise backward error of one pair (file comment).
struct PairResidual {
  double relative = 0.0;
  double backward = 0.0;
};
/// \param r_norm ||A x - lambda B x|| (projected by the caller if constrained)
/// \param ax_norm, bx_norm ||A x||, ||B x||; x_norm ||x||; norm_a, norm_b ||A||, ||B||
PairResidual pair_residual(double r_norm, double ax_norm, double bx_norm, double lambda, double x_norm,
                           double norm_a, double norm_b);
/// The same from the products A x and B x (r = ax - lambda bx, unprojected).
PairResidual pair_residual(const Eigen::Ref<const Eigen::VectorXd>& ax,
                           const Eigen::Ref<const Eigen::VectorXd>& bx, double lambda, double x_norm,
                           double norm_a, double norm_b);

/// 2-norm of a symmetric positive semidefinite operator, estimated by `iterations` steps
/// of power iteration from a fixed alternating start (the Rayleigh quotient, a lower
/// bound; ~1 % for the ring's spectra after 10 steps, which is all a backward error's
/// scale needs). Cost: `iterations` products.
double norm_estimate(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& op, Eigen::Index dim,
                     int iterations = 10);

/// The larger of a and b, or NaN when either is NaN. Residuals and backward errors are
/// accumulated with it: std::max(a, NaN) returns a, which let a NaN residual read as the
/// earlier, small one and pass an acceptance check (issue 46). O(1).
inline double worst(double a, double b) { return std::isnan(a) || a > b ? a : b; }

/// The largest relative backward error of a pair that is still an answer. Working runs reach
/// 2.6e-5 at the extreme the stress suite measures (the paper's dependent angles at n = 2000),
/// 1e-13 in the common case; a silently failed eigensolver gives order 1 (measured: the O(n)
/// Lanczos of a free chain that filled its whole Krylov space, and the paper's dependent angles
/// without rotary inertia at n = 2000, both 1.0; docs/commands.md, "Exit codes"). The bound sits between.
constexpr double kAcceptedResidual = 1e-2;

/// Throws ring::NumericalError naming result.solver when result.max_residual is above
/// kAcceptedResidual (or not a number): pairs that far from K x = omega^2 M x are not an
/// answer. For the chain's relative residuals (pair_residual), which multibody/modes.cpp
/// also accepts by a small backward error where their rounding floor grows with n; the
/// lumped model's 2-norm residual grows with (R/l) on correct pairs (3.4e-2 at n = 3 10^4)
/// and is not gated by it.
void require_eigenpairs(const ring::ModalResult& result);

/// Fills result.solver, rigid_modes, omega (sqrt of the selected elastic omega2,
/// ascending) and max_residual (the largest of `relative`, one per selected elastic mode,
/// or 0 if empty; NaN if any is NaN, so that require_eigenpairs refuses it). The caller adds model, shapes, unknowns and seconds.
void assemble(ring::ModalResult& result, const std::string& solver, const Eigen::VectorXd& omega2,
              const Selection& selection, const std::vector<double>& relative = {});

}  // namespace modal
