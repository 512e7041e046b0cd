// The geometrically exact FE beam's loads and terms (fem_reference/nonlinear.hpp, "Terms
// and loads") against oracles outside the code: finite differences of its own potential
// (the tangent with the load stiffness), the exact shrunk circle under uniform pressure,
// the axisymmetric ring on a foundation, global equilibrium (spring reactions = weight),
// the inextensible ring's static response by Fourier series (hung ring, clamped ring
// under a sideways weight), and the breathing oscillation under a suddenly applied
// pressure (one linear ODE, integrated exactly by Newmark's rule).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>

#include "fem_reference/beam_potential.hpp"
#include "fem_reference/checks.hpp"
#include "fem_reference/nonlinear.hpp"
#include "ring/errors.hpp"
#include "support/paper.hpp"
#include "tests/support/close.hpp"
#include "tests/support/convergence.hpp"

namespace {

using namespace dealii;
constexpr double kPi = 3.14159265358979323846;

/// A thick ring (R = 1 m, solid circle d = 0.3 m, steel): strains of 1e-3..1e-2 under
/// pressures below the critical ~3 EI/R^3, so that the follower, dead and central closed
/// forms differ by far more than the tolerances.
ring::RingSpec thick_ring() {
  ring::RingSpec s = ringtest::free_ring();
  s.radius = 1.0;
  s.section.diameter = 0.3;
  return s;
}

fem::detail::Setup setup_of(const ring::RingSpec& spec, int elements, int degree) {
  fem::detail::Setup s;
  s.elements = elements;
  s.degree = degree;
  s.EA = spec.EA();
  return s;
}

/// A measured value for the test's record.
std::string sci(double x) {
  std::ostringstream o;
  o.precision(3);
  o << std::scientific << x;
  return o.str();
}

double angle_of(const ring::RingSpec& spec, int k, int cells) {
  return spec.supports.pin.value_or(0.0) + 360.0 * k / cells;
}

// ---- The tangent: central differences of the potential and of the force ----------------

// Oracle: central finite differences (step 1e-6 m on a 1 m ring, displacements of 0.1 m:
// truncation ~ h^2 ~ 1e-12 relative, round-off ~ eps / h ~ 1e-10 of the largest entry;
// the bound 1e-6 leaves a factor >= 1e4). Three separate checks, because the beam's
// membrane stiffness EA/R^2 is ~100 times the terms' and the loads' stiffness and would
// hide their errors in one relative check: the load stiffness alone (-hess Phi against
// differences of grad Phi), the terms alone (springs, foundation) and the whole tangent.
class FemLoadsKernel : public ::testing::TestWithParam<ring::Pressure::Kind> {};

TEST_P(FemLoadsKernel, TangentIsTheDerivativeOfTheForceWithEveryTermAndLoad) {
  ring::RingSpec spec = thick_ring();
  const double EI = spec.EI(), R = spec.radius;
  spec.supports.pin = 0.0;
  spec.supports.pins = {180.0};
  spec.supports.clamp = 180.0;
  spec.supports.springs = {{90.0, 0.3 * EI, 0.7 * EI, 2.0 * EI}, {270.0, 0.5 * EI, 0.0, 1.5 * EI}};
  spec.masses = {{45.0, 500.0, 20.0}};
  spec.foundation = {0.8 * EI, 0.4 * EI};
  ring::Loads loads;
  loads.points = {{90.0, {0.3 * EI, -0.2 * EI}}, {225.0, {0.1 * EI, 0.4 * EI}}};
  loads.pressure = {1.5 * EI / (R * R * R), GetParam()};
  loads.gravity = {3e3, -1e4};  // m/s^2: a weight comparable to the other loads
  const fem::detail::RingModel model(spec, setup_of(spec, 8, 3));
  const fem::detail::BeamPotential potential(model, loads);
  const unsigned int N = model.n_free();
  Vector<double> q(N);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (unsigned int i = 0; i < N; ++i) q[i] = u(rng);
  const double s = 1.3;

  auto matrix = [&](double factor, Vector<double>* r, Vector<double>* F) {
    SparseMatrix<double> K(model.sparsity());
    potential.evaluate(q, factor, r, &K, F);
    return K;
  };
  Vector<double> r, F, r0, beam_grad;
  SparseMatrix<double> K = matrix(s, &r, &F), K0 = matrix(0.0, &r0, nullptr);
  SparseMatrix<double> Kbeam(model.sparsity());
  model.beam_energy(q, &beam_grad, &Kbeam);
  const double h = 1e-6;
  double e_total = 0, s_total = 0, e_load = 0, s_load = 0, e_terms = 0, s_terms = 0, e_grad = 0, e_F = 0;
  for (unsigned int j = 0; j < N; ++j) {
    Vector<double> qp = q, qm = q, rp, rm, Fp, Fm, bp, bm;
    qp[j] += h;
    qm[j] -= h;
    const auto vp = potential.evaluate(qp, s, &rp, nullptr, &Fp), vm = potential.evaluate(qm, s, &rm, nullptr, &Fm);
    e_grad = std::max(e_grad, std::abs((vp.stored - s * vp.load - vm.stored + s * vm.load) / (2 * h) - r[j]));
    e_F = std::max(e_F, std::abs((vp.load - vm.load) / (2 * h) - F[j]));
    Vector<double> rp0, rm0;
    potential.evaluate(qp, 0.0, &rp0, nullptr);
    potential.evaluate(qm, 0.0, &rm0, nullptr);
    model.beam_energy(qp, &bp, nullptr);
    model.beam_energy(qm, &bm, nullptr);
    for (unsigned int i = 0; i < N; ++i) {
      const double k_total = K.el(i, j), k_load = (K0.el(i, j) - K.el(i, j)) / s;  // hess Phi
      const double k_terms = K0.el(i, j) - Kbeam.el(i, j);
      e_total = std::max(e_total, std::abs((rp[i] - rm[i]) / (2 * h) - k_total));
      e_load = std::max(e_load, std::abs((Fp[i] - Fm[i]) / (2 * h) - k_load));
      e_terms = std::max(e_terms, std::abs((rp0[i] - bp[i] - rm0[i] + bm[i]) / (2 * h) - k_terms));
      s_total = std::max(s_total, std::abs(k_total));
      s_load = std::max(s_load, std::abs(k_load));
      s_terms = std::max(s_terms, std::abs(k_terms));
    }
  }
  RecordProperty("load_stiffness_error", sci(e_load / s_load));
  RecordProperty("terms_stiffness_error", sci(e_terms / s_terms));
  EXPECT_LT(e_grad, 1e-6 * r.linfty_norm());
  EXPECT_LT(e_F, 1e-6 * F.linfty_norm());
  EXPECT_LT(e_total, 1e-6 * s_total);
  EXPECT_LT(e_terms, 1e-6 * s_terms);
  if (GetParam() == ring::Pressure::Kind::dead) {
    // Dead pressure and gravity have no load stiffness: hess Phi is zero to round-off.
    EXPECT_LT(s_load, 1e-9 * s_total);
  } else {
    // present (the scale of p ds0 on one cell), and checked on its own scale
    EXPECT_GT(s_load, 1e-2 * loads.pressure.value * R * 2.0 * kPi / 8.0);
    EXPECT_LT(e_load, 1e-6 * s_load) << "relative " << e_load / s_load;
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, FemLoadsKernel,
                         ::testing::Values(ring::Pressure::Kind::follower, ring::Pressure::Kind::dead,
                                           ring::Pressure::Kind::central),
                         [](const auto& info) { return ring::to_string(info.param); });

// ---- Statics ------------------------------------------------------------------------------

/// The displacements of every vertex of a static result (ring-centred frame, m).
std::vector<std::array<double, 2>> vertex_displacements(const ring::RingSpec& spec, const ring::StaticResult& r) {
  const int n = static_cast<int>(r.node_x.size());
  std::vector<std::array<double, 2>> u(n);
  for (int k = 0; k < n; ++k) {
    const double a = angle_of(spec, k, n) * kPi / 180.0;
    u[k] = {r.node_x[k] - spec.radius * std::cos(a), r.node_y[k] - spec.radius * std::sin(a)};
  }
  return u;
}

/// Largest |U - expected| over the vertices, relative to the largest |expected|.
template <class Expected>
double vertex_error(const ring::RingSpec& spec, const ring::StaticResult& r, Expected&& expected) {
  const auto u = vertex_displacements(spec, r);
  double err = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const std::array<double, 2> e = expected(angle_of(spec, static_cast<int>(k), static_cast<int>(u.size())) * kPi / 180.0);
    err = std::max(err, std::hypot(u[k][0] - e[0], u[k][1] - e[1]));
    scale = std::max(scale, std::hypot(e[0], e[1]));
  }
  return err / scale;
}

ring::StaticOptions pressure_load(double p, ring::Pressure::Kind kind) {
  ring::StaticOptions st;
  st.loads.pressure = {p, kind};
  st.steps = 4;
  return st;
}

// Oracle: the shrunk circle. A ring pinned at 180 deg with a roller at 0 deg (on the
// x axis) under uniform pressure stays a circle, by symmetry and because the circle
// satisfies every equation: the tangent keeps its rest direction at every material point,
// so the tangent angle, the curvature change and the bending moment are zero, and the
// hoop force N = EA (lambda - 1), lambda = r/R, balances the pressure: N = -q r with q the
// pressure per deformed length. Follower (p per deformed length): EA (r/R - 1) = -p r,
// r = EA R / (EA + p R). Dead (p per undeformed length, along the undeformed normal,
// which is the deformed one here): q = p / lambda, r = R - p R^2 / EA. The pin keeps its
// place, the roller slides along the x axis, so the circle's centre moves to (r - R, 0)
// and every point moves by U(theta) = (r - R) ((1, 0) + n0(theta)).
// Tolerance: the FE represents the trigonometric fields of U to its interpolation error
// (16 cells of degree 6: measured 1.7e-13 follower, 1.6e-13 dead; the bound 1e-8).
class FemLoadsShrunkCircle : public ::testing::TestWithParam<ring::Pressure::Kind> {};

TEST_P(FemLoadsShrunkCircle, PinnedRingUnderUniformPressureIsTheShrunkCircle) {
  ring::RingSpec spec = thick_ring();
  spec.supports.pin = 180.0;
  spec.supports.roller = 0.0;
  const double R = spec.radius, EA = spec.EA(), p = 1.0 * spec.EI() / (R * R * R);  // critical ~ 3 EI/R^3
  ring::FemOptions o;
  o.elements = 16;
  o.degree = 6;
  const ring::StaticResult res = fem::solve_static(spec, o, pressure_load(p, GetParam()));
  const double r = GetParam() == ring::Pressure::Kind::follower ? EA * R / (EA + p * R) : R - p * R * R / EA;
  const double err = vertex_error(spec, res, [&](double a) {
    return std::array<double, 2>{(r - R) * (1.0 + std::cos(a)), (r - R) * std::sin(a)};
  });
  RecordProperty("error", sci(err));
  EXPECT_LT(err, 1e-8);
  // The other kind's radius is (p R / EA) ~ 6e-3 of the shrink away: the test tells them apart.
  const double other = GetParam() == ring::Pressure::Kind::follower ? R - p * R * R / EA : EA * R / (EA + p * R);
  EXPECT_GT(std::abs(other - r) / std::abs(r - R), 1e3 * 1e-8);
  // Circular: every vertex at distance r from the new centre.
  double roundness = 0.0;
  for (std::size_t k = 0; k < res.node_x.size(); ++k)
    roundness = std::max(roundness, std::abs(std::hypot(res.node_x[k] - (r - R), res.node_y[k]) - r));
  EXPECT_LT(roundness, 1e-8 * (R - r));
}

INSTANTIATE_TEST_SUITE_P(Kinds, FemLoadsShrunkCircle,
                         ::testing::Values(ring::Pressure::Kind::follower, ring::Pressure::Kind::dead),
                         [](const auto& info) { return ring::to_string(info.param); });

// fem.extensible = false (the inextensible limit, extrapolated in 1/beta from
// EA = 1e6 and 2e6 EI/R^2): the shrink p R^2/EA is linear in 1/EA (dead) or linear plus
// O(1/EA^2) (follower), so the extrapolation leaves O(1/beta^2): the ring stays in place.
// Bound: 1e-4 of the shrink at beta = 1e6 (R/beta p R^3/EI); measured 1.0e-6 (follower),
// 2.1e-9 (dead), 6.0e-7 (central).
TEST(FemLoadsShrunkCircle, InextensibleRingDoesNotShrink) {
  ring::RingSpec spec = thick_ring();
  spec.supports.pin = 180.0;
  spec.supports.roller = 0.0;
  const double R = spec.radius, p = 1.0 * spec.EI() / (R * R * R);
  ring::FemOptions o;
  o.elements = 16;
  o.degree = 6;
  o.extensible = false;
  for (auto kind : {ring::Pressure::Kind::follower, ring::Pressure::Kind::dead, ring::Pressure::Kind::central}) {
    const ring::StaticResult res = fem::solve_static(spec, o, pressure_load(p, kind));
    const double shrink_at_beta = p * R * R / (1e6 * spec.EI() / (R * R));
    double largest = 0.0;
    for (const auto& u : vertex_displacements(spec, res)) largest = std::max(largest, std::hypot(u[0], u[1]));
    RecordProperty("inextensible_" + ring::to_string(kind), sci(largest / shrink_at_beta));
    EXPECT_LT(largest, 1e-4 * shrink_at_beta) << ring::to_string(kind);
  }
}

// Oracle: the axisymmetric ring on a foundation. A free ring on radial and tangential
// Winkler foundations (they hold the rigid motions) under uniform pressure shrinks
// uniformly about its centre: u = 0 (the tangential foundation does no work), w const.
// Per undeformed length the stored energy is EA/2 (w/R)^2 + k_r/2 w^2 (a_t = 1 + w/R,
// a_n = 0, no bending: the tangent keeps its direction), and the load potential is
//   dead    -p w,                 central  -p (|x| - R) = -p w,
//   follower -p (A - A0) / (2 pi R) = -p (w + w^2 / (2 R)).
// Stationarity: dead and central  w = -p / (EA/R^2 + k_r),
//               follower          w = -p / (EA/R^2 + k_r + p/R).
// With k_r = 0 these are the shrunk circles above (r = R - p R^2/EA, r = EA R/(EA + p R)),
// now about the fixed centre (the only closed form for the central pressure: on the
// pinned ring its force points to the origin, not to the moved centre).
// Tolerance: the uniform field is exactly in the FE space (w constant, u = 0): 1e-10,
// Newton's stopping rule and round-off (measured 1.6e-13 to 3.1e-13).
struct FoundationCase {
  ring::Pressure::Kind kind;
  double radial;  ///< k_r in units of EA / R^2
};

class FemLoadsFoundation : public ::testing::TestWithParam<FoundationCase> {};

TEST_P(FemLoadsFoundation, UniformPressureOnAFoundationIsAxisymmetric) {
  ring::RingSpec spec = thick_ring();
  const double R = spec.radius, EA = spec.EA(), p = 1.0 * spec.EI() / (R * R * R);
  const double kr = GetParam().radial * EA / (R * R);
  spec.foundation = {kr, EA / (R * R)};
  ring::FemOptions o;
  o.elements = 12;
  o.degree = 3;
  const ring::StaticResult res = fem::solve_static(spec, o, pressure_load(p, GetParam().kind));
  const double w = GetParam().kind == ring::Pressure::Kind::follower ? -p / (EA / (R * R) + kr + p / R)
                                                                      : -p / (EA / (R * R) + kr);
  const double err = vertex_error(spec, res, [&](double a) { return std::array<double, 2>{w * std::cos(a), w * std::sin(a)}; });
  RecordProperty("error", sci(err));
  EXPECT_LT(err, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(KindsAndModuli, FemLoadsFoundation,
                         ::testing::Values(FoundationCase{ring::Pressure::Kind::follower, 0.0},
                                           FoundationCase{ring::Pressure::Kind::dead, 0.0},
                                           FoundationCase{ring::Pressure::Kind::central, 0.0},
                                           FoundationCase{ring::Pressure::Kind::follower, 1.0},
                                           FoundationCase{ring::Pressure::Kind::dead, 1.0},
                                           FoundationCase{ring::Pressure::Kind::central, 1.0}),
                         [](const auto& info) {
                           return ring::to_string(info.param.kind) + (info.param.radial > 0 ? "_radial" : "_tangential");
                         });

/// The linear static response of the thin inextensible ring held at one point by Fourier
/// series (an oracle independent of the FE).
///
/// Derivation. Polar angle theta, psi = theta - theta_s from the support; u tangential
/// (counter-clockwise), w radial (outward); Love's kinematics (modes.hpp): rotation
/// phi = (u - w')/R, curvature change kappa = (u' - w'')/R^2, inextensible u' + w = 0.
/// The inextensible fields of harmonic n >= 2 are
///   C_n: w = cos n psi, u = -sin(n psi)/n,    S_n: w = sin n psi, u = cos(n psi)/n,
/// with kappa = (n^2 - 1) (cos | sin) n psi / R^2: orthogonal in the bending energy
/// EI/2 int kappa^2 ds, each with the modal stiffness k_n = pi EI (n^2 - 1)^2 / R^3.
/// Harmonics 0 and 1 are rigid motions (and the uniform stretch, which inextensibility
/// forbids). The support's reaction (force F_s, moment M_s) makes the loads a
/// self-equilibrated set: F_s = -(total weight), M_s = -(moment of the loads and F_s
/// about the centre). The free ring's elastic response to it is, per harmonic,
/// c = Q / k_n with Q the virtual work of the loads on the field: a point force F at psi
/// does F_r w(psi) + F_t u(psi) (F_r = F . n0, F_t = F . t0); the moment M_s at psi = 0
/// does M_s phi(0), 0 on C_n and (1/n - n)/R on S_n; a uniform weight is harmonic 1 only
/// and does nothing on n >= 2. The held ring is this response plus the rigid motion that
/// brings the support point back (translation) and, for a clamp, its rotation phi(0) to
/// zero (a rotation alpha about the centre: u += R alpha, phi += alpha). A pin with a
/// roller on the ring's axis of symmetry under a symmetric load gives the same field:
/// the symmetric solution has phi(0) = 0 and no roller reaction.
/// Series: the moment's part of phi(0) is M_s R / (pi EI) sum 1/n^2, summed in closed
/// form (pi^2/6 - 1); every other sum converges like 1/n^3 or faster (1e5 terms: < 1e-9).
namespace fourier {

struct PointForce {
  double theta;                ///< rad
  std::array<double, 2> force; ///< N, Cartesian
};

std::vector<std::array<double, 2>> held_ring(double R, double EI, std::array<double, 2> weight_per_length,
                                             std::vector<PointForce> forces, double theta_s,
                                             const std::vector<double>& at, int terms = 100000) {
  auto n0 = [](double t) { return std::array<double, 2>{std::cos(t), std::sin(t)}; };
  auto t0 = [](double t) { return std::array<double, 2>{-std::sin(t), std::cos(t)}; };
  auto dot = [](const std::array<double, 2>& a, const std::array<double, 2>& b) { return a[0] * b[0] + a[1] * b[1]; };
  std::array<double, 2> Fs{-2 * kPi * R * weight_per_length[0], -2 * kPi * R * weight_per_length[1]};
  for (const auto& f : forces) {
    Fs[0] -= f.force[0];
    Fs[1] -= f.force[1];
  }
  forces.push_back({theta_s, Fs});
  double moment = 0.0;  // of the point forces about the centre (the uniform weight has none)
  for (const auto& f : forces) moment += R * (std::cos(f.theta) * f.force[1] - std::sin(f.theta) * f.force[0]);
  const double Ms = -moment;
  std::vector<double> cC(terms + 1), cS(terms + 1);
  double phi0 = 0.0, w0 = 0.0, u0 = 0.0, partial = 0.0;
  for (int n = 2; n <= terms; ++n) {
    const double nn = static_cast<double>(n) * n;  // n^2 overflows an int beyond 46340
    const double kn = kPi * EI * (nn - 1.0) * (nn - 1.0) / (R * R * R);
    double QC = 0.0, QS = Ms * (1.0 / n - n) / R;
    for (const auto& f : forces) {
      const double psi = f.theta - theta_s, Fr = dot(f.force, n0(f.theta)), Ft = dot(f.force, t0(f.theta));
      QC += Fr * std::cos(n * psi) - Ft * std::sin(n * psi) / n;
      QS += Fr * std::sin(n * psi) + Ft * std::cos(n * psi) / n;
    }
    cC[n] = QC / kn;
    cS[n] = QS / kn;
    phi0 += cS[n] * (1.0 / n - n) / R;
    partial += 1.0 / (double(n) * n);
    w0 += cC[n];
    u0 += cS[n] / n;
  }
  phi0 += Ms * R / (kPi * EI) * (kPi * kPi / 6.0 - 1.0 - partial);  // the moment's tail
  const double alpha = -phi0;
  std::array<double, 2> T{0, 0};
  for (int c = 0; c < 2; ++c) T[c] = -w0 * n0(theta_s)[c] - (u0 + R * alpha) * t0(theta_s)[c];
  std::vector<std::array<double, 2>> out;
  for (double theta : at) {
    const double psi = theta - theta_s;
    double w = 0.0, u = R * alpha;
    for (int n = 2; n <= terms; ++n) {
      const double c = std::cos(n * psi), s = std::sin(n * psi);
      w += cC[n] * c + cS[n] * s;
      u += (-cC[n] * s + cS[n] * c) / n;
    }
    out.push_back({u * t0(theta)[0] + w * n0(theta)[0] + T[0], u * t0(theta)[1] + w * n0(theta)[1] + T[1]});
  }
  return out;
}

}  // namespace fourier

struct HeldCase {
  std::string name;
  bool clamp;                    ///< clamp at the pin (else a roller at 270 deg)
  std::array<double, 2> gravity; ///< m/s^2
  double mass_angle;             ///< deg, a 300 kg point mass
};

// The ring's weight (and a point mass's) in the small-load limit against the Fourier
// series (fourier::held_ring): the paper's thin ring (R/d = 83, slenderness 333) in the
// inextensible limit (fem.extensible = false), held at its top (90 deg):
//  - hung: pin at the top, roller at the bottom (270 deg), gravity down, the mass at the
//    bottom: symmetric, the roller carries nothing;
//  - clamped: clamp at the top, gravity sideways (+x), the mass at 0 deg: the clamp
//    carries the weight's moment 2 pi R^2 rho A g.
// g = 1e-5 m/s^2: displacements ~2e-6 m, so the geometric nonlinearity is ~1e-7 of them.
// Convergence: p = 3 on 8, 16, 32 elements; the error at the vertices falls at the fitted
// order 2 (p - 1) = 4 of the C0 interior-penalty beam's nodal displacements (as in
// fem_nonlinear_test; measured 3.96 and 3.97, errors 5.3e-3 .. 2.2e-5 hung, 3.6e-3 ..
// 1.5e-5 clamped). p = 6 on 16 elements reaches the floor, 1.8e-7 hung and 3.3e-7
// clamped: the geometric nonlinearity, which halves with the load.
class FemLoadsHeldRing : public ::testing::TestWithParam<HeldCase> {};

TEST_P(FemLoadsHeldRing, SmallWeightIsTheInextensibleFourierSolutionAndConverges) {
  const HeldCase& c = GetParam();
  ring::RingSpec spec = ringtest::free_ring();
  spec.supports.pin = 90.0;
  if (c.clamp)
    spec.supports.clamp = 90.0;
  else
    spec.supports.roller = 270.0;
  const double mass = 300.0;
  spec.masses = {{c.mass_angle, mass, 0.0}};
  ring::StaticOptions st;
  st.loads.gravity = c.gravity;
  st.steps = 1;
  const double q0 = spec.rhoA() * c.gravity[0], q1 = spec.rhoA() * c.gravity[1];
  std::vector<double> errors;
  // p = 3 on 8, 16, 32 elements (the order), then p = 6 on 16 (the floor).
  const std::vector<std::array<int, 2>> runs{{8, 3}, {16, 3}, {32, 3}, {16, 6}, {16, 6}};
  for (const auto& [n, degree] : runs) {
    if (errors.size() == 4) {  // the last run: half the load
      st.loads.gravity = {0.5 * c.gravity[0], 0.5 * c.gravity[1]};
    }
    const double g_scale = errors.size() == 4 ? 0.5 : 1.0;
    ring::FemOptions o;
    o.elements = n;
    o.degree = degree;
    o.extensible = false;
    const ring::StaticResult res = fem::solve_static(spec, o, st);
    std::vector<double> at;
    for (int k = 0; k < n; ++k) at.push_back(angle_of(spec, k, n) * kPi / 180.0);
    const auto exact = fourier::held_ring(
        spec.radius, spec.EI(), {g_scale * q0, g_scale * q1},
        {{c.mass_angle * kPi / 180.0, {g_scale * mass * c.gravity[0], g_scale * mass * c.gravity[1]}}}, kPi / 2.0, at);
    const auto u = vertex_displacements(spec, res);
    double err = 0.0, scale = 0.0;
    for (int k = 0; k < n; ++k) {
      err = std::max(err, std::hypot(u[k][0] - exact[k][0], u[k][1] - exact[k][1]));
      scale = std::max(scale, std::hypot(exact[k][0], exact[k][1]));
    }
    errors.push_back(err / scale);
    RecordProperty("error_" + std::to_string(n) + "_p" + std::to_string(degree) + (g_scale < 1 ? "_half_load" : ""),
                   sci(err / scale));
  }
  // The order from 8 and 32 elements (two points).
  const auto samples = ringtest::in_n(std::vector<int>{8, 32}, {errors[0], errors[2]});
  const double order = ringtest::fit_order(samples).order;
  RecordProperty("order", sci(order));
  std::cout << c.name << ": errors " << errors[0] << " " << errors[1] << " " << errors[2] << ", order " << order
            << "; p = 6 on 16: " << errors[3] << "\n";
  EXPECT_TRUE(ringtest::OrderNear(samples, 4.0, 0.3, 5e-5));
  EXPECT_LT(errors[3], 1e-6);
  // The floor is the geometric nonlinearity, O(displacement / R): half the load, half of it.
  EXPECT_NEAR(errors[3] / errors[4], 2.0, 0.1) << errors[4];
}

INSTANTIATE_TEST_SUITE_P(Supports, FemLoadsHeldRing,
                         ::testing::Values(HeldCase{"hung", false, {0.0, -1e-5}, 270.0},
                                           HeldCase{"clamped", true, {1e-5, 0.0}, 0.0}),
                         [](const auto& info) { return info.param.name; });

// Global equilibrium under the full weight: the paper's ring held by springs alone
// (kx, ky at the top, kx at the bottom; no pin), a 1000 kg point mass at 0 deg, g = 9.81:
// the ring sags ~2 m and tilts (large displacements). The springs' forces -k U are the
// reactions: -ky Uy(top) = the total weight, kx (Ux(top) + Ux(bottom)) = 0. The FE
// satisfies global equilibrium up to how well its polar fields represent a rigid
// translation (16 cells of degree 10: interpolation error ~ (h/2)^11 / 11! ~ 1e-13 of R);
// bound 1e-9 of the weight (measured 9.4e-15 vertical, 3.9e-15 horizontal).
TEST(FemLoadsSprings, SpringReactionsCarryTheWholeWeight) {
  ring::RingSpec spec = ringtest::free_ring();
  const double k = 1e8;
  spec.supports.springs = {{90.0, k, k, 0.0}, {270.0, k, 0.0, 0.0}};
  const double mass = 1000.0, g = 9.81;
  spec.masses = {{0.0, mass, 0.0}};
  ring::StaticOptions st;
  st.loads.gravity = {0.0, -g};
  st.steps = 20;
  st.record = {90.0, 270.0, 0.0};
  ring::FemOptions o;
  o.elements = 16;
  o.degree = 10;
  const ring::StaticResult res = fem::solve_static(spec, o, st);
  const double weight = g * (spec.rhoA() * 2.0 * kPi * spec.radius + mass);
  const auto& top = res.displacements[0];
  const auto& bottom = res.displacements[1];
  const double vertical = -k * top.uy, horizontal = -k * (top.ux + bottom.ux);
  RecordProperty("vertical_error", sci(std::abs(vertical - weight) / weight));
  RecordProperty("horizontal_error", sci(std::abs(horizontal) / weight));
  EXPECT_TRUE(ringtest::IsClose(vertical, weight, 1e-9));
  EXPECT_LT(std::abs(horizontal), 1e-9 * weight);
  EXPECT_GT(std::abs(res.displacements[2].uy), 1.0);  // large: the mass's side sags by metres
}

// Refusals: what has no meaning for the beam's nonlinear analyses names its key.
TEST(FemLoadsChecks, RefusesWhatHasNoMeaning) {
  ring::RingSpec spec = ringtest::pinned_ring(180.0);
  ring::FemOptions o;
  ring::StaticOptions st;
  st.loads.points = {{0.0, {-1.0, 0.0}}, {45.0, {0.0, 1.0}}};
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  // A ring on one pin swings about it: no regular tangent at rest.
  EXPECT_NE(message([&] { fem::check_static(spec, o, st); }).find("rigid"), std::string::npos);
  spec.supports.roller = 0.0;
  st.loads.points.push_back({91.0, {0.0, 1.0}});
  EXPECT_NE(message([&] { fem::check_static(spec, o, st); }).find("static.loads[3].at"), std::string::npos);
  st.loads.points.pop_back();
  EXPECT_NO_THROW(fem::check_static(spec, o, st));
  st.loads.pressure = {std::nan(""), ring::Pressure::Kind::central};
  EXPECT_NE(message([&] { fem::check_static(spec, o, st); }).find("static.pressure.value"), std::string::npos);
  st.loads.pressure = {1.0, ring::Pressure::Kind::central};
  st.loads.gravity = {0.0, INFINITY};
  EXPECT_NE(message([&] { fem::check_static(spec, o, st); }).find("static.gravity"), std::string::npos);
  st.loads.gravity = {0.0, -9.81};
  // A free ring in a response drifts away; springs or a foundation that hold it are enough.
  ring::RingSpec free = ringtest::free_ring();
  ring::ResponseOptions rs;
  rs.loads.pressure = {1.0, ring::Pressure::Kind::follower};
  EXPECT_NE(message([&] { fem::check_response(free, o, rs); }).find("supports.pin"), std::string::npos);
  free.foundation.tangential = 1.0;
  EXPECT_NO_THROW(fem::check_response(free, o, rs));
  // Statics with every term of the linear model are accepted.
  spec.supports.pins = {90.0};
  spec.supports.clamp = 90.0;
  spec.supports.springs = {{270.0, 1.0, 1.0, 1.0}};
  spec.masses = {{45.0, 1.0, 1.0}};
  spec.foundation = {1.0, 1.0};
  EXPECT_NO_THROW(fem::check_static(spec, o, st));
}

// ---- Response -----------------------------------------------------------------------------

// Oracle: the breathing ring. A free ring on a tangential foundation (it holds the rigid
// motions and does no work on u = 0) under a uniform pressure applied suddenly at t = 0
// moves axisymmetrically, w(t) uniform, u = 0; per undeformed length (see the foundation
// test above) the motion is the linear ODE
//   rho A w'' + (EA/R^2 + c) w = -p,   c = p/R (follower: its load stiffness), 0 (dead, central),
// from rest: w(t) = w_s (1 - cos omega t), w_s = -p / (EA/R^2 + c), the static deflection
// (the mean of the motion), omega^2 = E/(rho R^2) + c/(rho A). E/(rho R^2) is the
// extensible ring's breathing mode n = 0 (Love; Soedel, Vibrations of Shells and Plates,
// the ring's n = 0 membrane mode): the geometrically exact beam measures the curvature per
// undeformed length, which a uniform shrink leaves unchanged, so no bending term adds to
// it. The follower pressure lowers nothing and raises omega^2 by p/(rho A R) (a
// shrinking ring feels less pressure: p acts per deformed length).
// Newmark's average acceleration is the trapezoidal rule on (w, w'), which on a linear
// oscillator keeps the amplitude and turns the phase per step by Omega dt with
// tan(Omega dt / 2) = omega dt / 2: the discrete solution is exactly
// w_k = w_s (1 - cos(Omega t_k)) (from rest, consistent start). The uniform field is
// exactly in the FE space, so the FE history must be this one to Newton's tolerance
// (1e-12 R on w_s ~ 6e-3 R: bound 1e-8 of w_s). And the balance T + V - W of a
// quadratic energy under a constant load is conserved by the trapezoidal rule: to
// round-off (bound 1e-9 of the work).
class FemLoadsBreathing : public ::testing::TestWithParam<ring::Pressure::Kind> {};

TEST_P(FemLoadsBreathing, SuddenPressureMakesTheRingBreatheAtTheClosedFormFrequency) {
  ring::RingSpec spec = thick_ring();
  const double R = spec.radius, EA = spec.EA(), p = 1.0 * spec.EI() / (R * R * R);
  spec.foundation.tangential = EA / (R * R);
  const double c = GetParam() == ring::Pressure::Kind::follower ? p / R : 0.0;
  const double omega = std::sqrt(spec.E / (spec.rho * R * R) + c / spec.rhoA());
  const double w_s = -p / (EA / (R * R) + c);
  ring::ResponseOptions rs;
  rs.loads.pressure = {p, GetParam()};
  rs.history.kind = ring::LoadHistory::Kind::step;
  rs.dt = 2.0 * kPi / omega / 40.0;
  rs.t_end = 3.0 * 2.0 * kPi / omega;
  rs.record = {0.0, 90.0, 210.0};
  ring::FemOptions o;
  o.elements = 12;
  o.degree = 3;
  const ring::TimeHistory h = fem::respond(spec, o, rs);
  const double Omega = 2.0 / rs.dt * std::atan(omega * rs.dt / 2.0);
  double err = 0.0, balance = 0.0, work = 0.0, mean = 0.0;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    const double w = w_s * (1.0 - std::cos(Omega * h.t[k]));
    for (std::size_t i = 0; i < rs.record.size(); ++i) {
      const double a = rs.record[i] * kPi / 180.0;
      err = std::max(err, std::hypot(h.ux[i][k] - w * std::cos(a), h.uy[i][k] - w * std::sin(a)));
    }
    balance = std::max(balance, std::abs(h.kinetic[k] + h.strain[k] - h.work[k]));
    work = std::max(work, std::abs(h.work[k]));
    if (k > 0) mean += 0.5 * (h.ux[0][k] + h.ux[0][k - 1]) * rs.dt;
  }
  mean /= h.t.back();
  RecordProperty("error", sci(err / std::abs(w_s)));
  RecordProperty("balance", sci(balance / work));
  EXPECT_LT(err, 1e-8 * std::abs(w_s));
  EXPECT_LT(balance, 1e-9 * work);
  // The mean deflection is the static one (three whole periods: to Omega's phase over them).
  EXPECT_TRUE(ringtest::IsClose(mean, w_s, 1e-2));
  // The follower's frequency differs from the dead load's by far more than the tolerance:
  // 3 periods shift the phase by 3 pi p R / (E A) ~ 0.05 rad.
  if (GetParam() == ring::Pressure::Kind::follower) {
    const double dead = std::sqrt(spec.E / (spec.rho * R * R));
    EXPECT_GT(3.0 * 2.0 * kPi * (omega - dead) / omega * std::abs(w_s), 1e4 * 1e-8 * std::abs(w_s));
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, FemLoadsBreathing,
                         ::testing::Values(ring::Pressure::Kind::follower, ring::Pressure::Kind::dead,
                                           ring::Pressure::Kind::central),
                         [](const auto& info) { return ring::to_string(info.param); });

/// The paper's ring on a pin (180 deg) and a roller (0 deg) with every term: a further
/// spring support (kx, ky, kr at 90 deg), a point mass with rotary inertia (270 deg), a
/// foundation; loaded by its weight, a follower pressure and a point load.
ring::RingSpec every_term_ring() {
  ring::RingSpec spec = ringtest::pin_roller_ring();
  const double EI = spec.EI(), R = spec.radius;
  spec.supports.springs = {{90.0, 10 * EI / (R * R * R), 10 * EI / (R * R * R), EI / R}};
  spec.masses = {{270.0, 500.0, 2000.0}};
  spec.foundation = {EI / (R * R * R * R), EI / (R * R * R * R)};
  return spec;
}

ring::Loads every_load(double scale) {
  ring::Loads loads;
  loads.gravity = {0.0, -9.81 * scale};
  loads.pressure = {1000.0 * scale, ring::Pressure::Kind::follower};
  loads.points = {{90.0, {0.0, -5e3 * scale}}, {45.0, {2e3 * scale, 0.0}}};
  return loads;
}

// The energy balance of a response with every term and load: a half-sine pulse (1 s) of
// weight, follower pressure and point loads on the ring with springs, a point mass and a
// foundation, Newmark, dt = 0.01 s, 3 s. The guard (ring/energy_guard.hpp, constructed
// with ring::load_scale) lets the run finish only if T + V - W never gains more than 1 %
// of the largest work; here checked from the history too, with the work and the
// translational spring's share of it from the record (leaving it out of V would move the
// balance by that share, > 1 %; measured gain 1e-5 of the work). After the pulse the
// loads are off: the work stays constant (to round-off) and T + V is conserved to
// Newmark's energy error on a non-quadratic energy.
TEST(FemLoadsResponse, PulseWithEveryTermAndLoadKeepsTheEnergyBalance) {
  const ring::RingSpec spec = every_term_ring();
  ring::ResponseOptions rs;
  rs.loads = every_load(1.0);
  rs.history.kind = ring::LoadHistory::Kind::half_sine;
  rs.history.period = 1.0;
  rs.dt = 0.01;
  rs.t_end = 3.0;
  rs.record = {90.0, 270.0};
  ring::FemOptions o;
  o.elements = 24;
  o.degree = 3;
  const ring::TimeHistory h = fem::respond(spec, o, rs);
  double gain = 0.0, work = 0.0, after = 0.0, work_drift = 0.0;
  std::size_t pulse_end = 0;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    const double e = h.kinetic[k] + h.strain[k] - h.work[k];
    gain = std::max(gain, e);
    work = std::max(work, std::abs(h.work[k]));
    if (h.t[k] <= 1.0 + 1e-9) pulse_end = k;
  }
  for (std::size_t k = pulse_end; k < h.t.size(); ++k) {
    after = std::max(after, std::abs(h.kinetic[k] + h.strain[k] - h.kinetic[pulse_end] - h.strain[pulse_end]));
    work_drift = std::max(work_drift, std::abs(h.work[k] - h.work[pulse_end]));
  }
  // The translational spring's energy (kx = ky at 90 deg, the first record point), from
  // the record: leaving it out of V would move the balance by this much.
  double spring = 0.0;
  const double k_spring = spec.supports.springs[0].kx;
  for (std::size_t k = 0; k < h.t.size(); ++k)
    spring = std::max(spring, 0.5 * k_spring * (h.ux[0][k] * h.ux[0][k] + h.uy[0][k] * h.uy[0][k]));
  RecordProperty("spring_share", sci(spring / work));
  RecordProperty("gain", sci(gain / work));
  RecordProperty("after_pulse", sci(after / work));
  RecordProperty("work", sci(work));
  std::cout << "work " << work << " J, gain " << gain / work << ", T + V after the pulse " << after / work
            << ", spring " << spring / work << "\n";
  EXPECT_LT(gain, 1e-2 * work);  // the guard's bound
  EXPECT_LT(gain, 1e-3 * work);  // measured 1e-5: Newmark's energy error at dt = 0.01 s
  EXPECT_GT(spring, 1e-2 * work);
  EXPECT_LT(work_drift, 1e-12 * work);
  EXPECT_LT(after, 1e-2 * work);
}

// Every term in the response, against the statics: with strong mass-proportional damping
// the response to a load applied by a ramp settles at the static equilibrium of the same
// loads (solve_static), which the statics reach by continuation. Both analyses assemble
// the same BeamPotential, so this checks the drivers (the loads' factor, the response's
// Newton residual with its mass and damping), not the terms; the terms have their own
// oracles above. Bound: the residual motion after 40 s of damping a = 2 1/s (e^-40 of the
// resolved modes' amplitude; the others damped by generalized-alpha), 1e-8 of the
// deflection.
TEST(FemLoadsResponse, DampedResponseSettlesAtTheStaticEquilibrium) {
  const ring::RingSpec spec = every_term_ring();
  ring::FemOptions o;
  o.elements = 24;
  o.degree = 3;
  ring::StaticOptions st;
  st.loads = every_load(0.2);
  st.steps = 10;
  st.record = {90.0, 270.0, 135.0};
  const ring::StaticResult s = fem::solve_static(spec, o, st);
  ring::ResponseOptions rs;
  rs.loads = st.loads;
  rs.history.kind = ring::LoadHistory::Kind::ramp;
  rs.history.period = 2.0;
  rs.dt = 0.05;
  rs.t_end = 40.0;
  rs.rayleigh_mass = 2.0;
  // Generalized-alpha damps the modes that dt does not resolve (omega dt >> 1: the
  // breathing and the high bending modes, which the ramp's corners excite and which
  // Newmark's rule would keep undamped at any Rayleigh a: measured 6e-7 left with it).
  rs.integrator = ring::ResponseOptions::Integrator::generalized_alpha;
  rs.rho_inf = 0.5;
  rs.record = st.record;
  const ring::TimeHistory h = fem::respond(spec, o, rs);
  double err = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < st.record.size(); ++i) {
    err = std::max(err, std::hypot(h.ux[i].back() - s.displacements[i].ux, h.uy[i].back() - s.displacements[i].uy));
    scale = std::max(scale, std::hypot(s.displacements[i].ux, s.displacements[i].uy));
  }
  RecordProperty("error", sci(err / scale));
  EXPECT_LT(err, 1e-8 * scale);
  EXPECT_GT(scale, 1e-2);  // a large deflection (m), not the linear limit
}

}  // namespace
