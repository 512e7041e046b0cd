// Closed-form results for thin circular rings: the oracles the solvers are tested
// against. Each formula names its source.
#pragma once

#include <array>

#include "ring/spec.hpp"

namespace ring::closed_form {

/// In-plane bending frequency of a free, inextensible thin ring with k full waves
/// around the circumference (k >= 2), Euler-Bernoulli, no rotary inertia:
/// \f$ \omega_k = \sqrt{EI/(\rho A R^4)}\; k(k^2-1)/\sqrt{k^2+1} \f$
/// (Hoppe 1871; Love, "Treatise on the Mathematical Theory of Elasticity", 4th ed.,
/// sec. 294; Soedel, "Vibrations of Shells and Plates", 3rd ed., eq. 6.6.14).
/// Each value is a double eigenvalue of the free ring (cos and sin k theta).
double free_ring_inextensional(const RingSpec& spec, int k);

/// The same ring with axial (membrane) strain energy: the two branches of the
/// 2x2 eigenproblem for u = B sin(k theta), w = A cos(k theta), with
/// strain (u' + w)/R and change of curvature (u' - w'')/R^2 (' = d/dtheta):
/// \f$ K = \frac{EA}{R^2}\begin{pmatrix}1&k\\k&k^2\end{pmatrix}
///      + \frac{EI}{R^4}\begin{pmatrix}k^4&k^3\\k^3&k^2\end{pmatrix},\ M = \rho A\,I \f$
/// (Soedel, sec. 6.6; Kirkhope 1976). Returns {flexural (lower), extensional (upper)}
/// in rad/s. k = 0: {0, breathing}; k = 1: {0 (rigid translation), upper}.
/// A Winkler foundation (spec.foundation) adds diag(k_r, k_t) to K (its energy
/// R/2 int (k_r w^2 + k_t u^2) on the same Fourier mode): k = 0 gives {sqrt(k_t/(rho A)),
/// breathing}; without one the values are the free ring's.
std::array<double, 2> free_ring_extensible(const RingSpec& spec, int k);

/// The free Timoshenko ring (shear deformation and cross-section rotary inertia) with axial
/// strain, k waves (k >= 0): the three branches, ascending, in rad/s. Fields u (tangential),
/// w (radial), psi (rotation of the cross-section), on the thin-ring kinematics of
/// free_ring_extensible: strain eps = (u' + w)/R, tangent rotation phi = (u - w')/R, shear
/// strain gamma = psi - phi, change of curvature kappa = psi'/R; energy per length
/// EA/2 eps^2 + kGA/2 gamma^2 + EI/2 kappa^2 (+ the foundation's), kinetic
/// rho A/2 (u'^2 + w'^2) + rho I/2 psi'^2 (dots). On u = U sin k theta, w = W cos k theta,
/// R psi = P sin k theta, with a = (k, 1, 0), b = (-1, -k, 1):
/// \f$ K = \frac{1}{R^2}\left(EA\,a a^T + \kappa G A\,b b^T + \frac{EI k^2}{R^2} e_3 e_3^T\right)
///      + \mathrm{diag}(k_t, k_r, 0),\quad M = \mathrm{diag}(\rho A, \rho A, \rho I/R^2) \f$
/// (the in-plane Timoshenko ring of Seidel & Erdelyi, J. Eng. Ind. 86, 1964, and Kirkhope,
/// J. Sound Vib. 50, 1976, in its thin-ring form: no 1 + z/R through the depth). As kGA -> inf
/// and rho I -> 0 the lower two are free_ring_extensible's; the third is the shear branch.
/// k = 0: {0 (rotation; k_t without a foundation), breathing sqrt(EA/(rho A R^2)) (w alone),
/// shear-rotation}; k = 1 holds the rigid translation (0). Needs spec.kappa() > 0.
std::array<double, 3> free_ring_timoshenko(const RingSpec& spec, int k);

/// The free Timoshenko ring of free_ring_timoshenko made inextensible (EA -> infinity: the
/// strain u' + w = 0, so w = -k U cos k theta on u = U sin k theta), k >= 2 waves: the two
/// branches {flexural, shear}, ascending, in rad/s, of the 2x2 pencil on (U, P), R psi =
/// P sin k theta:
/// \f$ K = \frac{\kappa G A}{R^2} b b^T + \frac{EI k^2}{R^4} e_2 e_2^T + (k_t + k^2 k_r) e_1 e_1^T,
///      b = (k^2 - 1, 1),\quad M = \mathrm{diag}(\rho A (1 + k^2), \rho I / R^2) \f$.
/// The limit of the Timoshenko chain (multibody/linear_model.hpp), whose rigid segments keep
/// the centroid line's length. As kGA -> infinity the flexural branch is the inextensible
/// ring with the cross-section's rotary inertia, omega^2 = EI k^2 (k^2-1)^2 / R^4 /
/// (rho A (1 + k^2) + rho I (k^2 - 1)^2 / R^2) (Love, sec. 294, with Rayleigh's rotary
/// inertia); with rho I -> 0 too, free_ring_inextensional. Needs spec.kappa() > 0.
std::array<double, 2> free_ring_timoshenko_inextensional(const RingSpec& spec, int k);

/// The free, inextensible thin ring on a Winkler foundation (spec.foundation: radial k_r,
/// tangential k_t, N/m^2), Euler-Bernoulli, no rotary inertia, k waves (k >= 0):
/// \f$ \omega_k^2 = \frac{EI\,k^2(k^2-1)^2/R^4 + k_r k^2 + k_t}{\rho A\,(k^2+1)} \f$.
/// Derivation: the inextensional Fourier mode v = V cos k theta, w = k V sin k theta
/// (inextensible: strain (v' + w)/R = 0) is exact for a uniform ring on a uniform foundation;
/// bending energy EI/(2R^3) int (w'' + w)^2, foundation energy R/2 int (k_r w^2 + k_t v^2),
/// kinetic energy rho A R/2 int (w^2 + v^2) give the Rayleigh quotient above (without the
/// foundation it is free_ring_inextensional; with it, the flexible-ring tyre model, e.g.
/// Gong, "A study of in-plane dynamics of tires", TU Delft 1993, ch. 3). k = 0 is the
/// rotation held by k_t, k = 1 the translation held by (k_r + k_t) / 2.
/// Under a uniform follower (hydrostatic) pressure p (N/m, inward) the circle stays the
/// equilibrium (hoop force p R, the foundation unloaded) and the pressure's potential p times
/// the enclosed area adds -p k^2 (k^2 - 1) / R to the numerator (the area an inextensible
/// wave of k lobes loses is pi (k^2 - 1) W^2 / 2 to second order, W = k V its radial
/// amplitude): omega_k^2 falls linearly in p, to zero at p = [EI (k^2 - 1)^2 / R^3 + (k_r k^2 +
/// k_t) R / k^2] / (k^2 - 1), (k^2 - 1) EI / R^3 without a foundation (Levy's hydrostatic
/// buckling pressure). NaN where omega_k^2 <= 0 (past that pressure).
double ring_on_foundation_inextensional(const RingSpec& spec, int k, double follower_pressure = 0.0);

/// First-order change of omega^2 of the free inextensible ring's mode pair k when a point
/// mass m0 is attached at polar angle 0 (perturbation of the Rayleigh quotient; the pair
/// splits into the mode with u_t, the other with u_r at the mass): relative changes
/// -m0 / (pi R rho A (k^2 + 1)) (tangential) and -m0 k^2 / (pi R rho A (k^2 + 1)) (radial).
/// Returns {tangential, radial} relative changes, exact to O(m0^2).
std::array<double, 2> point_mass_shift(const RingSpec& spec, double m0, int k);

/// Linear, inextensible ring squeezed by two equal and opposite forces P along a
/// diameter (Roark's Formulas, 7th ed., Table 9.2 case 1; Timoshenko, "Strength of
/// Materials" I, sec. 87), bending energy only:
/// shortening of the loaded diameter  (pi/4 - 2/pi) P R^3 / EI,
/// lengthening of the perpendicular diameter  (2/pi - 1/2) P R^3 / EI.
struct DiametralDeflection {
  double along = 0.0;   ///< m, shortening of the loaded diameter (positive)
  double across = 0.0;  ///< m, lengthening of the perpendicular diameter (positive)
};
DiametralDeflection diametral_load(const RingSpec& spec, double P);

/// Uniform pressure p (positive inward) on a thin inextensible ring, Euler-Bernoulli: the
/// prebuckling state is the undeformed circle with hoop force -p R. On the inextensional
/// mode w = W cos n psi, u = -(W/n) sin n psi (n >= 2) the second variation of the total
/// potential is (pi W^2 / 2) K_n(p), K_n(p) = EI (n^2 - 1)^2 / R^3 - p c_n, with the load's
/// own second-order potential in c_n (derivation: the enclosed area, the radius |x| and the
/// mean of w to second order under exact inextensibility, int w dtheta = -int (w' - u)^2
/// dtheta / 2R):
///   follower (hydrostatic, p A):              c_n = n^2 - 1
///   dead (fixed direction and magnitude):     c_n = (n^2 - 1)^2 / n^2
///   central (toward the centre):              c_n = ((n^2 - 1)^2 - 1) / n^2
/// The critical pressures p_n = EI (n^2 - 1)^2 / (R^3 c_n) are least at n = 2: 3, 4 and 4.5
/// EI/R^3 (Levy 1884; Timoshenko & Gere, "Theory of Elastic Stability", 2nd ed., sec. 7.3-7.4;
/// Brush & Almroth, "Buckling of Bars, Plates and Shells", sec. 4.4).
double pressure_stiffness_factor(Pressure::Kind kind, int n);
/// p_n of the formula above for wave number n >= 2, N/m.
double critical_pressure(const RingSpec& spec, Pressure::Kind kind, int n = 2);

/// The lowest critical uniform pressure (N/m, positive inward) of a thin inextensible ring
/// held by a pin and a roller diametrically opposite it (ring::Supports: the roller keeps
/// its point on the diameter through the pin; statically determinate, so no prebuckling
/// reactions). Every admissible shape is an elastic one (the harmonics n >= 2 of
/// critical_pressure) plus the rigid motion that the supports impose: the translation that
/// holds the pin, and for an even harmonic out of phase with the pin (its radial
/// displacement zero there) the rotation c = -(u_t(pin) + u_t(roller)) / 2R, odd harmonics
/// none. A rigid motion costs nothing under follower pressure (the area does not change)
/// and its translation nothing under dead pressure, but a dead pressure's second-order
/// work on a rotation c is pi p R^2 c^2 (the points move inward by c^2 R / 2 at second
/// order), and a central pressure resists translation (K_1 = p):
///   follower: 3 EI/R^3 (each n = 2 shape, with or without rotation);
///   central:  4.5 EI/R^3 (the even shape out of phase with the pin needs a rotation only,
///             which costs a central pressure nothing; every other shape costs more);
///   dead:     the root P in (0, 4) of  1 = 2 P sum_{n even >= 2} 1 / ((n^2 - 1)^2 (n^2 - P)),
///             P = p R^3 / EI (the out-of-phase even harmonics coupled through the rotation
///             they need: P = 3.27125), below Levy's 4 of the free ring, which the shape in
///             phase with the pin (a translation only) keeps.
/// Derivation as critical_pressure's, with the supports' rigid motion added (the second
/// variation of each pressure's potential on a rigid motion and its cross terms with the
/// harmonics n >= 1, which vanish by orthogonality). Sum to n = 20000, root by bisection.
double pinned_ring_critical_pressure(const RingSpec& spec, Pressure::Kind kind);

/// diametral_load (two equal and opposite forces P along a diameter) on the ring that also
/// carries a uniform pressure p below its critical value, linear in P about the pressurized
/// circle, the ring held by a pin on the diameter across the loads (and a roller opposite).
/// A radial point force F at theta_0 gives each harmonic n >= 1 the radial amplitude
/// F / (pi K_n(p)) in cos n (theta - theta_0); the squeeze loads excite the even n >= 2. A
/// central pressure also resists the translation (n = 1) of the ring against its centre,
/// K_1 = p (Pi_2 = p pi T^2 / 2; the other kinds have K_1 = 0): the pin's vertical reaction
/// V then holds the pin where it is, sum_n (V + squeeze terms at the pin) / (pi K_n) = 0, and
/// deforms the ring through every harmonic n >= 1. Sums to n = 40000 (terms ~ n^-4).
/// p = 0 (or dead, follower) gives V = 0 and, at p = 0, diametral_load.
DiametralDeflection diametral_load_under_pressure(const RingSpec& spec, double P, const Pressure& pressure);

/// A thin inextensible ring hanging from a pin under its own weight q = rho A |g| per unit
/// length, linear (small-load) limit, bending only: the point opposite the pin moves away
/// from it by (pi^2 - 8)/4 q R^4 / EI, and the diameter across shrinks by (2 - pi/2) q R^4 /
/// EI. Derivation: gravity is the n = 1 harmonic; the pin's reaction 2 pi R q has every
/// harmonic, each even n >= 2 giving W_n = 2 q R^4 / (EI (n^2 - 1)^2); the sums are
/// sum_m 1/(4m^2 - 1)^2 = (pi^2 - 8)/16 and sum_m (-1)^m/(4m^2 - 1)^2 = pi/8 - 1/2. (Roark's
/// Formulas, 7th ed., Table 9.2 case 15, the ring resting on its base under its own weight:
/// the same 0.4674 and 0.4292.)
struct HangingDeflection {
  double sag = 0.0;     ///< m, the lowest point moves away from the pin
  double across = 0.0;  ///< m, shortening of the horizontal diameter (positive)
};
HangingDeflection hanging_ring_self_weight(const RingSpec& spec, double g);

}  // namespace ring::closed_form
