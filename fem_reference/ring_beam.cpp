// The geometrically exact beam on RingModel's mesh: strain energy, internal force and
// consistent tangent (nonlinear.hpp has the formulation), its rotational springs, and the
// vertex helpers of either beam (BeamModel) that the nonlinear drivers use.
#include <optional>

#include "fem_reference/beam_scalar.hpp"
#include "fem_reference/ring_model.hpp"

namespace fem::detail {
namespace {

/// Energy per reference length at a point: EA/2 (|a| - 1)^2 + EI/2 (phi'/R)^2; without
/// `bending` (ring.plastic: the bending has points of its own) the first term only.
Scalar point_energy(const Vec4& g, double EA, double EI, double R, bool bending = true) {
  Scalar w;
  const double lambda = std::hypot(g[0], g[1]);
  w.value = 0.5 * EA * (lambda - 1.0) * (lambda - 1.0);
  for (int i = 0; i < 2; ++i) {
    w.d[i] = EA * (lambda - 1.0) / lambda * g[i];
    for (int j = 0; j < 2; ++j)
      w.dd[i][j] = EA * (g[i] * g[j] / (lambda * lambda * lambda) + (i == j) * (1.0 - 1.0 / lambda));
  }
  if (!bending) return w;
  const Scalar k = rotation_rate(g);
  const double c = EI / (R * R);
  w.value += 0.5 * c * k.value * k.value;
  for (int i = 0; i < 4; ++i) {
    w.d[i] += c * k.value * k.d[i];
    for (int j = 0; j < 4; ++j) w.dd[i][j] += c * (k.d[i] * k.d[j] + k.value * k.dd[i][j]);
  }
  return w;
}

/// ring.plastic: the bending density at a bending point, the section law's incremental
/// potential W(kappa) from the committed states `from` (section.states() of them),
/// kappa = phi'/R: gradient M dkappa, Hessian dM/dkappa dkappa dkappa^T + M d2kappa.
Scalar plastic_bending(const Vec4& g, double R, const ring::SectionLaw& section, const ring::PlasticState* from) {
  const Scalar k = rotation_rate(g);
  const ring::BilinearLaw::Point p = section.at(from, k.value / R);
  const double m = p.force / R, t = p.tangent / (R * R);
  Scalar w;
  w.value = p.potential;
  for (int i = 0; i < 4; ++i) {
    w.d[i] = m * k.d[i];
    for (int j = 0; j < 4; ++j) w.dd[i][j] = t * k.d[i] * k.d[j] + m * k.dd[i][j];
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

std::size_t RingModel::bending_point_count() const { return setup_.cells() * bend_rows_.size(); }

std::vector<BendingPoint> RingModel::bending_points(const Vector<double>& q, const Plasticity& plastic) const {
  const Vector<double> full = expand(q);
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells(), per_cell = bend_rows_.size();
  const double R = spec_.radius;
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<Vec4> g(n * per_cell, Vec4{1.0, 0.0, 0.0, 0.0});  // (a, b) at every bending point
  std::vector<BendingPoint> out;
  out.reserve(bending_point_count() + n);
  for (unsigned int cell = 0; cell < n; ++cell) {
    cells_[cell]->get_dof_indices(dofs);
    for (unsigned int j = 0; j < per_cell; ++j) {
      Vec4& at = g[cell * per_cell + j];
      for (unsigned int i = 0; i < dpc; ++i) {
        const Vec4 b = strain_row(i, bend_rows_[j]);
        for (int a = 0; a < 4; ++a) at[a] += full[dofs[i]] * b[a];
      }
      out.push_back({rotation_rate(at).value / R, bend_ds_[j], 1.0, std::nullopt});
    }
  }
  // The vertex hinges (beam_energy): e = J + {M} / P, {M} from the ends' committed states.
  const double P = penalty_;
  const ring::BilinearLaw hinge = plastic.law.hinge(P);
  const ring::SectionLaw& section = plastic.law.section;
  for (unsigned int v = first_joint(); v < n; ++v) {
    const unsigned int l = ((v + n - 1) % n) * per_cell + per_cell - 1, r = v * per_cell;
    const double J = std::remainder(tangent_angle(g[r]).value - tangent_angle(g[l]).value, 2.0 * kPi);
    const double M = 0.5 * (section.at(plastic.point(l), out[l].curvature).force +
                            section.at(plastic.point(r), out[r].curvature).force);
    out.push_back({J + M / P, 1.0, 1.0 / (R * h_), hinge});
  }
  return out;
}

double RingModel::beam_energy(const Vector<double>& q, Vector<double>* gradient, SparseMatrix<double>* tangent,
                              const Plasticity* plastic) const {
  if (setup_.geometry != Geometry::curved)
    throw std::invalid_argument("fem: the geometrically exact beam needs fem.geometry = \"curved\"");
  const Vector<double> full = expand(q);
  const double EI = spec_.EI(), EA = setup_.EA, R = spec_.radius;
  const unsigned int dpc = fe_.n_dofs_per_cell(), n = setup_.cells();
  if (gradient) gradient->reinit(n_free_);
  if (tangent) *tangent = 0.0;
  const unsigned int per_cell = bend_rows_.size();  // bending points per cell (plastic_points.hpp)
  if (plastic && plastic->committed.size() != plastic->law.states(bending_point_count(), n))
    throw std::logic_error("fem: " + std::to_string(plastic->committed.size()) + " plastic states for " +
                           std::to_string(plastic->law.states(bending_point_count(), n)) + " of the bending points");
  // The vertex hinges' states follow the bending points' (plastic_points.hpp).
  const std::size_t hinge_base = plastic ? plastic->law.states(bending_point_count(), 0) : 0;
  // The vertices' hinge law (used with `plastic` only): the interior penalty's stiffness, Mp.
  const std::optional<ring::BilinearLaw> hinge =
      plastic ? std::optional<ring::BilinearLaw>(plastic->law.hinge(penalty_)) : std::nullopt;

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
    // A density w at a point of weight ds whose rows are b: its energy, force and tangent.
    auto add_point = [&](const Scalar& w, double ds) {
      energy += ds * w.value;
      for (unsigned int i = 0; i < dpc; ++i) {
        Vec4 Hb{};
        for (int a = 0; a < 4; ++a) {
          f[i] += ds * w.d[a] * b[i][a];
          for (int c = 0; c < 4; ++c) Hb[a] += w.dd[a][c] * b[i][c];
        }
        if (tangent)
          for (unsigned int j = 0; j < dpc; ++j)
            k_cell(j, i) += ds * (b[j][0] * Hb[0] + b[j][1] * Hb[1] + b[j][2] * Hb[2] + b[j][3] * Hb[3]);
      }
    };
    for (unsigned int qp = 0; qp < nq_; ++qp) add_point(point_energy(strain(x, qp, b), EA, EI, R, !plastic), ds_[qp]);
    if (plastic)
      for (unsigned int j = 0; j < per_cell; ++j)
        add_point(plastic_bending(strain(x, bend_rows_[j], b), R, plastic->law.section, plastic->point(cell * per_cell + j)),
                  bend_ds_[j]);
    if (gradient) scatter(dofs, {f.begin(), f.begin() + dpc});
    if (tangent) add_local(k_cell, dofs, *tangent);
  }

  // Interior penalty at every vertex on the exact rotation jump J = phi_R - phi_L (the
  // angle from the left cell's tangent to the right one's, never wrapped: both are
  // measured from the same t0) and the mean moment {M} = EI (phi'_L + phi'_R) / (2 R):
  // E_v = {M} J + penalty / 2 J^2. (An arch's end vertices are no joints.)
  for (unsigned int v = first_joint(); v < n; ++v) {
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
    // {M} = (M_L + M_R) / 2 and its derivative mL dk_L + mR dk_R (k = phi', kappa = k / R):
    // elastic M = EI kappa; ring.plastic: the law at the two cells' end bending points
    // (plastic_points.hpp), whose tangent jumps are not in the Hessian (they meet J = 0).
    const double m = EI / (2.0 * R);
    double M = m * (kl.value + kr.value), mL = m, mR = m;
    if (plastic) {
      const ring::SectionLaw& section = plastic->law.section;
      const ring::BilinearLaw::Point l = section.at(plastic->point(left * per_cell + per_cell - 1), kl.value / R);
      const ring::BilinearLaw::Point r = section.at(plastic->point(v * per_cell), kr.value / R);
      M = 0.5 * (l.force + r.force);
      mL = 0.5 * l.tangent / R;
      mR = 0.5 * r.tangent / R;
    }
    const double P = penalty_;
    // Derivatives in the 8 local strain variables (left g | right g), then to the DoFs.
    std::array<double, 8> dJ{}, dM{};
    std::array<std::array<double, 8>, 8> H{};
    for (int a = 0; a < 4; ++a) {
      dJ[a] = -pl.d[a];
      dJ[4 + a] = pr.d[a];
      dM[a] = mL * kl.d[a];
      dM[4 + a] = mR * kr.d[a];
    }
    std::array<double, 8> dE{};
    if (plastic) {
      // E_v = {M} J + P/2 J^2 = P/2 e^2 - {M}^2 / (2 P) with e = J + {M} / P, and P e =
      // {M} + P J the moment the vertex passes on: the vertex is a hinge of stiffness P whose
      // moment the law caps (plastic_points.hpp), E_v = W_P(e) - {M}^2 / (2 P), W_P the
      // incremental potential of the law with stiffness P from the hinge's committed state.
      // With F = W_P'(e): dE_v = F dJ + j dM, j = (F - {M}) / P (J while the hinge is
      // elastic). That gradient is not continuous: dM = mL dk_L + mR dk_R carries the ends'
      // tangents, which drop from EI to 0 (perfectly plastic) as an end yields, so the force
      // jumps by j EI / 2 dk wherever an end yields under a vertex whose moment F is not the
      // ends' {M}. A committed end sits on its yield edge, so every equilibrium past it is on
      // that jump: Newton from it met a residual of O(j EI / h) whatever the step (the cubic
      // pinched ring past collapse: |r| = 4.97 for steps down to 1e-11 of the drive, stalled;
      // fem_driven_test, TheCubicBeamPassesCollapse). So the symmetry term j dM takes the
      // elastic moment's variation dMe = EI/(2R) (dk_L + dk_R), as nonsymmetric interior
      // penalty methods for plasticity take the elastic operator in their adjoint term: the
      // force F dJ + j dMe is continuous (F and {M} are), still the elastic beam's exactly
      // while no end yields, and consistent (j = 0 for the smooth solution); the moments it
      // passes, F at the vertex and the law's at the points, are those of the potential. Its
      // tangent, nonsymmetric where an end yields (the bordered matrix is factored by LU; the
      // inertia reads the symmetric part):
      // d(F dJ + j dMe) = T ge g^T - dMe dM^T / P + F d2J + j d2Me, g = dJ + dM / P,
      // ge = dJ + dMe / P (elastic: the Hessian of E_v). `energy` keeps E_v: the beam's stored
      // energy, with which the rig's work balances to the measured bounds (fem_driven_test).
      const ring::BilinearLaw::Point h = hinge->at(plastic->committed[hinge_base + v], J + M / P);
      energy += h.potential - 0.5 * M * M / P;
      // Only where PlasticLaw::elastic_symmetry says (the statics, resultant law): the fibre
      // law's tangent falls fibre by fibre (64 small jumps of the force, which Newton passes;
      // the elastic variation changed FemFibre's measured orders), and the response's energy
      // identity (fem_plastic_response_test) and the kernel's check that the force is the
      // potential's gradient (fem_plastic_kernel_test) need the potential's.
      const bool elastic_symmetry = plastic->law.elastic_symmetry;
      const double me = elastic_symmetry ? m : 0.0;  // dMe's coefficient, or the law's below
      std::array<double, 8> g{}, ge{}, dMe{};
      for (int a = 0; a < 4; ++a) {
        dMe[a] = elastic_symmetry ? me * kl.d[a] : dM[a];
        dMe[4 + a] = elastic_symmetry ? me * kr.d[a] : dM[4 + a];
      }
      for (int a = 0; a < 8; ++a) {
        g[a] = dJ[a] + dM[a] / P;
        ge[a] = dJ[a] + dMe[a] / P;
      }
      const double j = (h.force - M) / P;  // J when elastic
      for (int a = 0; a < 8; ++a) {
        dE[a] = h.force * dJ[a] + j * dMe[a];
        for (int c = 0; c < 8; ++c) H[a][c] = h.tangent * ge[a] * g[c] - dMe[a] * dM[c] / P;
      }
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c) {
          H[a][c] += j * (elastic_symmetry ? me : mL) * kl.dd[a][c] - h.force * pl.dd[a][c];
          H[4 + a][4 + c] += j * (elastic_symmetry ? me : mR) * kr.dd[a][c] + h.force * pr.dd[a][c];
        }
    } else {
      energy += M * J + 0.5 * P * J * J;
      const double s = M + P * J;
      for (int a = 0; a < 8; ++a)
        for (int c = 0; c < 8; ++c) H[a][c] = dM[a] * dJ[c] + dJ[a] * dM[c] + P * dJ[a] * dJ[c];
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 4; ++c) {
          H[a][c] += J * mL * kl.dd[a][c] - s * pl.dd[a][c];
          H[4 + a][4 + c] += J * mR * kr.dd[a][c] + s * pr.dd[a][c];
        }
      for (int a = 0; a < 8; ++a) dE[a] = J * dM[a] + s * dJ[a];
    }
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

double RingModel::rotation_spring(unsigned int v, double kr, const Vector<double>& full, Vector<double>* gradient,
                                  SparseMatrix<double>* tangent) const {
  // kr/2 {phi}^2 with {phi} = (phi_left + phi_right)/2 the mean of the two cells' exact
  // tangent angles at the vertex (measured from t0, the right one as the left one plus the
  // jump [[phi]] reduced to (-pi, pi], as the beam's vertex terms). At an arch's end the
  // one cell's angle, written as both sides (so the mean is that angle).
  const unsigned int dpc = fe_.n_dofs_per_cell();
  const auto sides = cells_at(v);
  const auto& [left_cell, left_end] = sides.front();
  const auto& [right_cell, right_end] = sides.back();
  std::vector<types::global_dof_index> dofs(2 * dpc), side(dpc);
  cells_[left_cell]->get_dof_indices(side);
  std::copy(side.begin(), side.end(), dofs.begin());
  cells_[right_cell]->get_dof_indices(side);
  std::copy(side.begin(), side.end(), dofs.begin() + dpc);
  std::vector<Vec4> b(2 * dpc);
  Vec4 gl{1.0, 0.0, 0.0, 0.0}, gr{1.0, 0.0, 0.0, 0.0};
  for (unsigned int i = 0; i < dpc; ++i) {
    b[i] = strain_row(i, left_end == 0.0 ? nq_ : nq_ + 1);         // right end of the left cell
    b[dpc + i] = strain_row(i, right_end == 0.0 ? nq_ : nq_ + 1);  // left end of the right cell
    for (int a = 0; a < 4; ++a) {
      gl[a] += full[dofs[i]] * b[i][a];
      gr[a] += full[dofs[dpc + i]] * b[dpc + i][a];
    }
  }
  const Scalar pl = tangent_angle(gl), pr = tangent_angle(gr);
  const double mean = pl.value + 0.5 * std::remainder(pr.value - pl.value, 2.0 * kPi);
  // d mean / d g (left | right) = (pl.d | pr.d) / 2; the Hessian is block-diagonal.
  std::vector<double> f(2 * dpc), dm(2 * dpc);
  for (unsigned int i = 0; i < 2 * dpc; ++i) {
    const Scalar& side_angle = i < dpc ? pl : pr;
    for (int a = 0; a < 4; ++a) dm[i] += 0.5 * side_angle.d[a] * b[i][a];
    f[i] = kr * mean * dm[i];
  }
  if (gradient)
    for (unsigned int i = 0; i < 2 * dpc; ++i)
      for (const auto& [j, w] : expansion_[dofs[i]]) (*gradient)[j] += w * f[i];
  if (tangent) {
    FullMatrix<double> k(2 * dpc, 2 * dpc);
    for (unsigned int i = 0; i < 2 * dpc; ++i)
      for (unsigned int j = 0; j < 2 * dpc; ++j) {
        double h = 0.0;
        if ((i < dpc) == (j < dpc)) {
          const Scalar& side_angle = i < dpc ? pl : pr;
          for (int a = 0; a < 4; ++a)
            for (int c = 0; c < 4; ++c) h += 0.5 * b[i][a] * side_angle.dd[a][c] * b[j][c];
        }
        k(i, j) = kr * (dm[i] * dm[j] + mean * h);
      }
    add_local(k, dofs, *tangent);
  }
  return 0.5 * kr * mean * mean;
}

// ---- BeamModel: the vertices and the centreline, either model ----

BeamModel::BeamModel(const ring::RingSpec& spec, const Setup& setup)
    : LinearModel(spec, setup),
      open_(spec.is_arch()),
      theta0_(spec.anchor() * kPi / 180.0),
      h_(spec.opening() / setup.cells()) {}

void BeamModel::measure_lengths() {
  lengths_.assign(n_free_, 1.0);
  const FESystem<1>& fe = this->fe();
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto& cell : cells_) {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (fe.system_to_component_index(i).first == 2 && free_[dofs[i]] >= 0) lengths_[free_[dofs[i]]] = spec_.radius;
  }
}

unsigned int BeamModel::vertex_of(double degrees) const {
  const double pin = spec_.anchor();
  const unsigned int n = setup_.cells();
  if (open_) {
    const int k = ring::node_index(spec_, degrees, static_cast<int>(n));
    if (k < 0) throw std::logic_error("fem: " + std::to_string(degrees) + " deg is no vertex of the arch");
    return static_cast<unsigned int>(k);
  }
  return static_cast<unsigned int>(std::lround(ring::wrap_degrees(degrees - pin) * n / 360.0)) % n;
}

std::array<double, 2> BeamModel::vertex_position(unsigned int k) const {
  const double a = theta0_ + k * h_;
  return {spec_.radius * std::cos(a), spec_.radius * std::sin(a)};
}

Vector<double> BeamModel::vertex_force(unsigned int k, const std::array<double, 2>& f) const {
  // U = u t0 + w n0 at the vertex: the force's work is u (f . t0) + w (f . n0).
  const double a = theta0_ + k * h_;
  const std::array<double, 2> coef{-f[0] * std::sin(a) + f[1] * std::cos(a), f[0] * std::cos(a) + f[1] * std::sin(a)};
  const auto dofs = translation_dofs(k);
  Vector<double> out(n_free_);
  for (unsigned int c = 0; c < 2; ++c)
    for (const auto& [j, w] : expansion_[dofs[c]]) out[j] += w * coef[c];
  return out;
}

std::array<double, 2> BeamModel::vertex_displacement(const Vector<double>& full, unsigned int k) const {
  const double a = theta0_ + k * h_;
  const auto dofs = translation_dofs(k);
  const double u = full[dofs[0]], w = full[dofs[1]];
  return {-u * std::sin(a) + w * std::cos(a), u * std::cos(a) + w * std::sin(a)};
}

std::vector<std::array<double, 2>> BeamModel::centreline(const Vector<double>& full, unsigned int per_cell) const {
  const FESystem<1>& fe = this->fe();
  const unsigned int dpc = fe.n_dofs_per_cell(), n = setup_.cells();
  // Shape values at the points of the reference cell (all cells are affine images of it).
  std::vector<double> table(per_cell * dpc);
  std::vector<unsigned int> component(dpc);
  for (unsigned int i = 0; i < dpc; ++i) component[i] = fe.system_to_component_index(i).first;
  for (unsigned int k = 0; k < per_cell; ++k)
    for (unsigned int i = 0; i < dpc; ++i)
      table[k * dpc + i] = fe.shape_value(i, Point<1>(static_cast<double>(k) / per_cell));
  std::vector<types::global_dof_index> dofs(dpc);
  std::vector<std::array<double, 2>> out;
  out.reserve(n * per_cell);
  for (unsigned int cell = 0; cell < n; ++cell) {
    cells_[cell]->get_dof_indices(dofs);
    for (unsigned int k = 0; k < per_cell; ++k) {
      double U[2] = {0.0, 0.0};  // (u, w): tangential, radial (a rotation field is not position)
      for (unsigned int i = 0; i < dpc; ++i)
        if (component[i] < 2) U[component[i]] += full[dofs[i]] * table[k * dpc + i];
      const double a = theta0_ + (cell + static_cast<double>(k) / per_cell) * h_;
      const double r = spec_.radius + U[1];
      out.push_back({r * std::cos(a) - U[0] * std::sin(a), r * std::sin(a) + U[0] * std::cos(a)});
    }
  }
  if (open_) {  // an arch: its `to` end closes the open curve
    const auto X = vertex_position(n);
    const auto u = vertex_displacement(full, n);
    out.push_back({X[0] + u[0], X[1] + u[1]});
  }
  return out;
}

}  // namespace fem::detail
