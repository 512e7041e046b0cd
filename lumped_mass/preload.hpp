// Frequencies under load (modes.preload = "static") of the lumped-mass `chain` (and of the
// corotational Timoshenko frame, frame.hpp: its tangent at its equilibrium and its constant
// mass on the supports' kernel, the same pencil without links): the small
// vibrations about the static equilibrium of `statics` at its full load, on the nonlinear
// chain's own model (nonlinear.hpp: hinge positions x, rigid links c_j(x) = 0 and support
// rows, hinge springs EI/l, the spec's terms, the loads as potentials). The multibody chain's
// multibody::compute_modes_under_load is the same analysis in segment angles.
//
// ## Method
//  1. The statics' path to the full load (nonlinear.hpp, detail::follow_statics: the same
//     path as solve_static, without branch switching whatever static.path says, as the
//     multibody chain; static.record plays no part): the equilibrium x and its multipliers
//     lambda (the links' tensions and the supports' reactions).
//  2. There the tangent T = T(x, lambda, s = 1) (chain.hpp, tangent: the springs and terms'
//     Hessian, sum_j lambda_j Hess c_j (the prestress: the links' forces), Hess P (the
//     follower and central pressures' load stiffness); the statics' Newton matrix), the
//     constraint Jacobian G(x) at the deformed state and Z an orthonormal basis of its kernel
//     (modal::kernel_basis: column-pivoted Householder QR of G^T, rank-revealing).
//  3. The mass: chain.hpp's constant mass_matrix (the links' midpoint masses, the point
//     masses on their hinges). A point inertia J at an unclamped hinge of the chain rides on
//     the hinge's own rotation chi, an unknown after the kernel's coordinates, as in the
//     linear modes and the response (terms.hpp): the tangent is taken on (x, chi) with chi in
//     equilibrium with x (chain.hpp, relaxed_rotations, springs(): the split springs,
//     Terms::split), J is chi's mass, and the pencil lives on diag(Z, I).
//  4. The pencil (Z^T T Z, Z^T M Z) by the shifted inverse of the multibody version: the
//     largest mu of S^-1 M_r, S = T_r + sigma M_r = L L^T (Cholesky), sigma =
//     modal::bending_scale(spec), omega^2 = 1/mu - sigma; shapes Z y, the hinges'
//     displacements about x, at the common stations (modes.hpp, sample_shape, node 0 at the
//     pin: the linear modes' anchor).
// An omega^2 <= 0, or S not positive definite, means the loaded ring is at or past a
// critical load: ring::NumericalError, as a path that does not reach the full load.
// Under a uniform pressure the inextensible chain stays the regular n-gon (loads.hpp), so T
// is K_0 + s K_1 of the chain's linear buckling (buckling.hpp) and each omega^2 falls
// linearly to zero at its critical pressure.
//
// Cost: the statics (O(n) per Newton iteration, plus the dense count of unstable directions
// at every accepted step up to n = 200, stability.hpp), then dense O(n^3) time and O(n^2)
// memory: the QR's explicit Q (2n x 2n), the pencil (n - 3 square on a pin and a roller) and
// its full eigensolve; hence the limit kMaxPreloadHinges. Measured (release build, one core,
// another job running; the paper's ring on a pin and a roller under follower pressure at half
// its critical value, 10 modes; statics included): 0.015 s at n = 40, 0.3 s at n = 160 (nine
// tenths of it the statics' dense counts), 0.2 s at n = 320, 0.5 s at n = 500, 3.7 s and 89 MB
// peak at n = 1000.
// Accuracy: the tangent's entries are O(EI/l^3) while the low omega^2 are O(EI/(rho A R^4)), so
// rounding costs ~eps (R/l)^4 relative (buckling.hpp). Against the multibody chain (the same
// discrete model in segment angles, tests/lumped_mass/preload_test.cpp): all 37 omega within
// 5e-12 (follower pressure at half its critical value) and 2e-11 (two point loads P R^2/EI = 2
// that bend the ring, plus a dead pressure) at n = 40, the lowest ten within 1.2e-10 at
// n = 160. max_residual (the definition of ring/results.hpp on ker G): 1e-12 at n = 40,
// 5e-10 at n = 160, 1e-8 at n = 320, 6e-8 at n = 500, 1.2e-6 at n = 1000; it grows further
// as omega^2 falls towards a critical load (its floor is ~eps ||T_r|| / omega^2).
//
// Usage:
//   ring::RingSpec spec = ...;                 // pinned at 270 deg, roller at 90 deg
//   ring::StaticOptions st;
//   st.loads.pressure = {0.5 * p_critical, ring::Pressure::Kind::follower};
//   ring::LumpedOptions o;                     // n = 40, chain
//   ring::ModalResult r = lumped::compute_modes_under_load(spec, o, st, 4);
//   // r.omega[0]^2 ~ half the unloaded chain's lowest omega^2
#pragma once

#include "lumped_mass/checks.hpp"  // check_preloaded_modes: what compute_modes_under_load refuses
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The largest lumped.n the modes under load take: their eigen step is dense, O(n^3) time and
/// O(n^2) memory (3.7 s and 89 MB at n = 1000, eight times the time and four times the
/// memory per doubling), and its rounding ~eps (R/l)^4 grows sixteenfold per doubling
/// (max_residual 1.2e-6 at n = 1000): beyond it the digits go before the patience does.
constexpr int kMaxPreloadHinges = 1000;

/// The `count` lowest modes about the equilibrium of `statics` at its full load (file
/// comment). Requires what check_preloaded_modes checks (std::invalid_argument naming the key)
/// and 1 <= count <= dim ker G (n - 3 on a pin and a roller; std::invalid_argument naming
/// modes.count). Throws ring::NumericalError when the statics' path does not reach the full
/// load (a limit point, a bifurcation, self-contact) or the loaded ring is at or past a
/// critical load (omega^2 <= 0).
/// Result: solver "lumped"; model {n, variant ("chain" or "timoshenko-frame"), preload ("static")}; unknowns = the
/// pencil's size, dim ker G; omega (rad/s, ascending); shapes at the common stations (the
/// displacements about the deformed state); max_residual the largest
/// ||T_r y - w^2 M_r y|| / (||T_r y|| + w^2 ||M_r y||) on ker G; seconds (statics included).
/// Cost: the statics, then O(n^3) (file comment).
ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                           const ring::StaticOptions& statics, int count);

}  // namespace lumped
