// Internal to lumped_mass/: what the chain (nonlinear.cpp) and the frames (frame_nonlinear.cpp)
// add to the midpoint rule (paths/midpoint.hpp): their Rayleigh damping and their run of the
// time-stepping driver with the energy guard.
#pragma once

#include <Eigen/SparseCore>

#include <string>

#include "paths/midpoint.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped::detail {

using paths::MidpointStepper;

/// Rayleigh damping C = a M + b K0 on the unknowns (`r`'s rayleigh_mass and
/// rayleigh_stiffness), K0 from the Hessian triplets of the springs and terms at rest that
/// `k0()` returns: called only when a coefficient is not zero (C is empty then). O(nonzeros).
template <class RestHessian>
Eigen::SparseMatrix<double> rayleigh_damping(const ring::ResponseOptions& r, const Eigen::SparseMatrix<double>& M,
                                             const RestHessian& k0) {
  Eigen::SparseMatrix<double> C(M.rows(), M.cols());
  if (r.rayleigh_mass > 0 || r.rayleigh_stiffness > 0) {
    const auto triplets = k0();
    Eigen::SparseMatrix<double> K0(M.rows(), M.cols());
    K0.setFromTriplets(triplets.begin(), triplets.end());
    C = r.rayleigh_mass * M + r.rayleigh_stiffness * K0;
  }
  return C;
}

/// Runs `stepper` on the response's time grid with the one energy guard (ring/energy_guard.hpp:
/// the midpoint rule's O(h^2) balance error, either sign; a gain beyond its bound is a failed
/// integration), as `who` in messages; the history names the solver and its unknowns (its
/// seconds are the caller's).
ring::TimeHistory integrate_midpoint(paths::Stepper& stepper, const ring::RingSpec& spec, int nodes,
                                     const ring::ResponseOptions& r, const std::string& who, int unknowns);

}  // namespace lumped::detail
