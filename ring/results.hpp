// Result types shared by all solvers, so that the driver can compare them.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace ring {

/// Mode shapes are sampled at these common stations so that the driver can pair
/// the modes of different solvers by MAC and plot them: kStations points at polar
/// angles a_s = 360 * s / kStations degrees (every degree), counter-clockwise from +x.
/// On a polygonal model with consecutive nodes at angles a_k < a_s < a_{k+1}, station s
/// is the point at fraction (a_s - a_k) / (a_{k+1} - a_k) along that side, displaced
/// by the model's own interpolation (linear along a rigid segment, the element's shape
/// functions in FE). Radial and tangential are taken along the circle's unit vectors
/// at a_s. Nodes coincide with stations whenever their angles are whole degrees.
constexpr int kStations = 360;
/// Polar angle of station s, degrees.
inline double station_angle(int s) { return 360.0 * s / kStations; }

/// One mode shape at the common stations: radial (outward) and tangential
/// (counter-clockwise) displacement, scaled so that the largest |component| is 1 and
/// its sign is positive.
struct ModeShape {
  std::vector<double> radial;
  std::vector<double> tangential;
};

/// ModalResult::residual_norm of the one definition of ModalResult::max_residual.
inline const char* const kResidual2Norm = "2-norm";

/// A value describing a model (JSON scalar).
using ModelValue = std::variant<long long, double, bool, std::string>;

/// A mode of a spinning ring (rotation.speed != 0): the travelling wave its complex shape is.
/// x(t) = Re(x e^{i omega t}); the Fourier coefficients c_k of its radial and tangential shape (w = sum c_k e^{i k theta})
/// name it: `number` the wave number k >= 0 of the largest |c_k|^2 + |c_-k|^2, `direction` +1 when
/// it travels in the sense of the spin (c_-k the larger for a positive speed), -1 against it, 0
/// standing (|c_k| = |c_-k| to 1e-6 of them, as at rest). modal::classify_wave.
struct Wave {
  int number = 0;
  int direction = 0;
};

/// A spinning ring's wave pair k (the driver's compare/spin.hpp): its lowest forward and lowest
/// backward mode. rad/s.
struct SpinPair {
  int wave = 0;
  double forward = 0.0, backward = 0.0;              ///< in the turning frame
  /// In the fixed frame, signed: forward + k |speed| and backward - k |speed|; a negative
  /// backward_fixed is a backward wave that the spin carries forward in space (past the
  /// critical speed, where it stands still).
  double forward_fixed = 0.0, backward_fixed = 0.0;
  /// Bryan's factor: the rate at which the pair's standing pattern turns in space over the
  /// spin's, 1 - (backward - forward) / (2 k |speed|); (k^2 - 1)/(k^2 + 1) for the inextensible ring.
  double bryan = 0.0;
};

/// Natural frequencies and mode shapes of one model.
struct ModalResult {
  std::string solver;                         ///< "multibody", "fem", "lumped"
  std::map<std::string, ModelValue> model;    ///< the discretization (n, degree, ...)
  int rigid_modes = 0;                        ///< zero modes found, excluded from numbering
  std::vector<double> omega;                  ///< elastic modes, rad/s, ascending
  std::vector<ModeShape> shapes;              ///< same order as omega
  long long unknowns = 0;                     ///< size of the eigenproblem solved
  double seconds = 0.0;                       ///< solver wall time (process-internal)
  /// The one residual of a modal result: over the returned (elastic) pairs, the largest
  ///   ||K x - w^2 M x|| / (||K x|| + w^2 ||M x||)   (modal::relative_residual),
  /// in the 2-norm of the solver's admissible coordinates: the constraints eliminated, or
  /// the residual projected onto the admissible space so that constraint forces do not
  /// count. Rigid pairs are not included. For a double-precision vector this ratio has a
  /// rounding floor ~eps ||K|| / w^2 that grows with the discretization whatever the
  /// solver (modal/modes.hpp); a solver whose floor would hide every digit reports the
  /// same ratio in another norm and names it in residual_norm. Empty where the solver
  /// reports none (ccx, an imported column): printed empty or "-" and written as JSON null,
  /// never as NaN or as a perfect 0.
  std::optional<double> max_residual = 0.0;
  /// The norm of max_residual: kResidual2Norm (the definition above), or the solver's own,
  /// documented where it is computed ("dual norm of K - sigma M": fem_reference/modes.hpp).
  std::string residual_norm = kResidual2Norm;
  /// Estimated remaining relative error (reference runs only; 0 if not estimated).
  double error_estimate = 0.0;
  /// The model is an arch (ring.arc): its modes come in no degenerate pairs (compare/pairs.hpp).
  bool arch = false;
  /// A spinning ring (rotation.speed != 0): each mode's wave, same order as omega (empty at
  /// rest). Its omega are then in the rotating frame as the solvers return them (frame =
  /// "rotating"), or the fixed frame's |omega + direction k speed| re-sorted by the driver
  /// (modes.frame = "fixed"), shapes the real part x at t = 0, phased so that the largest
  /// radial entry is real.
  std::vector<Wave> waves;
  std::string frame;  ///< "rotating" or "fixed" for a spinning ring, "" at rest
  /// A spinning ring's wave pairs, by wave number (the driver fills them from the turning
  /// frame's waves: compare/spin.hpp).
  std::vector<SpinPair> spin_pairs;
};

/// Linear buckling of one model (ring::BucklingOptions): the lowest positive critical load
/// factors of the reference loads, ascending, and their mode shapes at the common stations
/// (ModeShape's scaling); a load factor of 1 is the loads as given.
struct BucklingResult {
  std::string solver;                         ///< "multibody", "fem", "lumped"
  std::map<std::string, ModelValue> model;    ///< the discretization (n, degree, ...)
  std::vector<double> factors;                ///< lambda_1 <= lambda_2 <= ...
  std::vector<ModeShape> shapes;              ///< same order as factors
  long long unknowns = 0;                     ///< size of the eigenproblem solved
  double seconds = 0.0;                       ///< solver wall time
  double error_estimate = 0.0;                ///< reference runs only; 0 if not estimated
};

/// Displacement of a named point, ring-centred frame.
struct PointDisplacement {
  double angle = 0.0;  ///< degrees
  double ux = 0.0, uy = 0.0;  ///< m
};

/// One accepted equilibrium of a static path (static.path = true).
struct PathPoint {
  double load_factor = 0.0;                      ///< s: the loads are s times those given
  std::vector<PointDisplacement> displacements;  ///< at the recorded points
  /// (largest - smallest distance between opposite nodes) / R: 0 on the circle, about
  /// 2.7 for the inextensible ring flattened until its sides touch (its length is 2 pi R)
  double ovalisation = 0.0;
  /// The deformed ring: every node's position (every ceil(nodes / kPathShapeNodes)-th node
  /// of a finer model), ring-centred frame, m; for the figure of the ring as it flattens.
  std::vector<double> node_x, node_y;
  /// ring.plastic: the plastic work done so far (the integral of M d(kappa_p) over the ring), J,
  /// and the largest |plastic curvature| kappa_p anywhere on the ring, 1/m (a chain's hinge:
  /// its plastic rotation over the segment length). 0 for an elastic ring.
  double dissipated = 0.0;
  double plastic_curvature = 0.0;
  /// static.displacement: the force the ring needs at the driven point to be there, N, x
  /// and y (the force the rig applies to the ring; a pinch downwards has reaction[1] < 0).
  /// 0 without displacement control.
  std::array<double, 2> reaction{0.0, 0.0};
  /// [plates]: the contact length on each plate (the one at plates.axis, then the opposite
  /// one), m (ring::PlatePair::contact_lengths); `reaction` is then the force of the plate at
  /// plates.axis on the ring, N, x and y (along -d_0). 0 without plates.
  std::array<double, 2> contact_length{0.0, 0.0};
};

/// The most nodes a PathPoint keeps of its deformed ring: a figure's resolution, and the
/// path's memory bounded (16 B x 720 per equilibrium) whatever the model's size.
constexpr int kPathShapeNodes = 720;

/// The stride that keeps at most kPathShapeNodes of `nodes` nodes.
inline int path_shape_stride(long long nodes) {
  return static_cast<int>((nodes + kPathShapeNodes - 1) / kPathShapeNodes);
}

/// Nonlinear static equilibrium.
struct StaticResult {
  std::string solver;                            ///< "multibody", "fem", "lumped"
  long long unknowns = 0;                        ///< size of the nonlinear system
  double seconds = 0.0;                          ///< solver wall time
  std::vector<PointDisplacement> displacements;  ///< at the recorded points
  int steps = 0;
  int newton_iterations = 0;
  /// Deformed shape at every node (for figures), ring-centred frame, m.
  std::vector<double> node_x, node_y;
  /// static.path = true: every accepted equilibrium from rest, the load factors where the
  /// path switched onto a branch, and how it ended: at the full load, or where the ring
  /// touched itself (a result: the equilibrium above is the last one before the touch).
  std::vector<PathPoint> path;
  std::vector<double> branch_points;
  /// static.path = true: the located limit points (maxima of the load factor along the path,
  /// paths::Trace::limit_state), each with the recorded points' displacements there.
  std::vector<PathPoint> limit_points;
  std::string end = "full load";  ///< "full load", "end of the history" or "contact: <where>"
  double end_load = 1.0;          ///< load factor where the path ended
  /// ring.plastic, at the end: as PathPoint's (J, 1/m).
  double dissipated = 0.0;
  double plastic_curvature = 0.0;
  /// static.displacement, at the end: as PathPoint's (N, x and y).
  std::array<double, 2> reaction{0.0, 0.0};
  /// [plates], at the end: as PathPoint's (m).
  std::array<double, 2> contact_length{0.0, 0.0};
  /// The path was driven by static.displacement or [plates] (the registry sets it from the
  /// scene): the load factor is the fraction of the prescribed motion, `reaction` the result.
  bool driven = false;
  /// The drive was [plates] (the registry sets it): contact_length is a result.
  bool plates = false;
};

/// Time history of a forced response; one entry per accepted step (t = 0 first).
struct TimeHistory {
  std::string solver;                    ///< "multibody", "fem", "lumped"
  long long unknowns = 0;                ///< size of the nonlinear system per step
  double seconds = 0.0;                  ///< solver wall time
  std::vector<double> record_angles;     ///< degrees
  std::vector<double> t;                 ///< s
  std::vector<std::vector<double>> ux;   ///< [point][step], m
  std::vector<std::vector<double>> uy;   ///< [point][step], m
  std::vector<double> kinetic, strain, work, energy_error, constraint_residual;
  /// ring.plastic: the plastic work done up to each step (J; empty for an elastic ring).
  /// `strain` is then the elastic energy stored, and energy_error measures
  /// kinetic + strain + dissipated - work.
  std::vector<double> dissipated;
  std::vector<int> newton_iterations;
  /// Deformed node positions at selected instants (for the paper's Figure 5).
  std::vector<double> snapshot_t;
  std::vector<std::vector<double>> snapshot_x, snapshot_y;
};

}  // namespace ring
