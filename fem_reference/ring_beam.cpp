// The geometrically exact beam on RingModel's mesh: strain energy, internal force and
// consistent tangent (nonlinear.hpp has the formulation), and the vertex helpers the
// nonlinear drivers use.
#include "fem_reference/beam_scalar.hpp"
#include "fem_reference/ring_model.hpp"

namespace fem::detail {
namespace {

/// Energy per reference length at a point: EA/2 (|a| - 1)^2 + EI/2 (phi'/R)^2.
Scalar point_energy(const Vec4& g, double EA, double EI, double R) {
  Scalar w;
  const double lambda = std::hypot(g[0], g[1]);
  w.value = 0.5 * EA * (lambda - 1.0) * (lambda - 1.0);
  for (int i = 0; i < 2; ++i) {
    w.d[i] = EA * (lambda - 1.0) / lambda * g[i];
    for (int j = 0; j < 2; ++j)
      w.dd[i][j] = EA * (g[i] * g[j] / (lambda * lambda * lambda) + (i == j) * (1.0 - 1.0 / lambda));
  }
  const Scalar k = rotation_rate(g);
  const double c = EI / (R * R);
  w.value += 0.5 * c * k.value * k.value;
  for (int i = 0; i < 4; ++i) {
    w.d[i] += c * k.value * k.d[i];
    for (int j = 0; j < 4; ++j) w.dd[i][j] += c * (k.d[i] * k.d[j] + k.value * k.dd[i][j]);
  }
  return w;
}

}  // namespace

std::array<double, 4> RingModel::strain_row(unsigned int i, unsigned int qp) const {
  const unsigned int k = qp * fe_.n_dofs_per_cell() + i;
  const double R = spec_.radius, v = v0_[k] / R, v1 = v1_[k] / R, v2 = v2_[k] / R;
  if (component_[i] == 0) return {v1, -v, v2, -v1};
  return {v, v1, v1, v2};
}

double RingModel::beam_energy(const Vector<double>& q, Vector<double>* gradient,
                              SparseMatrix<double>* tangent) const {
  if (setup_.geometry != Geometry::curved)
    throw std::invalid_argument("fem: the geometrically exact beam needs fem.geometry = \"curved\"");
  const Vector<double> full = expand(q);
  const double EI = spec_.EI(), EA = setup_.EA, R = spec_.radius;
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  if (gradient) gradient->reinit(n_free_);
  if (tangent) *tangent = 0.0;

  auto strain = [&](const std::vector<double>& x, unsigned int qp, std::vector<Vec4>& b) {
    Vec4 g{1.0, 0.0, 0.0, 0.0};
    for (unsigned int i = 0; i < dpc; ++i) {
      b[i] = strain_row(i, qp);
      for (int a = 0; a < 4; ++a) g[a] += x[i] * b[i][a];
    }
    return g;
  };
  auto scatter = [&](const std::vector<types::global_dof_index>& dofs, const std::vector<double>& local) {
    for (unsigned int i = 0; i < dofs.size(); ++i)
      for (const auto& [f, w] : expansion_[dofs[i]]) (*gradient)[f] += w * local[i];
  };

  double energy = 0.0;
  std::vector<types::global_dof_index> dofs(dpc), right(dpc), pair(2 * dpc);
  std::vector<double> x(dpc), xr(dpc), f(2 * dpc);
  std::vector<Vec4> b(dpc), br(dpc);
  FullMatrix<double> k_cell(dpc, dpc), k_vertex(2 * dpc, 2 * dpc);
  for (unsigned int cell = 0; cell < n; ++cell) {
    cells_[cell]->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dpc; ++i) x[i] = full[dofs[i]];
    std::fill(f.begin(), f.end(), 0.0);
    k_cell = 0;
    for (unsigned int qp = 0; qp < nq_; ++qp) {
      const Scalar w = point_energy(strain(x, qp, b), EA, EI, R);
      energy += ds_[qp] * w.value;
      for (unsigned int i = 0; i < dpc; ++i) {
        Vec4 Hb{};
        for (int a = 0; a < 4; ++a) {
          f[i] += ds_[qp] * w.d[a] * b[i][a];
          for (int c = 0; c < 4; ++c) Hb[a] += w.dd[a][c] * b[i][c];
        }
        if (tangent)
          for (unsigned int j = 0; j < dpc; ++j)
            k_cell(j, i) += ds_[qp] * (b[j][0] * Hb[0] + b[j][1] * Hb[1] + b[j][2] * Hb[2] + b[j][3] * Hb[3]);
      }
    }
    if (gradient) scatter(dofs, {f.begin(), f.begin() + dpc});
    if (tangent) add_local(k_cell, dofs, *tangent);
  }

  // Interior penalty at every vertex on the exact rotation jump J = phi_R - phi_L (the
  // angle from the left cell's tangent to the right one's, never wrapped: both are
  // measured from the same t0) and the mean moment {M} = EI (phi'_L + phi'_R) / (2 R):
  // E_v = {M} J + penalty / 2 J^2.
  for (unsigned int v = 0; v < n; ++v) {
    const unsigned int left = (v + n - 1) % n;
    cells_[left]->get_dof_indices(dofs);
    cells_[v]->get_dof_indices(right);
    for (unsigned int i = 0; i < dpc; ++i) {
      x[i] = full[dofs[i]];
      xr[i] = full[right[i]];
    }
    const Vec4 gl = strain(x, nq_ + 1, b), gr = strain(xr, nq_, br);
    const Scalar pl = tangent_angle(gl), pr = tangent_angle(gr);
    const Scalar kl = rotation_rate(gl), kr = rotation_rate(gr);
    const double J = std::remainder(pr.value - pl.value, 2.0 * kPi);
    const double m = EI / (2.0 * R);
    const double M = m * (kl.value + kr.value), P = penalty_;
    energy += M * J + 0.5 * P * J * J;
    // Derivatives in the 8 local strain variables (left g | right g), then to the DoFs.
    std::array<double, 8> dJ{}, dM{};
    std::array<std::array<double, 8>, 8> H{};
    for (int a = 0; a < 4; ++a) {
      dJ[a] = -pl.d[a];
      dJ[4 + a] = pr.d[a];
      dM[a] = m * kl.d[a];
      dM[4 + a] = m * kr.d[a];
    }
    const double s = M + P * J;
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 8; ++c) H[a][c] = dM[a] * dJ[c] + dJ[a] * dM[c] + P * dJ[a] * dJ[c];
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) {
        H[a][c] += J * m * kl.dd[a][c] - s * pl.dd[a][c];
        H[4 + a][4 + c] += J * m * kr.dd[a][c] + s * pr.dd[a][c];
      }
    std::array<double, 8> dE{};
    for (int a = 0; a < 8; ++a) dE[a] = J * dM[a] + s * dJ[a];
    auto local_b = [&](unsigned int i) -> const Vec4& { return i < dpc ? b[i] : br[i - dpc]; };
    for (unsigned int i = 0; i < 2 * dpc; ++i) {
      const Vec4& bi = local_b(i);
      const unsigned int off_i = i < dpc ? 0 : 4;
      f[i] = 0.0;
      for (int a = 0; a < 4; ++a) f[i] += dE[off_i + a] * bi[a];
      if (!tangent) continue;
      for (unsigned int j = 0; j < 2 * dpc; ++j) {
        const Vec4& bj = local_b(j);
        const unsigned int off_j = j < dpc ? 0 : 4;
        double sum = 0.0;
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 4; ++c) sum += bi[a] * H[off_i + a][off_j + c] * bj[c];
        k_vertex(i, j) = sum;
      }
    }
    std::copy(dofs.begin(), dofs.end(), pair.begin());
    std::copy(right.begin(), right.end(), pair.begin() + dpc);
    if (gradient) scatter(pair, f);
    if (tangent) add_local(k_vertex, pair, *tangent);
  }
  return energy;
}

unsigned int RingModel::vertex_of(double degrees) const {
  const double pin = spec_.supports.pin.value_or(0.0);
  const unsigned int n = setup_.cells();
  return static_cast<unsigned int>(std::lround(ring::wrap_degrees(degrees - pin) * n / 360.0)) % n;
}

std::array<double, 2> RingModel::vertex_position(unsigned int k) const {
  const double a = theta0_ + k * h_;
  return {spec_.radius * std::cos(a), spec_.radius * std::sin(a)};
}

Vector<double> RingModel::vertex_force(unsigned int k, const std::array<double, 2>& f) const {
  // U = u t0 + w n0 at the vertex: the force's work is u (f . t0) + w (f . n0).
  const double a = theta0_ + k * h_;
  const std::array<double, 2> coef{-f[0] * std::sin(a) + f[1] * std::cos(a), f[0] * std::cos(a) + f[1] * std::sin(a)};
  const auto dofs = end_dofs(k, 0.0);
  Vector<double> out(n_free_);
  for (unsigned int c = 0; c < 2; ++c)
    for (const auto& [j, w] : expansion_[dofs[c]]) out[j] += w * coef[c];
  return out;
}

std::array<double, 2> RingModel::vertex_displacement(const Vector<double>& full, unsigned int k) const {
  const double a = theta0_ + k * h_;
  const auto dofs = end_dofs(k, 0.0);
  const double u = full[dofs[0]], w = full[dofs[1]];
  return {-u * std::sin(a) + w * std::cos(a), u * std::cos(a) + w * std::sin(a)};
}

std::vector<std::array<double, 2>> RingModel::centreline(const Vector<double>& full, unsigned int per_cell) const {
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  // Shape values at the points of the reference cell (all cells are affine images of it).
  std::vector<double> table(per_cell * dpc);
  for (unsigned int k = 0; k < per_cell; ++k)
    for (unsigned int i = 0; i < dpc; ++i)
      table[k * dpc + i] = fe_.shape_value(i, Point<1>(static_cast<double>(k) / per_cell));
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<std::array<double, 2>> out;
  out.reserve(n * per_cell);
  for (unsigned int cell = 0; cell < n; ++cell) {
    cells_[cell]->get_dof_indices(dofs);
    for (unsigned int k = 0; k < per_cell; ++k) {
      double U[2] = {0.0, 0.0};  // (u, w): tangential, radial
      for (unsigned int i = 0; i < dpc; ++i) U[component_[i]] += full[dofs[i]] * table[k * dpc + i];
      const double a = theta0_ + (cell + static_cast<double>(k) / per_cell) * h_;
      const double r = spec_.radius + U[1];
      out.push_back({r * std::cos(a) - U[0] * std::sin(a), r * std::sin(a) + U[0] * std::cos(a)});
    }
  }
  return out;
}

}  // namespace fem::detail
