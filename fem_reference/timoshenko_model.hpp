// Internal to fem_reference/: the deal.II model of the linear Timoshenko ring (the
// formulation, and why it does not lock, is in modes.hpp, "Timoshenko"). It shares the
// eigen-solve, its refinement, the reduced numbering and the point terms with the
// Euler-Bernoulli RingModel through LinearModel (ring_model.hpp).
//
// Shape of the program (deal.II step-47): the constructor runs make_grid(),
// setup_constraints(), setup_reduced_system(), setup_point_terms(), assemble()
// (timoshenko_model.cpp); solve() is LinearModel's (ring_eigen.cpp).
#pragma once

#include "fem_reference/ring_model.hpp"

namespace fem::detail {

/// The curved Timoshenko ring: fields u (tangential), w (radial), psi (cross-section
/// rotation, counter-clockwise) of the polar angle, each C0 FE_Q of degree p, DoF order of
/// the FESystem (components 0, 1, 2). Membrane and shear strains are integrated with p
/// Gauss points (their L2 projection onto discontinuous P_{p-1}), bending, foundation and
/// mass with p + 1 (exact). It is also the geometrically exact Reissner beam (BeamModel;
/// reissner_beam.cpp, formulation in nonlinear.hpp, "Timoshenko").
class TimoshenkoModel : public BeamModel {
 public:
  /// Builds mesh, constraints and matrices. O(cells (3p+3)^2).
  TimoshenkoModel(const ring::RingSpec& spec, const Setup& setup);

  /// Radial and tangential displacement at the common stations, normalized. O(kStations p).
  ring::ModeShape sample(const Vector<double>& full) const override;
  /// Writes the given full vectors to a VTU file (write_ring_vtu: u, w and the rotation psi).
  void write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                 const std::string& file) const override;

  /// The Reissner beam's strain energy, its exact gradient and Hessian (reissner_beam.cpp):
  /// membrane and shear with the p-point rule, bending with p + 1 points, as the linear
  /// model's stiffness, which is its tangent at rest. O(cells (p+1) (3p+3)^2).
  using BeamModel::beam_energy;
  double beam_energy(const Vector<double>& q, Vector<double>* gradient, SparseMatrix<double>* tangent,
                     const Plasticity* plastic) const override;
  std::vector<BendingPoint> bending_points(const Vector<double>& q, const Plasticity& plastic) const override;
  /// ring.plastic is not offered on the Reissner beam (check_static): these throw
  /// std::logic_error, and beam_energy does with a non-null `plastic`.
  std::size_t bending_point_count() const override { return 0; }

 private:
  std::array<types::global_dof_index, 2> translation_dofs(unsigned int k) const override {
    const auto d = vertex_dofs(k);
    return {d[0], d[1]};
  }
  /// kr/2 psi^2 at the vertex: exact (psi is the section's rotation from its rest direction).
  double rotation_spring(unsigned int v, double kr, const Vector<double>& full, Vector<double>* gradient,
                         SparseMatrix<double>* tangent) const override;
  const FESystem<1>& fe() const override { return fe_; }

  /// What one shape function contributes at one point: tangential and radial displacement,
  /// rotation psi, strain eps = (u' + w)/R, shear gamma = psi - (u - w')/R, change of
  /// curvature kappa = psi'/R.
  struct Strains {
    double u = 0.0, w = 0.0, psi = 0.0, eps = 0.0, gamma = 0.0, kappa = 0.0;
  };
  /// Shape functions on the reference cell (all cells are the same affine image of it):
  /// Strains of shape function i at point q, index [q * dofs per cell + i], and the
  /// quadrature weight times ds at q.
  struct Table {
    std::vector<Strains> at;
    std::vector<double> ds;
    unsigned int points = 0;
  };

  void make_grid();
  void setup_constraints();
  void setup_reduced_system();
  /// Springs and point masses as PointTerms: kx, ky, m on the vertex's Cartesian
  /// displacement, kr and J on its psi.
  void setup_point_terms();
  void assemble();
  void apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const override;

  /// The table of `quadrature` on the reference cell.
  Table make_table(const Quadrature<1>& quadrature) const;
  /// DoFs of u, w, psi at vertex v (the left end of cell v).
  std::array<types::global_dof_index, 3> vertex_dofs(unsigned int v) const;

  Triangulation<1> triangulation_;
  FESystem<1> fe_;
  DoFHandler<1> dof_handler_;
  Table full_;     ///< p + 1 Gauss points: bending, foundation, mass
  Table reduced_;  ///< p Gauss points: membrane and shear
};

}  // namespace fem::detail
