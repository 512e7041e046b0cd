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
  /// [plates]: the path is driven by two rigid, frictionless flat plates instead of loads (a
  /// tube crushed between plates, DeRuntz & Hodge 1963). The plates are normal to the
  /// diameter at `axis` and touch the ring's outer surface at rest, at the points `axis` and
  /// `axis` + 180; each moves towards the centre by s travel / 2 (s the load factor, through
  /// the history), so that they approach each other by s travel and the ring's centre stays.
  /// See PlatePair for the contact law every solver uses. No loads act with them, and the
  /// ring has no supports: the plates hold it along the axis, the two points of first contact
  /// keep their position along the plates (one constraint row each, e . u = 0 with e the
  /// plates' direction: the ring's sliding and turning between frictionless plates), and
  /// their midpoint stays on the plates' midline (d . (u_a + u_b) = 0: a ring that springs
  /// back clear of both plates stays where it is). The symmetric crushing leaves the three
  /// rows unloaded (their multipliers stay ~0). Both points are nodes of every model.
  struct Plates {
    double axis = 90.0;      ///< degrees: the plates' normal, and the first contact point
    double travel = 0.0;     ///< m, the plates' approach at load factor 1, in (0, 2 R)
    double stiffness = 0.0;  ///< N/m^2: the penalty per metre of ring (PlatePair)
  };
  std::optional<Plates> plates;
  /// The path is driven (static.displacement or [plates]): the load factor is the fraction of
  /// the prescribed motion, and the reaction (PathPoint::reaction) is the result.
  bool driven() const { return displacement.has_value() || plates.has_value(); }
};

/// The contact law of [plates], one for every solver. Frictionless plate p (0: the plate at
/// `axis`, 1: the one at `axis` + 180) is a half-plane whose boundary lies R - s travel / 2
/// from the ring's centre along its normal d_p (d_0 = (cos axis, sin axis), d_1 = -d_0). The
/// ring's outer surface at a point x of the centroid line (ring-centred, m) is taken as
/// x + (h / 2) d_p, the section lying flat on the plate, so the half thickness cancels and
/// the gap is
///
///   g_p(x, s) = R - s travel / 2 - d_p . x    (m; 0 at the contact points at rest).
///
/// The plate presses the ring with k <-g>, N per metre of centroid line, along -d_p (a
/// penalty: the energy 1/2 k <-g>^2 per metre, integrated by each solver's rule for its
/// foundation). k defaults to E A^2 / (12 I), which is E b / h for a b x h rectangle: the
/// wall's own stiffness through its thickness, so that the plate sinks into the wall by about
/// what the wall itself would be squeezed, F / (k l) over a contact length l, a few 1e-5 R
/// at a crushing load (rigid plates are the limit k -> infinity). The tangent stiffness is k
/// where in_contact(g) (g <= 1e-12 R, which holds the two touching points at rest, so that
/// the first tangent is regular along the axis), else 0. The point x is the centroid line's
/// own point (on the circle at rest), not a chain's hinge (outside it by O(R / n^2)), and a
/// solver with a stiff penalty computes g from the displacement, R (1 - cos(theta - axis)) -
/// d_p . u - s travel / 2, since R - d_p . x keeps only ~1e-16 R of a sinking of 1e-10 R.
struct PlatePair {
  double R = 1.0;
  double travel = 0.0;
  double k = 0.0;
  std::array<double, 2> d{0.0, 1.0};  ///< d_0, the unit normal of the plate at `axis`

  PlatePair(const RingSpec& spec, const StaticOptions::Plates& plates);
  /// g_p at (x, y), load factor s; m.
  double gap(int plate, double x, double y, double s) const {
    const double along = d[0] * x + d[1] * y;
    return R - 0.5 * s * travel - (plate == 0 ? along : -along);
  }
  bool in_contact(double g) const { return g <= 1e-12 * R; }
  /// The pressure k <-g>, N/m; 0 out of contact.
  double pressure(double g) const { return g < 0.0 ? -k * g : 0.0; }
  /// The penalty energy per metre, 1/2 k <-g>^2, J/m.
  double energy(double g) const { return g < 0.0 ? 0.5 * k * g * g : 0.0; }
  /// The gaps of both plates at every point of a closed ring's centroid line, and the
  /// contact length on each: the arc length (along the chords between consecutive points)
  /// from the first to the last point in contact on the half of the ring that faces the
  /// plate, each end extended to where the gap, linear between two points, crosses zero.
  /// This is the extent of the contact, the length of DeRuntz & Hodge's flat part (a plate
  /// may touch an elastic wall at the ends of that part only, the middle lifting by far less
  /// than the penalty's sinking). (x[i], y[i]): deformed points in order around the ring,
  /// m, at least 4. O(points).
  std::array<double, 2> contact_lengths(const std::vector<double>& x, const std::vector<double>& y, double s) const;
};

/// The rigid motions that `statics` leaves free (a static analysis needs 0):
/// static_rigid_modes(spec, statics.loads), with a driven point (static.displacement)
/// counted as a pin, and none with [plates] (the plates and the two points of first contact
/// hold the free ring).
int static_rigid_modes(const RingSpec& spec, const StaticOptions& statics);

/// Refuses [plates] (exit 2 naming the key) for `who`, a solver that has no plates yet.
void refuse_plates(const StaticOptions& statics, const std::string& who);

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
