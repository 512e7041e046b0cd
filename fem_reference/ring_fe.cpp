// The finite-element reference (issue 4): the only translation unit of ringvib that
// includes deal.II. Model, formulation and conventions: fem_reference/modes.hpp.
//
// Shape of the program (deal.II step-47): RingModel's constructor runs make_grid(),
// setup_constraints(), setup_reduced_system(), assemble(); solve() computes the lowest
// modes; sample() evaluates the FE fields at the common stations.
#include "fem_reference/modes.hpp"

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

namespace fem {
namespace {

using namespace dealii;
using Geometry = ring::FemOptions::Geometry;

constexpr double kPi = 3.14159265358979323846;
/// Above this many free unknowns the dense O(N^3) LAPACK solve gives way to ARPACK.
constexpr unsigned int kDenseLimit = 150;
/// Highest degree the reference refinement raises p to before it refines h instead
/// (FE_Q uses Gauss-Lobatto support points, well conditioned at these degrees).
constexpr int kReferenceMaxDegree = 16;
constexpr int kReferenceMaxSteps = 40;
/// Extra eigenpairs computed above the wanted ones for the refinement (refine()).
constexpr unsigned int kGuardModes = 8;
/// Reference runs refine the eigenpairs once successive frequencies change by less.
constexpr double kRefineBelowChange = 1e-5;
/// Subspace-iteration corrections in refine().
constexpr unsigned int kRefinementRounds = 1;
/// Relative round-off of refined frequencies (measured, see the estimate below).
constexpr double kRoundOffFloor = 1e-12;
/// Inextensible limit: EA -> beta EI / R^2 for these beta, then Richardson in 1/beta.
constexpr double kInextensibleBeta = 1e6;

/// One discretization of the ring: what RingModel is built from.
struct Setup {
  int elements = 40;      ///< equal pieces (chords on the polygon), vertex 0 at the pin
  int subdivisions = 1;   ///< cells per piece
  int degree = 3;         ///< p: degree of the bending field
  Geometry geometry = Geometry::curved;
  bool rotary_inertia = false;
  double EA = 0.0;        ///< axial stiffness used (EA, or the inextensible penalty)
  int cells() const { return elements * subdivisions; }
};

/// What one shape function contributes at one point: displacement components in the
/// fields' own orthonormal basis (polar (u, w) or Cartesian (ux, uy)), centreline
/// strain, change of curvature and cross-section rotation (counter-clockwise).
struct Kinematics {
  std::array<double, 2> d{0.0, 0.0};
  double eps = 0.0, kappa = 0.0, phi = 0.0;
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

class RingModel {
 public:
  /// Builds mesh, constraints and matrices. O(cells (2p+3)^2).
  RingModel(const ring::RingSpec& spec, const Setup& setup);

  unsigned int n_free() const { return n_free_; }
  /// The `n` lowest eigenpairs, refined (see refine()). Dense LAPACK (O(N^3)) up to
  /// kDenseLimit unknowns, ARPACK shift-invert on UMFPACK above (O(N p^2)
  /// factorization + O(N p) per Lanczos step).
  /// With refine = false the raw pairs come back (frequencies to ~eps lambda_max / lambda,
  /// residuals NaN): enough while a reference refinement is far from converged.
  EigenPairs solve(unsigned int n, bool refine = true) const;
  /// Reduced vector -> all DoFs (constraints distributed). O(N).
  Vector<double> expand(const Vector<double>& q) const;
  /// Radial and tangential displacement of a full DoF vector at the common stations,
  /// normalized. O(kStations (2p+3)).
  ring::ModeShape sample(const Vector<double>& full) const;
  /// Writes the given full vectors to a VTU file with DataOut.
  void write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                 const std::string& file) const;

 private:
  void make_grid();
  void setup_constraints();
  void setup_reduced_system();
  void assemble();

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
  /// Adds a local matrix on `dofs` to the reduced global matrix (constraints expanded).
  void add_local(const FullMatrix<double>& local, const std::vector<types::global_dof_index>& dofs,
                 SparseMatrix<double>& global) const;
  /// K q and M q (reduced) accumulated in extended precision from the strain fields of
  /// q, never from the assembled entries: q^T K q then loses no digits to the stiff
  /// membrane part (the assembled product cancels to ~eps lambda_max / lambda). O(N p).
  void apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const;
  /// Improves raw eigenpairs: Rayleigh-Ritz on their span with Gram matrices from
  /// apply(), one subspace-iteration correction q -= (K - sigma M)^{-1} r, Ritz again.
  /// Residuals ||r||_* / (||K q||_* + lambda ||M q||_*) in the dual norm of
  /// K - sigma M (||r||_*^2 = r^T (K - sigma M)^{-1} r), the norm that bounds the
  /// frequency error; the Euclidean norm would only show the round-off of the stiff
  /// entries. O(m^2 N) for m pairs.
  EigenPairs refine(EigenPairs raw, const SparseDirectUMFPACK& shifted_inverse) const;

  const ring::RingSpec& spec_;
  const Setup setup_;
  const double theta0_;  ///< polar angle of vertex 0 (the pin), rad
  const double h_;       ///< cell size in theta, rad
  const double sigma_;   ///< spectral shift, < 0 (rad/s)^2

  Triangulation<1> triangulation_;
  FESystem<1> fe_;
  DoFHandler<1> dof_handler_;
  std::vector<DoFHandler<1>::active_cell_iterator> cells_;  ///< counter-clockwise order
  std::vector<std::array<double, 2>> chord_t_;  ///< polygon: unit tangent of each chord
  AffineConstraints<double> constraints_;

  /// Shape functions on the reference cell (all cells are equal affine images of it):
  /// value, d/dtheta, d2/dtheta2 at the Gauss points, then at xi = 0 and xi = 1;
  /// index [q * dpc + i]. ds_[q]: quadrature weight times ds/dtheta.
  unsigned int nq_ = 0;
  std::vector<double> v0_, v1_, v2_, ds_;
  std::vector<unsigned int> component_;
  double penalty_ = 0.0;  ///< sigma EI / h of the interior penalty

  /// Reduced numbering: free_[i] = index of unconstrained DoF i, or -1; expansion_[i]
  /// lists (free index, weight) with U_i = sum weight * q_free (homogeneous constraints).
  std::vector<int> free_;
  std::vector<std::vector<std::pair<unsigned int, double>>> expansion_;
  unsigned int n_free_ = 0;
  SparsityPattern sparsity_;
  SparseMatrix<double> K_, M_;
};

template <int spacedim = 1>
FESystem<1, spacedim> make_fe(const Setup& s) {
  // Curved: u (tangential) one degree above w (radial), so that u' and w share a space
  // and inextensional motion is exact (no membrane locking). Polygon: ux, uy of degree p.
  if (s.geometry == Geometry::curved)
    return FESystem<1, spacedim>(FE_Q<1, spacedim>(s.degree + 1), 1, FE_Q<1, spacedim>(s.degree), 1);
  return FESystem<1, spacedim>(FE_Q<1, spacedim>(s.degree), 2);
}

/// For the VTU output: the Cartesian displacement of a mode from its two field
/// components (polar (u, w) on the circle, or already Cartesian on the polygon).
class CartesianDisplacement : public DataPostprocessorVector<2> {
 public:
  CartesianDisplacement(const std::string& name, bool polar)
      : DataPostprocessorVector<2>(name, update_values | update_quadrature_points), polar_(polar) {}
  void evaluate_vector_field(const DataPostprocessorInputs::Vector<2>& in,
                             std::vector<Vector<double>>& out) const override {
    for (unsigned int q = 0; q < in.solution_values.size(); ++q) {
      const double a0 = in.solution_values[q][0], a1 = in.solution_values[q][1];
      if (!polar_) {
        out[q][0] = a0;
        out[q][1] = a1;
        continue;
      }
      const double t = std::atan2(in.evaluation_points[q][1], in.evaluation_points[q][0]);
      out[q][0] = -std::sin(t) * a0 + std::cos(t) * a1;
      out[q][1] = std::cos(t) * a0 + std::sin(t) * a1;
    }
  }

 private:
  bool polar_;
};

RingModel::RingModel(const ring::RingSpec& spec, const Setup& setup)
    : spec_(spec),
      setup_(setup),
      theta0_(spec.supports.pin.value_or(0.0) * kPi / 180.0),
      h_(2.0 * kPi / setup.cells()),
      sigma_(-std::pow(spec.bending_frequency_scale(), 2)),
      fe_(make_fe(setup)),
      dof_handler_(triangulation_) {
  make_grid();
  setup_constraints();
  setup_reduced_system();
  assemble();
}

void RingModel::make_grid() {
  GridGenerator::subdivided_hyper_cube(triangulation_, setup_.cells(), theta0_, theta0_ + 2.0 * kPi);
  dof_handler_.distribute_dofs(fe_);
  for (const auto& cell : dof_handler_.active_cell_iterators()) cells_.push_back(cell);
  std::sort(cells_.begin(), cells_.end(),
            [](const auto& a, const auto& b) { return a->center()[0] < b->center()[0]; });
  const double chord_angle = 2.0 * kPi / setup_.elements;
  for (int j = 0; j < setup_.elements; ++j) {
    const double a0 = theta0_ + j * chord_angle, a1 = a0 + chord_angle;
    const double tx = std::cos(a1) - std::cos(a0), ty = std::sin(a1) - std::sin(a0);
    const double len = std::hypot(tx, ty);
    chord_t_.push_back({tx / len, ty / len});
  }
  // Reference tables: every cell is the same affine image of [0, 1] in theta, so one
  // FEValues evaluation serves all cells. Gauss with p+2 points integrates the
  // polynomial integrands (degree <= 2p+2) exactly.
  const QGauss<1> gauss(setup_.degree + 2);
  std::vector<Point<1>> points = gauss.get_points();
  points.push_back(Point<1>(0.0));
  points.push_back(Point<1>(1.0));
  std::vector<double> weights = gauss.get_weights();
  weights.push_back(0.0);
  weights.push_back(0.0);
  const Quadrature<1> table_points(points, weights);
  FEValues<1> fev(fe_, table_points, update_values | update_gradients | update_hessians | update_JxW_values);
  fev.reinit(cells_[0]);
  const unsigned int dpc = fe_.n_dofs_per_cell();
  nq_ = gauss.size();
  for (unsigned int q = 0; q < table_points.size(); ++q) {
    ds_.push_back(fev.JxW(q) * ds_dtheta());
    for (unsigned int i = 0; i < dpc; ++i) {
      v0_.push_back(fev.shape_value(i, q));
      v1_.push_back(fev.shape_grad(i, q)[0]);
      v2_.push_back(fev.shape_hessian(i, q)[0][0]);
    }
  }
  for (unsigned int i = 0; i < dpc; ++i) component_.push_back(fe_.system_to_component_index(i).first);
  // sigma = 2 (q+1)(q+2) > (q+1)^2, the trace-inverse constant for kappa of degree
  // q = p (u' on the circle), makes the form coercive; h = arc length of a cell.
  const double q_kappa = setup_.degree;
  penalty_ = 2.0 * (q_kappa + 1) * (q_kappa + 2) * spec_.EI() / (ds_dtheta() * h_);
}

std::array<types::global_dof_index, 2> RingModel::end_dofs(unsigned int cell, double xi) const {
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  cells_[cell]->get_dof_indices(dofs);
  std::array<types::global_dof_index, 2> out{numbers::invalid_dof_index, numbers::invalid_dof_index};
  const auto& points = fe_.get_unit_support_points();
  for (unsigned int i = 0; i < dofs.size(); ++i)
    if (std::abs(points[i][0] - xi) < 1e-12) out[fe_.system_to_component_index(i).first] = dofs[i];
  return out;
}

void RingModel::setup_constraints() {
  const unsigned int n = setup_.cells();
  // Periodic closure: the vertex at theta0 + 2 pi is the vertex at theta0. The field
  // components are the same there (polar basis at the same angle, or Cartesian).
  const auto first = end_dofs(0, 0.0), last = end_dofs(n - 1, 1.0);
  for (unsigned int c = 0; c < 2; ++c) {
    constraints_.add_line(last[c]);
    constraints_.add_entry(last[c], first[c], 1.0);
  }
  if (spec_.supports.pin) {
    for (unsigned int c = 0; c < 2; ++c) {
      constraints_.add_line(first[c]);  // both components zero at vertex 0
    }
    if (spec_.supports.roller) {
      // The roller vertex stays on the line pin-roller: the displacement component
      // along e, the unit normal of that line, is zero.
      const double steps = ring::wrap_degrees(*spec_.supports.roller - *spec_.supports.pin) * n / 360.0;
      const unsigned int k = static_cast<unsigned int>(std::lround(steps)) % n;
      const double a = theta0_ + k * h_;
      const std::array<double, 2> d{std::cos(a) - std::cos(theta0_), std::sin(a) - std::sin(theta0_)};
      const double len = std::hypot(d[0], d[1]);
      const std::array<double, 2> e{-d[1] / len, d[0] / len};
      // coefficient of each field component in e.U at the roller
      std::array<double, 2> coef;
      if (setup_.geometry == Geometry::curved)
        coef = {e[0] * -std::sin(a) + e[1] * std::cos(a), e[0] * std::cos(a) + e[1] * std::sin(a)};
      else
        coef = e;
      const auto dofs = end_dofs(k, 0.0);
      const unsigned int m = std::abs(coef[0]) >= std::abs(coef[1]) ? 0 : 1;
      constraints_.add_line(dofs[m]);
      if (std::abs(coef[1 - m]) > 1e-14 * std::abs(coef[m]))
        constraints_.add_entry(dofs[m], dofs[1 - m], -coef[1 - m] / coef[m]);
    }
  }
  constraints_.close();
}

void RingModel::setup_reduced_system() {
  const auto n_dofs = dof_handler_.n_dofs();
  free_.assign(n_dofs, -1);
  for (types::global_dof_index i = 0; i < n_dofs; ++i)
    if (!constraints_.is_constrained(i)) free_[i] = n_free_++;
  expansion_.resize(n_dofs);
  for (types::global_dof_index i = 0; i < n_dofs; ++i) {
    if (free_[i] >= 0) {
      expansion_[i] = {{static_cast<unsigned int>(free_[i]), 1.0}};
    } else if (const auto* entries = constraints_.get_constraint_entries(i)) {
      for (const auto& [j, w] : *entries) expansion_[i].emplace_back(free_[j], w);
    }
  }
  // Couplings: each cell with itself, and the two cells beside every vertex (the
  // interior-penalty terms).
  DynamicSparsityPattern dsp(n_free_);
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  std::vector<types::global_dof_index> a(dpc), b(dpc);
  for (unsigned int v = 0; v < n; ++v) {
    cells_[(v + n - 1) % n]->get_dof_indices(a);
    cells_[v]->get_dof_indices(b);
    std::vector<unsigned int> rows;
    for (const auto* list : {&a, &b})
      for (const auto i : *list)
        for (const auto& [f, w] : expansion_[i]) rows.push_back(f);
    for (const auto r : rows)
      for (const auto c : rows) dsp.add(r, c);
  }
  sparsity_.copy_from(dsp);
  K_.reinit(sparsity_);
  M_.reinit(sparsity_);
}

double RingModel::ds_dtheta() const {
  // Circle: ds = R dtheta. Polygon: the n-gon of side 2 pi R / n (perimeter = the
  // circumference, as the paper's SAP5 run and its multibody chain), so a chord of
  // angle 2 pi / n has length R * 2 pi / n as well.
  return spec_.radius;
}

Kinematics RingModel::kinematics(unsigned int cell, unsigned int i, unsigned int q) const {
  const unsigned int k = q * fe_.n_dofs_per_cell() + i, c = component_[i];
  const double v = v0_[k], v1 = v1_[k], v2 = v2_[k];
  Kinematics out;
  const double R = spec_.radius;
  if (setup_.geometry == Geometry::curved) {
    if (c == 0) {  // u, tangential
      out.d[0] = v;
      out.eps = v1 / R;
      out.kappa = v1 / (R * R);
      out.phi = v / R;
    } else {  // w, radial
      out.d[1] = v;
      out.eps = v / R;
      out.kappa = -v2 / (R * R);
      out.phi = -v1 / R;
    }
    return out;
  }
  // Polygon: chord j from vertex j to j+1, unit tangent t, outward normal n = t turned
  // clockwise; theta is proportional to arc length along the chord.
  const auto& t = chord_t_[cell / setup_.subdivisions];
  const std::array<double, 2> n{t[1], -t[0]};
  const double J = ds_dtheta();
  out.d[c] = v;
  out.eps = t[c] * v1 / J;
  out.kappa = -n[c] * v2 / (J * J);
  out.phi = -n[c] * v1 / J;
  return out;
}

void RingModel::vertex_terms(unsigned int v, std::vector<double>& jump, std::vector<double>& mean) const {
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  const unsigned int left = (v + n - 1) % n;
  const double EI = spec_.EI();
  for (unsigned int i = 0; i < dpc; ++i) {
    const auto l = kinematics(left, i, nq_ + 1);  // right end of the left cell
    jump[i] = -l.phi;
    mean[i] = 0.5 * EI * l.kappa;
    const auto r = kinematics(v, i, nq_);  // left end of the right cell
    jump[dpc + i] = r.phi;
    mean[dpc + i] = 0.5 * EI * r.kappa;
  }
}

void RingModel::add_local(const FullMatrix<double>& local, const std::vector<types::global_dof_index>& dofs,
                          SparseMatrix<double>& global) const {
  for (unsigned int i = 0; i < dofs.size(); ++i)
    for (const auto& [fi, wi] : expansion_[dofs[i]])
      for (unsigned int j = 0; j < dofs.size(); ++j) {
        const double lij = local(i, j);
        if (lij == 0.0) continue;
        for (const auto& [fj, wj] : expansion_[dofs[j]]) global.add(fi, fj, wi * wj * lij);
      }
}

void RingModel::assemble() {
  const double EI = spec_.EI(), EA = setup_.EA, rhoA = spec_.rhoA();
  const double rhoI = setup_.rotary_inertia ? spec_.rho * spec_.I() : 0.0;
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  FullMatrix<double> k_cell(dpc, dpc), m_cell(dpc, dpc);
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<Kinematics> kin(dpc);
  for (unsigned int cell = 0; cell < n; ++cell) {
    k_cell = 0;
    m_cell = 0;
    for (unsigned int q = 0; q < nq_; ++q) {
      for (unsigned int i = 0; i < dpc; ++i) kin[i] = kinematics(cell, i, q);
      for (unsigned int i = 0; i < dpc; ++i)
        for (unsigned int j = 0; j < dpc; ++j) {
          k_cell(i, j) += (EA * kin[i].eps * kin[j].eps + EI * kin[i].kappa * kin[j].kappa) * ds_[q];
          m_cell(i, j) += (rhoA * (kin[i].d[0] * kin[j].d[0] + kin[i].d[1] * kin[j].d[1]) +
                           rhoI * kin[i].phi * kin[j].phi) * ds_[q];
        }
    }
    cells_[cell]->get_dof_indices(dofs);
    add_local(k_cell, dofs, K_);
    add_local(m_cell, dofs, M_);
  }
  // Symmetric interior penalty on the rotation jump at every vertex.
  std::vector<double> jump(2 * dpc), mean(2 * dpc);
  std::vector<types::global_dof_index> pair_dofs(2 * dpc), right(dpc);
  FullMatrix<double> k_vertex(2 * dpc, 2 * dpc);
  for (unsigned int v = 0; v < n; ++v) {
    vertex_terms(v, jump, mean);
    for (unsigned int i = 0; i < 2 * dpc; ++i)
      for (unsigned int j = 0; j < 2 * dpc; ++j)
        k_vertex(i, j) = mean[i] * jump[j] + mean[j] * jump[i] + penalty_ * jump[i] * jump[j];
    cells_[(v + n - 1) % n]->get_dof_indices(dofs);
    cells_[v]->get_dof_indices(right);
    std::copy(dofs.begin(), dofs.end(), pair_dofs.begin());
    std::copy(right.begin(), right.end(), pair_dofs.begin() + dpc);
    add_local(k_vertex, pair_dofs, K_);
  }
}

void RingModel::apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const {
  const Vector<double> full = expand(q);
  const Real EI = spec_.EI(), EA = setup_.EA, rhoA = spec_.rhoA();
  const Real rhoI = setup_.rotary_inertia ? spec_.rho * spec_.I() : 0.0;
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  kq.assign(n_free_, 0.0L);
  mq.assign(n_free_, 0.0L);
  std::vector<types::global_dof_index> dofs(dpc), right(dpc);
  std::vector<Real> lk(2 * dpc), lm(dpc), x(2 * dpc);
  std::vector<Kinematics> kin(dpc);
  auto scatter = [&](const std::vector<types::global_dof_index>& d, unsigned int offset, unsigned int count,
                     const std::vector<Real>& local, std::vector<Real>& global) {
    for (unsigned int i = 0; i < count; ++i)
      for (const auto& [f, w] : expansion_[d[i]]) global[f] += w * local[offset + i];
  };
  for (unsigned int cell = 0; cell < n; ++cell) {
    cells_[cell]->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dpc; ++i) x[i] = full[dofs[i]];
    std::fill(lk.begin(), lk.end(), 0.0L);
    std::fill(lm.begin(), lm.end(), 0.0L);
    for (unsigned int qp = 0; qp < nq_; ++qp) {
      Real eps = 0, kappa = 0, d0 = 0, d1 = 0, phi = 0;
      for (unsigned int i = 0; i < dpc; ++i) {
        kin[i] = kinematics(cell, i, qp);
        eps += x[i] * kin[i].eps;
        kappa += x[i] * kin[i].kappa;
        d0 += x[i] * kin[i].d[0];
        d1 += x[i] * kin[i].d[1];
        phi += x[i] * kin[i].phi;
      }
      const Real ds = ds_[qp];
      for (unsigned int i = 0; i < dpc; ++i) {
        lk[i] += ds * (EA * eps * kin[i].eps + EI * kappa * kin[i].kappa);
        lm[i] += ds * (rhoA * (d0 * kin[i].d[0] + d1 * kin[i].d[1]) + rhoI * phi * kin[i].phi);
      }
    }
    scatter(dofs, 0, dpc, lk, kq);
    scatter(dofs, 0, dpc, lm, mq);
  }
  std::vector<double> jump(2 * dpc), mean(2 * dpc);
  for (unsigned int v = 0; v < n; ++v) {
    vertex_terms(v, jump, mean);
    cells_[(v + n - 1) % n]->get_dof_indices(dofs);
    cells_[v]->get_dof_indices(right);
    for (unsigned int i = 0; i < dpc; ++i) {
      x[i] = full[dofs[i]];
      x[dpc + i] = full[right[i]];
    }
    Real J = 0, M = 0;
    for (unsigned int a = 0; a < 2 * dpc; ++a) {
      J += x[a] * jump[a];
      M += x[a] * mean[a];
    }
    for (unsigned int a = 0; a < 2 * dpc; ++a) lk[a] = mean[a] * J + jump[a] * M + penalty_ * J * jump[a];
    scatter(dofs, 0, dpc, lk, kq);
    scatter(right, dpc, dpc, lk, kq);
  }
}

EigenPairs RingModel::solve(unsigned int n_wanted, bool refine_pairs) const {
  const unsigned int N = n_free_;
  // A few guard pairs above the wanted ones keep the refinement's gap large.
  const unsigned int n_compute = std::min(n_wanted + kGuardModes, N - 1);
  // K - sigma M with sigma < 0 is positive definite even with rigid modes.
  SparseMatrix<double> shifted(sparsity_);
  shifted.copy_from(K_);
  shifted.add(-sigma_, M_);
  SparseDirectUMFPACK inverse;
  inverse.initialize(shifted);

  EigenPairs raw;
  if (N <= kDenseLimit) {
    LAPACKFullMatrix<double> Kd(N, N), Md(N, N);
    for (auto it = K_.begin(); it != K_.end(); ++it) Kd(it->row(), it->column()) = it->value();
    for (auto it = M_.begin(); it != M_.end(); ++it) Md(it->row(), it->column()) = it->value();
    std::vector<Vector<double>> vectors(n_compute, Vector<double>(N));
    Kd.compute_generalized_eigenvalues_symmetric(Md, vectors);
    for (unsigned int i = 0; i < n_compute; ++i) raw.lambda.push_back(Kd.eigenvalue(i).real());
    raw.q = std::move(vectors);
  } else {
    // Shift-invert Lanczos about sigma: the eigenvalues nearest sigma (the lowest)
    // converge first.
    const unsigned int ncv = std::min(N - 1, std::max(2 * n_compute + 2, n_compute + 20));
    SolverControl control(std::max(1000u, 10 * N), 1e-12);
    ArpackSolver::AdditionalData data(ncv, ArpackSolver::largest_magnitude, true);
    ArpackSolver arpack(control, data);
    arpack.set_shift(sigma_);
    // A fixed pseudo-random start: reproducible, and not orthogonal to any symmetry class.
    Vector<double> start(N);
    std::mt19937 gen(20261121);
    std::uniform_real_distribution<double> dist(-1.0, 1.0);
    for (auto& s : start) s = dist(gen);
    arpack.set_initial_vector(start);
    std::vector<std::complex<double>> lambda(n_compute);
    std::vector<Vector<double>> vectors(n_compute, Vector<double>(N));
    arpack.solve(K_, M_, inverse, lambda, vectors, n_compute);
    std::vector<unsigned int> order(n_compute);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) { return lambda[a].real() < lambda[b].real(); });
    for (const auto i : order) {
      raw.lambda.push_back(lambda[i].real());
      raw.q.push_back(vectors[i]);
    }
  }
  EigenPairs out = refine_pairs ? refine(std::move(raw), inverse) : std::move(raw);
  out.residual.resize(n_compute, std::numeric_limits<double>::quiet_NaN());
  out.lambda.resize(n_wanted);
  out.q.resize(n_wanted);
  out.residual.resize(n_wanted);
  return out;
}

EigenPairs RingModel::refine(EigenPairs raw, const SparseDirectUMFPACK& shifted_inverse) const {
  const unsigned int m = raw.q.size(), N = n_free_;
  std::vector<Vector<double>>& X = raw.q;
  std::vector<std::vector<Real>> KX(m), MX(m);
  auto to_double = [N](const std::vector<Real>& a) {
    Vector<double> v(N);
    for (unsigned int i = 0; i < N; ++i) v[i] = static_cast<double>(a[i]);
    return v;
  };
  // Rayleigh-Ritz on span(X) with Gram matrices X^T K X, X^T M X from apply().
  auto ritz = [&]() {
    for (unsigned int k = 0; k < m; ++k) apply(X[k], KX[k], MX[k]);
    LAPACKFullMatrix<double> A(m, m), B(m, m);
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int l = 0; l < m; ++l) {
        Real a = 0, b = 0;
        for (unsigned int i = 0; i < N; ++i) {
          a += X[k][i] * KX[l][i];
          b += X[k][i] * MX[l][i];
        }
        A(k, l) = static_cast<double>(a);
        B(k, l) = static_cast<double>(b);
      }
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int l = 0; l < k; ++l) {
        A(k, l) = A(l, k) = 0.5 * (A(k, l) + A(l, k));
        B(k, l) = B(l, k) = 0.5 * (B(k, l) + B(l, k));
      }
    std::vector<Vector<double>> Y(m, Vector<double>(m));
    A.compute_generalized_eigenvalues_symmetric(B, Y);
    std::vector<Vector<double>> next(m, Vector<double>(N));
    for (unsigned int k = 0; k < m; ++k) {
      raw.lambda[k] = A.eigenvalue(k).real();
      for (unsigned int j = 0; j < m; ++j) next[k].add(Y[k][j], X[j]);
    }
    X = std::move(next);
    for (unsigned int k = 0; k < m; ++k) apply(X[k], KX[k], MX[k]);
  };
  auto residual_vector = [&](unsigned int k) {
    std::vector<Real> r(N);
    for (unsigned int i = 0; i < N; ++i) r[i] = KX[k][i] - static_cast<Real>(raw.lambda[k]) * MX[k][i];
    return to_double(r);
  };
  ritz();
  for (unsigned int round = 0; round < kRefinementRounds; ++round) {
    // One step of subspace (inverse) iteration, q -= (K - sigma M)^{-1} r: damps the
    // error along mode j by (lambda - sigma) / (lambda_j - sigma); Ritz then removes
    // the error inside the span.
    for (unsigned int k = 0; k < m; ++k) {
      Vector<double> z(N);
      shifted_inverse.vmult(z, residual_vector(k));
      X[k] -= z;
    }
    ritz();
  }
  auto dual_norm = [&](const Vector<double>& r) {
    Vector<double> z(N);
    shifted_inverse.vmult(z, r);
    return std::sqrt(std::max(0.0, r * z));
  };
  // Denominator: for an eigenpair K q = lambda M q and (K - sigma M)^{-1} M q =
  // q / (lambda - sigma), so ||K q||_* + lambda ||M q||_* = 2 lambda sqrt(q^T M q / (lambda - sigma))
  // up to O(residual); this saves two solves per pair.
  raw.residual.resize(m);
  for (unsigned int k = 0; k < m; ++k) {
    Real qmq = 0;
    for (unsigned int i = 0; i < N; ++i) qmq += X[k][i] * MX[k][i];
    const double lambda = std::abs(raw.lambda[k]);
    const double denominator = 2.0 * lambda * std::sqrt(static_cast<double>(qmq) / (lambda - sigma_));
    raw.residual[k] = dual_norm(residual_vector(k)) / denominator;
  }
  return raw;
}

Vector<double> RingModel::expand(const Vector<double>& q) const {
  Vector<double> full(dof_handler_.n_dofs());
  for (types::global_dof_index i = 0; i < full.size(); ++i)
    if (free_[i] >= 0) full[i] = q[free_[i]];
  constraints_.distribute(full);
  return full;
}

ring::ModeShape RingModel::sample(const Vector<double>& full) const {
  ring::ModeShape shape;
  shape.radial.resize(ring::kStations);
  shape.tangential.resize(ring::kStations);
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  std::vector<types::global_dof_index> dofs(dpc);
  for (int s = 0; s < ring::kStations; ++s) {
    const double a = ring::station_angle(s) * kPi / 180.0;
    double t = std::fmod(a - theta0_, 2.0 * kPi);
    if (t < 0) t += 2.0 * kPi;
    const unsigned int cell = std::min(n - 1, static_cast<unsigned int>(t / h_));
    const double xi = std::clamp(t / h_ - cell, 0.0, 1.0);
    cells_[cell]->get_dof_indices(dofs);
    std::array<double, 2> U{0.0, 0.0};
    for (unsigned int i = 0; i < dpc; ++i)
      U[fe_.system_to_component_index(i).first] += full[dofs[i]] * fe_.shape_value(i, Point<1>(xi));
    if (setup_.geometry == Geometry::curved) {
      shape.tangential[s] = U[0];
      shape.radial[s] = U[1];
    } else {
      shape.radial[s] = U[0] * std::cos(a) + U[1] * std::sin(a);
      shape.tangential[s] = -U[0] * std::sin(a) + U[1] * std::cos(a);
    }
  }
  ring::normalize(shape);
  return shape;
}

void RingModel::write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                          const std::string& file) const {
  // The same cells as a curve in the plane (Triangulation<1,2>, a closed loop), so that
  // ParaView shows the ring: the circle through a SphericalManifold, or the n-gon of
  // side 2 pi R / n. Local DoF orderings agree, so values are copied cell by cell.
  const bool curved = setup_.geometry == Geometry::curved;
  const unsigned int n = setup_.cells(), m = setup_.subdivisions;
  const double chord_angle = 2.0 * kPi / setup_.elements;
  const double corner = curved ? spec_.radius : spec_.radius * (chord_angle / 2.0) / std::sin(chord_angle / 2.0);
  std::vector<Point<2>> vertices(n);
  for (unsigned int i = 0; i < n; ++i) {
    const double a0 = theta0_ + (i / m) * chord_angle, a1 = a0 + chord_angle, f = double(i % m) / m;
    if (curved)
      vertices[i] = Point<2>(spec_.radius * std::cos(theta0_ + i * h_), spec_.radius * std::sin(theta0_ + i * h_));
    else
      vertices[i] = Point<2>(corner * ((1 - f) * std::cos(a0) + f * std::cos(a1)),
                             corner * ((1 - f) * std::sin(a0) + f * std::sin(a1)));
  }
  std::vector<CellData<1>> cells(n);
  for (unsigned int i = 0; i < n; ++i) cells[i].vertices = {i, (i + 1) % n};
  Triangulation<1, 2> plane;
  plane.create_triangulation(vertices, cells, SubCellData());
  const SphericalManifold<1, 2> circle;
  if (curved) {
    plane.set_all_manifold_ids(0);
    plane.set_manifold(0, circle);
  }
  const FESystem<1, 2> fe(make_fe<2>(setup_));
  DoFHandler<1, 2> dofs(plane);
  dofs.distribute_dofs(fe);

  DataOut<1, 2> data_out;
  data_out.attach_dof_handler(dofs);
  std::vector<Vector<double>> fields(modes.size(), Vector<double>(dofs.n_dofs()));
  std::vector<std::unique_ptr<CartesianDisplacement>> displacement;
  Vector<double> local(fe.n_dofs_per_cell());
  for (unsigned int k = 0; k < modes.size(); ++k) {
    for (const auto& cell : dofs.active_cell_iterators()) {
      cells_[cell->index()]->get_dof_values(modes[k], local);
      cell->set_dof_values(local, fields[k]);
    }
    const double largest = fields[k].linfty_norm();
    if (largest > 0) fields[k] /= largest;
    std::ostringstream suffix;  // mode number and frequency (rad/s) in every name
    suffix << "_" << (k + 1) << "_omega_" << omega[k];
    data_out.add_data_vector(fields[k], std::vector<std::string>{(curved ? "tangential" : "ux") + suffix.str(),
                                                                 (curved ? "radial" : "uy") + suffix.str()});
    displacement.push_back(std::make_unique<CartesianDisplacement>("displacement" + suffix.str(), curved));
    data_out.add_data_vector(fields[k], *displacement.back());
  }
  const MappingQ<1, 2> mapping(std::max(2, setup_.degree));
  data_out.build_patches(mapping, setup_.degree + 1, DataOut<1, 2>::curved_inner_cells);
  std::ofstream out(file);
  if (!out) throw ring::NumericalError("fem: cannot write " + file);
  data_out.write_vtu(out);
  if (!out) throw ring::NumericalError("fem: writing " + file + " failed");
}

// ---------------------------------------------------------------------------------

void validate(const ring::RingSpec& spec, const ring::FemOptions& o, int count) {
  auto need = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("fem: " + what);
  };
  need(spec.radius > 0 && std::isfinite(spec.radius), "ring.radius must be > 0");
  need(spec.E > 0 && spec.rho > 0, "ring.E and ring.rho must be > 0");
  need(spec.A() > 0 && spec.I() > 0, "the section's area and inertia must be > 0");
  need(o.elements >= 4, "fem.elements (=" + std::to_string(o.elements) + ") must be >= 4");
  need(o.degree >= 2 && o.degree <= 30, "fem.degree (=" + std::to_string(o.degree) + ") must be in 2..30");
  need(!o.reference || (o.tolerance > 0 && o.tolerance < 1), "fem.tolerance must be in (0, 1)");
  need(count >= 1, "count (=" + std::to_string(count) + ") must be >= 1");
  need(!spec.supports.roller || spec.supports.pin, "supports.roller needs supports.pin");
  if (spec.supports.roller) {
    need(ring::wrap_degrees(*spec.supports.roller - *spec.supports.pin) > 1e-9 &&
             ring::wrap_degrees(*spec.supports.pin - *spec.supports.roller) > 1e-9,
         "supports.roller must differ from supports.pin");
    need(ring::on_node(*spec.supports.roller, *spec.supports.pin, o.elements),
         "supports.roller (=" + std::to_string(*spec.supports.roller) +
             ") must fall on an FE vertex: pin + k * 360 / fem.elements");
  }
}

/// Frequencies, shapes and residual of one discretization (with the inextensible
/// extrapolation when asked). `full` receives the full DoF vectors if not null.
struct Solved {
  ring::ModalResult result;
  std::vector<Vector<double>> full;
};

Solved solve_once(const ring::RingSpec& spec, Setup setup, bool extensible, int count, bool keep_full,
                  bool refine = true) {
  const int rigid = spec.supports.rigid_modes();
  auto run = [&](double EA, std::vector<double>& lambda, double& max_res, ring::ModalResult& r,
                 std::vector<Vector<double>>* full) {
    setup.EA = EA;
    const RingModel model(spec, setup);
    const unsigned int wanted = static_cast<unsigned int>(count + rigid);
    if (wanted > model.n_free())
      throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be <= unknowns - rigid modes (=" +
                                  std::to_string(static_cast<int>(model.n_free()) - rigid) + ") for " +
                                  std::to_string(setup.cells()) + " cells of degree " + std::to_string(setup.degree));
    EigenPairs pairs;
    try {
      pairs = model.solve(wanted, refine);
    } catch (const ring::NumericalError&) {
      throw;
    } catch (const std::exception& e) {
      throw ring::NumericalError(std::string("fem: eigen-solver failed: ") + e.what());
    }
    // Elastic eigenvalues must be positive (a negative one would mean a non-coercive
    // penalty); rigid ones are zero up to round-off (~eps lambda_max, either sign) and,
    // on the circle, the approximation of rigid translations by polar fields.
    for (unsigned int i = 0; i < wanted; ++i)
      if (!std::isfinite(pairs.lambda[i]) || (static_cast<int>(i) >= rigid && !(pairs.lambda[i] > 0)))
        throw ring::NumericalError("fem: eigenvalue " + std::to_string(pairs.lambda[i]) + " of mode " +
                                   std::to_string(i + 1) + " is not positive and finite");
    if (rigid > 0 && std::abs(pairs.lambda[rigid - 1]) > 1e-2 * pairs.lambda[rigid])
      throw ring::NumericalError("fem: the mesh is too coarse to represent the " + std::to_string(rigid) +
                                 " rigid modes (lowest elastic/rigid eigenvalue ratio < 100)");
    lambda.assign(pairs.lambda.begin() + rigid, pairs.lambda.end());
    max_res = 0.0;
    r.shapes.clear();
    for (unsigned int i = rigid; i < wanted; ++i) {
      max_res = std::max(max_res, pairs.residual[i]);
      const auto f = model.expand(pairs.q[i]);
      r.shapes.push_back(model.sample(f));
      if (full) full->push_back(f);
    }
    r.unknowns = model.n_free();
  };
  Solved out;
  auto& r = out.result;
  std::vector<double> lambda;
  double max_res = 0.0;
  if (extensible) {
    run(spec.EA(), lambda, max_res, r, keep_full ? &out.full : nullptr);
  } else {
    // omega^2(beta) = omega^2_inf - c / beta + O(beta^-2): extrapolate from beta, 2 beta.
    const double base = kInextensibleBeta * spec.EI() / (spec.radius * spec.radius);
    std::vector<double> lambda1;
    double res1 = 0.0;
    run(base, lambda1, res1, r, nullptr);
    run(2.0 * base, lambda, max_res, r, keep_full ? &out.full : nullptr);
    for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = 2.0 * lambda[i] - lambda1[i];
    max_res = std::max(max_res, res1);
  }
  for (double l : lambda) {
    if (!(l > 0)) throw ring::NumericalError("fem: non-positive elastic eigenvalue " + std::to_string(l));
    r.omega.push_back(std::sqrt(l));
  }
  r.max_residual = max_res;
  r.rigid_modes = spec.supports.rigid_modes();
  return out;
}

Solved run(const ring::RingSpec& spec, const ring::FemOptions& o, int count, bool keep_full) {
  validate(spec, o, count);
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup;
  setup.elements = o.elements;
  setup.degree = o.degree;
  setup.geometry = o.geometry;
  setup.rotary_inertia = o.rotary_inertia;
  Solved s = solve_once(spec, setup, o.extensible, count, keep_full && !o.reference, !o.reference || !o.extensible);
  int refinements = 0;
  if (o.reference) {
    // p-refinement (exponential convergence on these smooth, piecewise analytic modes),
    // h-refinement once p reaches kReferenceMaxDegree. Stop when the largest relative
    // change of the requested frequencies is below the tolerance.
    double previous_change = 0.0;
    bool refined = true;
    for (;;) {
      if (++refinements > kReferenceMaxSteps)
        throw ring::NumericalError("fem: reference not converged after " + std::to_string(kReferenceMaxSteps) +
                                   " refinements (degree " + std::to_string(setup.degree) + ", cells " +
                                   std::to_string(setup.cells()) + ")");
      if (setup.degree < kReferenceMaxDegree)
        ++setup.degree;
      else
        setup.subdivisions *= 2;
      // Raw pairs carry ~1e-7 round-off; refine them only once the changes get near it.
      // (The inextensible penalty makes raw pairs far noisier: always refine them.)
      refined = !o.extensible || (refinements > 1 && previous_change < kRefineBelowChange);
      Solved next = solve_once(spec, setup, o.extensible, count, false, refined);
      double change = 0.0;
      for (int i = 0; i < count; ++i)
        change = std::max(change, std::abs(next.result.omega[i] - s.result.omega[i]) / next.result.omega[i]);
      s = std::move(next);
      if (change < o.tolerance) {
        // The change is the error of the previous solution; with a contraction
        // r = change / previous_change per step the current one has about change * r / (1 - r).
        const double ratio = previous_change > 0 ? change / previous_change : 1.0;
        // Not below the refined solve's round-off: the free ring's k = 2..13 match the
        // closed form to ~1e-12, not better.
        s.result.error_estimate = std::max(kRoundOffFloor, ratio < 0.5 ? change * ratio / (1.0 - ratio) : change);
        break;
      }
      previous_change = change;
    }
    if (keep_full || !refined) {
      const double estimate = s.result.error_estimate;
      s = solve_once(spec, setup, o.extensible, count, keep_full);
      s.result.error_estimate = estimate;
    }
  }
  auto& r = s.result;
  r.solver = "fem";
  r.model["elements"] = static_cast<long long>(setup.elements);
  r.model["cells"] = static_cast<long long>(setup.cells());
  r.model["degree"] = static_cast<long long>(setup.degree);
  r.model["geometry"] = ring::to_string(setup.geometry);
  r.model["extensible"] = o.extensible;
  r.model["rotary_inertia"] = o.rotary_inertia;
  r.model["reference"] = o.reference;
  r.model["refinements"] = static_cast<long long>(refinements);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.result.model["subdivisions"] = static_cast<long long>(setup.subdivisions);
  return s;
}

}  // namespace

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::FemOptions& options, int count) {
  return run(spec, options, count, false).result;
}

std::string write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count,
                      const std::string& dir) {
  Solved s = run(spec, options, count, true);
  Setup setup;
  setup.elements = options.elements;
  setup.subdivisions = static_cast<int>(std::get<long long>(s.result.model.at("subdivisions")));
  setup.degree = static_cast<int>(std::get<long long>(s.result.model.at("degree")));
  setup.geometry = options.geometry;
  setup.rotary_inertia = options.rotary_inertia;
  setup.EA = spec.EA();
  const RingModel model(spec, setup);  // the same mesh and DoF numbering as the solve
  const std::string file = dir + "/fem_modes.vtu";
  model.write_vtu(s.full, s.result.omega, file);
  return file;
}

}  // namespace fem
