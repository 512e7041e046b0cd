// The Timoshenko chain's geometrically nonlinear statics and response (multibody/sections.hpp,
// the dense path). Oracles that do not come from the code under test:
// - the linear model (linear_model.cpp, assembled apart): the response's tangent and mass at
//   rest on its null-space basis are its K0 and M0; the statics' condensed tangent at rest is
//   the Schur complement of K0 over the shear angles (the exact condensation);
// - central differences of the residuals (statics and response) against their tangents;
// - kGA -> infinity (section inertia off): today's Euler-Bernoulli chain, the difference
//   falling as 1/kGA;
// - small loads: the linear model's solution K0 x = D^T f, the difference O(load^2);
// - the refusals (O(n) paths, energy-momentum, modes under load).
// The comparison with the FE Reissner beam is test_timoshenko_fem.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "modal/buckling.hpp"
#include "multibody/attachments.hpp"
#include "multibody/buckling.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/linear_model.hpp"
#include "multibody/modes.hpp"
#include "multibody/newton_backend.hpp"
#include "multibody/sections.hpp"
#include "multibody/statics.hpp"
#include "tests/multibody/common.hpp"
#include "tests/support/thick.hpp"

namespace {

using multibody::Chain;
using multibody::Matrix;
using multibody::Vector;
using Shape = ring::Section::Shape;
namespace detail = multibody::detail;

/// The thick steel ring of tests/support/thick.hpp (R = 1 m, rectangle 0.02 m wide, depth
/// `depth`) on a pin at 180 deg and a roller at 0 deg; with `terms`, a clamp, a rotational and
/// a translational spring and a foundation of the bending stiffness's scale.
ring::RingSpec pinned(double depth, bool terms = false) {
  ring::RingSpec s = ringtest::thick_ring(Shape::rectangle, depth);
  s.supports.pin = 180.0;
  s.supports.roller = 0.0;
  if (terms) {
    const double k = s.EI() / std::pow(s.radius, 3);
    s.supports.springs.push_back({90.0, 0.0, 0.0, 2.0 * s.EI() / s.radius});
    s.supports.springs.push_back({270.0, 0.5 * k, 2.0 * k, 0.3 * s.EI() / s.radius});
    s.foundation.radial = 0.5 * k / s.radius;
    s.foundation.tangential = 0.2 * k / s.radius;
    s.supports.clamp = 45.0;
  }
  return s;
}

double rel_diff(const Matrix& a, const Matrix& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

/// The largest |u| difference between two static results, over the largest |u| of `b`.
double static_gap(const ring::StaticResult& a, const ring::StaticResult& b) {
  double d = 0.0, m = 0.0;
  for (std::size_t i = 0; i < a.displacements.size(); ++i) {
    d = std::max(
        d, std::hypot(a.displacements[i].ux - b.displacements[i].ux, a.displacements[i].uy - b.displacements[i].uy));
    m = std::max(m, std::hypot(b.displacements[i].ux, b.displacements[i].uy));
  }
  return d / m;
}

/// The same for two histories on one grid, over every point and step.
double history_gap(const ring::TimeHistory& a, const ring::TimeHistory& b) {
  double d = 0.0, m = 0.0;
  for (std::size_t p = 0; p < a.ux.size(); ++p)
    for (std::size_t k = 0; k < a.ux[p].size(); ++k) {
      d = std::max(d, std::hypot(a.ux[p][k] - b.ux[p][k], a.uy[p][k] - b.uy[p][k]));
      m = std::max(m, std::hypot(b.ux[p][k], b.uy[p][k]));
    }
  return d / m;
}

ring::StaticOptions point_load(double fy) {
  ring::StaticOptions st;
  st.loads.points.push_back({90.0, {0.0, fy}});
  st.record = {0.0, 45.0, 90.0, 135.0, 270.0};
  st.steps = 10;
  return st;
}

/// A half-sine pulse at 90 deg toward the centre, recorded at 0, 90 and 270 deg.
ring::ResponseOptions pulse(double fy, double period, double dt, double t_end) {
  ring::ResponseOptions r;
  r.loads.points.push_back({90.0, {0.0, fy}});
  r.history.kind = ring::LoadHistory::Kind::half_sine;
  r.history.period = period;
  r.dt = dt;
  r.t_end = t_end;
  r.integrator = ring::ResponseOptions::Integrator::newmark;
  r.record = {0.0, 90.0, 270.0};
  return r;
}

// The response's residual and tangent at rest are the linear model's K and M (assembled apart
// in linear_model.cpp) on its orthonormal null-space basis D: D^T T D = K0, D^T M D = M0, to
// round-off (1e-12 of the largest entry: sums of O(n) terms of one scale).
TEST(TimoshenkoNonlinear, ResponseTangentAtRestIsTheLinearModel) {
  for (const bool terms : {false, true}) {
    const ring::RingSpec spec = pinned(0.2, terms);
    const Chain ch(spec, mbtest::dense_chain(24), 90.0);
    const detail::Attachments att(ch, spec);
    const detail::LinearTerms lt = detail::linear_terms(ch, spec);
    const multibody::Shear sh = multibody::Shear::of(spec, ch.l());
    const detail::Sections sec(ch, &att, sh);
    auto nb = detail::make_newton_backend(ch, detail::DeadLoad{}, detail::Damping{}, false, nullptr, &att, &sec);
    const int n = ch.n(), N = 2 * n;
    Vector q = Vector::Zero(N), r;
    q.head(n) = ch.q0();
    const Vector zero = Vector::Zero(N);
    nb->residual(q, zero, zero, 0.0, 0.0, 0.0, r, true);
    // Rest is an equilibrium: the forces are the rounding of the rest hinges (1e-16 R) times
    // the springs, far below 1e-12 EI / R.
    EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-12 * spec.EI() / spec.radius);
    const Matrix K = *nb->dense_tangent();
    // The mass as the tangent's cm-part; cm large so that K (1e6 times M here) does not
    // round it away.
    constexpr double cm = 1e6;
    nb->residual(q, zero, zero, 0.0, cm, 0.0, r, true);
    const Matrix M = (*nb->dense_tangent() - K) / cm;
    const multibody::LinearModel lm = multibody::linearize(ch, ring::MultibodyOptions::Dependent::robust, &lt, &sh);
    const Matrix D = lm.basis();
    ASSERT_EQ(D.rows(), N);
    EXPECT_LT(rel_diff(D.transpose() * K * D, lm.K0), 1e-12) << "terms " << terms;
    EXPECT_LT(rel_diff(D.transpose() * M * D, lm.M0), 1e-12) << "terms " << terms;
  }
}

// The statics condense the shear angles (sections.hpp): on the constraints' tangent space
// Z = diag(Z_phi, I) (the same space as the linear model's D: C = Z^T D is orthogonal), the
// Schur complement of Z^T K Z = C K0 C^T over the shear angles is Z_phi^T K_c Z_phi.
TEST(TimoshenkoNonlinear, StaticTangentAtRestIsTheLinearModelCondensed) {
  for (const bool terms : {false, true}) {
    const ring::RingSpec spec = pinned(0.2, terms);
    const Chain ch(spec, mbtest::dense_chain(24), 90.0);
    const int n = ch.n();
    const detail::DenseTangent dt(ch, spec, ring::Loads{}, "static");
    const Vector q0 = ch.q0();
    const Chain::ConstraintKinematics ck = dt.constraints(q0);
    Matrix Kc = Matrix::Zero(n, n);
    dt.add_tangent(q0, Vector::Zero(dt.rows()), 0.0, ck, Kc);
    const Matrix Zp = modal::kernel_basis(ck.G, n);
    const int rp = static_cast<int>(Zp.cols());
    Matrix Z = Matrix::Zero(2 * n, rp + n);
    Z.topLeftCorner(n, rp) = Zp;
    Z.bottomRightCorner(n, n).setIdentity();
    const detail::LinearTerms lt = detail::linear_terms(ch, spec);
    const multibody::Shear sh = multibody::Shear::of(spec, ch.l());
    const multibody::LinearModel lm = multibody::linearize(ch, ring::MultibodyOptions::Dependent::robust, &lt, &sh);
    const Matrix C = Z.transpose() * lm.basis();
    ASSERT_EQ(C.rows(), C.cols());
    EXPECT_LT((C.transpose() * C - Matrix::Identity(C.rows(), C.cols())).cwiseAbs().maxCoeff(), 1e-12);
    const Matrix KZ = C * lm.K0 * C.transpose();
    const Matrix schur = KZ.topLeftCorner(rp, rp) -
                         KZ.topRightCorner(rp, n) * KZ.bottomRightCorner(n, n).ldlt().solve(KZ.bottomLeftCorner(n, rp));
    EXPECT_LT(rel_diff(Zp.transpose() * Kc * Zp, schur), 1e-10) << "terms " << terms;
  }
}

// Central differences (h = 1e-6 rad: truncation O(h^2), round-off O(eps / h) relative, both
// below 1e-7 of these O(1)-scaled forces) of the statics' forces and of the response's
// residual along the integrator's formulas (qdd = a + cm dq, v = v0 + cv dq) against their
// analytic tangents, at a random deformed, moving state, with every term, a load and damping.
TEST(TimoshenkoNonlinear, TangentsAreTheResidualsDerivatives) {
  const ring::RingSpec spec = pinned(0.2, true);
  const Chain ch(spec, mbtest::dense_chain(16), 90.0);
  const int n = ch.n(), N = 2 * n;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  constexpr double h = 1e-6;
  // Statics.
  ring::Loads loads;
  loads.points.push_back({90.0, {0.3 * spec.EI(), -spec.EI()}});
  const detail::DenseTangent dt(ch, spec, loads, "static");
  Vector q = ch.q0();
  for (int i = 0; i < n; ++i) q[i] += 0.2 * u(gen);
  const double s = 0.7;
  auto fs = [&](const Vector& x) -> Vector { return dt.internal_forces(x) - s * dt.loads().forces(x); };
  Matrix T = Matrix::Zero(n, n), fd(n, n);
  dt.add_tangent(q, Vector::Zero(dt.rows()), s, dt.constraints(q), T);
  for (int j = 0; j < n; ++j) {
    Vector a = q, b = q;
    a[j] += h;
    b[j] -= h;
    fd.col(j) = (fs(a) - fs(b)) / (2 * h);
  }
  EXPECT_LT(rel_diff(T, fd), 1e-7);
  // Response.
  const detail::Attachments att(ch, spec);
  const detail::Sections sec(ch, &att, multibody::Shear::of(spec, ch.l()));
  const detail::DeadLoad load{ch.hinge_at(90.0), {0.3 * spec.EI(), -spec.EI()}};
  auto nb = detail::make_newton_backend(ch, load, detail::Damping{0.5, 0.1 * ch.K()}, false, nullptr, &att, &sec);
  Vector x = Vector::Zero(N), v(N), a(N);
  x.head(n) = q;
  for (int i = 0; i < N; ++i) {
    if (i >= n) x[i] = 0.05 * u(gen);
    v[i] = u(gen);
    a[i] = 3.0 * u(gen);
  }
  const double cm = 40.0, cv = 6.0, f = 0.8;
  Vector r;
  nb->residual(x, v, a, f, cm, cv, r, true);
  const Matrix Tr = *nb->dense_tangent();
  auto fr = [&](const Vector& y) {
    Vector out;
    nb->residual(y, v + cv * (y - x), a + cm * (y - x), f, cm, cv, out, false);
    return out;
  };
  Matrix fdr(N, N);
  for (int j = 0; j < N; ++j) {
    Vector p = x, m = x;
    p[j] += h;
    m[j] -= h;
    fdr.col(j) = (fr(p) - fr(m)) / (2 * h);
  }
  EXPECT_LT(rel_diff(Tr, fdr), 1e-7);
}

// kGA -> infinity: the Euler-Bernoulli chain with the same terms, the difference falling as
// 1/kGA (the shear's compliance, kGA l against the springs EI / l). Statics at rotations of
// ~0.3 rad; the response (section inertia rho I l off: the Euler chain has none) on a pulse.
TEST(TimoshenkoNonlinear, StiffShearIsTheEulerChain) {
  ring::RingSpec euler = pinned(0.2, true);
  euler.theory = ring::Theory::euler_bernoulli;
  const double fy = -2.0 * euler.EI() / (euler.radius * euler.radius);
  const ring::StaticOptions st = point_load(fy);
  const ring::StaticResult e = multibody::solve_static(euler, mbtest::dense_chain(24), st);
  std::vector<double> gaps;
  for (double kappa : {1e3, 1e4}) {
    ring::RingSpec t = pinned(0.2, true);
    t.shear_coefficient = kappa;
    gaps.push_back(static_gap(multibody::solve_static(t, mbtest::dense_chain(24), st), e));
  }
  RecordProperty("static_gaps", mbtest::sci(gaps[0]) + " " + mbtest::sci(gaps[1]));
  EXPECT_LT(gaps[0], 1e-3);
  EXPECT_NEAR(gaps[0] / gaps[1], 10.0, 0.5) << gaps[0] << " " << gaps[1];

  const double T1 = 2 * M_PI / (2.68 * euler.bending_frequency_scale());  // ~ the first period
  const ring::ResponseOptions r = pulse(fy, 0.3 * T1, T1 / 200, T1);
  const ring::TimeHistory he = multibody::respond(euler, mbtest::dense_chain(24), r);
  std::vector<double> rgaps;
  for (double kappa : {1e3, 1e4}) {
    ring::RingSpec t = pinned(0.2, true);
    t.shear_coefficient = kappa;
    const Chain ch(t, mbtest::dense_chain(24), 90.0);
    rgaps.push_back(history_gap(multibody::respond(t, mbtest::dense_chain(24), r, {}, {t.kGA() * ch.l(), 0.0}), he));
  }
  RecordProperty("response_gaps", mbtest::sci(rgaps[0]) + " " + mbtest::sci(rgaps[1]));
  EXPECT_LT(rgaps[0], 1e-3);
  EXPECT_NEAR(rgaps[0] / rgaps[1], 10.0, 1.0) << rgaps[0] << " " << rgaps[1];
}

// Small loads: the linear model's static solution K0 x = D^T f (linear_model.cpp), dq = D x,
// hinge displacements to first order; the nonlinear equilibrium differs by O(load^2), so the
// relative difference halves with the load.
TEST(TimoshenkoNonlinear, SmallLoadIsTheLinearSolution) {
  const ring::RingSpec spec = pinned(0.2, true);
  const Chain ch(spec, mbtest::dense_chain(24), 90.0);
  const detail::LinearTerms lt = detail::linear_terms(ch, spec);
  const multibody::Shear sh = multibody::Shear::of(spec, ch.l());
  const multibody::LinearModel lm = multibody::linearize(ch, ring::MultibodyOptions::Dependent::robust, &lt, &sh);
  const Matrix D = lm.basis();
  std::vector<double> errors;
  const double unit = 1e-3 * spec.EI() / (spec.radius * spec.radius);
  for (double scale : {1.0, 0.5, 0.25}) {
    const Eigen::Vector2d F(0.4 * scale * unit, -scale * unit);
    const ring::StaticOptions st = [&] {
      ring::StaticOptions o = point_load(F.y());
      o.loads.points[0].force = {F.x(), F.y()};
      return o;
    }();
    Vector f = Vector::Zero(D.rows());
    f.head(ch.n()) = ch.point_load_forces(ch.q0(), ch.hinge_at(90.0), F);
    const Vector dq = D * lm.K0.ldlt().solve(D.transpose() * f);
    const Eigen::Matrix2Xd u = ch.rest_displacements(dq.head(ch.n()));
    const ring::StaticResult res = multibody::solve_static(spec, mbtest::dense_chain(24), st);
    double d = 0.0, m = 0.0;
    for (const ring::PointDisplacement& p : res.displacements) {
      const Eigen::Vector2d ul = u.col(ch.hinge_at(p.angle));
      d = std::max(d, (Eigen::Vector2d(p.ux, p.uy) - ul).norm());
      m = std::max(m, ul.norm());
    }
    errors.push_back(d / m);
  }
  RecordProperty("relative_errors",
                 mbtest::sci(errors[0]) + " " + mbtest::sci(errors[1]) + " " + mbtest::sci(errors[2]));
  // Rotations ~1e-3 rad at the largest load: the quadratic terms are ~1e-3 of the linear ones.
  EXPECT_LT(errors[0], 1e-2);
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.1);
  EXPECT_NEAR(errors[1] / errors[2], 2.0, 0.1);
}

// The undamped pulse response of the thick ring conserves T + V - W: newmark to its
// discretization of the load's work (the balance's own bound, energy_guard.hpp, applies),
// and generalized-alpha (rho_inf = 0.8) never gains energy.
TEST(TimoshenkoNonlinear, PulseResponseKeepsTheEnergyBalance) {
  const ring::RingSpec spec = pinned(0.2, true);
  const double fy = -2.0 * spec.EI() / (spec.radius * spec.radius);
  const double T1 = 2 * M_PI / (2.68 * spec.bending_frequency_scale());
  for (auto integ :
       {ring::ResponseOptions::Integrator::newmark, ring::ResponseOptions::Integrator::generalized_alpha}) {
    ring::ResponseOptions r = pulse(fy, 0.3 * T1, T1 / 200, 2 * T1);
    r.integrator = integ;
    r.rho_inf = 0.8;
    const ring::TimeHistory h = multibody::respond(spec, mbtest::dense_chain(24), r);
    const mbtest::Balance b = mbtest::balance(h);
    EXPECT_EQ(h.unknowns, 2 * 24 + 3);
    EXPECT_LT(b.constraint, 1e-11);
    // The pulse's work is trapezoidal in time: exact for the energy when the load point's
    // path is resolved (dt = T1/200); after the pulse W is constant and T + V must stay.
    const double final_balance = h.energy_error.back();
    if (integ == ring::ResponseOptions::Integrator::newmark)
      EXPECT_LT(std::abs(final_balance), 1e-3 * b.work) << "newmark";
    else
      EXPECT_LT(final_balance, 1e-6 * b.work) << "generalized-alpha gained energy";
  }
  // Damped (Rayleigh on the full mass, hinge dampers between the sections): the balance
  // T + V + D - W, D the dissipation (midpoint rule, exact for newmark on a linear system),
  // holds to the same 1e-3 of the work, and D is a real share of it.
  ring::ResponseOptions r = pulse(fy, 0.3 * T1, T1 / 200, 2 * T1);
  r.rayleigh_mass = 0.05 / T1;
  r.hinge_damping = 1e-3 * T1 * spec.EI() / (2 * M_PI * spec.radius / 24);
  const ring::TimeHistory h = multibody::respond(spec, mbtest::dense_chain(24), r);
  const mbtest::Balance b = mbtest::balance(h);
  EXPECT_LT(b.worst, 1e-3 * b.work);
  EXPECT_LT(h.kinetic.back() + h.strain.back(), 0.99 * h.work.back()) << "the dampers took no energy";
}

// Mass-proportional damping C = a M, M the whole mass (the chain's and the sections' rotary
// inertia [M + J, J; J, J]), removes power v^T C v = 2 a T at every instant (Rayleigh's
// identity, independent of the code): the dissipation D = W - T - V + (balance error) over the
// pulse's history equals the time integral of 2 a T (trapezoidal over the steps) to the step's
// O(dt^2) (C is taken at rest: a small load keeps M(q) at M(q0)). A C that left out the
// sections' inertia blocks misses their share of T. Measured at dt = T1/800: 9.5e-5 relative
// (1.6e-3 at T1/200: order 2.0); 2.8e-3 with those blocks left out; bound 1e-3.
TEST(TimoshenkoNonlinear, MassProportionalDampingRemovesTwiceItsRateTimesTheKineticEnergy) {
  const ring::RingSpec spec = pinned(0.2, true);
  const double fy = -2.0 * spec.EI() / (spec.radius * spec.radius);
  const double T1 = 2 * M_PI / (2.68 * spec.bending_frequency_scale());
  ring::ResponseOptions r = pulse(1e-3 * fy, 0.3 * T1, T1 / 800, 2 * T1);
  r.rayleigh_mass = 0.2 / T1;
  const ring::TimeHistory h = multibody::respond(spec, mbtest::dense_chain(24), r);
  const std::size_t last = h.t.size() - 1;
  const double dissipated = h.energy_error[last] - h.kinetic[last] - h.strain[last] + h.work[last];
  double rayleigh = 0.0;
  for (std::size_t i = 1; i <= last; ++i)
    rayleigh += 0.5 * (h.t[i] - h.t[i - 1]) * 2.0 * r.rayleigh_mass * (h.kinetic[i] + h.kinetic[i - 1]);
  RecordProperty("dissipation_vs_rayleigh", mbtest::sci(std::abs(dissipated - rayleigh) / rayleigh));
  RecordProperty("dissipated_share_of_work", mbtest::sci(dissipated / h.work[last]));
  EXPECT_GT(dissipated, 0.05 * h.work[last]) << "the damping must take a real share";
  EXPECT_NEAR(dissipated, rayleigh, 1e-3 * rayleigh);
}

// Frequencies under a vanishing load are the linear Timoshenko chain's (linear_model.cpp, the
// (q, gamma) pencil assembled on its own): the shear angles restored about the statics'
// equilibrium (statics.cpp) must give back the same model, with the rotation terms on the
// sections (clamp, kr) and the foundation. The load's effect is O(load): 1e-9 at 1e-6 N.
TEST(TimoshenkoNonlinear, FrequenciesUnderAVanishingLoadAreTheLinearChainsModes) {
  for (bool terms : {false, true}) {
    const ring::RingSpec spec = pinned(0.2, terms);
    ring::StaticOptions st;
    st.loads.points = {{90.0, {0.0, -1e-6}}};
    st.steps = 1;
    const auto loaded = multibody::compute_modes_under_load(spec, mbtest::dense_chain(40), st, 8);
    const auto linear = multibody::compute_modes(spec, mbtest::dense_chain(40), 8);
    for (int k = 0; k < 8; ++k)
      EXPECT_NEAR(loaded.omega.at(k) / linear.omega.at(k), 1.0, 1e-9) << "terms " << terms << ", mode " << k + 1;
  }
}

TEST(TimoshenkoNonlinear, RefusesThePathsWithoutShearAngles) {
  const ring::RingSpec spec = pinned(0.2);
  ring::MultibodyOptions sparse = mbtest::dense_chain(40);
  sparse.method = ring::MultibodyOptions::Method::sparse;
  auto expect_refusal = [](auto&& run, const std::string& key, const std::string& what) {
    try {
      run();
      ADD_FAILURE() << what << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  const ring::StaticOptions st = point_load(-1e3);
  expect_refusal([&] { multibody::solve_static(spec, sparse, st); }, "multibody.method = \"dense\"", "sparse statics");
  ring::ResponseOptions r = pulse(-1e3, 1e-3, 1e-4, 1e-3);
  expect_refusal([&] { multibody::respond(spec, sparse, r); }, "multibody.method = \"dense\"", "sparse response");
  r.integrator = ring::ResponseOptions::Integrator::energy_momentum;
  expect_refusal([&] { multibody::respond(spec, mbtest::dense_chain(40), r); }, "response.integrator", "energy-momentum");
  // "auto" keeps the Timoshenko chain dense above the statics' and the response's crossovers.
  ring::MultibodyOptions automatic = mbtest::dense_chain(1000);
  automatic.method = ring::MultibodyOptions::Method::automatic;
  EXPECT_EQ(multibody::backend(automatic, spec, st.loads, multibody::Analysis::statics), multibody::Backend::dense);
  EXPECT_EQ(multibody::backend(automatic, spec, r.loads, multibody::Analysis::response), multibody::Backend::dense);
}

}  // namespace
