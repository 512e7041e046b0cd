// The linear Timoshenko ring: mesh, constraints, reduced system, assembly with selective
// reduced integration, operator application and sampling (timoshenko_model.hpp; the
// formulation in modes.hpp).
#include "fem_reference/timoshenko_model.hpp"

namespace fem::detail {

TimoshenkoModel::TimoshenkoModel(const ring::RingSpec& spec, const Setup& setup)
    : BeamModel(spec, setup),
      fe_(make_fe(setup)),
      dof_handler_(triangulation_) {
  make_grid();
  setup_constraints();
  setup_reduced_system();
  setup_point_terms();
  assemble();
  measure_lengths();
}

void TimoshenkoModel::make_grid() {
  GridGenerator::subdivided_hyper_cube(triangulation_, setup_.cells(), theta0_, theta0_ + 2.0 * kPi);
  dof_handler_.distribute_dofs(fe_);
  for (const auto& cell : dof_handler_.active_cell_iterators()) cells_.push_back(cell);
  std::sort(cells_.begin(), cells_.end(),
            [](const auto& a, const auto& b) { return a->center()[0] < b->center()[0]; });
  // Every integrand is a polynomial in theta (ds = R dtheta): p + 1 Gauss points integrate
  // the bending (degree 2p - 2), foundation and mass (2p) terms exactly; p points integrate
  // the membrane and shear terms as the square of the strain's L2 projection onto P_{p-1}
  // (modes.hpp).
  const QGauss<1> full(setup_.degree + 1);
  full_ = make_table(full);
  reduced_ = make_table(QGauss<1>(setup_.degree));
  // The Reissner beam's distributed terms (foundation, pressure, gravity) use the full
  // rule, as the linear foundation: rows of x = u t0 + (R + w) n0 and a = dx/ds0 with
  // a_t = 1 + eps, a_n = gamma - psi = (w' - u)/R.
  const unsigned int dpc = fe_.n_dofs_per_cell();
  for (unsigned int q = 0; q < full_.points; ++q) {
    load_rule_.xi.push_back(full.point(q)[0]);
    load_rule_.ds.push_back(full_.ds[q]);
    for (unsigned int i = 0; i < dpc; ++i) {
      const Strains& t = full_.at[q * dpc + i];
      load_rule_.row.push_back({t.u, t.w, t.eps, t.gamma - t.psi});
    }
  }
}

TimoshenkoModel::Table TimoshenkoModel::make_table(const Quadrature<1>& quadrature) const {
  FEValues<1> fev(fe_, quadrature, update_values | update_gradients | update_JxW_values);
  fev.reinit(cells_[0]);
  const double R = spec_.radius;
  Table t;
  t.points = quadrature.size();
  for (unsigned int q = 0; q < t.points; ++q) {
    t.ds.push_back(fev.JxW(q) * R);
    for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i) {
      const double v = fev.shape_value(i, q), d = fev.shape_grad(i, q)[0];  // d/dtheta
      Strains s;
      switch (fe_.system_to_component_index(i).first) {
        case 0:  // u, tangential
          s.u = v;
          s.eps = d / R;
          s.gamma = -v / R;
          break;
        case 1:  // w, radial
          s.w = v;
          s.eps = v / R;
          s.gamma = d / R;
          break;
        default:  // psi, the cross-section's rotation
          s.psi = v;
          s.gamma = v;
          s.kappa = d / R;
      }
      t.at.push_back(s);
    }
  }
  return t;
}

std::array<types::global_dof_index, 3> TimoshenkoModel::vertex_dofs(unsigned int v) const {
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  cells_[v % setup_.cells()]->get_dof_indices(dofs);
  std::array<types::global_dof_index, 3> out{};
  const auto& points = fe_.get_unit_support_points();
  for (unsigned int i = 0; i < dofs.size(); ++i)
    if (std::abs(points[i][0]) < 1e-12) out[fe_.system_to_component_index(i).first] = dofs[i];
  return out;
}

void TimoshenkoModel::setup_constraints() {
  const unsigned int n = setup_.cells();
  // Periodic closure: the right end of the last cell is vertex 0 (the same polar basis).
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  cells_[n - 1]->get_dof_indices(dofs);
  const auto& points = fe_.get_unit_support_points();
  const auto first = vertex_dofs(0);
  for (unsigned int i = 0; i < dofs.size(); ++i)
    if (std::abs(points[i][0] - 1.0) < 1e-12) {
      constraints_.add_line(dofs[i]);
      constraints_.add_entry(dofs[i], first[fe_.system_to_component_index(i).first], 1.0);
    }
  if (spec_.supports.pin) {
    // Pins hold u and w (psi stays free); the roller holds the component normal to the
    // line pin-roller, as in the Euler-Bernoulli model; the clamp holds psi as well.
    for (unsigned int c = 0; c < 2; ++c) constraints_.add_line(first[c]);
    if (spec_.supports.roller) {
      const unsigned int k = vertex_of(*spec_.supports.roller);
      const double a = theta0_ + k * h_;
      const std::array<double, 2> d{std::cos(a) - std::cos(theta0_), std::sin(a) - std::sin(theta0_)};
      const double len = std::hypot(d[0], d[1]);
      const std::array<double, 2> e{-d[1] / len, d[0] / len};
      const std::array<double, 2> coef{e[0] * -std::sin(a) + e[1] * std::cos(a), e[0] * std::cos(a) + e[1] * std::sin(a)};
      const auto at = vertex_dofs(k);
      const unsigned int m = std::abs(coef[0]) >= std::abs(coef[1]) ? 0 : 1;
      constraints_.add_line(at[m]);
      if (std::abs(coef[1 - m]) > 1e-14 * std::abs(coef[m])) constraints_.add_entry(at[m], at[1 - m], -coef[1 - m] / coef[m]);
    }
    for (double a : spec_.supports.pins) {
      const auto at = vertex_dofs(vertex_of(a));
      for (unsigned int c = 0; c < 2; ++c)
        if (!constraints_.is_constrained(at[c])) constraints_.add_line(at[c]);
    }
    if (spec_.supports.clamp) constraints_.add_line(vertex_dofs(vertex_of(*spec_.supports.clamp))[2]);
  }
  constraints_.close();
}

void TimoshenkoModel::setup_reduced_system() {
  number_free_dofs(dof_handler_.n_dofs());
  // An H1 form: each cell couples with itself only (the periodic closure and the roller
  // act through expansion_, the point terms within one vertex).
  DynamicSparsityPattern dsp(n_free_);
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  for (const auto& cell : cells_) {
    cell->get_dof_indices(dofs);
    std::vector<unsigned int> rows;
    for (const auto i : dofs)
      for (const auto& [f, w] : expansion_[i]) rows.push_back(f);
    for (const auto r : rows)
      for (const auto c : rows) dsp.add(r, c);
  }
  sparsity_.copy_from(dsp);
  K_.reinit(sparsity_);
  M_.reinit(sparsity_);
}

void TimoshenkoModel::setup_point_terms() {
  auto translation = [&](unsigned int v, unsigned int direction, double stiffness, double mass) {
    if (stiffness == 0.0 && mass == 0.0) return;
    const auto d = vertex_dofs(v);
    const double a = theta0_ + v * h_;  // U = u t0 + w n0, t0 = (-sin a, cos a), n0 = (cos a, sin a)
    PointTerm t{{d[0], d[1]}, {}, stiffness, mass};
    t.coef = direction == 0 ? std::vector<double>{-std::sin(a), std::cos(a)} : std::vector<double>{std::cos(a), std::sin(a)};
    point_terms_.push_back(std::move(t));
  };
  auto rotation = [&](unsigned int v, double stiffness, double mass) {
    if (stiffness == 0.0 && mass == 0.0) return;
    point_terms_.push_back(PointTerm{{vertex_dofs(v)[2]}, {1.0}, stiffness, mass});
  };
  for (const ring::Spring& s : spec_.supports.springs) {
    const unsigned int v = vertex_of(s.angle);
    translation(v, 0, s.kx, 0.0);
    translation(v, 1, s.ky, 0.0);
    rotation(v, s.kr, 0.0);
  }
  for (const ring::PointMass& pm : spec_.masses) {
    const unsigned int v = vertex_of(pm.angle);
    translation(v, 0, 0.0, pm.mass);
    translation(v, 1, 0.0, pm.mass);
    rotation(v, 0.0, pm.inertia);
  }
}

void TimoshenkoModel::assemble() {
  const double EA = setup_.EA, kGA = spec_.kGA(), EI = spec_.EI(), rhoA = spec_.rhoA(), rhoI = spec_.rhoI();
  const double kt = spec_.foundation.tangential, kr = spec_.foundation.radial;
  const unsigned int dpc = fe_.n_dofs_per_cell();
  // Every cell is the same affine image of the reference cell: one local matrix serves all.
  FullMatrix<double> k_cell(dpc, dpc), m_cell(dpc, dpc);
  for (unsigned int q = 0; q < reduced_.points; ++q)
    for (unsigned int i = 0; i < dpc; ++i)
      for (unsigned int j = 0; j < dpc; ++j) {
        const Strains &a = reduced_.at[q * dpc + i], &b = reduced_.at[q * dpc + j];
        k_cell(i, j) += (EA * a.eps * b.eps + kGA * a.gamma * b.gamma) * reduced_.ds[q];
      }
  for (unsigned int q = 0; q < full_.points; ++q)
    for (unsigned int i = 0; i < dpc; ++i)
      for (unsigned int j = 0; j < dpc; ++j) {
        const Strains &a = full_.at[q * dpc + i], &b = full_.at[q * dpc + j];
        k_cell(i, j) += (EI * a.kappa * b.kappa + kt * a.u * b.u + kr * a.w * b.w) * full_.ds[q];
        m_cell(i, j) += (rhoA * (a.u * b.u + a.w * b.w) + rhoI * a.psi * b.psi) * full_.ds[q];
      }
  std::vector<types::global_dof_index> dofs(dpc);
  for (const auto& cell : cells_) {
    cell->get_dof_indices(dofs);
    add_local(k_cell, dofs, K_);
    add_local(m_cell, dofs, M_);
  }
  assemble_point_terms();
}

void TimoshenkoModel::apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const {
  const Vector<double> full = expand(q);
  const Real EA = setup_.EA, kGA = spec_.kGA(), EI = spec_.EI(), rhoA = spec_.rhoA(), rhoI = spec_.rhoI();
  const Real kt = spec_.foundation.tangential, kr = spec_.foundation.radial;
  const unsigned int dpc = fe_.n_dofs_per_cell();
  kq.assign(n_free_, 0.0L);
  mq.assign(n_free_, 0.0L);
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<Real> x(dpc), lk(dpc), lm(dpc);
  for (const auto& cell : cells_) {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dpc; ++i) x[i] = full[dofs[i]];
    std::fill(lk.begin(), lk.end(), 0.0L);
    std::fill(lm.begin(), lm.end(), 0.0L);
    // The strains in extended precision: a bending mode's shear strain is psi - (u - w')/R,
    // a difference ~(depth/R)^2 below its terms.
    for (unsigned int p = 0; p < reduced_.points; ++p) {
      Real eps = 0, gamma = 0;
      for (unsigned int i = 0; i < dpc; ++i) {
        eps += x[i] * reduced_.at[p * dpc + i].eps;
        gamma += x[i] * reduced_.at[p * dpc + i].gamma;
      }
      const Real ds = reduced_.ds[p];
      for (unsigned int i = 0; i < dpc; ++i)
        lk[i] += ds * (EA * eps * reduced_.at[p * dpc + i].eps + kGA * gamma * reduced_.at[p * dpc + i].gamma);
    }
    for (unsigned int p = 0; p < full_.points; ++p) {
      Real kappa = 0, u = 0, w = 0, psi = 0;
      for (unsigned int i = 0; i < dpc; ++i) {
        const Strains& s = full_.at[p * dpc + i];
        kappa += x[i] * s.kappa;
        u += x[i] * s.u;
        w += x[i] * s.w;
        psi += x[i] * s.psi;
      }
      const Real ds = full_.ds[p];
      for (unsigned int i = 0; i < dpc; ++i) {
        const Strains& s = full_.at[p * dpc + i];
        lk[i] += ds * (EI * kappa * s.kappa + kt * u * s.u + kr * w * s.w);
        lm[i] += ds * (rhoA * (u * s.u + w * s.w) + rhoI * psi * s.psi);
      }
    }
    for (unsigned int i = 0; i < dpc; ++i)
      for (const auto& [f, weight] : expansion_[dofs[i]]) {
        kq[f] += weight * lk[i];
        mq[f] += weight * lm[i];
      }
  }
  apply_point_terms(full, kq, mq);
}

ring::ModeShape TimoshenkoModel::sample(const Vector<double>& full) const {
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
    std::array<double, 3> U{0.0, 0.0, 0.0};
    for (unsigned int i = 0; i < dpc; ++i)
      U[fe_.system_to_component_index(i).first] += full[dofs[i]] * fe_.shape_value(i, Point<1>(xi));
    shape.tangential[s] = U[0];
    shape.radial[s] = U[1];
  }
  ring::normalize(shape);
  return shape;
}

void TimoshenkoModel::write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                                const std::string& file) const {
  write_ring_vtu(spec_, setup_, theta0_, cells_, modes, omega, file);
}

}  // namespace fem::detail
