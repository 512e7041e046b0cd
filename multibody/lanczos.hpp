// A hand-written Lanczos for the sparse path, kept beside the eigen layer's
// (modal/lanczos.hpp, Spectra) because it is measurably faster on this operator
// (multibody/README.md, "Large n"); tests/multibody/test_modes_sparse.cpp checks that
// both agree.
//
// ## Method
// The largest eigenvalues mu of T = S_c M (S_c: the constrained solve
// ShiftedSolve::solve_full), run in chain coordinates on the null space of J: T is
// self-adjoint there in the S inner product and equals S0^{-1} M0 in the reduced
// coordinates x = D^T dq, so the Ritz values are those of the reduced pencil and the
// Householder basis D is applied only to the final vectors. No restart: the wanted
// mu = 1/(omega^2 + s) are the best separated end of the spectrum (omega^2 grows like
// k^4), so ~2 nev steps converge them (measured: 45..50 steps for nev = 26, n = 2000 ..
// 10^6). Ritz values come from the exact Rayleigh quotient V^T M V, so the solve's
// rounding only slows convergence.
// Step k: p = M v_k, w = S_c p (the solve unrefined: lanczos.cpp); since S w = p - J^T
// lambda and J v_j = 0, the coefficients <w, v_j>_S = v_j^T p need no S product: the
// three-term part (j = k - 1, k) is subtracted with them, then one classical Gram-Schmidt
// pass over the whole basis with the true S w, and a second (DGKS) only if that one
// cancelled (measured: never). A closed Krylov space
// (multiple eigenvalues: the free ring's rigid modes and cos/sin pairs) continues with a
// fresh random direction (fixed seed). Stops when the nev largest Ritz values have
// residual |beta_k y_k| <= 1e-8 theta (the estimate stagnates near 1e-9, the solve's
// rounding in the S norm; the Ritz values' error is quadratic in it), or when the Krylov
// space is invariant.
//
// ## Cost
// Per step: one Riccati solve (two sweeps), two M products and one K product (O(n)), and
// three reads of the basis for the reorthogonalization, 3 k N (k = step: V^T p, V^T S w and
// the update w -= V g, taken 8 columns at a time, see lanczos.cpp). Memory: N x (steps + 1)
// doubles; the Ritz vectors overwrite the basis.
#pragma once

#include "multibody/shifted_solve.hpp"

namespace multibody {

/// Eigenpairs of the chain's pencil from the sparse path, chain coordinates.
struct SparsePairs {
  Vector omega2;  ///< nev values, ascending
  Matrix dq;      ///< N x nev, in the null space of J (any scale), same order
  int steps = 0;  ///< Lanczos steps (hand-written) or operator applications (library)
};

/// The nev lowest eigenpairs by the hand-written Lanczos (file comment), for the shift
/// `sp` was factored with. Throws ring::NumericalError if it does not converge within
/// min(r, 4 nev + 60) steps or a Ritz value of S0^{-1} M0 is not positive.
/// \param nev 1 <= nev <= r - 1.
SparsePairs hand_lanczos(const ShiftedSolve& sp, int nev);

}  // namespace multibody
