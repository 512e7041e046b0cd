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
std::array<double, 2> free_ring_extensible(const RingSpec& spec, int k);

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

}  // namespace ring::closed_form
