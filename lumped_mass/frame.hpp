// The nonlinear (corotational) Timoshenko frame (lumped.variant = "timoshenko-frame"): the
// model shared by its statics and response (frame.cpp). An internal header of lumped_mass/:
// the driver and the other solvers never include it.
//
// Unknowns q = (x_0, y_0, th_0, x_1, ...) (3n values, model.hpp's frame order): the node
// positions in the ring-centred frame, m, and th the rotation of the cross-section from its
// rest orientation, rad (ccw). No internal constraints (the frame is extensible); the support
// rows of the linear model, S (q - rest) = 0 (pins, further pins, roller, the clamp's rotation).
//
// Element j (node j to j+1, rest chord of the n-gon, rest length L0 = l): the corotational
// form (Crisfield, Non-linear Finite Element Analysis of Solids and Structures, vol. 1, 1991,
// ch. 7; Battini). With the deformed chord d = x_{j+1} - x_j, L = |d| and its rotation from
// the rest chord e0, alpha = atan2(e0 x d, e0 . d) (exact for element rotations below pi),
// the local deformations are
//   e = L - L0,   t1 = th_j - alpha,   t2 = th_{j+1} - alpha,
// and the energy is 1/2 EA/L0 e^2 + 1/2 t^T Kb t with Kb the bending block of the linear
// element (model.hpp natural_stiffness: Przemieniecki's with the shear for timoshenko-frame,
// the Hermite element's for frame and frame-consistent). Gradient
// and Hessian by the chain rule, exact (terms.hpp angle_gradient, angle_hessian). At rest
// e = t = 0, so the Hessian there is the linear timoshenko-frame's element stiffness: the
// nonlinear frame is the linear one in small displacements (tests/lumped_mass/frame_test.cpp
// checks both to round-off). The bending part is evaluated as bending.hpp splits it: the
// constant-curvature mode th_{j+1} - th_j (linear in q) under the bending law, elastic or
// ring.plastic's, and the linear mode t1 + t2 elastic; elastic, the sum is 1/2 t^T Kb t. The rest section rotations are zero: th counts from rest, the
// linear model's convention, so no initial curvature enters the element.
//
// The spec's terms (terms.hpp, dofs_per_node = 3: springs kx, ky on the translations, kr and
// the point inertia J on th, the foundation on the fixed rest directions) and the loads
// (loads.hpp, ChainLoads on the node positions: point loads, follower, dead and central
// pressure on the deformed chords, half to each end, gravity on the translational mass) are
// the same code as the chain's. Mass: the linear model's (model.cpp), rho A l per node on the
// translations and rho I l on th, plus the point masses: constant and exact in large rotations
// (plane rotation: the rotary kinetic energy is J thdot^2 / 2 whatever th).
//
// Every frame variant takes this corotational form with its linear element's stiffness; the
// statics converge when no node moves by more than 1e-12 R (frame_nonlinear.cpp), and the
// response's energy error is the midpoint rule's O(dt^2) once dt resolves the axial and shear
// periods.
//
// Cost: O(n) time and memory for every function here.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>

#include "lumped_mass/chain.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/model.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "lumped_mass/terms.hpp"
#include "paths/continuation.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped {

struct Frame {
  int n = 0;
  double l = 0.0;               ///< rest chord length = 2 pi R / n, m
  NaturalStiffness k;           ///< EA/l and the bending block (model.hpp)
  /// The bending block split (bending.hpp): the constant-curvature mode u = th_{j+1} - th_j
  /// under the law `bending` (stiffness (Kb00 - Kb01) / 2 = EI / l), the linear mode
  /// v = t1 + t2 elastic with `linear_mode` = (Kb00 + Kb01) / 2, N m/rad.
  Bending bending;
  double linear_mode = 0.0;
  Eigen::VectorXd rest;         ///< 3n: rest positions on the n-gon and zero rotations
  Eigen::VectorXd rest_xy;      ///< 2n: the rest positions alone
  Eigen::SparseMatrix<double> S;  ///< support rows on q (model.cpp), S (q - rest) = 0
  Eigen::SparseMatrix<double> M;  ///< 3n x 3n constant mass (model.cpp), kg and kg m^2
  std::optional<Terms> terms;   ///< springs, the foundation, point masses (terms.hpp)
  Chain geometry;               ///< n, l, depth, circumradius, anchor: the contact check's view
  double scale = 0.0;           ///< EI / l^3: the constraint rows' scaling in the KKT systems
  /// static.displacement: the driven node (-1: none), whose two rows are S's last (the chain's
  /// with_point_rows), held at S (q - rest) = s `drive` (m at load factor 1).
  int driven = -1;
  Eigen::Vector2d drive{0.0, 0.0};

  /// The node positions (2n) of q.
  Eigen::VectorXd positions(const Eigen::VectorXd& q) const;
};

/// The frame of `spec` with n = o.n (the caller has run the checks of checks.hpp).
Frame make_frame(const ring::RingSpec& spec, const ring::LumpedOptions& o);

/// One element's energy, gradient and Hessian on (x_j, y_j, th_j, x_{j+1}, y_{j+1}, th_{j+1}).
struct FrameElement {
  double energy = 0.0;
  Eigen::Matrix<double, 6, 1> grad;
  Eigen::Matrix<double, 6, 6> hess;
};
FrameElement frame_element(const Frame& f, const Eigen::VectorXd& q, int j, bool with_hessian);

/// The elements' bending strains u_j = th_{j+1} - th_j at q (f.bending's rotations), rad.
std::vector<double> bending_strains(const Frame& f, const Eigen::VectorXd& q);

/// V (elements and terms; the bending law's incremental potential from its committed states), grad V and, scaled by hess_scale (if not zero), Hess V on q.
Springs frame_energy(const Frame& f, const Eigen::VectorXd& q, double hess_scale);

/// The loads (loads.hpp) as functions of q: the chain's potential of the node positions.
class FrameLoads {
 public:
  FrameLoads(const Frame& f, const ring::RingSpec& spec, const ring::Loads& loads, const std::string& section);
  double potential(const Eigen::VectorXd& q) const;
  Eigen::VectorXd gradient(const Eigen::VectorXd& q) const;
  void add_hessian(const Eigen::VectorXd& q, double scale, Triplets& out) const;
  /// Adds the spin's centrifugal body force on the translational mass (ChainLoads::set_spin).
  void set_spin(double speed);

 private:
  const Frame& f_;
  std::optional<ChainLoads> loads_;
};

/// What the frame's path accumulated (StaticDetail's and ring::StaticResult's meanings): the
/// plastic work and the largest |plastic curvature| at the end (J, 1/m), the loads' work along
/// the path and the elastic energy at the end (J).
struct FramePathEnergy {
  double dissipated = 0.0, plastic_curvature = 0.0, work = 0.0, stored = 0.0;
  std::array<double, 2> reaction{0.0, 0.0};  ///< static.displacement: the rig's force at the end, N
  std::array<double, 2> contact_length{0.0, 0.0};  ///< [plates]: at the end, m
};

/// The frame's equilibrium path from rest to the full load (or through statics.history) (the continuation driver on
/// FrameStatics: frame_nonlinear.cpp), z = (q, mu scaled); throws ring::NumericalError
/// "`who`: ..." when it does not reach the full load. `energy` (if not null) gets the path's
/// energies.
paths::Trace frame_path(const Frame& f, const FrameLoads& loads, double radius, const ring::StaticOptions& statics,
                        const std::string& who, FramePathEnergy* energy = nullptr);

/// The frame's statics and response, the entry points of nonlinear.hpp for this variant
/// (the caller has run check_static / check_response).
StaticDetail frame_static(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                const ring::StaticOptions& statics);
ring::TimeHistory frame_respond(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                const ring::ResponseOptions& response);

}  // namespace lumped
