// The FE modes driver: one discretization (with the inextensible
// extrapolation), and the p/h refinement to the converged reference (modes.hpp).
#include "fem_reference/checks.hpp"
#include "fem_reference/ring_model.hpp"
#include "fem_reference/spin.hpp"
#include "fem_reference/timoshenko_model.hpp"
#include "modal/modes.hpp"

namespace fem::detail {

std::unique_ptr<LinearModel> make_model(const ring::RingSpec& spec, const Setup& setup) {
  if (setup.theory == ring::Theory::timoshenko) return std::make_unique<TimoshenkoModel>(spec, setup);
  return std::make_unique<RingModel>(spec, setup);
}

std::unique_ptr<BeamModel> make_beam(const ring::RingSpec& spec, const Setup& setup) {
  if (setup.theory == ring::Theory::timoshenko) return std::make_unique<TimoshenkoModel>(spec, setup);
  return std::make_unique<RingModel>(spec, setup);
}

namespace {

/// `refining`: a step of the reference refinement (not the user's own discretization).
Solved solve_once(const ring::RingSpec& spec, Setup setup, bool extensible, int count, bool keep_full,
                  bool refine = true, bool refining = false) {
  const int rigid = spec.rigid_modes();
  auto run = [&](double EA, std::vector<double>& lambda, double& max_res, ring::ModalResult& r,
                 std::vector<Vector<double>>* full) {
    setup.EA = EA;
    const auto built = make_model(spec, setup);
    const LinearModel& model = *built;
    const unsigned int wanted = static_cast<unsigned int>(count + rigid);
    if (wanted > model.n_free())
      throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be <= unknowns - rigid modes (=" +
                                  std::to_string(static_cast<int>(model.n_free()) - rigid) + ") for " +
                                  std::to_string(setup.cells()) + " cells of degree " + std::to_string(setup.degree));
    // Too fine for double precision: the eigen-solve would return wrong frequencies
    // (ring_model.hpp, kPrecisionLimit). The ratio grows like cells^4, so the largest
    // discretization of this degree that stays below the limit has about
    // cells (limit / ratio)^(1/4) cells.
    const double ratio = model.precision_ratio();
    if (!(ratio <= kPrecisionLimit)) {
      std::ostringstream m;
      m.precision(3);
      m << setup.cells() << " cells of degree " << setup.degree
        << " are too fine for double precision: the stiffness spans " << ratio / kPrecisionLimit
        << " times more of the spectrum than the eigen-solve resolves (eps lambda_max / |sigma| = " << ratio
        << ", limit " << kPrecisionLimit << "), and its lowest frequencies would be wrong";
      if (refining) throw ring::NumericalError("fem: the reference refinement reached " + m.str());
      const int most = static_cast<int>(setup.cells() * std::pow(kPrecisionLimit / ratio, 0.25));
      throw std::invalid_argument("fem: fem.elements (=" + std::to_string(setup.elements) + ") with fem.degree (=" +
                                  std::to_string(setup.degree) + "): " + m.str() + "; use at most about " +
                                  std::to_string(most) + " elements of this degree, or a lower degree");
    }
    EigenPairs pairs;
    try {
      pairs = model.solve(wanted, refine);
    } catch (const ring::NumericalError&) {
      throw;
    } catch (const std::exception& e) {
      throw ring::NumericalError(std::string("fem: eigen-solver failed: ") + e.what());
    }
    // Elastic eigenvalues must be positive (a negative one would mean a non-coercive
    // penalty); rigid ones are zero up to round-off (~eps lambda_max, either sign) and,
    // on the circle, the approximation of rigid translations by polar fields.
    for (unsigned int i = 0; i < wanted; ++i)
      if (!std::isfinite(pairs.lambda[i]) || (static_cast<int>(i) >= rigid && !(pairs.lambda[i] > 0)))
        throw ring::NumericalError("fem: eigenvalue " + std::to_string(pairs.lambda[i]) + " of mode " +
                                   std::to_string(i + 1) + " is not positive and finite");
    // Refined pairs whose residual stayed large are not a result (kAcceptedResidual).
    if (refine)
      for (unsigned int i = rigid; i < wanted; ++i)
        if (!(pairs.residual[i] <= kAcceptedResidual)) {
          std::ostringstream m;
          m.precision(3);
          m << "fem: the eigen-solve lost its accuracy: mode " << i + 1 - rigid << " keeps a relative residual of "
            << pairs.residual[i] << " after refinement (accepted: " << kAcceptedResidual << "; " << setup.cells()
            << " cells of degree " << setup.degree << ", precision ratio " << ratio << " of " << kPrecisionLimit
            << "): use fewer elements or a lower degree";
          throw ring::NumericalError(m.str());
        }
    // With accurate pairs, a rigid eigenvalue far from zero is the discretization's: the
    // polar fields approximate the rigid translations only.
    // Rigid modes are counted, not recognized by a threshold (ring_model.hpp, kRigidSeparation).
    if (rigid > 0 && std::abs(pairs.lambda[rigid - 1]) > kRigidSeparation * pairs.lambda[rigid])
      throw ring::NumericalError("fem: the mesh is too coarse to represent the " + std::to_string(rigid) +
                                 " rigid modes (lowest elastic/rigid eigenvalue ratio < " +
                                 std::to_string(static_cast<int>(1.0 / kRigidSeparation)) + ")");
    lambda.assign(pairs.lambda.begin() + rigid, pairs.lambda.end());
    max_res = 0.0;
    r.shapes.clear();
    for (unsigned int i = rigid; i < wanted; ++i) {
      if (refine) max_res = modal::worst(max_res, pairs.residual[i]);  // raw pairs carry NaN: none measured
      const auto f = model.expand(pairs.q[i]);
      r.shapes.push_back(model.sample(f));
      if (full) full->push_back(f);
    }
    r.unknowns = model.n_free();
  };
  Solved out;
  auto& r = out.result;
  std::vector<double> lambda;
  double max_res = 0.0;
  if (extensible) {
    run(spec.EA(), lambda, max_res, r, keep_full ? &out.full : nullptr);
  } else {
    // omega^2(beta) = omega^2_inf - c / beta + O(beta^-2): extrapolate from beta, 2 beta.
    const double base = kInextensibleBeta * spec.EI() / (spec.radius * spec.radius);
    std::vector<double> lambda1;
    double res1 = 0.0;
    run(base, lambda1, res1, r, nullptr);
    run(2.0 * base, lambda, max_res, r, keep_full ? &out.full : nullptr);
    for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = 2.0 * lambda[i] - lambda1[i];
    max_res = modal::worst(max_res, res1);
  }
  for (double l : lambda) {
    if (!(l > 0)) throw ring::NumericalError("fem: non-positive elastic eigenvalue " + std::to_string(l));
    r.omega.push_back(std::sqrt(l));
  }
  r.max_residual = max_res;
  r.residual_norm = kDualResidualNorm;  // not the 2-norm: modes.hpp
  r.rigid_modes = spec.rigid_modes();
  return out;
}

}  // namespace

Solved run(const ring::RingSpec& spec, const ring::FemOptions& o, int count, bool keep_full) {
  check_modes(spec, o);
  if (count < 1) throw std::invalid_argument("fem: count (=" + std::to_string(count) + ") must be >= 1");
  const auto t0 = std::chrono::steady_clock::now();
  Setup setup;
  setup.elements = o.elements;
  setup.degree = o.degree;
  setup.geometry = o.geometry;
  setup.rotary_inertia = o.rotary_inertia;
  setup.theory = spec.theory;
  // The Timoshenko theory has the cross-section's rotary inertia by definition (ring/spec.hpp).
  const bool rotary_inertia = o.rotary_inertia || spec.theory == ring::Theory::timoshenko;
  Solved s = solve_once(spec, setup, o.extensible, count, keep_full && !o.reference, !o.reference || !o.extensible);
  int refinements = 0;
  if (o.reference) {
    // p-refinement (exponential convergence on these smooth, piecewise analytic modes),
    // h-refinement once p reaches kMaxDegree. Stop when the largest relative change of the
    // requested frequencies is below the tolerance, or when the current solution's error,
    // extrapolated from the last two changes, is (modes.hpp, "Reference").
    double previous_change = 0.0, before_previous = 0.0;
    bool refined = !o.extensible;  // as the first solve above
    bool previous_refined = false, previous_clean = false;
    for (;;) {
      if (++refinements > kReferenceMaxSteps)
        throw ring::NumericalError("fem: reference not converged after " + std::to_string(kReferenceMaxSteps) +
                                   " refinements (degree " + std::to_string(setup.degree) + ", cells " +
                                   std::to_string(setup.cells()) + ")");
      if (setup.degree < kMaxDegree)
        ++setup.degree;
      else
        setup.subdivisions *= 2;
      // Raw pairs carry ~1e-7 round-off; refine them once the change this step is expected
      // to make (the last change times the last contraction) gets near it.
      // (The inextensible penalty and the Timoshenko ring's shear stiffness, kGA R^2/EI ~ 1e6
      // at depth/R = 1e-3, make raw pairs far noisier: always refine them; raw, a thin
      // Timoshenko ring's changes never fell below the tolerance and p ran to kMaxDegree.)
      const double expected =
          before_previous > 0 ? previous_change * std::min(1.0, previous_change / before_previous) : previous_change;
      previous_refined = refined;
      refined = !o.extensible || spec.theory == ring::Theory::timoshenko ||
                (refinements > 1 && expected < kRefineBelowChange);
      Solved next = solve_once(spec, setup, o.extensible, count, false, refined, true);
      double change = 0.0;
      for (int i = 0; i < count; ++i)
        change = std::max(change, std::abs(next.result.omega[i] - s.result.omega[i]) / next.result.omega[i]);
      s = std::move(next);
      // The change is the error of the previous solution; with a contraction
      // r = change / previous_change per step the current one has about change r / (1 - r).
      const double ratio = previous_change > 0 ? change / previous_change : 1.0;
      const double extrapolated = ratio < 0.5 ? change * ratio / (1.0 - ratio) : change;
      // The extrapolation is trusted when both changes are clean of the raw pairs' round-off
      // (this one between refined pairs, the last one far above 1e-7) and contract fast.
      const bool clean_now = refined && previous_refined;
      const bool clean = clean_now && (previous_clean || previous_change > kRefineBelowChange / 10);
      if (change < o.tolerance || (clean && ratio <= kTrustedContraction && extrapolated < o.tolerance)) {
        // Not below the refined solve's round-off: the free ring's k = 2..13 match the
        // closed form to ~1e-12, not better.
        s.result.error_estimate = std::max(kRoundOffFloor, extrapolated);
        break;
      }
      before_previous = previous_change;
      previous_change = change;
      previous_clean = clean_now;
    }
    if (keep_full || !refined) {
      const double estimate = s.result.error_estimate;
      s = solve_once(spec, setup, o.extensible, count, keep_full, true, true);
      s.result.error_estimate = estimate;
    }
  }
  auto& r = s.result;
  r.solver = "fem";
  r.model["elements"] = static_cast<long long>(setup.elements);
  r.model["cells"] = static_cast<long long>(setup.cells());
  r.model["degree"] = static_cast<long long>(setup.degree);
  r.model["geometry"] = ring::to_string(setup.geometry);
  r.model["extensible"] = o.extensible;
  r.model["theory"] = ring::to_string(spec.theory);
  r.model["rotary_inertia"] = rotary_inertia;
  r.model["reference"] = o.reference;
  r.model["refinements"] = static_cast<long long>(refinements);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.result.model["subdivisions"] = static_cast<long long>(setup.subdivisions);
  return s;
}

}  // namespace fem::detail

namespace fem {

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::FemOptions& options, int count) {
  // A spinning ring: the gyroscopic modes of the turning frame (spin.hpp); at rest, today's path.
  if (spec.rotation.spinning()) return detail::spinning_modes(spec, options, count);
  return detail::run(spec, options, count, false).result;
}

}  // namespace fem
