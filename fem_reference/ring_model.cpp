// The linear ring model: mesh, constraints, reduced system, assembly, operator
// application, expansion and sampling (ring_model.hpp).
#include "fem_reference/ring_model.hpp"

namespace fem::detail {

// ---- LinearModel: what every linear model shares ----

LinearModel::LinearModel(const ring::RingSpec& spec, const Setup& setup)
    : spec_(spec), setup_(setup), sigma_(-std::pow(spec.bending_frequency_scale(), 2)) {}

void LinearModel::number_free_dofs(types::global_dof_index n_dofs) {
  free_.assign(n_dofs, -1);
  n_free_ = 0;
  for (types::global_dof_index i = 0; i < n_dofs; ++i)
    if (!constraints_.is_constrained(i)) free_[i] = n_free_++;
  expansion_.assign(n_dofs, {});
  for (types::global_dof_index i = 0; i < n_dofs; ++i) {
    if (free_[i] >= 0) {
      expansion_[i] = {{static_cast<unsigned int>(free_[i]), 1.0}};
    } else if (const auto* entries = constraints_.get_constraint_entries(i)) {
      for (const auto& [j, w] : *entries) expansion_[i].emplace_back(free_[j], w);
    }
  }
}

void LinearModel::add_local(const FullMatrix<double>& local, const std::vector<types::global_dof_index>& dofs,
                            SparseMatrix<double>& global) const {
  for (unsigned int i = 0; i < dofs.size(); ++i)
    for (const auto& [fi, wi] : expansion_[dofs[i]])
      for (unsigned int j = 0; j < dofs.size(); ++j) {
        const double lij = local(i, j);
        if (lij == 0.0) continue;
        for (const auto& [fj, wj] : expansion_[dofs[j]]) global.add(fi, fj, wi * wj * lij);
      }
}

void LinearModel::assemble_point_terms() {
  for (const PointTerm& t : point_terms_) {
    const unsigned int m = t.dofs.size();
    FullMatrix<double> k_point(m, m), m_point(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j) {
        k_point(i, j) = t.stiffness * t.coef[i] * t.coef[j];
        m_point(i, j) = t.mass * t.coef[i] * t.coef[j];
      }
    if (t.stiffness > 0.0) add_local(k_point, t.dofs, K_);
    if (t.mass > 0.0) add_local(m_point, t.dofs, M_);
  }
}

void LinearModel::apply_point_terms(const Vector<double>& full, std::vector<Real>& kq, std::vector<Real>& mq) const {
  for (const PointTerm& t : point_terms_) {
    Real y = 0;
    for (unsigned int i = 0; i < t.dofs.size(); ++i) y += t.coef[i] * full[t.dofs[i]];
    for (unsigned int i = 0; i < t.dofs.size(); ++i)
      for (const auto& [f, w] : expansion_[t.dofs[i]]) {
        kq[f] += w * (t.stiffness * y * t.coef[i]);
        mq[f] += w * (t.mass * y * t.coef[i]);
      }
  }
}

double LinearModel::precision_ratio() const {
  std::vector<double> k(n_free_, 0.0), m(n_free_, 0.0);
  for (auto it = K_.begin(); it != K_.end(); ++it) k[it->row()] += std::abs(it->value());
  for (auto it = M_.begin(); it != M_.end(); ++it) m[it->row()] += it->value();
  // Point masses and inertias only lower eigenvalues (a positive semi-definite mass
  // added), but their rank-one rows c c^T have row sums of either sign: they are left
  // out of the estimate, which stays an estimate of the ring's own lambda_max.
  for (const PointTerm& t : point_terms_)
    for (unsigned int i = 0; i < t.dofs.size(); ++i)
      for (const auto& [fi, wi] : expansion_[t.dofs[i]])
        for (unsigned int j = 0; j < t.dofs.size(); ++j)
          for (const auto& [fj, wj] : expansion_[t.dofs[j]]) m[fi] -= wi * wj * t.mass * t.coef[i] * t.coef[j];
  double lambda_max = 0.0;
  for (unsigned int i = 0; i < n_free_; ++i)
    lambda_max = std::max(lambda_max, m[i] > 0 ? k[i] / m[i] : std::numeric_limits<double>::infinity());
  return std::numeric_limits<double>::epsilon() * lambda_max / std::abs(sigma_);
}

Vector<double> LinearModel::expand(const Vector<double>& q) const {
  Vector<double> full(free_.size());
  for (types::global_dof_index i = 0; i < full.size(); ++i)
    if (free_[i] >= 0) full[i] = q[free_[i]];
  constraints_.distribute(full);
  return full;
}

// ---- RingModel: the Euler-Bernoulli ring ----

RingModel::RingModel(const ring::RingSpec& spec, const Setup& setup)
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

void RingModel::make_grid() {
  GridGenerator::subdivided_hyper_cube(triangulation_, setup_.cells(), theta0_, theta0_ + setup_.cells() * h_);
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
  int extra = 0;
  if (spec_.varies()) {
    int top = 0;
    for (const ring::Variation& v : spec_.variations) top = std::max(top, v.harmonic);
    extra = kVariationPoints + static_cast<int>(std::ceil(2.0 * top * h_));
  }
  const QGauss<1> gauss(setup_.degree + 2 + extra);
  std::vector<Point<1>> points = gauss.get_points();
  points.push_back(Point<1>(0.0));
  points.push_back(Point<1>(1.0));
  std::vector<double> weights = gauss.get_weights();
  weights.push_back(0.0);
  weights.push_back(0.0);
  // ring.plastic's bending points (plastic_points.hpp): the (p + 1)-point Gauss-Lobatto
  // rule, whose ends are the two above; its interior points follow them in the table.
  const QGaussLobatto<1> lobatto(setup_.degree + 1);
  for (unsigned int j = 1; j + 1 < lobatto.size(); ++j) {
    points.push_back(lobatto.point(j));
    weights.push_back(lobatto.weight(j));
  }
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
  // The bending points' rows (left end, interior in order, right end) and ds0 weights: the
  // Lobatto weight times the cell's length (the Gauss weights of ds_ sum to that length).
  const double cell_length = std::accumulate(ds_.begin(), ds_.begin() + nq_, 0.0);
  for (unsigned int j = 0; j < lobatto.size(); ++j) {
    bend_rows_.push_back(j == 0 ? nq_ : j + 1 == lobatto.size() ? nq_ + 1 : nq_ + 1 + j);
    bend_ds_.push_back(lobatto.weight(j) * cell_length);
  }
  // The geometrically exact beam's distributed terms use the same Gauss rule (curved
  // geometry: the rows of x = u t0 + (R + w) n0 and a = dx/ds0, nonlinear.hpp).
  if (setup_.geometry == Geometry::curved)
    for (unsigned int q = 0; q < nq_; ++q) {
      load_rule_.xi.push_back(gauss.point(q)[0]);
      load_rule_.ds.push_back(ds_[q]);
      for (unsigned int i = 0; i < dpc; ++i) {
        const auto row = strain_row(i, q);
        const double v = v0_[q * dpc + i];
        load_rule_.row.push_back(component_[i] == 0 ? std::array<double, 4>{v, 0.0, row[0], row[1]}
                                                    : std::array<double, 4>{0.0, v, row[0], row[1]});
      }
    }
  // sigma = 2 (q+1)(q+2) > (q+1)^2, the trace-inverse constant for kappa of degree
  // q = p (u' on the circle), makes the form coercive; h = arc length of a cell.
  const double q_kappa = setup_.degree;
  penalty_ = 2.0 * (q_kappa + 1) * (q_kappa + 2) * spec_.EI() / (ds_dtheta() * h_);
  // ring.variations: the section at every Gauss point's and every vertex's polar angle.
  // EA scales the axial stiffness in use (EA, or the inextensible penalty) by the local ratio.
  if (spec_.varies()) {
    constexpr double kDegrees = 180.0 / kPi;
    const unsigned int n = setup_.cells();
    const double EA_scale = setup_.EA / spec_.EA();
    for (unsigned int cell = 0; cell < n; ++cell)
      for (unsigned int q = 0; q < nq_; ++q) {
        const double deg = (theta0_ + (cell + gauss.point(q)[0]) * h_) * kDegrees;
        sections_.push_back({spec_.EI_at(deg), EA_scale * spec_.EA_at(deg), spec_.rhoA_at(deg),
                             setup_.rotary_inertia ? spec_.rhoI_at(deg) : 0.0});
      }
    for (unsigned int v = 0; v <= n; ++v) vertex_EI_.push_back(spec_.EI_at((theta0_ + v * h_) * kDegrees));
  }
}

RingModel::Section RingModel::section(unsigned int cell, unsigned int q) const {
  if (!sections_.empty()) return sections_[cell * nq_ + q];
  return {spec_.EI(), setup_.EA, spec_.rhoA(), setup_.rotary_inertia ? spec_.rho * spec_.I() : 0.0};
}

std::vector<std::pair<unsigned int, double>> RingModel::cells_at(unsigned int v) const {
  const unsigned int n = setup_.cells();
  std::vector<std::pair<unsigned int, double>> out;
  if (!open_ || v > 0) out.emplace_back((v + n - 1) % n, 1.0);
  if (!open_ || v < n) out.emplace_back(v % n, 0.0);
  return out;
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
  // components are the same there (polar basis at the same angle, or Cartesian). An arch
  // (ring.arc) is the same mesh without the wrap: its end vertices 0 and n are distinct,
  // and an end without a support has the natural (free-end) conditions.
  const auto first = end_dofs(0, 0.0), last = end_dofs(n - 1, 1.0);
  if (!open_)
    for (unsigned int c = 0; c < 2; ++c) {
      constraints_.add_line(last[c]);
      constraints_.add_entry(last[c], first[c], 1.0);
    }
  if (spec_.supports.pin) {
    // Both components zero at the pin's vertex (the ring's vertex 0; an arch's pin may sit
    // at either end).
    const auto pinned = vertex_dofs(vertex_of(*spec_.supports.pin));
    for (unsigned int c = 0; c < 2; ++c) constraints_.add_line(pinned[c]);
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
    // Further pins: both components zero at their vertices.
    for (double a : spec_.supports.pins) {
      const auto dofs = vertex_dofs(vertex_of(a));
      for (unsigned int c = 0; c < 2; ++c)
        if (!constraints_.is_constrained(dofs[c])) constraints_.add_line(dofs[c]);
    }
    if (spec_.supports.clamp) constrain_rotation(vertex_of(*spec_.supports.clamp));
  }
  constraints_.close();
}

void RingModel::constrain_rotation(unsigned int v) {
  // The C0 interior-penalty model has one rotation per cell end, so a clamp is two rows:
  // phi = 0 at the right end of cell v-1 and at the left end of cell v. The exact
  // (C1) solution satisfies both and the test functions do too, so the penalty and
  // moment terms at the clamp vanish and the form stays consistent. Each row eliminates
  // the interior DoF of its cell with the largest coefficient (degree >= 2: w has one).
  const unsigned int dpc = fe_.n_dofs_per_cell();
  const auto& points = fe_.get_unit_support_points();
  std::vector<types::global_dof_index> dofs(dpc);
  for (const auto& [cell, end] : cells_at(v)) {
    cells_[cell]->get_dof_indices(dofs);
    const unsigned int q = end == 0.0 ? nq_ : nq_ + 1;
    std::vector<double> coef(dpc, 0.0);
    unsigned int m = dpc;
    for (unsigned int i = 0; i < dpc; ++i) {
      const double xi = points[i][0];
      if (std::abs(xi - end) < 1e-12) continue;  // the clamp's own (pinned) DoFs
      coef[i] = kinematics(cell, i, q).phi;
      const bool interior = xi > 1e-12 && xi < 1.0 - 1e-12;
      if (interior && (m == dpc || std::abs(coef[i]) > std::abs(coef[m]))) m = i;
    }
    constraints_.add_line(dofs[m]);
    for (unsigned int i = 0; i < dpc; ++i)
      if (i != m && coef[i] != 0.0) constraints_.add_entry(dofs[m], dofs[i], -coef[i] / coef[m]);
  }
}

void RingModel::vertex_rotation(unsigned int v, std::vector<types::global_dof_index>& dofs,
                                std::vector<double>& coef) const {
  // The rotation at a vertex is the mean of the two cells' end rotations: on the exact
  // (C1) solution both are the rotation, and the mean keeps the form consistent (the
  // vertex's natural condition [[M]] = kr {phi} pairs with {phi} of the test function).
  // At an arch's end the one cell's end rotation is the rotation.
  const unsigned int dpc = fe_.n_dofs_per_cell();
  const auto sides = cells_at(v);
  const double weight = 1.0 / sides.size();
  dofs.clear();
  coef.clear();
  std::vector<types::global_dof_index> side(dpc);
  for (const auto& [cell, end] : sides) {
    cells_[cell]->get_dof_indices(side);
    for (unsigned int i = 0; i < dpc; ++i) {
      dofs.push_back(side[i]);
      coef.push_back(weight * kinematics(cell, i, end == 0.0 ? nq_ : nq_ + 1).phi);
    }
  }
}

void RingModel::setup_point_terms() {
  // Cartesian components of the vertex displacement: U = u t0 + w n0 (curved, t0 =
  // (-sin a, cos a), n0 = (cos a, sin a)) or (ux, uy) (polygon).
  auto translation = [&](unsigned int v, unsigned int direction, double stiffness, double mass) {
    if (stiffness == 0.0 && mass == 0.0) return;
    const auto d = vertex_dofs(v);
    PointTerm t{{d[0], d[1]}, {0.0, 0.0}, stiffness, mass};
    if (setup_.geometry == Geometry::curved) {
      const double a = theta0_ + v * h_;
      t.coef = direction == 0 ? std::vector<double>{-std::sin(a), std::cos(a)}
                              : std::vector<double>{std::cos(a), std::sin(a)};
    } else {
      t.coef[direction] = 1.0;
    }
    point_terms_.push_back(std::move(t));
  };
  auto rotation = [&](unsigned int v, double stiffness, double mass) {
    if (stiffness == 0.0 && mass == 0.0) return;
    PointTerm t;
    vertex_rotation(v, t.dofs, t.coef);
    t.stiffness = stiffness;
    t.mass = mass;
    point_terms_.push_back(std::move(t));
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

void RingModel::setup_reduced_system() {
  number_free_dofs(dof_handler_.n_dofs());
  // Couplings: each cell with itself, and the two cells beside every vertex (the
  // interior-penalty terms).
  DynamicSparsityPattern dsp(n_free_);
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  std::vector<types::global_dof_index> a(dpc), b(dpc);
  for (unsigned int v = first_joint(); v < n; ++v) {
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
  const double EI = vertex_EI(v);
  for (unsigned int i = 0; i < dpc; ++i) {
    const auto l = kinematics(left, i, nq_ + 1);  // right end of the left cell
    jump[i] = -l.phi;
    mean[i] = 0.5 * EI * l.kappa;
    const auto r = kinematics(v, i, nq_);  // left end of the right cell
    jump[dpc + i] = r.phi;
    mean[dpc + i] = 0.5 * EI * r.kappa;
  }
}

void RingModel::assemble() {
  // Winkler foundation on the polar fields (curved geometry only: check_modes).
  const double kt = spec_.foundation.tangential, kr = spec_.foundation.radial;
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  FullMatrix<double> k_cell(dpc, dpc), m_cell(dpc, dpc);
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<Kinematics> kin(dpc);
  for (unsigned int cell = 0; cell < n; ++cell) {
    k_cell = 0;
    m_cell = 0;
    for (unsigned int q = 0; q < nq_; ++q) {
      const auto [EI, EA, rhoA, rhoI] = section(cell, q);
      for (unsigned int i = 0; i < dpc; ++i) kin[i] = kinematics(cell, i, q);
      for (unsigned int i = 0; i < dpc; ++i)
        for (unsigned int j = 0; j < dpc; ++j) {
          k_cell(i, j) += (EA * kin[i].eps * kin[j].eps + EI * kin[i].kappa * kin[j].kappa +
                           kt * kin[i].d[0] * kin[j].d[0] + kr * kin[i].d[1] * kin[j].d[1]) * ds_[q];
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
  for (unsigned int v = first_joint(); v < n; ++v) {
    vertex_terms(v, jump, mean);
    const double penalty = penalty_ * (vertex_EI_.empty() ? 1.0 : vertex_EI(v) / spec_.EI());
    for (unsigned int i = 0; i < 2 * dpc; ++i)
      for (unsigned int j = 0; j < 2 * dpc; ++j)
        k_vertex(i, j) = mean[i] * jump[j] + mean[j] * jump[i] + penalty * jump[i] * jump[j];
    cells_[(v + n - 1) % n]->get_dof_indices(dofs);
    cells_[v]->get_dof_indices(right);
    std::copy(dofs.begin(), dofs.end(), pair_dofs.begin());
    std::copy(right.begin(), right.end(), pair_dofs.begin() + dpc);
    add_local(k_vertex, pair_dofs, K_);
  }
  assemble_point_terms();
}

void RingModel::apply(const Vector<double>& q, std::vector<Real>& kq, std::vector<Real>& mq) const {
  const Vector<double> full = expand(q);
  const Real kt = spec_.foundation.tangential, kr = spec_.foundation.radial;
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
      const Section local = section(cell, qp);
      const Real EI = local.EI, EA = local.EA, rhoA = local.rhoA, rhoI = local.rhoI;
      for (unsigned int i = 0; i < dpc; ++i) {
        lk[i] += ds * (EA * eps * kin[i].eps + EI * kappa * kin[i].kappa + kt * d0 * kin[i].d[0] +
                       kr * d1 * kin[i].d[1]);
        lm[i] += ds * (rhoA * (d0 * kin[i].d[0] + d1 * kin[i].d[1]) + rhoI * phi * kin[i].phi);
      }
    }
    scatter(dofs, 0, dpc, lk, kq);
    scatter(dofs, 0, dpc, lm, mq);
  }
  std::vector<double> jump(2 * dpc), mean(2 * dpc);
  for (unsigned int v = first_joint(); v < n; ++v) {
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
    const Real penalty = penalty_ * (vertex_EI_.empty() ? 1.0 : vertex_EI(v) / spec_.EI());
    for (unsigned int a = 0; a < 2 * dpc; ++a) lk[a] = mean[a] * J + jump[a] * M + penalty * J * jump[a];
    scatter(dofs, 0, dpc, lk, kq);
    scatter(right, dpc, dpc, lk, kq);
  }
  apply_point_terms(full, kq, mq);
}

ring::ModeShape RingModel::sample(const Vector<double>& full) const {
  if (open_) {
    // An arch: the Cartesian displacement at kArchSamples points per cell, equally spaced
    // from arc.from to arc.to, to ring::sample_arc (its nodes; stations off the arc are 0).
    constexpr unsigned int kArchSamples = 8;
    const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells(), m = n * kArchSamples;
    std::vector<double> ux(m + 1), uy(m + 1);
    std::vector<types::global_dof_index> dofs(dpc);
    for (unsigned int k = 0; k <= m; ++k) {
      const unsigned int cell = std::min(n - 1, k / kArchSamples);
      const double xi = static_cast<double>(k) / kArchSamples - cell;
      cells_[cell]->get_dof_indices(dofs);
      std::array<double, 2> U{0.0, 0.0};
      for (unsigned int i = 0; i < dpc; ++i) U[component_[i]] += full[dofs[i]] * fe_.shape_value(i, Point<1>(xi));
      const double a = theta0_ + (cell + xi) * h_;
      ux[k] = -U[0] * std::sin(a) + U[1] * std::cos(a);
      uy[k] = U[0] * std::cos(a) + U[1] * std::sin(a);
    }
    return ring::sample_arc(*spec_.arc, ux, uy);
  }
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

}  // namespace fem::detail
