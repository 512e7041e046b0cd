// The geometrically exact Timoshenko (Reissner) beam on TimoshenkoModel's mesh and fields:
// strain energy, internal force and consistent tangent, and its rotational springs
// (formulation in nonlinear.hpp, "Timoshenko").
#include "fem_reference/timoshenko_model.hpp"

namespace fem::detail {
namespace {

/// The membrane and shear energy per reference length, EA/2 G1^2 + kGA/2 G2^2, as a
/// function of g = (a_t, a_n, psi) with its gradient and Hessian:
///   G1 = a . d1 - 1 = a_t cos psi - a_n sin psi - 1,  G2 = a . d2 = a_t sin psi + a_n cos psi,
///   dG1 = (c, -s, -G2),  dG2 = (s, c, 1 + G1)  (c = cos psi, s = sin psi),
///   d2G1 = [0 0 -s; 0 0 -c; -s -c -(1 + G1)],  d2G2 = [0 0 c; 0 0 -s; c -s -G2].
struct Density {
  double value = 0.0;
  std::array<double, 3> d{};
  std::array<std::array<double, 3>, 3> dd{};
};

Density membrane_shear(const std::array<double, 3>& g, double EA, double kGA) {
  const double c = std::cos(g[2]), s = std::sin(g[2]);
  const double G1 = g[0] * c - g[1] * s - 1.0, G2 = g[0] * s + g[1] * c;
  const std::array<double, 3> d1{c, -s, -G2}, d2{s, c, 1.0 + G1};
  const double h1[3][3] = {{0.0, 0.0, -s}, {0.0, 0.0, -c}, {-s, -c, -(1.0 + G1)}};
  const double h2[3][3] = {{0.0, 0.0, c}, {0.0, 0.0, -s}, {c, -s, -G2}};
  Density w;
  w.value = 0.5 * (EA * G1 * G1 + kGA * G2 * G2);
  for (int i = 0; i < 3; ++i) {
    w.d[i] = EA * G1 * d1[i] + kGA * G2 * d2[i];
    for (int j = 0; j < 3; ++j) w.dd[i][j] = EA * (d1[i] * d1[j] + G1 * h1[i][j]) + kGA * (d2[i] * d2[j] + G2 * h2[i][j]);
  }
  return w;
}

}  // namespace

std::vector<BendingPoint> TimoshenkoModel::bending_points(const Vector<double>&, const Plasticity&) const {
  throw std::logic_error("fem: the Reissner beam takes no plastic law (check_static refuses ring.plastic with it)");
}

double TimoshenkoModel::beam_energy(const Vector<double>& q, Vector<double>* gradient, SparseMatrix<double>* tangent,
                                    const Plasticity* plastic) const {
  if (plastic)
    throw std::logic_error("fem: the Reissner beam takes no plastic law (check_static refuses ring.plastic with it)");
  const Vector<double> full = expand(q);
  const double EA = setup_.EA, kGA = spec_.kGA(), EI = spec_.EI();
  const unsigned int dpc = fe_.n_dofs_per_cell();
  if (gradient) gradient->reinit(n_free_);
  if (tangent) *tangent = 0.0;
  double energy = 0.0;
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<double> x(dpc), f(dpc);
  std::vector<std::array<double, 3>> b(dpc);
  FullMatrix<double> k_cell(dpc, dpc);
  for (const auto& cell : cells_) {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dpc; ++i) x[i] = full[dofs[i]];
    std::fill(f.begin(), f.end(), 0.0);
    k_cell = 0;
    // Membrane and shear at the p reduced points, in g = (a_t, a_n, psi): rows
    // a_t = 1 + eps, a_n = gamma - psi (the linear model's strains of each shape function).
    for (unsigned int p = 0; p < reduced_.points; ++p) {
      std::array<double, 3> g{1.0, 0.0, 0.0};
      for (unsigned int i = 0; i < dpc; ++i) {
        const Strains& s = reduced_.at[p * dpc + i];
        b[i] = {s.eps, s.gamma - s.psi, s.psi};
        for (int a = 0; a < 3; ++a) g[a] += x[i] * b[i][a];
      }
      const Density w = membrane_shear(g, EA, kGA);
      const double ds = reduced_.ds[p];
      energy += ds * w.value;
      for (unsigned int i = 0; i < dpc; ++i) {
        std::array<double, 3> Hb{};
        for (int a = 0; a < 3; ++a) {
          f[i] += ds * w.d[a] * b[i][a];
          for (int c = 0; c < 3; ++c) Hb[a] += w.dd[a][c] * b[i][c];
        }
        if (tangent)
          for (unsigned int j = 0; j < dpc; ++j) k_cell(j, i) += ds * (b[j][0] * Hb[0] + b[j][1] * Hb[1] + b[j][2] * Hb[2]);
      }
    }
    // Bending EI/2 kappa^2, kappa = psi'/R: linear in the DoFs (p + 1 points, exact).
    for (unsigned int p = 0; p < full_.points; ++p) {
      double kappa = 0.0;
      for (unsigned int i = 0; i < dpc; ++i) kappa += x[i] * full_.at[p * dpc + i].kappa;
      const double ds = full_.ds[p];
      energy += ds * 0.5 * EI * kappa * kappa;
      for (unsigned int i = 0; i < dpc; ++i) {
        const double ki = full_.at[p * dpc + i].kappa;
        f[i] += ds * EI * kappa * ki;
        if (tangent)
          for (unsigned int j = 0; j < dpc; ++j) k_cell(i, j) += ds * EI * ki * full_.at[p * dpc + j].kappa;
      }
    }
    if (gradient)
      for (unsigned int i = 0; i < dpc; ++i)
        for (const auto& [j, w] : expansion_[dofs[i]]) (*gradient)[j] += w * f[i];
    if (tangent) add_local(k_cell, dofs, *tangent);
  }
  return energy;
}

double TimoshenkoModel::rotation_spring(unsigned int v, double kr, const Vector<double>& full,
                                        Vector<double>* gradient, SparseMatrix<double>* tangent) const {
  const types::global_dof_index d = vertex_dofs(v)[2];
  const double psi = full[d];
  if (gradient)
    for (const auto& [j, w] : expansion_[d]) (*gradient)[j] += w * kr * psi;
  if (tangent) {
    FullMatrix<double> k(1, 1);
    k(0, 0) = kr;
    add_local(k, {d}, *tangent);
  }
  return 0.5 * kr * psi * psi;
}

}  // namespace fem::detail
