// The geometrically exact beam's drivers: statics by load stepping and Newton, forced
// response by Newmark or generalized-alpha, and their converged references
// (nonlinear.hpp).
#include "fem_reference/nonlinear.hpp"

#include "fem_reference/beam_potential.hpp"
#include "fem_reference/checks.hpp"
#include "fem_reference/newton.hpp"
#include "paths/schemes.hpp"
#include "fem_reference/reference.hpp"
#include "fem_reference/static_path.hpp"
#include "paths/time_stepping.hpp"
#include "ring/energy_guard.hpp"

namespace fem::detail {
namespace {

/// Inextensible limit: EA = beta EI / R^2 (statics extrapolate from beta and 2 beta).
constexpr double kResponseBeta = 1e7;

/// ring.plastic's response: the smallest sub-step, dt / this (respond_once).
constexpr int kPlasticSubsteps = 64;

Setup make_setup(const ring::RingSpec& spec, const ring::FemOptions& o, double beta) {
  Setup s;
  s.elements = o.elements;
  s.degree = o.degree;
  s.geometry = o.geometry;
  s.theory = spec.theory;  // Euler-Bernoulli: RingModel; Timoshenko: the Reissner beam (make_beam)
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
  double &la = a.trace.limit, &lb = b.trace.limit;
  lb = std::isnan(la) ? lb : std::isnan(lb) ? la : extrapolate(la, lb);
  b.trace.iterations += a.trace.iterations;
  if (!a.reached() && b.reached()) {
    la = lb;  // report the path that failed
    return a;
  }
  if (!b.reached()) return b;
  for (std::size_t i = 0; i < b.record.size(); ++i)
    for (int c = 0; c < 2; ++c) b.record[i][c] = extrapolate(a.record[i][c], b.record[i][c]);
  for (std::size_t i = 0; i < b.node_x.size(); ++i) {
    b.node_x[i] = extrapolate(a.node_x[i], b.node_x[i]);
    b.node_y[i] = extrapolate(a.node_y[i], b.node_y[i]);
  }
  b.dissipated = extrapolate(a.dissipated, b.dissipated);
  for (int c = 0; c < 2; ++c) b.reaction[c] = extrapolate(a.reaction[c], b.reaction[c]);
  b.plastic_curvature = extrapolate(a.plastic_curvature, b.plastic_curvature);
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

ring::StaticResult to_result(StaticSolve sol, const ring::StaticOptions& st) {
  ring::StaticResult r;
  r.solver = "fem";
  r.unknowns = sol.unknowns;
  r.steps = sol.trace.steps;
  r.newton_iterations = sol.trace.iterations;
  for (std::size_t i = 0; i < st.record.size(); ++i) r.displacements.push_back({st.record[i], sol.record[i][0], sol.record[i][1]});
  r.node_x = std::move(sol.node_x);
  r.node_y = std::move(sol.node_y);
  r.dissipated = sol.dissipated;
  r.plastic_curvature = sol.plastic_curvature;
  r.reaction = sol.reaction;
  r.contact_length = sol.contact_length;
  if (st.path) {
    const bool touched = sol.trace.end == paths::Trace::End::contact;
    r.path = std::move(sol.points);
    r.branch_points = sol.trace.branch_points;
    r.limit_points = std::move(sol.limits);
    r.end = touched ? "contact: " + sol.trace.contact : st.history.empty() ? "full load" : "end of the history";
    r.end_load = sol.trace.end_load;  // the touch, or the full load (a history: its last factor)
  }
  return r;
}

ring::StaticResult statics(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  check_static(spec, o, st);
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup = make_setup(spec, o, kInextensibleBeta);
  const ContinuationOptions continuation;
  auto solve = [&](const Setup& s) {
    StaticSolve sol = static_at(spec, o, s, st, continuation);
    // static.path (one extensible discretization, check_static): contact is a result.
    const bool touched = st.path && sol.trace.end == paths::Trace::End::contact;
    if (!sol.reached() && !touched) throw ring::NumericalError(failure_message(sol, continuation));
    return sol;
  };
  StaticSolve sol;
  double estimate = 0.0;
  int refinements = 0;
  if (o.reference) {
    sol = refine_until(setup, o.tolerance, solve,
                       [](const StaticSolve& a, const StaticSolve& b) {
                         // A driven path's result is its reaction as much as its record.
                         return std::max(largest_change(a.record, b.record),
                                         largest_change({a.reaction}, {b.reaction}));
                       },
                       estimate, refinements, "static");
  } else {
    sol = solve(setup);
  }
  ring::StaticResult r = to_result(std::move(sol), st);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

/// The beam's Newmark / generalized-alpha step (Chung & Hulbert 1993; Newmark's average
/// acceleration is am = af = 0) for the time-stepping driver (paths/time_stepping.hpp):
/// full Newton on the generalized-midpoint balance M a + C v + grad V(q) = g grad Phi(q)
/// (BeamPotential: the beam, its terms and its loads, each load at the generalized
/// midpoint), the loads' work g_mean (Phi(q_1) - Phi(q_0)) per step (exact for a load
/// factor constant over the step: every load has a potential), the damping's dissipation
/// by the trapezoidal rule on v^T C v.
/// ring.plastic: the plastic states of the bending points (and vertex hinges) are internal
/// variables (paths/internal.hpp): every Newton iterate evaluates the law at the generalized
/// midpoint from the committed states (a return map, so a rejected attempt leaves nothing
/// behind and reject() has nothing to discard), and accept() commits them at the step's end
/// q_1, adding the step's plastic work; V is then the elastic energy stored.
class BeamStepper : public paths::Stepper {
 public:
  BeamStepper(const BeamModel& model, const ring::RingSpec& spec, const ring::ResponseOptions& rs)
      : model_(model), potential_(model, rs.loads), rs_(rs), radius_(spec.radius), N_(model.n_free()), M_(model.mass()),
        damped_(rs.rayleigh_mass > 0 || rs.rayleigh_stiffness > 0), scheme_(paths::Scheme::of(rs)), am_(scheme_.alpha_m),
        af_(scheme_.alpha_f), gamma_(scheme_.gamma), beta_(scheme_.beta), law_(potential_.plastic_law()),
        S_(model.sparsity()) {
    if (law_) plastic_.assign(potential_.plastic_states(), ring::PlasticState{});
    for (double a : rs.record) record_vertex_.push_back(model.vertex_of(a));
    for (auto* v : {&q_, &v_, &a_, &q1_, &v1_, &a1_, &Cv_, &tmp_, &internal_, &qa_, &va_, &aa_}) v->reinit(N_);
    Vector<double> F0;  // the load at rest, grad Phi(0)
    potential_.evaluate(q_, 0.0, nullptr, nullptr, &F0);
    // Start from rest. The acceleration is M qdd_0 = F g(0) (no internal or damping force
    // in the rest state). Newmark starts there. Generalized-alpha starts from the
    // acceleration that its first step's Newton matrix filters, as the multibody chain's
    // (multibody/integrators.hpp, starting_pseudo_acceleration):
    //   [(1 - af) K_t(0) + c_m M + c_c C] a_0 = c_m F g(0)  (K_t with the load stiffness at g(0)),
    // per undamped linear mode a_0 = c qdd_0 / (c + w^2), c = c_m / (1 - af): qdd_0
    // (1 + O(w^2 dt^2)) in the modes the step resolves (second order kept), -> 0 where
    // w dt >> 1. Started at qdd_0, the method's velocity overshoot in the unresolved modes
    // (the point step load gives every mode the acceleration F_k / m_k) gained energy in the
    // first step, the more the smaller rho_inf (its am < 0 from rho_inf < 0.5): on the 20 kN
    // scene (40 cubic elements, dt = 0.01 s) T + V - W after one step was +65 J (rho_inf = 0),
    // +20 J (0.25), +3.3 J (0.5), +1.1 J (0.6) against a work of 67-78 J, and Rayleigh
    // damping b = 0.05 s made it +650 J at rho_inf = 0.8.
    SparseDirectUMFPACK lu;
    a_ = F0;
    if (rs.integrator == ring::ResponseOptions::Integrator::generalized_alpha) {
      lu.initialize(newton_matrix(q_, rs.dt, rs.history.factor(0.0)));
      a_ *= scheme_.mass_rate(rs.dt) * rs.history.factor(0.0);
    } else {
      lu.initialize(M_);
      a_ *= rs.history.factor(0.0);
    }
    lu.solve(a_);
  }

  paths::StepOutcome try_step(double t, double h) override {
    const double g_alpha = rs_.history.factor(t + h - af_ * h);
    g_mean_ = 0.5 * (rs_.history.factor(t) + rs_.history.factor(t + h));
    h_ = h;
    q1_ = q_;
    const int it = newton(q1_, radius_, [&](const Vector<double>& x, Vector<double>& res) -> SparseMatrix<double>& {
      kinematics(x, h);
      qa_ = x;
      qa_.sadd(1.0 - af_, af_, q_);
      va_ = v1_;
      va_.sadd(1.0 - af_, af_, v_);
      aa_ = a1_;
      aa_.sadd(1.0 - am_, am_, a_);
      newton_matrix(qa_, h, g_alpha);
      res.reinit(N_);
      M_.vmult(res, aa_);
      res += internal_;
      if (damped_) {
        damping(va_, Cv_);
        res += Cv_;
      }
      return S_;
    }, std::numeric_limits<double>::infinity(), &model_.lengths());
    if (it < 0) return {false, false, paths::kNewtonCap, g_mean_};
    kinematics(q1_, h);
    return {true, false, it, g_mean_};
  }

  void accept(double) override {
    if (law_) {
      // Commit first: V below is then the elastic energy stored at the new state.
      const Committed step = commit(*law_, model_.bending_points(q1_, Plasticity{*law_, plastic_}), plastic_);
      plastic_work_ += step.dissipated;
    }
    const BeamPotential::Value next = potential_.evaluate(q1_, 0.0, nullptr, nullptr, nullptr, committed());
    work_ += g_mean_ * (next.load - energy_.load);
    energy_ = next;
    if (damped_) {
      damping(v_, Cv_);
      double p = v_ * Cv_;
      damping(v1_, Cv_);
      p += v1_ * Cv_;
      dissipated_ += 0.5 * h_ * p;
    }
    q_ = q1_;
    v_ = v1_;
    a_ = a1_;
  }

  bool finite() const override { return std::isfinite(q_.l2_norm()) && std::isfinite(v_.l2_norm()); }

  paths::Sample sample() const override {
    paths::Sample out;
    const Vector<double> full = model_.expand(q_);
    for (unsigned int vertex : record_vertex_) {
      const auto u = model_.vertex_displacement(full, vertex);
      out.ux.push_back(u[0]);
      out.uy.push_back(u[1]);
    }
    Vector<double> Mv(N_);
    M_.vmult(Mv, v_);
    out.kinetic = 0.5 * (v_ * Mv);
    out.strain = energy_.stored;
    out.work = work_;
    out.dissipated = dissipated_;
    if (law_) out.plastic = plastic_work_;  // the record's dissipated; the balance and the guard count it
    return out;
  }

  void shape(std::vector<double>& x, std::vector<double>& y) const override {
    const Vector<double> full = model_.expand(q_);
    x.clear();
    y.clear();
    for (unsigned int k = 0; k < model_.vertices(); ++k) {
      const auto X = model_.vertex_position(k);
      const auto u = model_.vertex_displacement(full, k);
      x.push_back(X[0] + u[0]);
      y.push_back(X[1] + u[1]);
    }
  }

 private:
  /// a_1 and v_1 from Newmark's relations for the end position x of a step of h:
  /// a_1 = (x - q - h v) / (beta h^2) - (1/(2 beta) - 1) a, v_1 = v + h ((1 - gamma) a + gamma a_1).
  void kinematics(const Vector<double>& x, double h) {
    a1_ = x;
    a1_.add(-1.0, q_, -h, v_);
    a1_ *= scheme_.acceleration_rate(h);
    a1_.add(-(0.5 / beta_ - 1.0), a_);
    v1_ = v_;
    v1_.add((1.0 - gamma_) * h, a_, gamma_ * h, a1_);
  }
  /// The Newton matrix of a step of h at the generalized midpoint x with the load factor g
  /// there (grad V - g grad Phi into internal_): (1 - af) K_t(x) + c_m M + c_c C, K_t the
  /// tangent of V - g Phi (the load stiffness of follower and central pressure included).
  SparseMatrix<double>& newton_matrix(const Vector<double>& x, double h, double g) {
    const double c_m = scheme_.mass_rate(h), c_c = (1.0 - af_) * scheme_.velocity_rate(h);
    potential_.evaluate(x, g, &internal_, &S_, nullptr, committed());
    S_ *= (1.0 - af_);
    S_.add(c_m, M_);
    if (rs_.rayleigh_mass > 0) S_.add(c_c * rs_.rayleigh_mass, M_);
    if (rs_.rayleigh_stiffness > 0) S_.add(c_c * rs_.rayleigh_stiffness, model_.stiffness());
    return S_;
  }
  /// out = C x, C = a M + b K0.
  void damping(const Vector<double>& x, Vector<double>& out) {
    M_.vmult(out, x);
    out *= rs_.rayleigh_mass;
    if (rs_.rayleigh_stiffness > 0) {
      model_.stiffness().vmult(tmp_, x);
      out.add(rs_.rayleigh_stiffness, tmp_);
    }
  }

  /// The committed plastic states for BeamPotential::evaluate; null without ring.plastic.
  const std::vector<ring::PlasticState>* committed() const { return law_ ? &plastic_ : nullptr; }

  const BeamModel& model_;
  const BeamPotential potential_;
  const ring::ResponseOptions& rs_;
  const double radius_;
  const unsigned int N_;
  const SparseMatrix<double>& M_;
  const bool damped_;
  const paths::Scheme scheme_;  ///< Newmark or generalized-alpha (paths/schemes.hpp)
  const double am_, af_, gamma_, beta_;  ///< its coefficients, by their short names
  const std::optional<PlasticLaw>& law_;  ///< ring.plastic's, or nullopt
  std::vector<ring::PlasticState> plastic_;  ///< committed, per bending point (plastic_points.hpp)
  double plastic_work_ = 0.0;                ///< J, from rest
  std::vector<unsigned int> record_vertex_;
  SparseMatrix<double> S_;
  Vector<double> q_, v_, a_, q1_, v1_, a1_, Cv_, tmp_, internal_, qa_, va_, aa_;
  double h_ = 0.0, g_mean_ = 0.0, work_ = 0.0, dissipated_ = 0.0;
  BeamPotential::Value energy_;  ///< V and Phi of the accepted state (0 at rest)
};

/// One time integration with one discretization. The elastic beam takes no sub-steps: a step
/// whose Newton fails ends the run (step_too_small), and the reference refines dt itself.
/// ring.plastic: the driver halves a failed step down to dt / 64 (kPlasticSubsteps): Newton on
/// the piecewise quadratic potential can fail where a bending point, a fibre or a hinge sits
/// at its yield edge. Measured on the pinched ring (fem_plastic_response_test): the fibre law
/// under a step load 0.9 P_c at dt = 0.04 s failed at t = 1.96 s without sub-steps and runs
/// with them. Not every failure yields: the resultant law under an undamped 3 s ramp to
/// 0.9 P_c (held) failed at t = 4.16 s at dt = 0.04 s with the step halved to dt / 128 too.
/// The record is the driver's, at the grid points (paths::Sample::plastic included).
ring::TimeHistory respond_once(const ring::RingSpec& spec, const Setup& setup, const ring::ResponseOptions& rs) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::unique_ptr<BeamModel> built = make_beam(spec, setup);
  const BeamModel& model = *built;
  BeamStepper stepper(model, spec, rs);
  // A gain is a failed integration, not a result (the one rule: ring/energy_guard.hpp).
  ring::EnergyGuard guard(spec, int(setup.elements * setup.subdivisions * setup.degree), ring::load_scale(spec, rs.loads));
  paths::Grid grid;
  grid.dt = rs.dt;
  grid.t_end = rs.t_end;
  grid.min_dt_factor = spec.plastic ? 1.0 / kPlasticSubsteps : 1.0;
  grid.check_contact = false;
  grid.guard = &guard;
  grid.who = "fem response";
  grid.progress = rs.progress;
  ring::TimeHistory h = paths::integrate(stepper, grid, rs.record);
  h.solver = "fem";
  h.unknowns = model.n_free();
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
  path.limit_load_factor = sol.trace.limit;
  path.continuation = sol.trace.continuation;
  path.arc_steps = sol.trace.arc_steps;
  path.reached = sol.reached();
  if (path.reached) {
    path.result = detail::to_result(std::move(sol), statics);
    path.result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } else {
    path.failure = detail::failure_message(sol, continuation);
  }
  return path;
}

}  // namespace fem
