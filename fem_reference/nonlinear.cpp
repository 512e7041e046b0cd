// The geometrically exact beam's drivers: statics by load stepping and Newton, forced
// response by Newmark or generalized-alpha, and their converged references
// (nonlinear.hpp).
#include "fem_reference/nonlinear.hpp"

#include "fem_reference/checks.hpp"
#include "fem_reference/newton.hpp"
#include "fem_reference/static_path.hpp"
#include "ring/energy_guard.hpp"

namespace fem::detail {
namespace {

/// Inextensible limit: EA = beta EI / R^2 (statics extrapolate from beta and 2 beta).
constexpr double kResponseBeta = 1e7;

Setup make_setup(const ring::RingSpec& spec, const ring::FemOptions& o, double beta) {
  Setup s;
  s.elements = o.elements;
  s.degree = o.degree;
  s.geometry = o.geometry;
  s.EA = o.extensible ? spec.EA() : beta * spec.EI() / (spec.radius * spec.radius);
  return s;
}

/// One discretization's path; inextensible: Richardson in 1/beta from beta and 2 beta
/// (the displacements at the full load and the limit load factor; the path is 2 beta's).
StaticSolve static_at(const ring::RingSpec& spec, const ring::FemOptions& o, Setup setup, const ring::StaticOptions& st,
                      const ContinuationOptions& continuation) {
  if (o.extensible) return trace_path(spec, setup, st, continuation);
  const double base = kInextensibleBeta * spec.EI() / (spec.radius * spec.radius);
  setup.EA = base;
  StaticSolve a = trace_path(spec, setup, st, continuation);
  setup.EA = 2.0 * base;
  StaticSolve b = trace_path(spec, setup, st, continuation);
  auto extrapolate = [](double lo, double hi) { return 2.0 * hi - lo; };
  // Both paths meet the limit point, or (close to a limit at the full load) only one.
  b.limit = std::isnan(a.limit) ? b.limit : std::isnan(b.limit) ? a.limit : extrapolate(a.limit, b.limit);
  b.iterations += a.iterations;
  if (a.end != StaticSolve::End::reached && b.end == StaticSolve::End::reached) {
    a.limit = b.limit;  // report the path that failed
    return a;
  }
  if (b.end != StaticSolve::End::reached) return b;
  for (std::size_t i = 0; i < b.record.size(); ++i)
    for (int c = 0; c < 2; ++c) b.record[i][c] = extrapolate(a.record[i][c], b.record[i][c]);
  for (std::size_t i = 0; i < b.node_x.size(); ++i) {
    b.node_x[i] = extrapolate(a.node_x[i], b.node_x[i]);
    b.node_y[i] = extrapolate(a.node_y[i], b.node_y[i]);
  }
  return b;
}

double largest_change(const std::vector<std::array<double, 2>>& a, const std::vector<std::array<double, 2>>& b) {
  double change = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    change = std::max(change, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1]));
    scale = std::max(scale, std::hypot(b[i][0], b[i][1]));
  }
  return scale > 0 ? change / scale : change;
}

/// Refines the degree (then the cells) until `change(previous, next)` < tolerance;
/// returns the last discretization's result and the number of refinements.
template <class Solve, class Change>
auto refine_until(Setup& setup, double tolerance, Solve&& solve, Change&& change, double& estimate,
                  int& refinements, const std::string& what) {
  auto current = solve(setup);
  for (refinements = 1;; ++refinements) {
    if (refinements > kReferenceMaxSteps)
      throw ring::NumericalError("fem: " + what + " reference not converged after " +
                                 std::to_string(kReferenceMaxSteps) + " refinements");
    if (setup.degree < 12)
      ++setup.degree;
    else
      setup.subdivisions *= 2;
    auto next = solve(setup);
    estimate = change(current, next);
    current = std::move(next);
    if (estimate < tolerance) return current;
  }
}

ring::StaticResult to_result(StaticSolve sol, const ring::StaticOptions& st) {
  ring::StaticResult r;
  r.solver = "fem";
  r.unknowns = sol.unknowns;
  r.steps = sol.steps;
  r.newton_iterations = sol.iterations;
  for (std::size_t i = 0; i < st.record.size(); ++i) r.displacements.push_back({st.record[i], sol.record[i][0], sol.record[i][1]});
  r.node_x = std::move(sol.node_x);
  r.node_y = std::move(sol.node_y);
  return r;
}

ring::StaticResult statics(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  check_static(spec, o, st);
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup = make_setup(spec, o, kInextensibleBeta);
  const ContinuationOptions continuation;
  auto solve = [&](const Setup& s) {
    StaticSolve sol = static_at(spec, o, s, st, continuation);
    if (sol.end != StaticSolve::End::reached) throw ring::NumericalError(failure_message(sol, continuation));
    return sol;
  };
  StaticSolve sol;
  double estimate = 0.0;
  int refinements = 0;
  if (o.reference) {
    sol = refine_until(setup, o.tolerance, solve,
                       [](const StaticSolve& a, const StaticSolve& b) { return largest_change(a.record, b.record); },
                       estimate, refinements, "static");
  } else {
    sol = solve(setup);
  }
  ring::StaticResult r = to_result(std::move(sol), st);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

/// One time integration with one discretization (the file comment's scheme).
ring::TimeHistory respond_once(const ring::RingSpec& spec, const Setup& setup, const ring::ResponseOptions& rs) {
  using Integrator = ring::ResponseOptions::Integrator;
  const auto t0 = std::chrono::steady_clock::now();
  const RingModel model(spec, setup);
  const unsigned int N = model.n_free();
  const Vector<double> F = model.vertex_force(model.vertex_of(rs.load.angle), rs.load.force);
  const SparseMatrix<double>& M = model.mass();
  const bool damped = rs.rayleigh_mass > 0 || rs.rayleigh_stiffness > 0;
  // Generalized-alpha (Chung & Hulbert 1993); Newmark average acceleration is am = af = 0.
  double am = 0.0, af = 0.0, gamma = 0.5, beta = 0.25;
  if (rs.integrator == Integrator::generalized_alpha) {
    am = (2.0 * rs.rho_inf - 1.0) / (rs.rho_inf + 1.0);
    af = rs.rho_inf / (rs.rho_inf + 1.0);
    gamma = 0.5 - am + af;
    beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  }
  const double dt = rs.dt;
  const long long steps = std::llround(rs.t_end / dt);

  ring::TimeHistory h;
  h.solver = "fem";
  h.unknowns = N;
  h.record_angles = rs.record;
  h.ux.resize(rs.record.size());
  h.uy.resize(rs.record.size());
  std::vector<unsigned int> record_vertex;
  for (double a : rs.record) record_vertex.push_back(model.vertex_of(a));
  std::vector<long long> snap_steps;
  for (int k = 0; k < 6; ++k) snap_steps.push_back(std::llround(k * steps / 5.0));

  Vector<double> q(N), v(N), a(N), Cv(N), tmp(N);
  auto damping = [&](const Vector<double>& x, Vector<double>& out) {  // C x
    M.vmult(out, x);
    out *= rs.rayleigh_mass;
    if (rs.rayleigh_stiffness > 0) {
      model.stiffness().vmult(tmp, x);
      out.add(rs.rayleigh_stiffness, tmp);
    }
  };
  double work = 0.0, dissipated = 0.0, strain = 0.0;
  ring::EnergyGuard guard(spec, int(setup.elements * setup.subdivisions * setup.degree), rs.load.force);
  auto record = [&](double t, int iterations) {
    const Vector<double> full = model.expand(q);
    h.t.push_back(t);
    for (std::size_t i = 0; i < record_vertex.size(); ++i) {
      const auto u = model.vertex_displacement(full, record_vertex[i]);
      h.ux[i].push_back(u[0]);
      h.uy[i].push_back(u[1]);
    }
    M.vmult(tmp, v);
    const double T = 0.5 * (v * tmp);
    h.kinetic.push_back(T);
    h.strain.push_back(strain);
    h.work.push_back(work);
    h.energy_error.push_back(T + strain + dissipated - work);
    h.constraint_residual.push_back(0.0);
    h.newton_iterations.push_back(iterations);
  };
  auto snapshot = [&](long long step) {
    if (std::find(snap_steps.begin(), snap_steps.end(), step) == snap_steps.end()) return;
    const Vector<double> full = model.expand(q);
    h.snapshot_t.push_back(h.t.back());
    std::vector<double> sx, sy;
    for (unsigned int k = 0; k < model.cells(); ++k) {
      const auto X = model.vertex_position(k);
      const auto u = model.vertex_displacement(full, k);
      sx.push_back(X[0] + u[0]);
      sy.push_back(X[1] + u[1]);
    }
    h.snapshot_x.push_back(sx);
    h.snapshot_y.push_back(sy);
  };
  auto fail = [&](ring::IntegrationFailure::Reason why, const std::string& msg) {
    h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    throw ring::IntegrationFailure(why, h.t.empty() ? 0.0 : h.t.back(), h, "fem response: " + msg);
  };

  SparseMatrix<double> S(model.sparsity());
  Vector<double> internal(N), qa(N), va(N), aa(N), r(N);
  const double c_m = (1.0 - am) / (beta * dt * dt), c_c = (1.0 - af) * gamma / (beta * dt);
  // The Newton matrix of a step at the generalized midpoint x (internal forces there into
  // `internal`): (1 - af) K_t(x) + c_m M + c_c C.
  auto newton_matrix = [&](const Vector<double>& x) -> SparseMatrix<double>& {
    model.beam_energy(x, &internal, &S);
    S *= (1.0 - af);
    S.add(c_m, M);
    if (rs.rayleigh_mass > 0) S.add(c_c * rs.rayleigh_mass, M);
    if (rs.rayleigh_stiffness > 0) S.add(c_c * rs.rayleigh_stiffness, model.stiffness());
    return S;
  };

  // Start from rest. The acceleration is M qdd_0 = F g(0) (no internal or damping force
  // in the rest state). Newmark starts there. Generalized-alpha starts from the
  // acceleration that its first step's Newton matrix filters, as the multibody chain's
  // (multibody/integrators.hpp, starting_pseudo_acceleration):
  //   [(1 - af) K_t(0) + c_m M + c_c C] a_0 = c_m F g(0),
  // per undamped linear mode a_0 = c qdd_0 / (c + w^2), c = c_m / (1 - af): qdd_0
  // (1 + O(w^2 dt^2)) in the modes the step resolves (second order kept), -> 0 where
  // w dt >> 1. Started at qdd_0, the method's velocity overshoot in the unresolved modes
  // (the point step load gives every mode the acceleration F_k / m_k) gained energy in the
  // first step, the more the smaller rho_inf (its am < 0 from rho_inf < 0.5): on the 20 kN
  // scene (40 cubic elements, dt = 0.01 s) T + V - W after one step was +65 J (rho_inf = 0),
  // +20 J (0.25), +3.3 J (0.5), +1.1 J (0.6) against a work of 67-78 J, and Rayleigh
  // damping b = 0.05 s made it +650 J at rho_inf = 0.8.
  if (rs.integrator == Integrator::generalized_alpha) {
    SparseDirectUMFPACK lu;
    lu.initialize(newton_matrix(q));
    a = F;
    a *= c_m * rs.load.history.factor(0.0);
    lu.solve(a);
  } else {
    SparseDirectUMFPACK lu;
    lu.initialize(M);
    a = F;
    a *= rs.load.history.factor(0.0);
    lu.solve(a);
  }
  record(0.0, 0);
  guard.start(h.kinetic.back(), h.strain.back(), h.work.back());
  snapshot(0);

  double g_old = rs.load.history.factor(0.0);
  for (long long step = 1; step <= steps; ++step) {
    const double t_next = step * dt, t_alpha = t_next - af * dt;
    const double g_alpha = rs.load.history.factor(t_alpha), g_next = rs.load.history.factor(t_next);
    const Vector<double> q_old = q, v_old = v, a_old = a;
    // Predictor q = q_old: then a_{n+1} and v_{n+1} follow from Newmark's relations.
    auto kinematics = [&](const Vector<double>& x) {
      // a_{n+1} = (x - q_n - dt v_n) / (beta dt^2) - (1/(2 beta) - 1) a_n
      a = x;
      a.add(-1.0, q_old, -dt, v_old);
      a *= 1.0 / (beta * dt * dt);
      a.add(-(0.5 / beta - 1.0), a_old);
      v = v_old;
      v.add((1.0 - gamma) * dt, a_old, gamma * dt, a);
    };
    q = q_old;
    const int it = newton(q, spec.radius, [&](const Vector<double>& x, Vector<double>& res) -> SparseMatrix<double>& {
      kinematics(x);
      qa = x;
      qa.sadd(1.0 - af, af, q_old);
      va = v;
      va.sadd(1.0 - af, af, v_old);
      aa = a;
      aa.sadd(1.0 - am, am, a_old);
      newton_matrix(qa);
      res.reinit(N);
      M.vmult(res, aa);
      res += internal;
      if (damped) {
        damping(va, Cv);
        res += Cv;
      }
      res.add(-g_alpha, F);
      return S;
    });
    if (it < 0)
      fail(ring::IntegrationFailure::Reason::step_too_small,
           "Newton did not converge in " + std::to_string(kMaxNewton) + " iterations at t = " + std::to_string(t_next) +
               " s (dt = " + std::to_string(dt) + " s; try a smaller response.dt)");
    kinematics(q);
    if (!std::isfinite(q.l2_norm()) || !std::isfinite(v.l2_norm()))
      fail(ring::IntegrationFailure::Reason::not_finite, "a non-finite state at t = " + std::to_string(t_next) + " s");
    tmp = q;
    tmp -= q_old;
    work += 0.5 * (g_old + g_next) * (F * tmp);
    guard.step(dt, 0.5 * (g_old + g_next));
    g_old = g_next;
    if (damped) {  // trapezoidal rule on v^T C v
      damping(v_old, Cv);
      double p = v_old * Cv;
      damping(v, Cv);
      p += v * Cv;
      dissipated += 0.5 * dt * p;
    }
    strain = model.beam_energy(q, nullptr, nullptr);
    record(t_next, it);
    snapshot(step);
    // A gain is a failed integration, not a result (the one rule: ring/energy_guard.hpp).
    const ring::EnergyGuard::Verdict verdict =
        guard.check(h.kinetic.back(), h.strain.back(), work);
    if (verdict.gained) fail(ring::IntegrationFailure::Reason::energy_growth, ring::describe(verdict, t_next));
  }
  h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}

double peak_change(const ring::TimeHistory& a, const ring::TimeHistory& b) {
  double change = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.ux.size(); ++i) {
    auto peak = [&](const ring::TimeHistory& h) {
      double p = 0.0;
      for (std::size_t k = 0; k < h.t.size(); ++k) p = std::max(p, std::hypot(h.ux[i][k], h.uy[i][k]));
      return p;
    };
    const double pa = peak(a), pb = peak(b);
    change = std::max(change, std::abs(pa - pb));
    scale = std::max(scale, pb);
  }
  return scale > 0 ? change / scale : change;
}

ring::TimeHistory response(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::ResponseOptions& rs) {
  check_response(spec, o, rs);
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup = make_setup(spec, o, kResponseBeta);
  if (!o.reference) return respond_once(spec, setup, rs);
  ring::ResponseOptions fine = rs;
  int refinements = 0;
  double estimate = 0.0;
  auto solve = [&](const Setup& s) {
    ring::TimeHistory h = respond_once(spec, s, fine);
    fine.dt *= 0.5;
    return h;
  };
  ring::TimeHistory h = refine_until(setup, o.response_tolerance, solve, peak_change, estimate, refinements, "response");
  h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}

}  // namespace
}  // namespace fem::detail

namespace fem {

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::FemOptions& options,
                                const ring::StaticOptions& statics) {
  return detail::statics(spec, options, statics);
}

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::ResponseOptions& response) {
  return detail::response(spec, options, response);
}

StaticPath trace_static(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& statics,
                        const ContinuationOptions& continuation) {
  check_static(spec, options, statics);
  if (options.reference)
    throw std::invalid_argument("fem::trace_static: traces one discretization (fem.reference must be false)");
  if (continuation.max_arc_steps < 1)
    throw std::invalid_argument("fem::trace_static: max_arc_steps (=" + std::to_string(continuation.max_arc_steps) +
                                ") must be >= 1");
  const auto t0 = std::chrono::steady_clock::now();
  detail::StaticSolve sol =
      detail::static_at(spec, options, detail::make_setup(spec, options, detail::kInextensibleBeta), statics, continuation);
  StaticPath path;
  path.points = sol.path;
  path.limit_load_factor = sol.limit;
  path.continuation = sol.continuation;
  path.arc_steps = sol.arc_steps;
  path.reached = sol.end == detail::StaticSolve::End::reached;
  if (path.reached) {
    path.result = detail::to_result(std::move(sol), statics);
    path.result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } else {
    path.failure = detail::failure_message(sol, continuation);
  }
  return path;
}

}  // namespace fem
