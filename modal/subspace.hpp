// The one subspace-size rule of the project's Lanczos/Arnoldi eigen-solves: how many basis
// vectors an implicitly restarted solve keeps for nev wanted pairs. Every solver that runs
// such a solve takes its size from here: modal::ShiftInvertLanczos and multibody's dense
// Spectra solve (lanczos.hpp), the FE reference's ARPACK (fem_reference/ring_eigen.cpp).
// Nothing but the standard library here, so that deal.II translation units include it too.
#pragma once

namespace modal {

/// ncv = min(n, max(2 nev + 1, nev + 20)) basis vectors for nev wanted pairs of an
/// n-dimensional problem: ARPACK's advice ncv >= 2 nev, plus a floor of 20 extra vectors
/// that lets one pass converge the ring's separated spectra. Satisfies Spectra's and
/// ARPACK's nev < ncv <= n. O(1).
/// \param nev 1 <= nev <= n - 1, else std::invalid_argument naming the range.
int subspace_size(int nev, int n);

}  // namespace modal
