// The options of the nonlinear analyses (forced response and statics), shared by every
// solver that offers them. The scene reader fills them; solvers read them and never
// include the scene format (ring/scene.hpp).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ring/spec.hpp"

namespace ring {

/// Forced nonlinear response from rest in the undeformed state (the paper's section 5).
struct ResponseOptions {
  Loads loads;                         ///< point loads, pressure, gravity
  LoadHistory history;                 ///< f(t) that scales every load
  double dt = 0.01;                    ///< s
  double t_end = 5.0;                  ///< s
  /// newmark: average acceleration (the paper's); generalized_alpha: Chung & Hulbert
  /// (1993) with rho_inf; energy_momentum: a scheme that conserves the undamped energy
  /// balance T + V - W to the Newton tolerance for any dt (only such a scheme carries this
  /// name); midpoint: the implicit midpoint rule (second order, its energy error O(dt^2)
  /// on a non-quadratic energy). Each solver offers some of them (docs/scenes.md,
  /// response.integrator) and refuses the others in its check_response.
  enum class Integrator { newmark, generalized_alpha, energy_momentum, midpoint };
  Integrator integrator = Integrator::newmark;
  double rho_inf = 0.8;                ///< generalized-alpha spectral radius, [0, 1]
  std::vector<double> record;          ///< degrees, points written
  double rayleigh_mass = 0.0;          ///< C = a M + b K: a, 1/s
  double rayleigh_stiffness = 0.0;     ///< b, s
  double hinge_damping = 0.0;          ///< N m s/rad at every hinge (a rotational damper
                                       ///< on the relative rotation of neighbouring pieces)
  /// Optional: told the fraction of t_end reached (0 .. 1), by the time-stepping driver
  /// (paths::Grid::progress), every ~1/200 of the run and at least every 0.05 s of work,
  /// on the integrating thread. Empty (the default): never called, no cost. The driver's
  /// progress line uses it; a solver only hands it on. An exception it throws ends the run:
  /// the Python module's Ctrl-C check does so. No exception crosses the FE plug-in's
  /// boundary (fem_reference/plugin.hpp): there it becomes a failure status, and the
  /// thrower, which knows why, reports it.
  std::function<void(double fraction)> progress;
};

/// Nonlinear statics under the loads, by load stepping (full load at the end).
struct StaticOptions {
  Loads loads;                         ///< point loads, pressure, gravity
  int steps = 20;                      ///< load increments
  std::vector<double> record;          ///< degrees, points reported
  /// The equilibrium path from rest as the result: every accepted equilibrium, branch
  /// switching at a bifurcation (onto the least stable direction), and the ring touching
  /// itself as an end that is a result, not a failure.
  bool path = false;
  /// static.branch: at a branch point, the side of the critical direction the path takes
  /// (+1 "positive": where the direction's largest unknown is positive; -1 "negative").
  /// The two sides of a symmetric pitchfork are mirror images with one load path.
  int branch_side = 1;
  /// static.history: the load factors visited in turn from rest, `steps` increments per
  /// leg (loading, unloading, reversed loading, cycles). Empty: one leg from 0 to 1.
  std::vector<double> history;
  /// static.displacement: the path is driven by a point's displacement instead of loads (a
  /// crushing test's way, and the way along a collapse plateau): the node at `at` is held at
  /// s times `value` (its x and y displacement, m; s the load factor, through the history as
  /// loads are), and the force the ring needs there is the result (PathPoint::reaction). No
  /// loads act with it (the scene reader refuses them); the point counts as a pin in the
  /// rigid-mode rule, and lies on a node of every model and on no support.
  struct Displacement {
    double at = 0.0;                   ///< degrees
    std::array<double, 2> value{0, 0};  ///< m, x and y, at load factor 1
  };
  std::optional<Displacement> displacement;
};

/// Refuses static.displacement (exit 2 naming the key) for `who`, a solver that has no
/// displacement control: "<who> has no displacement control (static.displacement) yet".
void refuse_displacement(const StaticOptions& statics, const std::string& who);

/// Linear buckling about the undeformed ring ([buckling]): the load factors lambda and
/// modes phi of the reference loads with
///
///   (K_0 + lambda K_1) phi = 0,   K_1 = d/ds K_T(s u_1, s) at s = 0,
///
/// K_T(u, s) the model's tangent stiffness at the state u under s times the loads (its
/// constraints' multipliers included; on the constraints' tangent space at rest), K_0 =
/// K_T(0, 0) and u_1 the linear static response to the loads (K_0 u_1 = f). K_1 holds the
/// initial stress of the linear prebuckling state, the load stiffness of follower and
/// central pressure, gravity's and a dead pressure's none, and the first-order
/// initial-displacement terms. Where the prebuckling state is a membrane state (uniform
/// pressure: u_1 = 0 on an inextensible model, a uniform contraction on an extensible
/// one) lambda is the bifurcation load of the continuum; where the loads bend the ring
/// (point loads) it is the model's first-order estimate and differs between formulations
/// by O(lambda |u_1|), which the nonlinear path does not.
struct BucklingOptions {
  Loads loads;     ///< the reference loads (buckling.loads, or [static]'s)
  int count = 4;   ///< the lowest positive critical load factors wanted
};

std::string to_string(ResponseOptions::Integrator i);

}  // namespace ring
