// The geometrically exact beam's terms and loads (beam_potential.hpp; the formulation is
// in nonlinear.hpp, "Terms and loads"). Every distributed term is a density per undeformed
// length in the local variables y = (x_t, x_n, a_t, a_n): the current position
// x = x_t t0 + x_n n0 = u t0 + (R + w) n0 and the stretch vector a = dx/ds0 = a_t t0 + a_n n0
// of the rest frame at the point. y is linear in the DoFs, so a density's gradient and
// Hessian in y give the term's generalized force and its exact tangent.
#include "fem_reference/beam_potential.hpp"

#include "fem_reference/beam_scalar.hpp"

namespace fem::detail {
namespace {

/// The plates' composite Gauss-Lobatto rule (beam_potential.hpp): pieces per cell, and
/// points per piece (3: Simpson's, exact for the smooth parts' cubics; the kink limits the
/// order anyway). A growing flat contact meets the plates point by point: its force and extent
/// err at first order in the points' spacing (measured: 1.3e-2 and one spacing at 8 pieces,
/// half at 16); more pieces shrink the vertex's weight and so raise the sinking of a point
/// contact. fem_reference/README.md, "Rigid plates", has the measurements.
constexpr unsigned int kPlateSubcells = 8;
constexpr unsigned int kPlateLobatto = 3;

using Y = Vec4;  // (x_t, x_n, a_t, a_n)

void add(Scalar& to, const Scalar& term, double factor = 1.0) {
  to.value += factor * term.value;
  for (int a = 0; a < 4; ++a) {
    to.d[a] += factor * term.d[a];
    for (int b = 0; b < 4; ++b) to.dd[a][b] += factor * term.dd[a][b];
  }
}

/// Foundation (stored energy): k_r/2 w^2 + k_t/2 u^2, w = x_n - R, u = x_t: the
/// displacement along the undeformed point's fixed radial and tangential directions.
Scalar foundation(const Y& y, double k_radial, double k_tangential, double R) {
  Scalar f;
  const double w = y[1] - R;
  f.value = 0.5 * (k_radial * w * w + k_tangential * y[0] * y[0]);
  f.d[0] = k_tangential * y[0];
  f.d[1] = k_radial * w;
  f.dd[0][0] = k_tangential;
  f.dd[1][1] = k_radial;
  return f;
}

/// Follower pressure p (load potential): -p (dA - dA0) with dA = (x cross a)/2 ds0 =
/// (x_n a_t - x_t a_n)/2 ds0 the area swept from the centre (rest: R/2 ds0). Its gradient
/// is the force p (R90 a) ds0 (a turned by +90 deg: the inward normal times |a| on the
/// counter-clockwise ring) after the integration by parts that a closed ring allows
/// (nonlinear.hpp); its Hessian, constant, is the load stiffness.
Scalar follower(const Y& y, double p, double R) {
  Scalar f;
  const double c = -0.5 * p;
  f.value = c * (y[1] * y[2] - y[0] * y[3] - R);
  f.d = {-c * y[3], c * y[2], c * y[1], -c * y[0]};
  f.dd[0][3] = f.dd[3][0] = -c;
  f.dd[1][2] = f.dd[2][1] = c;
  return f;
}

/// Dead pressure p (load potential): p n0 . U = -p w per ds0 (n0 inward, fixed).
Scalar dead(const Y& y, double p, double R) {
  Scalar f;
  f.value = -p * (y[1] - R);
  f.d[1] = -p;
  return f;
}

/// Central pressure p (load potential): -p (|x| - R) per ds0, whose gradient is the force
/// -p x / |x| toward the ring's centre.
Scalar central(const Y& y, double p, double R) {
  Scalar f;
  const double r = std::hypot(y[0], y[1]);
  f.value = -p * (r - R);
  for (int a = 0; a < 2; ++a) {
    f.d[a] = -p * y[a] / r;
    for (int b = 0; b < 2; ++b) f.dd[a][b] = -p * ((a == b) / r - y[a] * y[b] / (r * r * r));
  }
  return f;
}

/// A fixed force per undeformed length (the beam's weight rho A g), components c_t, c_n
/// along t0 and n0 of the point (load potential c . U).
Scalar fixed_force(const Y& y, double c_t, double c_n, double R) {
  Scalar f;
  f.value = c_t * y[0] + c_n * (y[1] - R);
  f.d[0] = c_t;
  f.d[1] = c_n;
  return f;
}

/// The centrifugal body force of the spin (load potential): c/2 (|x|^2 - R^2) per ds0,
/// c = rho A speed^2, x = x_t t0 + x_n n0; its gradient c x is the force outward from the
/// axis, its Hessian c I on (x_t, x_n) the centrifugal softening.
Scalar centrifugal(const Y& y, double c, double R) {
  Scalar f;
  f.value = 0.5 * c * (y[0] * y[0] + y[1] * y[1] - R * R);
  f.d[0] = c * y[0];
  f.d[1] = c * y[1];
  f.dd[0][0] = f.dd[1][1] = c;
  return f;
}

}  // namespace

BeamPotential::BeamPotential(const BeamModel& model, const ring::Loads& loads, bool statics,
                             const ring::StaticOptions::Plates* plates)
    : model_(model), loads_(loads), rhoA_(model.spec_.rhoA()), constant_load_(model.n_free()) {
  const ring::RingSpec& spec = model.spec_;
  if (plates) {
    plates_.emplace(spec, *plates);
    // The pieces' Lobatto points, shared ends merged (xi ascending in [0, 1]); the weights
    // times the cell's rest length, the sum of the Gauss rule's ds0.
    double cell_length = 0.0;
    for (double ds : model.load_rule_.ds) cell_length += ds;
    const QGaussLobatto<1> lobatto(kPlateLobatto);
    for (unsigned int piece = 0; piece < kPlateSubcells; ++piece)
      for (unsigned int j = 0; j < lobatto.size(); ++j) {
        const double xi = (piece + lobatto.point(j)[0]) / kPlateSubcells;
        const double ds = lobatto.weight(j) * cell_length / kPlateSubcells;
        if (j == 0 && piece > 0) {
          plate_rule_.ds.back() += ds;
          continue;
        }
        plate_rule_.xi.push_back(xi);
        plate_rule_.ds.push_back(ds);
      }
    const FESystem<1>& fe = model.fe();
    for (double xi : plate_rule_.xi)
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i) {
        const unsigned int c = fe.system_to_component_index(i).first;
        const double v = fe.shape_value(i, Point<1>(xi));
        plate_rule_.row.push_back({c == 0 ? v : 0.0, c == 1 ? v : 0.0});  // u along t0, w along n0
      }
  }
  for (const ring::PointLoad& p : loads.points)
    constant_load_ += model.vertex_force(model.vertex_of(p.angle), p.force);
  if (loads.has_gravity())
    for (const ring::PointMass& m : spec.masses)
      constant_load_ += model.vertex_force(model.vertex_of(m.angle), {m.mass * loads.gravity[0], m.mass * loads.gravity[1]});
  for (const ring::Spring& k : spec.supports.springs) {
    const unsigned int v = model.vertex_of(k.angle);
    const auto d = model.translation_dofs(v);
    const double a = model.theta0_ + v * model.h_;
    // U = u t0 + w n0: Ux = -u sin a + w cos a, Uy = u cos a + w sin a.
    if (k.kx > 0) translations_.push_back({{d[0], d[1]}, {-std::sin(a), std::cos(a)}, k.kx});
    if (k.ky > 0) translations_.push_back({{d[0], d[1]}, {std::cos(a), std::sin(a)}, k.ky});
    if (k.kr > 0) rotations_.emplace_back(v, k.kr);
  }
  // The spin's centrifugal force on the point masses: speed^2 m (X . U + |U|^2 / 2), the
  // fixed part with the constant loads, the quadratic one on the vertex's Ux and Uy.
  speed_ = spec.rotation.speed;
  if (spec.rotation.spinning())
    for (const ring::PointMass& pm : spec.masses) {
      if (!(pm.mass > 0)) continue;
      const unsigned int v = model.vertex_of(pm.angle);
      const double c = speed_ * speed_ * pm.mass;
      const auto X = model.vertex_position(v);
      constant_load_ += model.vertex_force(v, {c * X[0], c * X[1]});
      const auto d = model.translation_dofs(v);
      const double a = model.theta0_ + v * model.h_;
      spinning_masses_.push_back({{d[0], d[1]}, {-std::sin(a), std::cos(a)}, c});
      spinning_masses_.push_back({{d[0], d[1]}, {std::cos(a), std::sin(a)}, c});
    }
  distributed_ = spec.foundation.any() || loads.pressure.any() || loads.has_gravity() || spec.rotation.spinning();
  if (spec.plastic) {
    law_.emplace(::fem::detail::plastic_law(spec, *spec.plastic));
    law_->elastic_symmetry = statics && spec.plastic->law == ring::Plastic::Law::resultant;
  }
}

BeamPotential::Value BeamPotential::evaluate(const Vector<double>& q, double s, Vector<double>* residual,
                                             SparseMatrix<double>* tangent, Vector<double>* load,
                                             const std::vector<ring::PlasticState>* committed) const {
  const BeamModel& m = model_;
  const ring::RingSpec& spec = m.spec_;
  const double R = spec.radius;
  Value out;
  if (law_ && committed) {
    const Plasticity plastic{*law_, *committed};
    out.stored = m.beam_energy(q, residual, tangent, &plastic);  // residual reinit, tangent zeroed
  } else {
    out.stored = m.beam_energy(q, residual, tangent);
  }
  if (load) load->reinit(m.n_free());
  // Point loads and the point masses' weight: fixed forces, Phi = F . q.
  out.load += constant_load_ * q;
  if (residual) residual->add(-s, constant_load_);
  if (load) *load += constant_load_;

  const Vector<double> full = m.expand(q);
  const unsigned int dpc = m.fe().n_dofs_per_cell(), n = m.cells();
  auto scatter = [&](const std::vector<types::global_dof_index>& dofs, const std::vector<double>& local,
                     Vector<double>& global) {
    for (unsigned int i = 0; i < dofs.size(); ++i)
      for (const auto& [f, w] : m.expansion_[dofs[i]]) global[f] += w * local[i];
  };

  if (distributed_) {
    const ring::Pressure& pressure = loads_.pressure;
    const double p = pressure.value, kr = spec.foundation.radial, kt = spec.foundation.tangential;
    const auto& g = loads_.gravity;
    std::vector<types::global_dof_index> dofs(dpc);
    std::vector<double> x(dpc), fr(dpc), fl(dpc);
    std::vector<Y> dy(dpc);
    FullMatrix<double> k(dpc, dpc);
    for (unsigned int cell = 0; cell < n; ++cell) {
      m.cells_[cell]->get_dof_indices(dofs);
      for (unsigned int i = 0; i < dpc; ++i) x[i] = full[dofs[i]];
      std::fill(fr.begin(), fr.end(), 0.0);
      std::fill(fl.begin(), fl.end(), 0.0);
      k = 0;
      const BeamModel::LoadRule& rule = m.load_rule_;
      for (unsigned int qp = 0; qp < rule.xi.size(); ++qp) {
        Y y{0.0, R, 1.0, 0.0};
        for (unsigned int i = 0; i < dpc; ++i) {
          dy[i] = rule.row[qp * dpc + i];
          for (int a = 0; a < 4; ++a) y[a] += x[i] * dy[i][a];
        }
        Scalar stored, potential;
        if (spec.foundation.any()) add(stored, foundation(y, kr, kt, R));
        if (pressure.any()) {
          switch (pressure.kind) {
            case ring::Pressure::Kind::follower: add(potential, follower(y, p, R)); break;
            case ring::Pressure::Kind::dead: add(potential, dead(y, p, R)); break;
            case ring::Pressure::Kind::central: add(potential, central(y, p, R)); break;
          }
        }
        if (loads_.has_gravity()) {
          const double theta = m.theta0_ + (cell + rule.xi[qp]) * m.h_;
          const double gt = -g[0] * std::sin(theta) + g[1] * std::cos(theta);
          const double gn = g[0] * std::cos(theta) + g[1] * std::sin(theta);
          add(potential, fixed_force(y, rhoA_ * gt, rhoA_ * gn, R));
        }
        if (speed_ != 0.0) add(potential, centrifugal(y, rhoA_ * speed_ * speed_, R));
        const double ds = rule.ds[qp];
        out.stored += ds * stored.value;
        out.load += ds * potential.value;
        Scalar total = stored;
        add(total, potential, -s);
        for (unsigned int i = 0; i < dpc; ++i) {
          Y Hd{};
          for (int a = 0; a < 4; ++a) {
            fr[i] += ds * total.d[a] * dy[i][a];
            fl[i] += ds * potential.d[a] * dy[i][a];
            for (int b = 0; b < 4; ++b) Hd[a] += total.dd[a][b] * dy[i][b];
          }
          if (tangent)
            for (unsigned int j = 0; j < dpc; ++j)
              k(j, i) += ds * (dy[j][0] * Hd[0] + dy[j][1] * Hd[1] + dy[j][2] * Hd[2] + dy[j][3] * Hd[3]);
        }
      }
      if (residual) scatter(dofs, fr, *residual);
      if (load) scatter(dofs, fl, *load);
      if (tangent) m.add_local(k, dofs, *tangent);
    }
  }

  // Translational springs: k/2 (c . x)^2, exact (the ground's directions are fixed).
  for (const Translation& t : translations_) {
    double y = 0.0;
    for (unsigned int i = 0; i < t.dofs.size(); ++i) y += t.coef[i] * full[t.dofs[i]];
    out.stored += 0.5 * t.stiffness * y * y;
    if (residual) {
      std::vector<double> f(t.dofs.size());
      for (unsigned int i = 0; i < f.size(); ++i) f[i] = t.stiffness * y * t.coef[i];
      scatter(t.dofs, f, *residual);
    }
    if (tangent) {
      FullMatrix<double> k(t.dofs.size(), t.dofs.size());
      for (unsigned int i = 0; i < t.dofs.size(); ++i)
        for (unsigned int j = 0; j < t.dofs.size(); ++j) k(i, j) = t.stiffness * t.coef[i] * t.coef[j];
      m.add_local(k, t.dofs, *tangent);
    }
  }

  // The point masses' centrifugal force (load potential): speed^2 m / 2 (c . x)^2 per
  // Cartesian direction c (the fixed part speed^2 m X . U is in constant_load_).
  for (const Translation& t : spinning_masses_) {
    double y = 0.0;
    for (unsigned int i = 0; i < t.dofs.size(); ++i) y += t.coef[i] * full[t.dofs[i]];
    out.load += 0.5 * t.stiffness * y * y;
    std::vector<double> f(t.dofs.size());
    for (unsigned int i = 0; i < f.size(); ++i) f[i] = t.stiffness * y * t.coef[i];
    if (residual) {
      std::vector<double> minus(f.size());
      for (unsigned int i = 0; i < f.size(); ++i) minus[i] = -s * f[i];
      scatter(t.dofs, minus, *residual);
    }
    if (load) scatter(t.dofs, f, *load);
    if (tangent) {
      FullMatrix<double> k(t.dofs.size(), t.dofs.size());
      for (unsigned int i = 0; i < t.dofs.size(); ++i)
        for (unsigned int j = 0; j < t.dofs.size(); ++j) k(i, j) = -s * t.stiffness * t.coef[i] * t.coef[j];
      m.add_local(k, t.dofs, *tangent);
    }
  }

  // Rotational springs: kr/2 theta^2 on the vertex's rotation (the model's, exact).
  for (const auto& [v, kr] : rotations_) out.stored += m.rotation_spring(v, kr, full, residual, tangent);
  if (plates_) add_plates(full, s, out, residual, tangent, load);
  return out;
}

void BeamPotential::add_plates(const Vector<double>& full, double s, Value& out, Vector<double>* residual,
                               SparseMatrix<double>* tangent, Vector<double>* load) const {
  const BeamModel& m = model_;
  const ring::PlatePair& plates = *plates_;
  const double R = m.spec_.radius;
  const unsigned int dpc = m.fe().n_dofs_per_cell();
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<double> x(dpc), fr(dpc), fl(dpc), phi(dpc);
  FullMatrix<double> k(dpc, dpc);
  for (unsigned int cell = 0; cell < m.cells(); ++cell) {
    m.cells_[cell]->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dpc; ++i) x[i] = full[dofs[i]];
    bool touched = false;
    std::fill(fr.begin(), fr.end(), 0.0);
    std::fill(fl.begin(), fl.end(), 0.0);
    k = 0;
    for (unsigned int qp = 0; qp < plate_rule_.xi.size(); ++qp) {
      const std::array<double, 2>* row = &plate_rule_.row[qp * dpc];
      double u = 0.0, w = 0.0;  // x_t = u, x_n = R + w
      for (unsigned int i = 0; i < dpc; ++i) {
        u += x[i] * row[i][0];
        w += x[i] * row[i][1];
      }
      const double theta = m.theta0_ + (cell + plate_rule_.xi[qp]) * m.h_;
      const double c = std::cos(theta), sn = std::sin(theta);
      // PlatePair::gap(p, x, s) = R - s travel / 2 - (+-d_0) . x, written without its
      // cancellation: with delta = theta - axis, d_0 . n0 = cos delta, d_0 . t0 = -sin delta,
      //   g_0 = 2 R sin^2(delta / 2) - w cos delta + u sin delta - s travel / 2,
      //   g_1 = 2 R cos^2(delta / 2) + w cos delta - u sin delta - s travel / 2.
      // R - d_0 . x in doubles keeps only eps R ~ 2e-15 m of a gap whose negative part, the
      // plates' sinking, is ~1e-11 m under a stiff penalty (1e3 x the default on the paper's
      // ring at c = 1e-3 R): the force came in quanta of k ds eps R = 4.5e-4 of itself.
      const double delta = theta - std::atan2(plates.d[1], plates.d[0]);
      const double cd = std::cos(delta), sd = std::sin(delta);
      const double half = 0.5 * s * plates.travel, sh = std::sin(0.5 * delta), ch = std::cos(0.5 * delta);
      const double ds = plate_rule_.ds[qp];
      for (int p = 0; p < 2; ++p) {
        const double g = p == 0 ? 2.0 * R * sh * sh - w * cd + u * sd - half : 2.0 * R * ch * ch + w * cd - u * sd - half;
        if (!plates.in_contact(g)) continue;
        touched = true;
        // e = +-d_0 in (t0, n0): dg/d(x_t, x_n) = -e.
        const double sign = p == 0 ? 1.0 : -1.0;
        const double et = sign * (-plates.d[0] * sn + plates.d[1] * c), en = sign * (plates.d[0] * c + plates.d[1] * sn);
        const double pressure = plates.pressure(g);
        out.stored += ds * plates.energy(g);
        out.plate_forces[p][0] -= ds * pressure * sign * plates.d[0];
        out.plate_forces[p][1] -= ds * pressure * sign * plates.d[1];
        for (unsigned int i = 0; i < dpc; ++i) phi[i] = et * row[i][0] + en * row[i][1];
        for (unsigned int i = 0; i < dpc; ++i) {
          fr[i] += ds * pressure * phi[i];
          fl[i] -= ds * plates.k * 0.5 * plates.travel * phi[i];  // -dR/ds: the gap falls by travel / 2
          if (tangent)
            for (unsigned int j = 0; j < dpc; ++j) k(j, i) += ds * plates.k * phi[j] * phi[i];
        }
      }
    }
    if (!touched) continue;
    auto scatter = [&](const std::vector<double>& local, Vector<double>& global) {
      for (unsigned int i = 0; i < dpc; ++i)
        for (const auto& [f, w] : m.expansion_[dofs[i]]) global[f] += w * local[i];
    };
    if (residual) scatter(fr, *residual);
    if (load) scatter(fl, *load);
    if (tangent) m.add_local(k, dofs, *tangent);
  }
}

void BeamPotential::coriolis(SparseMatrix<double>& G) const {
  const BeamModel& m = model_;
  const ring::RingSpec& spec = m.spec_;
  G = 0;
  if (speed_ == 0.0) return;
  const unsigned int dpc = m.fe().n_dofs_per_cell();
  const BeamModel::LoadRule& rule = m.load_rule_;
  std::vector<types::global_dof_index> dofs(dpc);
  FullMatrix<double> k(dpc, dpc);
  // Every cell is the same image of the reference cell: one local matrix for all.
  for (unsigned int qp = 0; qp < rule.xi.size(); ++qp) {
    const double c = 2.0 * speed_ * rhoA_ * rule.ds[qp];
    for (unsigned int i = 0; i < dpc; ++i) {
      const auto& a = rule.row[qp * dpc + i];
      for (unsigned int j = 0; j < dpc; ++j) {
        const auto& b = rule.row[qp * dpc + j];
        k(i, j) += c * (a[0] * b[1] - a[1] * b[0]);  // u_i w_j - w_i u_j
      }
    }
  }
  for (unsigned int cell = 0; cell < m.cells(); ++cell) {
    m.cells_[cell]->get_dof_indices(dofs);
    m.add_local(k, dofs, G);
  }
  // Point masses: 2 speed m U_i . S U_j = 2 speed m (Uy_i Ux_j - Ux_i Uy_j) on the vertex's
  // (u, w) (at a = 0: Ux = w, Uy = u, the distributed term's u_i w_j - w_i u_j).
  for (const ring::PointMass& pm : spec.masses) {
    if (!(pm.mass > 0)) continue;
    const unsigned int v = m.vertex_of(pm.angle);
    const auto d = m.translation_dofs(v);
    const double a = m.theta0_ + v * m.h_;
    const double cx[2] = {-std::sin(a), std::cos(a)}, cy[2] = {std::cos(a), std::sin(a)};
    FullMatrix<double> g(2, 2);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) g(i, j) = 2.0 * speed_ * pm.mass * (cy[i] * cx[j] - cx[i] * cy[j]);
    m.add_local(g, {d[0], d[1]}, G);
  }
}

}  // namespace fem::detail
