// The stability of an equilibrium of the nonlinear chain (chain.hpp): how many independent
// directions it is unstable in, for the continuation driver's bifurcation test
// (paths/continuation.hpp, Equilibrium::unstable_directions). An internal header of
// lumped_mass/, like chain.hpp.
//
// The count is the number of negative eigenvalues of the tangent T = Hess V + sum lambda_j
// Hess c_j + s Hess P (chain.hpp, tangent) on ker G, G the constraint Jacobian (links and
// supports). Three ranges:
// - dense (2n <= kDenseInertiaUnknowns): modal::unstable_directions(T, G), the eigenvalues
//   of Z^T T Z (Z: orthonormal basis of ker G), as the multibody chain counts them.
//   O(n^3) time, O(n^2) memory.
// - frontal (kDenseInertiaUnknowns < 2n, n <= kMaxInertiaHinges): by Sylvester, the KKT
//   matrix K = [T G^T; G 0] with G of full row rank c has inertia (p + c, q + c, z) when
//   Z^T T Z has (p, q, z) (Gould 1985, Lemma 3.4; Nocedal & Wright, Thm. 16.3), so
//   q = negative(K) - c, with K's inertia from the block LDL^T of modal::frontal_inertia in
//   the chain's order (hinge j's x_j, y_j with its link's multiplier; the last two hinges
//   and the support rows as the border): O(n) time and memory, 0.03 s at n = 10^4.
//   G's rows are scaled to T's size (EI / l^3) first, a congruence. nullopt when K is
//   numerically singular, the counts contradict G's full rank (a redundant support), or
//   the front outgrows its bound.
// - none above kMaxInertiaHinges: nullopt, no bifurcation is detected.
//
// Resolution. The chain's bending stiffness is a fourth difference of the positions: the
// low eigenvalues of Z^T T Z are ~ (l/R)^4 of T's entries, and in the KKT form rounding is
// further amplified by about 1 / sigma_min(G)^2 ~ (n / 2 pi)^2 (the links' uniform stretch,
// a radial expansion, is nearly in G^T's kernel). Measured on the paper's ring on a pin and
// a roller at s lambda_1 on the circular path (the states of
// tests/lumped_mass/bifurcation_test.cpp): the dense count is exact beyond |s - 1| = 1e-7 at
// n = 40, but its floor (-1e-12 of the largest eigenvalue) makes it late by up to 1e-4 at
// n = 300 and 1e-2 at n = 1000; the frontal count flips at random within 3e-8 (n = 40),
// 1e-6 (n = 300), 1e-5 (n = 1000), 1e-2 (n = 10^4, the follower pair; 1e-4 dead and
// central) of lambda_1, and at n = 10^5 it is noise (1 to 3 at rest). Hence dense up to
// n = 200, frontal up to n = 10^4, none beyond.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "lumped_mass/chain.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/nonlinear.hpp"

namespace lumped {

/// Above this many position unknowns (2n) the count takes the frontal route.
constexpr int kDenseInertiaUnknowns = 400;
/// Above this many hinges no count is given (rounding decides it).
constexpr int kMaxInertiaHinges = 10000;

/// The unstable directions of the chain's equilibrium (x, lambda, s) (lambda: the
/// multipliers in N, as tangent() takes them), by `route` (automatic: dense up to
/// kDenseInertiaUnknowns, frontal above, nullopt above kMaxInertiaHinges; a forced route
/// ignores the limits). `scale`: the constraint rows' scale, EI / l^3.
std::optional<int> unstable_directions(const Chain& c, const ChainLoads& loads, const Eigen::VectorXd& x,
                                       const Eigen::VectorXd& lambda, double s, double scale, InertiaRoute route);

/// The least stable direction of the same tangent on ker G (2n position values, unit
/// length): modal::least_stable(T, G), the branch-switching direction of the continuation
/// driver (Equilibrium::critical_direction). Dense only, O(n^3): nullopt when the count
/// would not take the dense route (2n > kDenseInertiaUnknowns under `automatic`, or the
/// frontal route forced), so that above n = 200 there is no branch switching (the frontal
/// LDL^T gives the inertia, not an eigenvector, and the path ends at the bifurcation).
std::optional<Eigen::VectorXd> least_stable_direction(const Chain& c, const ChainLoads& loads,
                                                      const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                                                      double s, InertiaRoute route);

}  // namespace lumped
