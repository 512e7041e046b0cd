// The modes of a spinning ring (spin.hpp): the turning frame's tangent, mass and Coriolis
// matrix of the geometrically exact beam, the shared dense gyroscopic step and the
// inextensible extrapolation.
#include "fem_reference/spin.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "fem_reference/beam_potential.hpp"
#include "fem_reference/pencil.hpp"
#include "fem_reference/static_path.hpp"
#include "modal/gyroscopic.hpp"
#include "modal/modes.hpp"

namespace fem::detail {
namespace {

const std::string kWho = "fem modes of a spinning ring";

/// One discretization's gyroscopic modes (at one EA).
struct Spun {
  std::vector<double> omega2;  ///< ascending, turning frame
  std::vector<ring::ModeShape> shapes;
  std::vector<ring::Wave> waves;
  long long unknowns = 0;
  double residual = 0.0;
};

Spun spun_once(const ring::RingSpec& spec, const Setup& setup, int count) {
  const std::unique_ptr<BeamModel> built = make_beam(spec, setup);  // Euler or Reissner
  const BeamModel& model = *built;
  const unsigned int N = model.n_free();
  if (N > modal::kMaxGyroscopicUnknowns)
    throw std::invalid_argument("fem: fem.elements (=" + std::to_string(setup.elements) + ") with fem.degree (=" +
                                std::to_string(setup.degree) + ") give " + std::to_string(N) +
                                " unknowns: the modes of a spinning ring are a dense gyroscopic solve of at most " +
                                std::to_string(modal::kMaxGyroscopicUnknowns) +
                                " unknowns; use fewer elements or a lower degree");
  if (count > static_cast<int>(N))
    throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be <= the unknowns (=" +
                                std::to_string(N) + ") of " + std::to_string(setup.cells()) + " cells of degree " +
                                std::to_string(setup.degree));

  // The state about which the ring vibrates: the equilibrium under the centrifugal force
  // (the potential's own load, BeamPotential), or rest without the spin's tension.
  Vector<double> q(N);
  if (spec.rotation.tension == ring::Rotation::Tension::spin) {
    const ring::StaticOptions st;  // no other load
    const ContinuationOptions continuation;
    const StaticSolve path = trace_path(spec, setup, st, continuation);
    if (!path.reached())
      throw ring::NumericalError(kWho + ": the equilibrium under the centrifugal force is not reached: " +
                                 paths::failure_message(path.trace, continuation));
    for (unsigned int i = 0; i < N; ++i) q[i] = path.trace.state.z(i);
  }
  const ring::Loads none;  // outlives the potential, which keeps a reference
  const BeamPotential potential(model, none);
  SparseMatrix<double> T(model.sparsity()), G(model.sparsity());
  Vector<double> residual;
  potential.evaluate(q, 1.0, &residual, &T);  // K_beam(q) - speed^2 M_trans
  potential.coriolis(G);
  const modal::GyroscopicModes modes =
      modal::gyroscopic_modes("fem", dense(T), dense(model.mass()), dense(G), count);

  Spun out;
  out.unknowns = N;
  out.residual = modes.max_residual;
  const auto sample = [&](const Eigen::VectorXd& v) {
    Vector<double> x(N);
    for (unsigned int i = 0; i < N; ++i) x[i] = v(i);
    return model.sample(model.expand(x));
  };
  for (int k = 0; k < count; ++k) {
    out.omega2.push_back(modes.omega(k) * modes.omega(k));
    auto [shape, wave] = modal::travelling_mode(modes.vectors.col(k), sample, spec.rotation.speed);
    out.shapes.push_back(std::move(shape));
    out.waves.push_back(wave);
  }
  return out;
}

/// One discretization with the modes' inextensible extrapolation (spin.hpp).
Spun spun(const ring::RingSpec& spec, Setup setup, bool extensible, int count) {
  if (extensible) {
    setup.EA = spec.EA();
    return spun_once(spec, setup, count);
  }
  const double base = kInextensibleBeta * spec.EI() / (spec.radius * spec.radius);
  setup.EA = base;
  const Spun lo = spun_once(spec, setup, count);
  setup.EA = 2.0 * base;
  Spun hi = spun_once(spec, setup, count);
  for (std::size_t i = 0; i < hi.omega2.size(); ++i) {
    // Paired by order; the wave numbers must agree (not the directions: at a tiny speed the
    // pair's split is below the rounding and its waves are any combination of the two).
    if (hi.waves[i].number != lo.waves[i].number)
      throw ring::NumericalError(kWho + ": mode " + std::to_string(i + 1) + " is the wave " +
                                 std::to_string(lo.waves[i].number) + " at one axial stiffness of the inextensible "
                                 "extrapolation (fem.extensible = false) and the wave " +
                                 std::to_string(hi.waves[i].number) + " at the other: the modes cannot be paired");
    hi.omega2[i] = 2.0 * hi.omega2[i] - lo.omega2[i];
    if (!(hi.omega2[i] > 0.0))
      throw ring::NumericalError(kWho + ": the inextensible omega^2 = " + std::to_string(hi.omega2[i]) +
                                 " <= 0 for mode " + std::to_string(i + 1));
  }
  hi.residual = modal::worst(hi.residual, lo.residual);
  return hi;
}

}  // namespace

ring::ModalResult spinning_modes(const ring::RingSpec& spec, const ring::FemOptions& o, int count) {
  check_modes(spec, o);  // with a spin: what the spin refuses too (checks.cpp)
  if (count < 1) throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be >= 1");
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup;
  setup.elements = o.elements;
  setup.degree = o.degree;
  setup.geometry = o.geometry;
  setup.rotary_inertia = o.rotary_inertia;
  setup.theory = spec.theory;
  Spun result = spun(spec, setup, o.extensible, count);
  int refinements = 0;
  double estimate = 0.0;
  if (o.reference) {
    // p-refinement (then h) until the frequencies change by less than fem.tolerance, or stop
    // contracting: the dense solve's rounding (1e-9 to 1e-8 of omega, spin.hpp) is reached,
    // and that last change is the estimate reported.
    double previous = std::numeric_limits<double>::infinity();
    for (;;) {
      Setup next = setup;
      if (next.degree < kMaxDegree)
        ++next.degree;
      else
        next.subdivisions *= 2;
      Spun finer;
      try {
        finer = spun(spec, next, o.extensible, count);
      } catch (const std::invalid_argument& e) {
        throw ring::NumericalError(kWho + ": the reference refinement reached the dense solve's size before the "
                                   "frequencies settled (last change " + std::to_string(previous) + "): " + e.what());
      }
      double change = 0.0;
      for (int i = 0; i < count; ++i)
        change = std::max(change, std::abs(std::sqrt(finer.omega2[i]) - std::sqrt(result.omega2[i])) /
                                      std::sqrt(finer.omega2[i]));
      if (change > 0.5 * previous) {
        // The rounding is reached: this change is mostly the finer solve's (whose spread, and
        // rounding, grow with p), so the coarser solution stays, with this change as its error.
        estimate = change;
        break;
      }
      ++refinements;
      result = std::move(finer);
      setup = next;
      if (change < o.tolerance) {
        estimate = change;
        break;
      }
      previous = change;
    }
  }
  ring::ModalResult r;
  r.solver = "fem";
  r.model["elements"] = static_cast<long long>(setup.elements);
  r.model["cells"] = static_cast<long long>(setup.cells());
  r.model["subdivisions"] = static_cast<long long>(setup.subdivisions);
  r.model["degree"] = static_cast<long long>(setup.degree);
  r.model["geometry"] = ring::to_string(setup.geometry);
  r.model["extensible"] = o.extensible;
  r.model["theory"] = ring::to_string(spec.theory);
  r.model["rotary_inertia"] = o.rotary_inertia || spec.theory == ring::Theory::timoshenko;
  r.model["reference"] = o.reference;
  r.model["refinements"] = static_cast<long long>(refinements);
  r.error_estimate = estimate;
  r.rigid_modes = 0;
  for (double w2 : result.omega2) r.omega.push_back(std::sqrt(w2));
  r.shapes = result.shapes;
  r.waves = result.waves;
  r.frame = "rotating";
  r.unknowns = result.unknowns;
  r.max_residual = result.residual;
  r.residual_norm = ring::kResidual2Norm;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace fem::detail
