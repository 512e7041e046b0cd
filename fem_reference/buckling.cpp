// Linear buckling of the geometrically exact beam (buckling.hpp): the pencil of one
// discretization from the beam's own tangent, the inextensible extrapolation, and the
// statics' reference refinement.
#include "fem_reference/buckling.hpp"

#include <Eigen/Dense>

#include "fem_reference/beam_potential.hpp"
#include "fem_reference/pencil.hpp"
#include "fem_reference/reference.hpp"

namespace fem::detail {
namespace {

/// The strain (and rotation) scale x = h max|u_1| / R of the difference that gives K_1
/// (buckling.hpp). The tangent's entries are the membrane stiffness EA, its change along the
/// path EA x: the difference keeps ~eps / x of it, and that noise enters a bending mode's
/// factor amplified by the membrane-to-bending spread of K_0 (~1e8 here), while the
/// five-point stencil's truncation is O(x^4). Measured on the paper's ring (relative error
/// of the converged factors): x = 1e-6 (two-point stencil) 1e-7; 1e-4: 1e-9; 1e-3: 1e-10;
/// 3e-3: 2e-11; 1e-2: 2.3e-9 (truncation).
constexpr double kPathStrain = 3e-3;

/// One discretization's factors (at one EA).
struct Buckled {
  std::vector<double> factors;
  std::vector<ring::ModeShape> shapes;
  long long unknowns = 0;
  double path_step = 0.0;  ///< h: the difference's states are t u_1 at t = +-h, +-2h
  double residual = 0.0;   ///< the worst wanted pair's relative residual (refine())
};

/// The pencil (T_0, K_1) of `setup` and its lowest positive factors. `refining`: a step
/// of the reference (a size above the dense limit is then a failed refinement, not a
/// request that can never work).
Buckled buckle_once(const ring::RingSpec& spec, const Setup& setup, const ring::BucklingOptions& b, bool refining) {
  const std::unique_ptr<BeamModel> built = make_beam(spec, setup);  // Euler or Reissner
  const BeamModel& model = *built;
  const unsigned int N = model.n_free();
  check_dense_size(setup, N, refining, "buckling");
  if (b.count > static_cast<int>(N))
    throw std::invalid_argument("fem: buckling.count (=" + std::to_string(b.count) + ") must be <= the unknowns (=" +
                                std::to_string(N) + ") of " + std::to_string(setup.cells()) + " cells of degree " +
                                std::to_string(setup.degree));
  const BeamPotential potential(model, b.loads);
  SparseMatrix<double> T(model.sparsity());
  Vector<double> q(N), residual, f;
  potential.evaluate(q, 0.0, &residual, &T, &f);  // T_0 = K_0 and the load f = grad Phi(0)
  const Eigen::MatrixXd K0 = dense(T);

  // The linear prebuckling state u_1 (T_0 u_1 = f).
  Vector<double> u1 = f;
  SparseDirectUMFPACK lu;
  try {
    lu.initialize(T);
  } catch (const std::exception& e) {
    throw ring::NumericalError(std::string("fem buckling: the tangent at rest is singular: ") + e.what());
  }
  lu.solve(u1);
  const double largest = model.length_of(u1);  // a rotation psi counts as R psi
  if (!std::isfinite(largest)) throw ring::NumericalError("fem buckling: the linear prebuckling state is not finite");
  // Loads that do not displace the ring (f = 0) leave only their load stiffness; any h
  // then differences it exactly.
  const double h = largest > 0 ? kPathStrain * spec.radius / largest : 1.0;

  // K_1 = [8 (T(h) - T(-h)) - (T(2h) - T(-2h))] / 12h, T(t) = T(t u_1, t).
  auto tangent_at = [&](double t) {
    q = u1;
    q *= t;
    potential.evaluate(q, t, &residual, &T);
    return dense(T);
  };
  const Eigen::MatrixXd K1 =
      (8.0 * (tangent_at(h) - tangent_at(-h)) - (tangent_at(2.0 * h) - tangent_at(-2.0 * h))) / (12.0 * h);

  const Pairs pairs = refine(model, lu, Eigen::MatrixXd(), K1, raw_pairs(K0, K1, b.count, N), b.count, "fem buckling");
  Buckled out;
  out.unknowns = N;
  out.path_step = h;
  out.residual = pairs.residual;
  Vector<double> phi(N);
  for (int i = 0; i < b.count; ++i) {
    out.factors.push_back(pairs.factors[i]);
    for (unsigned int k = 0; k < N; ++k) phi[k] = pairs.vectors(k, i);
    out.shapes.push_back(model.sample(model.expand(phi)));
  }
  return out;
}

/// One discretization with the modes' inextensible extrapolation (buckling.hpp).
Buckled buckle(const ring::RingSpec& spec, Setup setup, bool extensible, const ring::BucklingOptions& b,
               bool refining) {
  if (extensible) {
    setup.EA = spec.EA();
    return buckle_once(spec, setup, b, refining);
  }
  const double base = kInextensibleBeta * spec.EI() / (spec.radius * spec.radius);
  setup.EA = base;
  const Buckled lo = buckle_once(spec, setup, b, refining);
  setup.EA = 2.0 * base;
  Buckled hi = buckle_once(spec, setup, b, refining);
  for (std::size_t i = 0; i < hi.factors.size(); ++i) hi.factors[i] = 2.0 * hi.factors[i] - lo.factors[i];
  return hi;
}

/// The largest relative change of the factors between two discretizations.
double largest_change(const Buckled& a, const Buckled& b) {
  double change = 0.0;
  for (std::size_t i = 0; i < a.factors.size(); ++i)
    change = std::max(change, std::abs(b.factors[i] - a.factors[i]) / std::abs(b.factors[i]));
  return change;
}

ring::BucklingResult buckling(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::BucklingOptions& b) {
  check_buckling(spec, o, b);
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup;
  setup.elements = o.elements;
  setup.degree = o.degree;
  setup.geometry = o.geometry;
  setup.theory = spec.theory;
  Buckled result;
  double estimate = 0.0;
  int refinements = 0;
  if (o.reference) {
    bool first = true;
    auto solve = [&](const Setup& s) {
      Buckled next = buckle(spec, s, o.extensible, b, !first);
      first = false;
      return next;
    };
    result = refine_until(setup, o.tolerance, solve, largest_change, estimate, refinements, "buckling");
  } else {
    result = buckle(spec, setup, o.extensible, b, false);
  }
  ring::BucklingResult r;
  r.solver = "fem";
  r.model["elements"] = static_cast<long long>(setup.elements);
  r.model["cells"] = static_cast<long long>(setup.cells());
  r.model["subdivisions"] = static_cast<long long>(setup.subdivisions);
  r.model["degree"] = static_cast<long long>(setup.degree);
  r.model["extensible"] = o.extensible;
  r.model["reference"] = o.reference;
  r.model["refinements"] = static_cast<long long>(refinements);
  r.model["path_step"] = result.path_step;
  r.model["max_residual"] = result.residual;  // refine(): dual norm of K_0
  r.factors = std::move(result.factors);
  r.shapes = std::move(result.shapes);
  r.unknowns = result.unknowns;
  r.error_estimate = estimate;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace
}  // namespace fem::detail

namespace fem {

ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::FemOptions& options,
                                      const ring::BucklingOptions& buckling) {
  return detail::buckling(spec, options, buckling);
}

}  // namespace fem
