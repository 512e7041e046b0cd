#include "lumped_mass/checks.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lumped {
namespace {

/// What every nonlinear analysis of the chain needs; `what` is "statics" or "response".
void check_chain(const ring::RingSpec& spec, const ring::LumpedOptions& o, const std::string& what) {
  auto need = [&](bool ok, const std::string& msg) {
    if (!ok) throw std::invalid_argument("lumped " + what + ": " + msg);
  };
  ring::refuse_timoshenko(spec, "lumped " + what);
  need(o.variant == ring::LumpedOptions::Variant::chain,
       "lumped.variant = \"" + ring::to_string(o.variant) + "\" has no nonlinear model here; use \"chain\"");
  need(o.n >= 4, "lumped.n (=" + std::to_string(o.n) + ") must be >= 4");
  need(spec.radius > 0 && spec.E > 0 && spec.rho > 0 && spec.A() > 0 && spec.I() > 0,
       "radius, E, rho, area and inertia must be > 0");
  need(spec.supports.pin.has_value(), "needs a pin (supports.pin): a free ring under a dead load has no equilibrium");
  ring::refuse_terms_beyond_paper(spec, "lumped " + what);
}

}  // namespace

void check_theory(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  const bool timoshenko_model = options.variant == ring::LumpedOptions::Variant::timoshenko_frame;
  const std::string variant = "lumped.variant = \"" + ring::to_string(options.variant) + "\"";
  if (spec.theory == ring::Theory::timoshenko && !timoshenko_model)
    throw std::invalid_argument("lumped: " + variant +
                                " is an Euler-Bernoulli model (no shear strain, no rotary inertia of the section), "
                                "but ring.theory = \"timoshenko\"; use lumped.variant = \"timoshenko-frame\"");
  if (spec.theory == ring::Theory::euler_bernoulli && timoshenko_model)
    throw std::invalid_argument("lumped: " + variant +
                                " has shear strain and the section's rotary inertia, which ring.theory = "
                                "\"euler-bernoulli\" leaves out; set ring.theory = \"timoshenko\", or use "
                                "\"chain\", \"frame\" or \"frame-consistent\"");
  if (timoshenko_model && !(spec.kGA() > 0.0 && std::isfinite(spec.kGA())))
    throw std::invalid_argument("lumped: " + variant + " needs a shear stiffness kappa G A > 0 (ring.shear_coefficient = " +
                                std::to_string(spec.kappa()) + ", ring.nu = " + std::to_string(spec.nu) + ")");
}

void check_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  // Every term of the spec is in the linear model (model.hpp); its points must be nodes.
  check_theory(spec, options);
  if (options.n < 4) throw std::invalid_argument("lumped.n (=" + std::to_string(options.n) + ") must be >= 4");
  const double anchor = spec.supports.pin.value_or(0.0);
  std::vector<std::pair<std::string, double>> points;
  for (double a : spec.supports.pins) points.emplace_back("supports.pins", a);
  if (spec.supports.clamp) points.emplace_back("supports.clamp", *spec.supports.clamp);
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i)
    points.emplace_back("supports.springs[" + std::to_string(i + 1) + "]", spec.supports.springs[i].angle);
  for (std::size_t i = 0; i < spec.masses.size(); ++i)
    points.emplace_back("masses[" + std::to_string(i + 1) + "]", spec.masses[i].angle);
  for (const auto& [key, a] : points)
    if (!std::isfinite(a) || !ring::on_node(a, anchor, options.n))
      throw std::invalid_argument("lumped: " + key + " (= " + std::to_string(a) + " deg) is not a node of the n = " +
                                  std::to_string(options.n) + " model (valid: anchor " + std::to_string(anchor) +
                                  " deg + 360 k / n)");
}

void check_static(const ring::RingSpec& spec, const ring::LumpedOptions& options, const ring::StaticOptions& statics) {
  check_chain(spec, options, "statics");
  if (!spec.supports.roller) throw std::invalid_argument("lumped statics: needs a roller as well as the pin");
  if (statics.steps < 1) throw std::invalid_argument("lumped statics: static.steps must be >= 1");
}

void check_response(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                    const ring::ResponseOptions& r) {
  check_chain(spec, options, "response");
  using Integrator = ring::ResponseOptions::Integrator;
  if (r.integrator == Integrator::energy_momentum)
    throw std::invalid_argument(
        "lumped response: response.integrator = \"energy-momentum\" is not offered by the lumped chain: its "
        "scheme is the implicit midpoint rule, which does not conserve energy; use \"midpoint\" (accepted: "
        "\"midpoint\", \"newmark\")");
  if (r.integrator != Integrator::midpoint && r.integrator != Integrator::newmark)
    throw std::invalid_argument("lumped response: response.integrator = \"" + ring::to_string(r.integrator) +
                                "\" is not offered by the lumped chain (accepted: \"midpoint\", \"newmark\")");
  if (!(r.dt > 0) || !(r.t_end >= r.dt))
    throw std::invalid_argument("lumped response: response.dt must be > 0 and <= response.t_end");
}

}  // namespace lumped
