// The modes of a spinning ring: the gyroscopic eigenproblem of the frame that turns with it,
//
//   M x'' + G x' + K x = 0,   x(t) = Re(x e^{i omega t}),   (K - omega^2 M + i omega G) x = 0,
//
// K symmetric (the stiffness with the centrifugal softening -speed^2 M and, for the spin's
// tension, its prestress), M symmetric positive definite, G skew (the Coriolis term,
// 2 speed sum m S on each mass's Cartesian velocity, S the quarter turn). Every solver forms
// its three matrices on its admissible coordinates and calls gyroscopic_modes; the
// frequencies are the rotating frame's, the waves tell the driver the fixed frame's.
//
// ## Method (structure preserving: the frequencies come out real and in +-pairs)
// With the state w = [x; x'], A = diag(K, M) and B = [[0, K], [-K, -G]] the equation is
// A w' = B w, A symmetric positive definite when K is, B skew. With A = L L^T (Cholesky of K
// and of M) and z = L^T w, z' = S z with S = L^-1 B L^-T real and skew:
//   S = [[0, Lk^T Lm^-T], [-Lm^-1 Lk, -Lm^-1 G Lm^-T]],
// so H = i S is Hermitian and its eigenvalues are -omega (z = e^{i omega t}): a dense
// Hermitian eigensolve of order 2N whose eigenvalues are real by construction, never a
// general complex one whose +-i omega pairs round off the imaginary axis. x = Lk^-T z_top.
// Cost O((2N)^3) time, O((2N)^2) complex memory: kMaxGyroscopicUnknowns bounds N.
// K not positive definite (a spin past the speed at which the centrifugal softening overcomes
// a mode's stiffness): the Coriolis coupling may still hold the ring (gyroscopic
// stabilization), and the general eigenproblem of the first-order form decides: the
// frequencies when every eigenvalue lies on the imaginary axis (to 1e-7 of the largest), else
// a ring::NumericalError with the growth rate (a divergence).
//
// ## The wave of a mode (travelling_mode)
// The shape at the common stations, w(theta) = sum_k c_k e^{i k theta} (radial and tangential
// parts, their powers added): the term
// c_k e^{i (k theta + omega t)} travels towards -theta, c_-k e^{i (omega t - k theta)} towards
// +theta. The wave number is the k >= 0 of the largest |c_k|^2 + |c_-k|^2; the direction is
// +1 (with the spin) when the part travelling in the spin's sense is the larger, -1 against,
// 0 when |c_k| and |c_-k| agree to 1e-6 of the larger (a standing wave, and k = 0).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <utility>

#include "ring/results.hpp"

namespace modal {

/// The largest N (size of K) gyroscopic_modes takes: the dense Hermitian problem of order
/// 2N holds (2N)^2 complex doubles, 256 MB at N = 2000.
constexpr long long kMaxGyroscopicUnknowns = 2000;

struct GyroscopicModes {
  Eigen::VectorXd omega;     ///< rad/s, > 0, ascending (the rotating frame)
  Eigen::MatrixXcd vectors;  ///< columns x, (K - omega^2 M + i omega G) x = 0, |x| = 1
  /// The largest ||(K - w^2 M + i w G) x|| / (||K x|| + w^2 ||M x|| + w ||G x||) over the pairs.
  double max_residual = 0.0;
};

/// The `count` lowest modes of M x'' + G x' + K x = 0 (file comment). Throws
/// std::invalid_argument for mismatched sizes, count < 1 or more than N, or N above
/// kMaxGyroscopicUnknowns; ring::NumericalError (naming `solver`) when M is not positive
/// definite, a value is not finite, or the motion is unstable (K indefinite and not held by G).
/// O(N^3).
GyroscopicModes gyroscopic_modes(const std::string& solver, const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                 const Eigen::MatrixXd& G, int count);

/// The shape a ModalResult shows for the complex mode x and its wave (file comment), through
/// the solver's own sampling of a real coordinate vector at the common stations (linear,
/// normalized by ring::normalize or not): x is phased so that its largest entry is real, the
/// shape is the sampled real part (t = 0), normalized; the wave comes from the sampled real
/// and imaginary parts, whose relative scale a third sample (their sum) restores. `speed`
/// (rad/s) gives the spin's sense. Cost: three samples.
std::pair<ring::ModeShape, ring::Wave> travelling_mode(const Eigen::VectorXcd& x,
                                                       const std::function<ring::ModeShape(const Eigen::VectorXd&)>& sample,
                                                       double speed);

/// The wave of a complex shape at the kStations common stations (file comment), from its
/// radial and tangential parts together: a wave k moves both alike, and the mode of a ring
/// turning on its tangential foundation (k = 0) has no radial part to speak of. O(kStations^2).
ring::Wave classify_wave(const Eigen::VectorXcd& radial, const Eigen::VectorXcd& tangential, double speed);

}  // namespace modal
