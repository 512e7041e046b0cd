// Frequencies under load of the geometrically exact beam (preload.hpp): the statics' own
// equilibrium path, the tangent and mass there, the shared dense step (pencil.hpp) and the
// inextensible extrapolation.
#include "fem_reference/preload.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "fem_reference/beam_potential.hpp"
#include "fem_reference/pencil.hpp"
#include "fem_reference/static_path.hpp"
#include "modal/buckling.hpp"
#include "modal/modes.hpp"

namespace fem::detail {
namespace {

const std::string kWho = "fem modes under load";

/// One discretization's modes (at one EA).
struct Loaded {
  std::vector<double> omega2;  ///< ascending
  std::vector<ring::ModeShape> shapes;
  long long unknowns = 0;
  double residual = 0.0;  ///< the worst mode's, in the modes' definition (preload.hpp)
};

/// The equilibrium of `st` at the full load with `setup` and the modes about it.
Loaded loaded_once(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st, int count) {
  const std::unique_ptr<BeamModel> built = make_beam(spec, setup);  // Euler or Reissner
  const BeamModel& model = *built;
  const unsigned int N = model.n_free();
  check_dense_size(setup, N, false, "modes under load");
  if (count > static_cast<int>(N))
    throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be <= the unknowns (=" +
                                std::to_string(N) + ") of " + std::to_string(setup.cells()) + " cells of degree " +
                                std::to_string(setup.degree));

  // q*: the statics' own path from rest to the full load (static_path.hpp).
  ring::StaticOptions at_full_load = st;
  at_full_load.path = false;
  const ContinuationOptions continuation;
  const StaticSolve path = trace_path(spec, setup, at_full_load, continuation);
  if (!path.reached()) {
    // A bifurcation or a limit point on the way: the full load lies past a critical load.
    const bool critical = path.trace.end == paths::Trace::End::bifurcation || !std::isnan(path.trace.limit);
    throw ring::NumericalError(kWho + (critical ? ": the loaded ring is at or past a critical load: " : ": ") +
                               "the equilibrium path from rest does not reach the full load: " +
                               paths::failure_message(path.trace, continuation));
  }
  Vector<double> q(N);
  for (unsigned int i = 0; i < N; ++i) q[i] = path.trace.state.z(i);

  // T(q*, 1), and T(0, 0) = K_0, whose product the refinement takes in extended precision.
  const BeamPotential potential(model, st.loads);
  SparseMatrix<double> T(model.sparsity());
  Vector<double> residual;
  potential.evaluate(Vector<double>(N), 0.0, &residual, &T);
  const Eigen::MatrixXd K0 = dense(T);
  potential.evaluate(q, 1.0, &residual, &T);
  const Eigen::MatrixXd M = dense(model.mass());
  const double s = modal::bending_scale(spec);
  const Eigen::MatrixXd Td = dense(T);

  // The raw pairs by the one loaded-modes step of every solver (modal::loaded_modes: the
  // shifted inverse of T + s M; it throws, saying the ring is at or past a critical load,
  // when T + s M is not positive definite or an omega^2 <= 0), with guard pairs for the
  // refinement, whose pencil is (P + lambda Q), P = T + s M, Q = -M, lambda = omega^2 + s.
  const int guarded = static_cast<int>(std::min<unsigned int>(N, count + kGuardModes));
  const modal::LoadedModes raw = modal::loaded_modes(Td, M, s, guarded, kWho);
  Pairs pairs;
  for (int k = 0; k < guarded; ++k) pairs.factors.push_back(raw.omega2(k) + s);
  pairs.vectors = raw.vectors;
  SparseMatrix<double>& S = T;  // the sparse P for the refinement's corrections
  S.add(s, model.mass());
  SparseDirectUMFPACK lu;
  try {
    lu.initialize(S);
  } catch (const std::exception& e) {
    throw ring::NumericalError(kWho + ": T + s M is singular: " + e.what());
  }
  pairs = refine(model, lu, Td - K0 + s * M, -M, std::move(pairs), count, kWho);

  Loaded out;
  out.unknowns = N;
  Vector<double> x(N);
  for (int k = 0; k < count; ++k) {
    const double w2 = pairs.factors[k] - s;
    if (!(w2 > 0.0))
      throw ring::NumericalError(kWho + ": omega^2 = " + std::to_string(w2) + " <= 0 for mode " +
                                 std::to_string(k + 1) +
                                 " at the equilibrium: the loaded ring is at or past a critical load");
    out.omega2.push_back(w2);
    // refine()'s sqrt(r^T P^-1 r / x^T P x) -> the modes' ||r||_* / (||T x||_* + w2 ||M x||_*):
    // for a pair, x^T P x = (w2 + s) x^T M x and the denominator is 2 w2 sqrt(x^T M x / (w2 + s)).
    out.residual = modal::worst(out.residual, pairs.residuals[k] * (w2 + s) / (2.0 * w2));
    for (unsigned int i = 0; i < N; ++i) x[i] = pairs.vectors(i, k);
    out.shapes.push_back(model.sample(model.expand(x)));
  }
  return out;
}

/// One discretization with the modes' inextensible extrapolation (preload.hpp).
Loaded loaded(const ring::RingSpec& spec, Setup setup, bool extensible, const ring::StaticOptions& st, int count) {
  if (extensible) {
    setup.EA = spec.EA();
    return loaded_once(spec, setup, st, count);
  }
  const double base = kInextensibleBeta * spec.EI() / (spec.radius * spec.radius);
  setup.EA = base;
  const Loaded lo = loaded_once(spec, setup, st, count);
  setup.EA = 2.0 * base;
  Loaded hi = loaded_once(spec, setup, st, count);
  for (std::size_t i = 0; i < hi.omega2.size(); ++i) {
    hi.omega2[i] = 2.0 * hi.omega2[i] - lo.omega2[i];
    if (!(hi.omega2[i] > 0.0))
      throw ring::NumericalError(kWho + ": the inextensible omega^2 = " + std::to_string(hi.omega2[i]) +
                                 " <= 0 for mode " + std::to_string(i + 1) +
                                 ": the loaded ring is at or past a critical load");
  }
  hi.residual = modal::worst(hi.residual, lo.residual);
  return hi;
}

ring::ModalResult modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& o,
                                   const ring::StaticOptions& st, int count) {
  check_preloaded_modes(spec, o, st);
  if (count < 1) throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be >= 1");
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup;
  setup.elements = o.elements;
  setup.degree = o.degree;
  setup.geometry = o.geometry;
  setup.theory = spec.theory;
  const Loaded result = loaded(spec, setup, o.extensible, st, count);
  ring::ModalResult r;
  r.solver = "fem";
  r.model["elements"] = static_cast<long long>(setup.elements);
  r.model["cells"] = static_cast<long long>(setup.cells());
  r.model["degree"] = static_cast<long long>(setup.degree);
  r.model["geometry"] = ring::to_string(setup.geometry);
  r.model["theory"] = ring::to_string(spec.theory);
  r.model["extensible"] = o.extensible;
  r.model["rotary_inertia"] = spec.theory == ring::Theory::timoshenko;  // the Reissner beam's mass has rho I
  r.model["preload"] = std::string("static");
  r.model["reference"] = false;  // refused (check_preloaded_modes)
  r.rigid_modes = 0;
  for (double w2 : result.omega2) r.omega.push_back(std::sqrt(w2));
  r.shapes = result.shapes;
  r.unknowns = result.unknowns;
  r.max_residual = result.residual;
  r.residual_norm = kDualResidualNorm;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace
}  // namespace fem::detail

namespace fem {

ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& options,
                                           const ring::StaticOptions& statics, int count) {
  return detail::modes_under_load(spec, options, statics, count);
}

}  // namespace fem
