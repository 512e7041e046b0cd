// Internal to fem_reference/: the deal.II model of the linear ring (mesh, constraints,
// assembly, the eigen-solve and its refinement, sampling and VTU output), shared by the
// files that implement fem/modes.hpp. The formulation is documented in modes.hpp.
//
// Shape of the program (deal.II step-47): RingModel's constructor runs make_grid(),
// setup_constraints(), setup_reduced_system(), assemble() (ring_model.cpp); solve()
// computes the lowest modes (ring_eigen.cpp); sample() evaluates the FE fields at the
// common stations; write_vtu() writes them for ParaView (ring_vtu.cpp); modes.cpp is the
// reference driver (validation, the inextensible extrapolation, p/h refinement).
// LinearModel is what the eigen-solve and the driver see of a model: RingModel
// (Euler-Bernoulli) and TimoshenkoModel (timoshenko_model.hpp) implement it.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ring/errors.hpp"
#include "ring/sampling.hpp"

#include "fem_reference/checks.hpp"
#include "fem_reference/modes.hpp"
#include "fem_reference/plastic_points.hpp"

namespace fem::detail {

using namespace dealii;
using Geometry = ring::FemOptions::Geometry;

constexpr double kPi = 3.14159265358979323846;
/// Above this many free unknowns the dense O(N^3) LAPACK solve gives way to ARPACK.
constexpr unsigned int kDenseLimit = 150;
/// Refinements a reference may take (p up to fem::kMaxDegree, checks.hpp, then h).
constexpr int kReferenceMaxSteps = 40;
/// Extra eigenpairs computed above the wanted ones for the refinement (refine()).
constexpr unsigned int kGuardModes = 8;
/// Reference runs refine the eigenpairs once successive frequencies change by less.
constexpr double kRefineBelowChange = 1e-5;
/// The reference stops on the extrapolated error of its latest solution (modes.cpp) only
/// where the changes contract at least this fast per refinement: p-refinement contracts them
/// by 0.03, 0.016, 0.011 at p = 4..7 on the paper's ring (raw and refined alike), and the
/// contraction itself shrinks, so the geometric extrapolation over-estimates (5.5e-10 at
/// p = 7 for a change of 3.2e-10 to p = 8).
constexpr double kTrustedContraction = 0.1;
/// Subspace-iteration corrections in refine(): until every pair's residual is below
/// kRefinedResidual or stops halving, at most this many.
constexpr unsigned int kMaxRefinementRounds = 8;
constexpr double kRefinedResidual = 1e-11;
/// Rigid modes are the supports' count of lowest pairs (spec.rigid_modes()), not
/// a threshold on lambda: on the exact circle the polar fields only approximate the rigid
/// translations, whose lambda is the discretization's error, up to 0.1 EI/(rho A R^4) on
/// 4 cells of degree 2, 1e-3 on 40 of degree 2, 4e-7 on 40 of degree 3 (measured, free
/// ring), mostly far above the round-off that modal::is_rigid recognizes. A discretization
/// whose highest rigid lambda is not below kRigidSeparation times the lowest elastic one
/// cannot represent the rigid modes and is refused (modes.cpp).
constexpr double kRigidSeparation = 1e-2;
/// A refined elastic pair whose residual (refine()) stays above this is not a result:
/// the eigen-solve has lost its accuracy (measured, the frequency error is 1e-2 to 1e-1
/// of the residual near the precision limit: 10^4 cells of degree 8, residual 1.9e-2,
/// frequency 0.09 % off; 3000 of degree 12 with one correction, 6.6e-3 and 0.007 %).
constexpr double kAcceptedResidual = 1e-4;
/// kPrecisionLimit (checks.hpp): the largest eps lambda_max / |sigma| (precision_ratio())
/// that the eigen-solve resolves, with its measurements.
/// Relative round-off of refined frequencies (measured, see the estimate below).
constexpr double kRoundOffFloor = 1e-12;
/// Inextensible limit: EA -> beta EI / R^2 for these beta, then Richardson in 1/beta.
constexpr double kInextensibleBeta = 1e6;
/// ring.variations: the Euler-Bernoulli cell rule takes p + 2 + kVariationPoints +
/// ceil(2 K h) Gauss points (K the highest harmonic, h the cell's angle) instead of p + 2.
/// The integrands are then a polynomial of degree <= 2p + 2 times the local section, whose
/// harmonics reach 4K (I ~ s^4 on a circle); the rule's error on them falls like h^(2n),
/// far faster than the FE's own h^(2p) (measured in fem_variations_test).
constexpr int kVariationPoints = 4;

/// One discretization of the ring: what RingModel is built from.
struct Setup {
  int elements = 40;      ///< equal pieces (chords on the polygon), vertex 0 at the pin
  int subdivisions = 1;   ///< cells per piece
  int degree = 3;         ///< p: degree of the bending field
  Geometry geometry = Geometry::curved;
  bool rotary_inertia = false;
  double EA = 0.0;        ///< axial stiffness used (EA, or the inextensible penalty)
  /// euler_bernoulli: RingModel; timoshenko: TimoshenkoModel (fields u, w, psi of degree p).
  ring::Theory theory = ring::Theory::euler_bernoulli;
  int cells() const { return elements * subdivisions; }
};

/// What one shape function contributes at one point: displacement components in the
/// fields' own orthonormal basis (polar (u, w) or Cartesian (ux, uy)), centreline
/// strain, change of curvature and cross-section rotation (counter-clockwise).
struct Kinematics {
  std::array<double, 2> d{0.0, 0.0};
  double eps = 0.0, kappa = 0.0, phi = 0.0;
};

/// A term concentrated at one vertex, on a linear functional c . x of the local DoFs
/// `dofs`: strain energy stiffness/2 (c . x)^2 and kinetic energy mass/2 (c . xdot)^2.
/// Springs kx, ky and a point mass's m act on the Cartesian components of the vertex's
/// displacement; kr and a point mass's inertia J on the vertex rotation {phi}, the mean of
/// the rotations phi = (u - w')/R of the two cells that meet there (ring_model.cpp).
struct PointTerm {
  std::vector<types::global_dof_index> dofs;
  std::vector<double> coef;
  double stiffness = 0.0, mass = 0.0;
};

/// Lowest eigenpairs of the reduced problem K q = lambda M q, lambda ascending, and
/// each pair's relative residual (see RingModel::refine).
struct EigenPairs {
  std::vector<double> lambda;
  std::vector<Vector<double>> q;
  std::vector<double> residual;
};

/// Extended precision for the operator applications that refine the eigenpairs.
using Real = long double;

/// A linear ring model as the eigen-solve (ring_eigen.cpp) and the modes driver (modes.cpp)
/// see it: the reduced system K q = lambda M q on the free DoFs (constraints eliminated,
/// homogeneous), its shift sigma, an extended-precision K q and M q from the strain fields
/// (apply), the point terms, and the way back to the fields (expand, sample, write_vtu).
/// It holds what every model shares; a model fills constraints_, calls
/// number_free_dofs(), builds sparsity_ and assembles K_, M_ and point_terms_.
class LinearModel {
 public:
  virtual ~LinearModel() = default;
  LinearModel(const LinearModel&) = delete;
  LinearModel& operator=(const LinearModel&) = delete;

  unsigned int n_free() const { return n_free_; }
  /// eps lambda_max / |sigma|: how much of the shifted operator's low end double
  /// precision resolves (sigma ~ -EI / (rho A R^4), the ring's bending scale; the lowest
  /// elastic eigenvalue is 2.6 |sigma| or more). lambda_max is estimated by the row sums
  /// max_i sum_j |K_ij| / sum_j M_ij (Gershgorin with the row-sum lumped mass; within a
  /// few times the true one). Above kPrecisionLimit the eigen-solve cannot be trusted.
  /// It grows like cells^4 (bending) and like p^6 to p^8 in the degree. O(nnz).
  double precision_ratio() const;
  /// The `n` lowest eigenpairs, refined (see refine()). Dense LAPACK (O(N^3)) up to
  /// kDenseLimit unknowns, ARPACK shift-invert on UMFPACK above (O(N p^2)
  /// factorization + O(N p) per Lanczos step).
  /// With refine = false the raw pairs come back (frequencies to ~eps lambda_max / lambda,
  /// residuals NaN): enough while a reference refinement is far from converged.
  EigenPairs solve(unsigned int n, bool refine = true) const;
  /// Reduced vector -> all DoFs (constraints distributed). O(N).
  Vector<double> expand(const Vector<double>& q) const;
  /// Radial and tangential displacement of a full DoF vector at the common stations,
  /// normalized. O(kStations dofs per cell).
  virtual ring::ModeShape sample(const Vector<double>& full) const = 0;
  /// Writes the given full vectors to a VTU file with DataOut (ring_vtu.cpp).
  virtual void write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                         const std::string& file) const = 0;
  /// K q (reduced) accumulated in extended precision from the strain fields (apply()),
  /// for the refinement of another pencil's eigenpairs with this K (pencil.cpp). O(N p).
  std::vector<Real> stiffness_product(const Vector<double>& q) const {
    std::vector<Real> kq, mq;
    apply(q, kq, mq);
    return kq;
  }
  /// The consistent mass matrix and the stiffness, reduced.
  const SparseMatrix<double>& mass() const { return M_; }
  const SparseMatrix<double>& stiffness() const { return K_; }
  const SparsityPattern& sparsity() const { return sparsity_; }

 protected:
  LinearModel(const ring::RingSpec& spec, const Setup& setup);

  /// K q and M q (reduced) accumulated in extended precision from the strain fields of
  /// q, never from the assembled entries: q^T K q then loses no digits to the stiff
  /// membrane (and shear) part (the assembled product cancels to ~eps lambda_max / lambda). O(N p).
  virtual void apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const = 0;
  /// free_, expansion_ and n_free_ from the closed constraints_ over n_dofs DoFs.
  void number_free_dofs(types::global_dof_index n_dofs);
  /// Adds a local matrix on `dofs` to the reduced global matrix (constraints expanded).
  void add_local(const FullMatrix<double>& local, const std::vector<types::global_dof_index>& dofs,
                 SparseMatrix<double>& global) const;
  /// The point terms' stiffness and mass into K_ and M_.
  void assemble_point_terms();
  /// The point terms' share of K q and M q (extended precision) for the full vector `full`.
  void apply_point_terms(const Vector<double>& full, std::vector<Real>& kq, std::vector<Real>& mq) const;
  /// Improves raw eigenpairs: Rayleigh-Ritz on their span with Gram matrices from
  /// apply(), then subspace-iteration corrections q -= (K - sigma M)^{-1} r, each
  /// followed by Ritz, until the residuals are below kRefinedResidual or stop halving
  /// (at most kMaxRefinementRounds; one is enough up to ~10^5 unknowns, near the precision
  /// limit each contracts by ~10: 3000 cells of degree 12, 6.6e-3 after one, 5e-7 after four).
  /// Residuals ||r||_* / (||K q||_* + lambda ||M q||_*) in the dual norm of
  /// K - sigma M (||r||_*^2 = r^T (K - sigma M)^{-1} r), the norm that bounds the
  /// frequency error; the Euclidean norm would only show the round-off of the stiff
  /// entries. A pair whose r^T (K - sigma M)^{-1} r comes out negative (the solve no
  /// longer represents the operator) gets an infinite residual. O(rounds m^2 N) for m pairs.
  EigenPairs refine(EigenPairs raw, unsigned int wanted, const SparseDirectUMFPACK& shifted_inverse) const;

  const ring::RingSpec& spec_;
  const Setup setup_;
  const double sigma_;   ///< spectral shift, < 0 (rad/s)^2
  AffineConstraints<double> constraints_;
  /// Reduced numbering: free_[i] = index of unconstrained DoF i, or -1; expansion_[i]
  /// lists (free index, weight) with U_i = sum weight * q_free (homogeneous constraints).
  std::vector<int> free_;
  std::vector<std::vector<std::pair<unsigned int, double>>> expansion_;
  unsigned int n_free_ = 0;
  SparsityPattern sparsity_;
  SparseMatrix<double> K_, M_;
  std::vector<PointTerm> point_terms_;
};

/// What the geometrically exact beam's terms and loads (BeamPotential) and its drivers
/// (static_path.cpp, nonlinear.cpp) see of a model: the beam's stored energy with its exact
/// gradient and Hessian, its rotational springs, the rows of the current position and
/// stretch for the distributed terms, and the vertices. Both models' fields u (tangential)
/// and w (radial) are components 0 and 1 of their FESystem on the same periodic mesh in the
/// polar angle; RingModel (Euler-Bernoulli, nonlinear.hpp) and TimoshenkoModel (Reissner,
/// reissner_beam.cpp) implement it. Curved geometry only.
class BeamModel : public LinearModel {
 public:
  /// Strain energy of the beam at the reduced displacement q; adds its gradient (the
  /// internal force) and its Hessian (the consistent tangent, on sparsity()) when not null
  /// (gradient reinit, tangent zeroed first).
  double beam_energy(const Vector<double>& q, Vector<double>* gradient, SparseMatrix<double>* tangent) const {
    return beam_energy(q, gradient, tangent, nullptr);
  }
  /// The same with the bending of ring.plastic (plastic_points.hpp): each bending point's
  /// energy density is the law's incremental potential from its committed state (the value
  /// returned is then the beam's incremental potential; equal to its elastic energy when
  /// q is the committed equilibrium). `plastic` null: elastic, bit for bit the 3-argument form.
  virtual double beam_energy(const Vector<double>& q, Vector<double>* gradient, SparseMatrix<double>* tangent,
                             const Plasticity* plastic) const = 0;
  /// The strain (curvature, or a vertex hinge's strain) and weight of every bending point,
  /// then of every vertex hinge, at q, in the model's order
  /// (plastic_points.hpp), as beam_energy evaluates them from the committed states: what
  /// the statics and the response commit. O(cells (p+2) (2p+3) + states).
  virtual std::vector<BendingPoint> bending_points(const Vector<double>& q, const Plasticity& plastic) const = 0;
  /// How many bending points the model has (vertex hinges not counted; its plastic states:
  /// PlasticLaw::states(bending_point_count(), cells())).
  virtual std::size_t bending_point_count() const = 0;
  // mass() (constant: the polar basis at fixed theta does not move) and stiffness() (the
  // tangent of beam_energy at q = 0) are LinearModel's.
  unsigned int cells() const { return setup_.cells(); }
  /// An arch (ring.arc): the cells run from arc.from to arc.to with no periodic wrap, and
  /// vertex cells() is the `to` end; a ring: vertex cells() is vertex 0.
  bool open() const { return open_; }
  /// Distinct vertices: cells() + 1 on an arch, cells() on the ring.
  unsigned int vertices() const { return open_ ? setup_.cells() + 1 : setup_.cells(); }
  /// The first vertex with a cell on either side (the joints first_joint()..cells()-1 carry
  /// the interior penalty): 1 on an arch (vertex 0 is an end), 0 on the ring.
  unsigned int first_joint() const { return open_ ? 1 : 0; }
  /// Index of the vertex at `degrees` (which must be a vertex: ring::on_node).
  unsigned int vertex_of(double degrees) const;
  /// Reduced generalized force of the force f (N, Cartesian) acting at vertex k.
  Vector<double> vertex_force(unsigned int k, const std::array<double, 2>& f) const;
  /// Cartesian displacement (m) at vertex k of a full DoF vector.
  std::array<double, 2> vertex_displacement(const Vector<double>& full, unsigned int k) const;
  /// Rest position of vertex k (ring-centred frame, m).
  std::array<double, 2> vertex_position(unsigned int k) const;
  /// Deformed centreline X + U (curved geometry) of a full DoF vector (ring-centred frame, m) at
  /// `per_cell` equally spaced points of every cell, counter-clockwise from vertex 0
  /// (point k at the polar angle theta0 + k h / per_cell). O(cells per_cell dofs per cell).
  std::vector<std::array<double, 2>> centreline(const Vector<double>& full, unsigned int per_cell) const;
  /// Per reduced unknown, the length by which one unit of it moves the ring: 1 for u and w
  /// (m), R for a section rotation psi (rad; TimoshenkoModel). The statics' basin and
  /// stopping rules (static_path.cpp) and the response's Newton (newton.hpp) measure a
  /// change dz as max_i |dz_i| lengths_i, so that a ring's size does not change how far
  /// its rotations may move in a step (with psi counted as 1 m, a ring of R = 1 cm took 728
  /// load steps where R = 1 m takes 15: fem_reissner_test, ScaledRingsHaveTheSameShape).
  const std::vector<double>& lengths() const { return lengths_; }
  /// max_i |dz_i| lengths()_i over the first n_free() entries of dz. O(N).
  template <class V>
  double length_of(const V& dz) const {
    double m = 0.0;
    for (unsigned int i = 0; i < n_free_; ++i) m = std::max(m, std::abs(dz[i]) * lengths_[i]);
    return m;
  }

 protected:
  BeamModel(const ring::RingSpec& spec, const Setup& setup);
  /// Fills lengths_ (after the reduced numbering and the cells exist).
  void measure_lengths();
  /// The terms and loads read the mesh, the rule and the reduced numbering.
  friend class BeamPotential;

  /// The DoFs of u and w at vertex k (the left end of cell k).
  virtual std::array<types::global_dof_index, 2> translation_dofs(unsigned int k) const = 0;
  /// A rotational spring kr/2 theta^2 at vertex v, theta the vertex's rotation (RingModel:
  /// the mean of the two cells' exact tangent angles; TimoshenkoModel: psi, exact): its
  /// energy, and its gradient and Hessian added to `gradient` and `tangent` when not null.
  virtual double rotation_spring(unsigned int v, double kr, const Vector<double>& full, Vector<double>* gradient,
                                 SparseMatrix<double>* tangent) const = 0;
  /// The FESystem (u component 0, w component 1).
  virtual const FESystem<1>& fe() const = 0;

  /// The cell rule of the distributed terms (foundation, pressure, gravity) on the
  /// reference cell: abscissae in [0, 1], weight times ds at each, and per point and local
  /// shape function i (index [q * dofs per cell + i]) the derivative of the local variables
  /// y = (x_t, x_n, a_t, a_n) (beam_potential.cpp) by DoF i. Filled by the model.
  struct LoadRule {
    std::vector<double> xi, ds;
    std::vector<std::array<double, 4>> row;
  };
  LoadRule load_rule_;
  std::vector<double> lengths_;

  const bool open_;      ///< an arch (ring.arc): no periodic wrap
  const double theta0_;  ///< polar angle of vertex 0 (the pin; an arch: arc.from), rad
  const double h_;       ///< cell size in theta (2 pi or the arch's span over the cells), rad
  std::vector<DoFHandler<1>::active_cell_iterator> cells_;  ///< counter-clockwise order
};

/// The Euler-Bernoulli ring (modes.hpp): C0 interior penalty for the bending field.
class RingModel : public BeamModel {
 public:
  /// Builds mesh, constraints and matrices. O(cells (2p+3)^2).
  RingModel(const ring::RingSpec& spec, const Setup& setup);

  /// Radial and tangential displacement of a full DoF vector at the common stations,
  /// normalized. O(kStations (2p+3)).
  ring::ModeShape sample(const Vector<double>& full) const override;
  /// Writes the given full vectors to a VTU file with DataOut.
  void write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                 const std::string& file) const override;

  // The geometrically exact beam on the same mesh, fields and constraints (ring_beam.cpp;
  // curved geometry only, formulation in nonlinear.hpp). O(cells (p+2) (2p+3)^2).
  using BeamModel::beam_energy;
  double beam_energy(const Vector<double>& q, Vector<double>* gradient, SparseMatrix<double>* tangent,
                     const Plasticity* plastic) const override;
  std::vector<BendingPoint> bending_points(const Vector<double>& q, const Plasticity& plastic) const override;
  std::size_t bending_point_count() const override;

 private:
  std::array<types::global_dof_index, 2> translation_dofs(unsigned int k) const override { return vertex_dofs(k); }
  double rotation_spring(unsigned int v, double kr, const Vector<double>& full, Vector<double>* gradient,
                         SparseMatrix<double>* tangent) const override;
  const FESystem<1>& fe() const override { return fe_; }

  /// d g / d x_i of local shape function i at table point qp, g = (a_t, a_n, b_t, b_n) the
  /// exact stretch vector a = dx/ds0 and b = da/dtheta in the rest frame (t0, n0)
  /// (nonlinear.hpp): a_t = 1 + (u' + w)/R, a_n = (w' - u)/R, b_t = (u'' + w')/R,
  /// b_n = (w'' - u')/R. Curved geometry.
  std::array<double, 4> strain_row(unsigned int i, unsigned int qp) const;

  void make_grid();
  void setup_constraints();
  void setup_reduced_system();
  /// Springs and point masses (spec.supports.springs, spec.masses) as PointTerms.
  void setup_point_terms();
  void assemble();

  /// The clamp: the rotation phi of both cells that meet at `vertex` (one at an arch's end)
  /// is zero (one interior DoF of each cell eliminated; the vertex itself is pinned).
  void constrain_rotation(unsigned int vertex);
  /// Coefficients of the vertex rotation {phi} = (phi_left + phi_right) / 2 on the local
  /// DoFs [cell vertex-1 | cell vertex] (the DoFs in `dofs`); at an arch's end the one
  /// cell's end rotation on that cell's DoFs.
  void vertex_rotation(unsigned int vertex, std::vector<types::global_dof_index>& dofs, std::vector<double>& coef) const;

  /// Kinematics of local shape function i of `cell` at cell quadrature point q
  /// (q = nq, nq+1: the left and right ends of the cell).
  Kinematics kinematics(unsigned int cell, unsigned int i, unsigned int q) const;
  /// Interior-penalty data at vertex v (between cell v-1 and cell v): for the 2 dpc
  /// local DoFs [cell v-1 | cell v], the rotation jump and the mean moment.
  void vertex_terms(unsigned int v, std::vector<double>& jump, std::vector<double>& mean) const;
  /// ds/dtheta on a cell: R (on the polygon: chord length / chord angle, also R).
  double ds_dtheta() const;
  /// DoFs at one end (xi = 0 or 1) of a cell, by component.
  std::array<types::global_dof_index, 2> end_dofs(unsigned int cell, double xi) const;
  /// The u and w DoFs of vertex k (0..vertices()-1; an arch's vertex cells() is the right
  /// end of the last cell).
  std::array<types::global_dof_index, 2> vertex_dofs(unsigned int k) const {
    return k < static_cast<unsigned int>(setup_.cells()) ? end_dofs(k, 0.0) : end_dofs(k - 1, 1.0);
  }
  /// The cells that meet at vertex v, each with its end there (1: the left cell's right
  /// end, 0: the right cell's left end): two at a joint, one at an arch's end.
  std::vector<std::pair<unsigned int, double>> cells_at(unsigned int v) const;
  void apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const override;

  Triangulation<1> triangulation_;
  FESystem<1> fe_;
  DoFHandler<1> dof_handler_;
  std::vector<std::array<double, 2>> chord_t_;  ///< polygon: unit tangent of each chord

  /// Shape functions on the reference cell (all cells are equal affine images of it):
  /// value, d/dtheta, d2/dtheta2 at the Gauss points, then at xi = 0 and xi = 1;
  /// index [q * dpc + i]. ds_[q]: quadrature weight times ds/dtheta.
  unsigned int nq_ = 0;
  std::vector<double> v0_, v1_, v2_, ds_;
  /// ring.plastic's bending points of a cell (plastic_points.hpp: the p + 1 Gauss-Lobatto
  /// points, ends included): their index in the table above (nq_ the left end, nq_ + 1
  /// the right end, the interior ones after them) and their weight times ds0/dxi (m).
  std::vector<unsigned int> bend_rows_;
  std::vector<double> bend_ds_;
  std::vector<unsigned int> component_;
  double penalty_ = 0.0;  ///< sigma EI / h of the interior penalty (uniform ring; vertex_EI scales it)

  /// ring.variations (ring/spec.hpp): the local section at every Gauss point of every cell
  /// (index [cell * nq_ + q], the point's polar angle theta0 + (cell + xi_q) h) and EI at
  /// every vertex (the penalty and the mean moment), filled once in make_grid(); the terms
  /// of assemble() (double) and apply() (long double) read them here and nowhere else.
  /// Empty on a uniform ring: section() is then the spec's constants, as before.
  struct Section {
    double EI = 0.0, EA = 0.0, rhoA = 0.0, rhoI = 0.0;
  };
  std::vector<Section> sections_;
  std::vector<double> vertex_EI_;
  Section section(unsigned int cell, unsigned int q) const;
  double vertex_EI(unsigned int v) const { return vertex_EI_.empty() ? spec_.EI() : vertex_EI_[v]; }
};

template <int spacedim = 1>
FESystem<1, spacedim> make_fe(const Setup& s) {
  // Curved: u (tangential) one degree above w (radial), so that u' and w share a space
  // and inextensional motion is exact (no membrane locking). Polygon: ux, uy of degree p.
  // Timoshenko (curved only): u, w, psi all of degree p (timoshenko_model.hpp).
  if (s.theory == ring::Theory::timoshenko) return FESystem<1, spacedim>(FE_Q<1, spacedim>(s.degree), 3);
  if (s.geometry == Geometry::curved)
    return FESystem<1, spacedim>(FE_Q<1, spacedim>(s.degree + 1), 1, FE_Q<1, spacedim>(s.degree), 1);
  return FESystem<1, spacedim>(FE_Q<1, spacedim>(s.degree), 2);
}

/// Writes `modes` (full DoF vectors on `cells`, counter-clockwise from the polar angle theta0)
/// to a VTU file: the cells as a curve in the plane (ring_vtu.cpp). Either model's fields.
void write_ring_vtu(const ring::RingSpec& spec, const Setup& setup, double theta0,
                    const std::vector<DoFHandler<1>::active_cell_iterator>& cells,
                    const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                    const std::string& file);

/// The model of setup.theory: RingModel or TimoshenkoModel (timoshenko_model.cpp).
std::unique_ptr<LinearModel> make_model(const ring::RingSpec& spec, const Setup& setup);
/// The geometrically exact beam of setup.theory: RingModel (Euler-Bernoulli, nonlinear.hpp)
/// or TimoshenkoModel (Reissner, reissner_beam.cpp). Curved geometry.
std::unique_ptr<BeamModel> make_beam(const ring::RingSpec& spec, const Setup& setup);

/// Frequencies, shapes and residual of one discretization (with the inextensible
/// extrapolation when asked). `full` receives the full DoF vectors if not null.
struct Solved {
  ring::ModalResult result;
  std::vector<Vector<double>> full;
};

/// The whole modal solve of compute_modes (validation, refinement to the reference);
/// keep_full keeps the full DoF vectors of the final discretization (for the VTU output).
Solved run(const ring::RingSpec& spec, const ring::FemOptions& o, int count, bool keep_full);

}  // namespace fem::detail
