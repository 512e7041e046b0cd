// Internal to fem_reference/: the total potential of the geometrically exact beam with
// every term and load of a nonlinear analysis (nonlinear.hpp, "Terms and loads"), the one
// model that the statics (static_path.cpp) and the response (nonlinear.cpp) assemble.
#pragma once

#include <optional>
#include <vector>

#include "fem_reference/ring_model.hpp"
#include "ring/analysis.hpp"

namespace fem::detail {

/// Pi(q; s) = V(q) - s Phi(q) on a beam model's reduced unknowns q (BeamModel: the
/// Euler-Bernoulli RingModel or the Reissner TimoshenkoModel):
///  - V, the stored energy: the beam (BeamModel::beam_energy), the springs (kx, ky on the
///    vertex's Cartesian displacement, kr on the vertex's rotation, BeamModel::rotation_spring:
///    the mean of the two cells' exact tangent angles, or the section's psi) and the
///    foundation (radial and tangential, on the displacement along the undeformed point's
///    fixed directions);
///  - Phi, the potential of the loads at load factor 1 (F = grad Phi the generalized load,
///    -hess Phi its load stiffness): point loads, the weight of the point masses, uniform
///    pressure (follower: -p (A - A0), A the enclosed area; dead: -p int w ds0; central:
///    -p int (|x| - R) ds0), the beam's weight rho A int g . U ds0 and, on a spinning ring
///    (spec.rotation, in the frame that turns with it), the centrifugal body force's
///    speed^2/2 (int rho A (|x|^2 - R^2) ds0 + sum m (|x|^2 - |X|^2)) over the beam and the
///    point masses, x = X + u t0 + w n0: its Hessian speed^2 M_trans (the mass of the
///    translations, no rotary inertia) makes the tangent's centrifugal softening.
///  - [plates] (statics only): the plates' penalty (ring::PlatePair) as stored energy,
///    int 1/2 k <-g_p>^2 ds0 over the deformed centroid line x = x_t t0 + x_n n0 for both
///    plates, g_p = R - s travel / 2 - (+-d_0) . x: its gradient the plates' pressure, its
///    Hessian k e e^T (e = +-d_0 in the local (t0, n0)) where in_contact, and its derivative in
///    s, k travel / 2 e where in_contact, entering `load` as -dR/ds (the load column of the
///    bordered system; the plates have no Phi). The integrand has a kink where the gap
///    crosses zero, so it is not integrated by the Gauss rule of the other distributed terms
///    but by a composite Gauss-Lobatto rule, kPlateSubcells pieces of each cell with
///    kPlateLobatto points each: its points include every vertex (the two points of first
///    contact are vertices, so that the tangent at rest holds the ring along the axis), and
///    the force and extent of a growing flat contact err at first order in the points'
///    spacing h / (2 kPlateSubcells) (measured; fem_reference/README.md, "Rigid plates").
/// Pins, roller and clamp are the model's constraints (exact at any displacement).
/// ring.plastic: the beam's bending is the plastic law's incremental potential from the
/// committed states that the caller passes in (plastic_points.hpp); V is then the
/// incremental potential, the elastic energy at the committed equilibrium itself.
/// The object holds only constants of the model and the loads; evaluate() is reentrant.
class BeamPotential {
 public:
  /// `model` and `loads` must outlive the object; every point on a vertex (check_nonlinear).
  /// `statics`: ring.plastic's resultant law takes the vertices' continuous force
  /// (PlasticLaw::elastic_symmetry, ring_beam.cpp), as the statics do.
  /// `plates`: [plates] (static.plates; must outlive the object), or null.
  BeamPotential(const BeamModel& model, const ring::Loads& loads, bool statics = false,
                const ring::StaticOptions::Plates* plates = nullptr);

  struct Value {
    double stored = 0.0;  ///< V(q), J
    double load = 0.0;    ///< Phi(q), J (0 at rest): the work of the loads at factor 1
    /// [plates]: the force of each plate on the ring (the one at plates.axis first),
    /// int k <-g_p> ds0 along -d_p, N, x and y (0 without plates). The plates' penalty
    /// energy is part of `stored`.
    std::array<std::array<double, 2>, 2> plate_forces{};
  };
  /// V and Phi at q; with non-null pointers also the residual grad V - s grad Phi (reinit),
  /// the tangent hess V - s hess Phi (on model.sparsity() or a pattern that contains it;
  /// the whole matrix is zeroed first) and the load grad Phi (reinit).
  /// `committed`: with ring.plastic, the committed state of every bending point of the model
  /// (BeamModel::bending_points' order); null, or without ring.plastic: elastic.
  /// O(cells (p+2) (2p+3)^2), the beam's assembly (Reissner: O(cells (p+1) (3p+3)^2)).
  Value evaluate(const Vector<double>& q, double s, Vector<double>* residual, SparseMatrix<double>* tangent,
                 Vector<double>* load = nullptr, const std::vector<ring::PlasticState>* committed = nullptr) const;
  /// The Coriolis matrix G of the spinning ring (spec.rotation.speed; zero at rest) on the
  /// reduced unknowns, for M x'' + G x' + K x = 0 in the turning frame (modal/gyroscopic.hpp):
  /// the Lagrangian's speed int rho A U_t . S U ds0 (S the quarter turn, S t0 = -n0, S n0 = t0)
  /// gives G_ij = 2 speed int rho A (u_i w_j - w_i u_j) ds0 over the shape functions' (u, w)
  /// and 2 speed m (Uy_i Ux_j - Ux_i Uy_j) on each point mass's vertex: skew. Assembled into
  /// `G` (on model.sparsity(); zeroed first) with the distributed terms' cell rule. O(cells (p+2) (2p+3)^2).
  void coriolis(SparseMatrix<double>& G) const;
  /// The law of ring.plastic at the beam's bending points (and vertex hinges); nullopt
  /// without ring.plastic.
  const std::optional<PlasticLaw>& plastic_law() const { return law_; }
  /// [plates]' contact law; nullopt without plates.
  const std::optional<ring::PlatePair>& plates() const { return plates_; }
  /// The count of plastic states of the model (0 without ring.plastic).
  std::size_t plastic_states() const {
    return law_ ? law_->states(model_.bending_point_count(), model_.cells()) : 0;
  }

 private:
  const BeamModel& model_;
  const ring::Loads& loads_;
  double rhoA_ = 0.0;
  /// The loads that do not depend on q: point loads and the point masses' weight.
  Vector<double> constant_load_;
  /// A translational spring: stiffness / 2 (c . x)^2 on the local DoFs of its vertex.
  struct Translation {
    std::vector<types::global_dof_index> dofs;
    std::vector<double> coef;
    double stiffness = 0.0;
  };
  std::vector<Translation> translations_;
  /// The spin's centrifugal force on each point mass: speed^2 m / 2 (c . x)^2 per Cartesian
  /// direction c (a load potential, not stored energy).
  std::vector<Translation> spinning_masses_;
  /// A rotational spring kr at a vertex.
  std::vector<std::pair<unsigned int, double>> rotations_;
  bool distributed_ = false;  ///< foundation, pressure, gravity or a spin: the cell loop runs
  double speed_ = 0.0;        ///< spec.rotation.speed, rad/s (the centrifugal potential and G)
  std::optional<PlasticLaw> law_;  ///< ring.plastic's law at the bending points
  std::optional<ring::PlatePair> plates_;
  /// The plates' cell rule (class comment): abscissae in [0, 1], weights times the cell's rest
  /// length (ds0), and per point and local shape function i (index [q * dofs per cell + i])
  /// the derivative of (x_t, x_n) by DoF i.
  struct PlateRule {
    std::vector<double> xi, ds;
    std::vector<std::array<double, 2>> row;
  };
  PlateRule plate_rule_;
  /// Adds the plates' penalty at load factor s (class comment) to `out` and the outputs.
  void add_plates(const Vector<double>& full, double s, Value& out, Vector<double>* residual,
                  SparseMatrix<double>* tangent, Vector<double>* load) const;
};

}  // namespace fem::detail
