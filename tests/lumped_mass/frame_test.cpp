// The corotational Timoshenko frame (lumped.variant = "timoshenko-frame" in statics and
// response, lumped_mass/frame.hpp) against oracles that do not come from its own assembly:
// - at rest its energy's Hessian is the linear timoshenko-frame's stiffness K (model.cpp:
//   the element rotated into global DOFs, R^T k R, plus the terms' rows B^T D B), an
//   independent assembly of the same small-displacement model: equal to round-off;
// - its gradient and Hessian at a deformed state (rotations ~0.3 rad) against central
//   differences of its energy and gradient;
// - in the small-load limit its statics are the linear frame's K u = f (KKT with the support
//   rows): the difference is the geometric nonlinearity, O(load^2), so the relative
//   difference falls at order 1 in the load (fitted);
// - the ground's force balances the applied load (equilibrium of the whole ring);
// - the response: the undamped energy balance T + V - W under a constant load, with the
//   midpoint rule's error O(dt^2) (fitted), and the supports held;
// - past the critical follower pressure the statics end at the bifurcation, at the closed
//   form's pressure of the ring on a pin and a roller;
// - the refusals of what the frame does not offer (checks.hpp).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "common.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/checks.hpp"
#include "lumped_mass/frame.hpp"
#include "lumped_mass/model.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "lumped_mass/preload.hpp"
#include "ring/analysis.hpp"
#include "ring/closed_form.hpp"
#include "ring/errors.hpp"
#include "tests/support/convergence.hpp"
#include "tests/support/thick.hpp"

namespace {

using ring::LumpedOptions;
using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;
constexpr LumpedOptions::Variant kTimoshenko = LumpedOptions::Variant::timoshenko_frame;

/// The ring of scenes/thick-ring.toml (R = 0.1 m, depth/R = 0.2, Cowper's kappa), on a pin at
/// 0 deg and a roller at 180 deg.
ring::RingSpec thick() {
  ring::RingSpec s = ringtest::scene_thick_ring();
  s.supports.pin = 0.0;
  s.supports.roller = 180.0;
  return s;
}

/// The same ring with every stiffness term: a foundation, springs kx, ky, kr, a clamp at the pin.
ring::RingSpec with_terms() {
  ring::RingSpec s = thick();
  const double k = s.EI() / std::pow(s.radius, 3);
  s.foundation.radial = 200.0 * k / s.radius;
  s.foundation.tangential = 50.0 * k / s.radius;
  s.supports.springs.push_back({90.0, 10.0 * k, 20.0 * k, 3.0 * k * s.radius * s.radius});
  s.supports.clamp = 0.0;
  return s;
}

Mat dense(const lumped::Triplets& t, int n) {
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return Mat(A);
}

// (1) The Hessian at rest is the linear frame's K, element by element rotated there, terms
// by their rows; both use the same element (Przemieniecki's, or the Hermite element of the
// Euler frames), so this checks the corotational kinematics and the assembly. Tolerance: K's
// entries reach EA/l (~4e11 N/m at n = 24); both sums round at a few eps of that.
TEST(LumpedFrame, RestHessianIsTheLinearFrameStiffness) {
  for (const auto variant : {kTimoshenko, lumptest::kFrame, LumpedOptions::Variant::frame_consistent})
  for (const ring::RingSpec& spec : {thick(), with_terms()})
    for (int n : {8, 24}) {
      const auto o = lumptest::options(n, variant);
      const lumped::Frame f = lumped::make_frame(spec, o);
      const lumped::Springs s = lumped::frame_energy(f, f.rest, 1.0);
      const Mat H = dense(s.hess, 3 * n);
      const Mat K = Mat(lumped::assemble(spec, o).K);
      const double scale = K.cwiseAbs().maxCoeff();
      EXPECT_LE((H - K).cwiseAbs().maxCoeff(), 1e-14 * scale) << "n = " << n;
      std::printf("frame rest Hessian, n = %d: |H - K| / |K| = %.2e\n", n, (H - K).cwiseAbs().maxCoeff() / scale);
      EXPECT_LE(s.grad.cwiseAbs().maxCoeff(), 1e-14 * scale * spec.radius);
      EXPECT_LE(std::abs(s.energy), 1e-30 * scale * spec.radius * spec.radius);  // alpha's rounding, squared
    }
}

// (2) Gradient and Hessian against central differences at a state far from rest: nodes moved
// by up to 0.05 R, elements turned and sections rotated by up to 0.3 rad (fixed seed).
// Central differences of step h err by O(h^2 f''') and by eps f / h: h = 1e-6 R for the
// positions, 1e-6 rad for the rotations (measured 7e-10 for the gradient, 3e-11 for the
// Hessian, relative to the largest entry of their kind); bound 1e-6.
TEST(LumpedFrame, GradientAndHessianMatchCentralDifferences) {
  const ring::RingSpec spec = with_terms();
  const int n = 12;
  const lumped::Frame f = lumped::make_frame(spec, lumptest::options(n, kTimoshenko));
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec q = f.rest;
  const double R = spec.radius;
  for (int j = 0; j < n; ++j) {
    // A rigid turn of 0.3 rad of the whole ring, plus random moves and section rotations.
    const double c = std::cos(0.3), s = std::sin(0.3);
    const double x = f.rest[3 * j], y = f.rest[3 * j + 1];
    q[3 * j] = c * x - s * y + 0.05 * R * u(gen);
    q[3 * j + 1] = s * x + c * y + 0.05 * R * u(gen);
    q[3 * j + 2] = 0.3 + 0.3 * u(gen);
  }
  const lumped::Springs s = lumped::frame_energy(f, q, 1.0);
  const Mat H = dense(s.hess, 3 * n);
  Vec g_fd(3 * n);
  Mat H_fd(3 * n, 3 * n);
  for (int i = 0; i < 3 * n; ++i) {
    const double h = i % 3 == 2 ? 1e-6 : 1e-6 * R;
    Vec qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    const lumped::Springs sp = lumped::frame_energy(f, qp, 0.0), sm = lumped::frame_energy(f, qm, 0.0);
    g_fd[i] = (sp.energy - sm.energy) / (2.0 * h);
    H_fd.col(i) = (sp.grad - sm.grad) / (2.0 * h);
  }
  const double hmax = H.cwiseAbs().maxCoeff();
  // Forces (N) and moments (N m) apart: each against the largest of its kind.
  double force = 0.0, moment = 0.0;
  for (int i = 0; i < 3 * n; ++i) {
    double& most = i % 3 == 2 ? moment : force;
    most = std::max(most, std::abs(s.grad[i]));
  }
  double worst = 0.0;
  for (int i = 0; i < 3 * n; ++i) {
    const double e = std::abs(g_fd[i] - s.grad[i]) / (i % 3 == 2 ? moment : force);
    worst = std::max(worst, e);
    EXPECT_LE(e, 1e-6) << "dof " << i;
  }
  EXPECT_LE((H - H_fd).cwiseAbs().maxCoeff(), 1e-6 * hmax);
  EXPECT_LE((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-15 * hmax);
  std::printf("frame FD: gradient %.2e, Hessian %.2e (relative to the largest entry)\n", worst,
              (H - H_fd).cwiseAbs().maxCoeff() / hmax);
}

/// Linear statics of the linear frame: [K S^T; S 0] (u, mu) = (f, 0), dense.
Vec linear_statics(const ring::RingSpec& spec, const LumpedOptions& o, const Vec& f) {
  const lumped::Model m = lumped::assemble(spec, o);
  const int N = static_cast<int>(m.K.rows()), R = static_cast<int>(m.S.rows());
  Mat A = Mat::Zero(N + R, N + R);
  A.topLeftCorner(N, N) = Mat(m.K);
  A.block(N, 0, R, N) = Mat(m.S);
  A.block(0, N, N, R) = Mat(m.S).transpose();
  Vec rhs = Vec::Zero(N + R);
  rhs.head(N) = f;
  return A.partialPivLu().solve(rhs).head(N);
}

// (3) Small loads: the statics tend to the linear frame's K u = f. A point load F at 90 deg and
// a radial one at 270 deg on the pin-and-roller ring with every term; the nonlinear part of
// the response is O(F^2), so |u - u_lin| / |u_lin| = c F: order 1 in F, fitted over F0, F0/4
// (F0 moves the loaded point by 2.6e-4 R; measured 2.15e-4, 5.38e-5: order 1.000). Bounds: slope within 0.05 of 1 (the O(F^3) rest of
// the Taylor series moves it by ~F, 1e-3 here) and the relative difference at F0 below 1e-2.
TEST(LumpedFrame, SmallLoadStaticsTendToTheLinearFrame) {
  const ring::RingSpec spec = with_terms();
  const auto o = lumptest::options(24, kTimoshenko);
  const double F0 = 1e-3 * spec.radius * 48.0 * spec.EI() / std::pow(spec.radius, 3);
  std::vector<double> load{F0, F0 / 4.0}, rel;
  for (double F : load) {
    ring::StaticOptions st;
    st.loads.points = {{90.0, {0.3 * F, -F}}, {270.0, {0.0, 0.5 * F}}};
    st.steps = 2;
    for (int k = 0; k < 24; ++k) st.record.push_back(15.0 * k);
    const ring::StaticResult r = lumped::solve_static(spec, o, st);
    Vec f = Vec::Zero(3 * 24);
    f[3 * 6] = 0.3 * F;
    f[3 * 6 + 1] = -F;
    f[3 * 18 + 1] = 0.5 * F;
    const Vec u = linear_statics(spec, o, f);
    double diff = 0.0, size = 0.0;
    for (int k = 0; k < 24; ++k) {
      diff = std::max({diff, std::abs(r.displacements[k].ux - u[3 * k]), std::abs(r.displacements[k].uy - u[3 * k + 1])});
      size = std::max({size, std::abs(u[3 * k]), std::abs(u[3 * k + 1])});
    }
    rel.push_back(diff / size);
    std::printf("frame small load: F = %.4e N, max |u| = %.3e m, |u - u_lin| / |u_lin| = %.3e\n", F, size, diff / size);
  }
  const auto samples = ringtest::in_h(load, rel);  // two points: the order in F
  std::printf("frame small load: order in F %.4f\n", ringtest::fit_order(samples).order);
  EXPECT_TRUE(ringtest::OrderNear(samples, 1.0, 0.05));
  EXPECT_LT(rel[0], 1e-2);
}

// (4) The ground's force (support multipliers, springs, foundation) balances the applied load:
// the whole ring's equilibrium, independent of the element. Tolerance: the Newton tolerance
// (1e-12 R) times the stiffest row, EA/l: ~1e-12 R EA/l = 1e-9 of the load here.
TEST(LumpedFrame, GroundForceBalancesTheLoad) {
  const ring::RingSpec spec = with_terms();
  ring::StaticOptions st;
  const double F = 0.05 * 48.0 * spec.EI() / std::pow(spec.radius, 2);
  st.loads.points = {{90.0, {0.4 * F, -F}}};
  st.loads.gravity = {0.0, -9.81e3};
  const auto d = lumped::solve_static_detail(spec, lumptest::options(24, kTimoshenko), st);
  const double weight = spec.rhoA() * 2.0 * M_PI * spec.radius * 9.81e3;
  EXPECT_NEAR(d.ground_force[0], -0.4 * F, 1e-8 * F);
  EXPECT_NEAR(d.ground_force[1], F + weight, 1e-8 * F);
}

/// A response under a step load (constant after t = 0), undamped, midpoint rule.
ring::TimeHistory step_response(const ring::RingSpec& spec, double dt, double t_end) {
  ring::ResponseOptions r;
  r.integrator = ring::ResponseOptions::Integrator::midpoint;
  // Statically ~0.07 R at the loaded point (0.149 F R^3 / EI for the diametral squeeze).
  const double F = 0.01 * 48.0 * spec.EI() / std::pow(spec.radius, 2);
  r.loads.points = {{90.0, {0.0, -F}}};
  r.loads.pressure = {0.2 * F / spec.radius, ring::Pressure::Kind::follower};
  r.history.kind = ring::LoadHistory::Kind::step;
  r.dt = dt;
  r.t_end = t_end;
  r.record = {90.0};
  return lumped::respond(spec, lumptest::options(24, kTimoshenko), r);
}

// (5) The undamped energy balance under a constant load (a point load and follower pressure,
// both conservative, applied as a step): T + V - W stays at the midpoint rule's O(dt^2) error
// of the non-quadratic energy. The step excites the frame's axial and shear modes (periods
// ~1.6e-5 s at n = 24, c / l with c = sqrt(E / rho)); the error is at its order once dt
// resolves them (measured: 1.3e-3, 7.2e-4 of the work at dt = 1e-4, 5e-5 s, order 0.9; 8.3e-6,
// 1.5e-6 at 4e-6, 2e-6 s, order 2.4; 3.8e-7, 9.6e-8 at 1e-6, 5e-7 s, order 2.00), so the fit
// takes dt = 1e-6 and 5e-7 s over two flexural periods: bounds 2 +- 0.2 (the O(dt^4)
// remainder) and 1e-5 of the largest work at dt; the pin and roller hold to round-off (1e-15 R).
TEST(LumpedFrame, UndampedEnergyBalanceIsSecondOrderInDt) {
  const ring::RingSpec spec = thick();
  const double dt = 1e-6, t_end = 2e-3;
  std::vector<double> err;
  for (double h : {dt, dt / 2.0}) {
    const ring::TimeHistory th = step_response(spec, h, t_end);
    double worst = 0.0, work = 0.0, constraint = 0.0;
    for (std::size_t i = 0; i < th.t.size(); ++i) {
      worst = std::max(worst, std::abs(th.kinetic[i] + th.strain[i] - th.work[i]));
      work = std::max(work, std::abs(th.work[i]));
      constraint = std::max(constraint, th.constraint_residual[i]);
    }
    err.push_back(worst / work);
    std::printf("frame response: dt = %.2e s, max |T + V - W| / max W = %.3e, max |S (q - rest)| = %.2e m\n", h,
                worst / work, constraint);
    EXPECT_LE(constraint, 1e-15 * spec.radius);
  }
  EXPECT_LT(err[0], 1e-5);
  const auto samples = ringtest::in_h({dt, dt / 2.0}, err);  // two points: the order in dt
  std::printf("frame response: energy error order in dt %.3f\n", ringtest::fit_order(samples).order);
  EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.2));
}

// (6) Past the critical pressure the statics end at a bifurcation (the driver's test on the
// tangent's count of unstable directions on ker S), bracketed at the continuum's critical
// follower pressure 3 EI/R^3 of a ring on a pin and a roller
// (ring::closed_form::pinned_ring_critical_pressure) on a thin ring (depth/R = 1e-2, where
// shear and the prebuckling shortening move it by ~1e-4) at n = 80. Bound 1 %: the frame's
// O(h^2) (the chain's buckling error is 2e-3 at n = 80; docs/measured.md, "lumped_mass: linear
// buckling") with room.
TEST(LumpedFrame, FollowerPressureBeyondCriticalEndsAtTheBifurcation) {
  ring::RingSpec spec = ringtest::thick_ring(ring::Section::Shape::rectangle, 0.01);
  spec.supports.pin = 180.0;
  spec.supports.roller = 0.0;
  const double critical = ring::closed_form::pinned_ring_critical_pressure(spec, ring::Pressure::Kind::follower);
  ring::StaticOptions st;
  st.loads.pressure = {1.1 * critical, ring::Pressure::Kind::follower};
  st.steps = 10;
  try {
    lumped::solve_static(spec, lumptest::options(80, kTimoshenko), st);
    ADD_FAILURE() << "the frame passed the critical pressure without a bifurcation";
  } catch (const ring::NumericalError& e) {
    const std::string what = e.what();
    const std::string key = "between load factors ";
    const auto at = what.find(key);
    ASSERT_NE(at, std::string::npos) << what;
    const double low = std::stod(what.substr(at + key.size()));
    const double found = 1.1 * low;
    std::printf("frame bifurcation: p_cr = %.6e EI/R^3 (closed form %.6e), relative %.3e\n",
                found * std::pow(spec.radius, 3) / spec.EI() * critical,
                critical * std::pow(spec.radius, 3) / spec.EI(), found - 1.0);
    EXPECT_NEAR(found, 1.0, 1e-2) << what;
  }
}

// The Euler frames' nonlinear model is the corotational frame with the Hermite element: the
// Timoshenko frame's limit as the shear stiffness grows (phi = 12 EI/(kGA l^2) -> 0, the
// Przemieniecki element -> the Hermite element exactly), so with kappa 1e6 times Cowper's the
// two statics agree to O(phi) = 1e-6 of the thick ring's 0.1 phi (measured 1.2e-7 relative).
// The response of frame-consistent (its consistent mass) is taken; the lumped "frame" has
// massless rotations and is refused for the response and the modes under load.
TEST(LumpedFrame, EulerFramesAreTheShearStiffLimitOfTheTimoshenkoFrame) {
  ring::RingSpec stiff = thick();
  stiff.shear_coefficient = 1e6 * stiff.kappa();
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -3.5e5}}};
  st.record = {45.0, 90.0, 135.0};
  st.steps = 10;
  const auto timo = lumped::solve_static(stiff, lumptest::options(40, kTimoshenko), st);
  const auto euler = lumped::solve_static(thick(), lumptest::options(40, lumptest::kFrame), st);
  double gap = 0.0, top = 0.0;
  for (std::size_t i = 0; i < st.record.size(); ++i) {
    gap = std::max(gap, std::hypot(timo.displacements[i].ux - euler.displacements[i].ux,
                                   timo.displacements[i].uy - euler.displacements[i].uy));
    top = std::max(top, std::hypot(euler.displacements[i].ux, euler.displacements[i].uy));
  }
  std::printf("Timoshenko frame, kappa x 1e6, against the Euler frame: %.2e of %.3e m\n", gap / top, top);
  EXPECT_LT(gap, 1e-6 * top);
  ring::ResponseOptions r;
  r.loads = st.loads;
  r.dt = 2e-6;
  r.t_end = 2e-5;
  EXPECT_NO_THROW(lumped::check_response(thick(), lumptest::options(40, LumpedOptions::Variant::frame_consistent), r));
  EXPECT_THROW(lumped::check_response(thick(), lumptest::options(40, lumptest::kFrame), r), std::invalid_argument);
  EXPECT_THROW(lumped::check_preloaded_modes(thick(), lumptest::options(40, lumptest::kFrame), st),
               std::invalid_argument);
}

// The frame's linear buckling under follower pressure (buckling.cpp: its tangent along the
// linear prebuckling path). Oracle: the inextensible ring with shear, p_cr = 3 EI/R^3 /
// (1 + 4 EI/(kGA R^2)) (derived in tests/multibody/test_buckling.cpp; Levy's 3 EI/R^3 with the
// shear in series with the bending), which the extensible frame meets up to its hoop strain,
// O(I/(A R^2)) = 8e-6 on this ring (depth/R = 0.01); the frame converges to it at its order 2.
TEST(LumpedFrame, BucklesUnderFollowerPressureAtTheShearReducedCriticalPressure) {
  ring::RingSpec spec = ringtest::thick_ring(ring::Section::Shape::rectangle, 0.01);
  spec.supports.pin = 180.0;
  spec.supports.roller = 0.0;
  const double R = spec.radius, exact = 3.0 * spec.EI() / std::pow(R, 3) / (1.0 + 4.0 * spec.EI() / (spec.kGA() * R * R));
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, ring::Pressure::Kind::follower};
  b.count = 1;
  const std::vector<int> ns{40, 80, 160};
  std::vector<double> err;
  for (int n : ns) {
    err.push_back(std::abs(lumped::compute_buckling(spec, lumptest::options(n, kTimoshenko), b).factors.at(0) / exact - 1.0));
    std::printf("frame buckling n = %d: relative error %.3e\n", n, err.back());
  }
  EXPECT_LT(err[2], 1e-3);
  for (int i = 0; i + 1 < 3; ++i)  // each refinement's two-point order
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{ns[i], ns[i + 1]}, {err[i], err[i + 1]}), 2.0, 0.15));
}

// Frequencies under a vanishing load are the linear frame's (model.cpp, an independent
// assembly of the same small-displacement model): the load's effect is O(load), 1e-9 of the
// frequencies at this load (1e-6 N against a collapse load of ~1e6 N).
TEST(LumpedFrame, FrequenciesUnderAVanishingLoadAreTheLinearFramesModes) {
  const ring::RingSpec spec = thick();
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -1e-6}}};
  st.steps = 1;
  for (const auto variant : {kTimoshenko, LumpedOptions::Variant::frame_consistent}) {
    const auto loaded = lumped::compute_modes_under_load(spec, lumptest::options(40, variant), st, 8);
    const auto linear = lumped::compute_modes(spec, lumptest::options(40, variant), 8);
    for (int k = 0; k < 8; ++k)
      EXPECT_NEAR(loaded.omega.at(k) / linear.omega.at(k), 1.0, 1e-9) << ring::to_string(variant) << " mode " << k + 1;
  }
}

// (7) What the frame does not offer is refused with the key named.
TEST(LumpedFrame, RefusesWhatItDoesNotOffer) {
  const ring::RingSpec spec = thick();
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -1.0}}};
  st.path = true;
  EXPECT_NE(message([&] { lumped::check_static(spec, lumptest::options(24, kTimoshenko), st); }).find("static.path"),
            std::string::npos);
  st.path = false;
  EXPECT_NO_THROW(lumped::check_static(spec, lumptest::options(24, lumptest::kFrame), st));
  ring::BucklingOptions b;
  b.loads = st.loads;
  EXPECT_NO_THROW(lumped::check_buckling(spec, lumptest::options(24, lumptest::kFrame), b));
  EXPECT_NE(message([&] { lumped::check_preloaded_modes(spec, lumptest::options(24, lumptest::kFrame), st); })
                .find("massless"),
            std::string::npos);
  ring::ResponseOptions r;
  r.loads = st.loads;
  r.hinge_damping = 1.0;
  EXPECT_NE(message([&] { lumped::check_response(spec, lumptest::options(24, kTimoshenko), r); })
                .find("response.hinge_damping"),
            std::string::npos);
}

}  // namespace
