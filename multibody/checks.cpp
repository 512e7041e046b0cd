#include "multibody/checks.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/backend.hpp"
#include "multibody/bending.hpp"
#include "modal/gyroscopic.hpp"
#include "ring/errors.hpp"

namespace multibody {
using detail::has_point_inertia;

namespace {

/// What the chain takes of an arch (chain.hpp: the open chain, dense angle paths): its ends
/// pinned, clamped or free, further pins, point loads. The rest is refused by key, naming
/// ring.arc. `who` names the analysis; `plastic`: whether it refuses ring.plastic, ignores it
/// (the linear modes are elastic, as the ring's) or takes it (the statics: the interior hinges'
/// law, bending.hpp; a clamped end's half-hinge is elastic, so not with a clamp). O(supports + masses).
/// What an analysis does with ring.plastic on an arch.
enum class PlasticUse { refused, ignored, taken };

void check_arch(const ring::RingSpec& spec, const ring::MultibodyOptions& options, const std::string& who,
                PlasticUse plastic) {
  if (!spec.is_arch()) return;
  auto refuse = [&](const std::string& key, const std::string& why) {
    throw std::invalid_argument(who + " on an arch (ring.arc) does not take " + key + " yet: " + why);
  };
  if (options.method == ring::MultibodyOptions::Method::sparse)
    refuse("multibody.method = \"sparse\"", "the O(n) paths close the chain; set multibody.method = \"dense\" or \"auto\"");
  if (options.dependent == ring::MultibodyOptions::Dependent::paper)
    refuse("multibody.dependent = \"paper\"", "its dependent angles are the closed ring's; use \"robust\"");
  if (spec.theory == ring::Theory::timoshenko)
    refuse("ring.theory = \"timoshenko\" (or multibody.theory)", "the shear chain is the closed ring's; use \"euler-bernoulli\"");
  if (spec.supports.roller) refuse("supports.roller", "pin or clamp its ends (supports.pin, supports.pins, supports.clamp)");
  if (!spec.supports.springs.empty()) refuse("supports.springs", "pin or clamp its ends");
  if (!spec.masses.empty()) refuse("masses", "remove the point masses");
  if (spec.foundation.any()) refuse("foundation", "remove the foundation");
  if (spec.plastic && plastic == PlasticUse::refused) refuse("ring.plastic", "remove ring.plastic");
  // The statics take the law at the interior hinges; a clamped end's half-hinge is elastic.
  if (plastic == PlasticUse::taken && spec.plastic && spec.supports.clamp)
    refuse("ring.plastic with supports.clamp", "a clamped end's half-hinge to the wall has no plastic law (attachments.hpp); "
                                              "pin the ends or remove ring.plastic");
}

/// True when both ends of the arch are pinned (supports.pin or .pins at `from` and `to`).
bool ends_pinned(const ring::RingSpec& spec) {
  bool from = false, to = false;
  for (double p : spec.supports.pinned()) {
    const double at = spec.arc->offset(p);
    from = from || at < 1e-9;
    to = to || std::abs(at - spec.arc->span()) < 1e-9;
  }
  return from && to;
}

/// The loads of a static analysis on an arch: point loads; uniform pressure of any kind and
/// gravity with both ends pinned (the follower pressure's potential p A closes the polygon
/// through its ends, loading.hpp, constant there; gravity tested on that arch).
void check_arch_loads(const ring::RingSpec& spec, const ring::Loads& loads, const std::string& section) {
  if (!spec.is_arch()) return;
  if (loads.pressure.any() && !ends_pinned(spec))
    throw std::invalid_argument("the multibody statics on an arch (ring.arc) takes " + section +
                                ".pressure with both ends pinned only (supports.pin and supports.pins at the ends)");
  if (loads.has_gravity() && !ends_pinned(spec))
    throw std::invalid_argument("the multibody statics on an arch (ring.arc) takes " + section +
                                ".gravity with both ends pinned only (supports.pin and supports.pins at the ends)");
}

}  // namespace

void check_arch_buckling(const ring::RingSpec& spec, const ring::MultibodyOptions& options, const ring::Loads& loads) {
  check_arch(spec, options, "the multibody buckling", PlasticUse::refused);
  check_arch_loads(spec, loads, "buckling");
}

namespace {

/// The spinning ring's modes (spin.hpp): dense, in robust coordinates, on a closed ring whose
/// rigid motions are held, at most modal::kMaxGyroscopicUnknowns unknowns. O(masses).
void check_spinning(const ring::RingSpec& spec, const ring::MultibodyOptions& options) {
  const double speed = spec.rotation.speed;
  if (!std::isfinite(speed))
    throw std::invalid_argument("rotation.speed = " + std::to_string(speed) + " rad/s must be finite");
  if (spec.is_arch())
    throw std::invalid_argument("the multibody modes of a spinning arch (ring.arc with rotation.speed) are not offered yet");
  if (options.method == ring::MultibodyOptions::Method::sparse)
    throw std::invalid_argument("multibody.method = \"sparse\" does not take rotation.speed yet (the spinning ring's "
                                "gyroscopic modes are dense): set multibody.method = \"dense\" or \"auto\"");
  if (options.dependent == ring::MultibodyOptions::Dependent::paper)
    throw std::invalid_argument("multibody.dependent = \"paper\" does not take rotation.speed yet (the spinning ring's "
                                "modes take the constraints' orthonormal tangent space): use \"robust\"");
  if (const int rigid = spec.rigid_modes(); rigid > 0)
    throw std::invalid_argument("rotation.speed: the spinning ring has " + std::to_string(rigid) +
                                " rigid motion(s) its supports leave free, and its stiffness in the turning frame must "
                                "hold every motion; add supports, springs or a foundation");
  // The spin's equilibrium and tangent are the nonlinear statics' (sections.hpp: the
  // Timoshenko chain's condensed sections need hinge 0 held).
  if (spec.theory == ring::Theory::timoshenko && spec.supports.free())
    throw std::invalid_argument("multibody: the spinning Timoshenko chain (ring.theory = \"timoshenko\" with "
                                "rotation.speed) needs a pinned ring (supports.pin)");
  // The unknowns: the angles [, x_0, y_0] less the constraint rows, [the shear angles,] the
  // point inertias' rotations; bounded above by this.
  long long unknowns = options.n + 2 + static_cast<long long>(spec.masses.size());
  if (spec.theory == ring::Theory::timoshenko) unknowns += options.n;
  if (unknowns > modal::kMaxGyroscopicUnknowns)
    throw std::invalid_argument("multibody.n = " + std::to_string(options.n) +
                                " is too large for the spinning ring's dense gyroscopic modes (at most " +
                                std::to_string(modal::kMaxGyroscopicUnknowns) + " unknowns, " + std::to_string(unknowns) +
                                " here): lower multibody.n (the chain's error is order 2 in 1/n)");
}

/// static.displacement (statics.hpp, "Displacement control"): the driven point is a hinge of
/// the chain other than a support's, and no loads act with it (the scene reader says so too;
/// this holds for a library caller's options). Both formulations take it; what they take of
/// the rest is the statics' own rule. O(supports).
void check_drive(const ring::RingSpec& spec, const ring::MultibodyOptions& options, const ring::StaticOptions& statics) {
  const ring::StaticOptions::Displacement& d = *statics.displacement;
  if (!statics.loads.points.empty() || statics.loads.pressure.any() || statics.loads.has_gravity())
    throw ring::InputError("", "static.displacement",
                           "drives the path, and the multibody chain would scale the loads of [static] with it: give "
                           "the one or the other");
  // A ring without supports.pin: the free chain's base unknowns (x_0, y_0) carry the drive's
  // rows as a further pin's. Measured (test_driven_statics.cpp) where springs or a foundation
  // hold every rigid motion by themselves; where only the driven point would hold some (a radial
  // foundation alone: the turning about the centre), the load-controlled path that measures it
  // buckles into that turning at once (the dead load at the point does work on it: a
  // bifurcation at 1.5e-3 of P R^2 / EI = 1 with k_t = 1e-4 k_r), so nothing measures it yet.
  if (spec.supports.free() && !spec.is_arch())
    if (const int rigid = ring::static_rigid_modes(spec, ring::Loads{}); rigid > 0)
      throw ring::InputError("", "static.displacement",
                             "the multibody chain drives a point of a ring without supports.pin only where springs or "
                             "a foundation hold every rigid motion by themselves; here " + std::to_string(rigid) +
                                 " rigid motion(s) would be held by the driven point alone, which is not measured: "
                                 "add a pin (supports.pin), a tangential foundation or springs");
  const double length = std::hypot(d.value[0], d.value[1]);
  if (!(length > 0.0) || !std::isfinite(length))
    throw ring::InputError("", "static.displacement.value",
                           "expected a finite, nonzero displacement [ux, uy] (m), got [" + std::to_string(d.value[0]) +
                               ", " + std::to_string(d.value[1]) + "]");
  if (ring::node_index(spec, d.at, options.n) < 0)
    throw ring::InputError("", "static.displacement.at",
                           std::to_string(d.at) + " deg is not a hinge of the n = " + std::to_string(options.n) +
                               " chain (valid: the anchor " + std::to_string(spec.anchor()) + " deg + 360 k / n)");
  std::vector<double> held = spec.supports.pinned();
  if (spec.supports.roller) held.push_back(*spec.supports.roller);
  for (const auto& sp : spec.supports.springs) held.push_back(sp.angle);
  for (double p : held)
    if (ring::node_index(spec, p, options.n) == ring::node_index(spec, d.at, options.n))
      throw ring::InputError("", "static.displacement.at",
                             "the point at " + std::to_string(d.at) + " deg is a support (supports); drive another point");
}

/// [plates] (statics.hpp, plates.hpp): no loads, no drive and no supports act with them (the
/// scene reader says so too; this holds for a library caller's options), the travel in
/// (0, 2 R), a positive stiffness, both points of first contact hinges of the chain, a closed
/// ring. Both formulations take them, and histories that withdraw the plates (the centre row,
/// plates.hpp, holds the ring along the axis when it springs back clear of both). O(supports).
void check_plates(const ring::RingSpec& spec, const ring::MultibodyOptions& options, const ring::StaticOptions& statics) {
  const ring::StaticOptions::Plates& p = *statics.plates;
  if (!statics.loads.points.empty() || statics.loads.pressure.any() || statics.loads.has_gravity())
    throw ring::InputError("", "plates",
                           "drive the path, and the multibody chain would scale the loads of [static] with them: give the "
                           "one or the other");
  if (statics.displacement)
    throw ring::InputError("", "plates", "drive the path, and so does static.displacement: give the one or the other");
  if (spec.is_arch())
    throw ring::InputError("", "plates", "crush a closed ring; the multibody arch (ring.arc) has no plates");
  if (spec.supports.pin || spec.supports.roller || !spec.supports.pins.empty() || spec.supports.clamp)
    throw ring::InputError("", "plates",
                           "hold the ring themselves (with the two no-slide rows at the points of first contact); remove "
                           "supports.pin, roller, pins and clamp (springs and a foundation may stay)");
  if (!(p.travel > 0.0 && p.travel < 2.0 * spec.radius))
    throw ring::InputError("", "plates.travel",
                           "expected the plates' approach in (0, 2 R) = (0, " + std::to_string(2.0 * spec.radius) +
                               ") m, got " + std::to_string(p.travel));
  if (!(p.stiffness > 0.0) || !std::isfinite(p.stiffness))
    throw ring::InputError("", "plates.stiffness",
                           "expected a finite, positive penalty stiffness (N/m^2), got " + std::to_string(p.stiffness));
  for (double a : {p.axis, p.axis + 180.0})
    if (ring::node_index(spec, a, options.n) < 0)
      throw ring::InputError("", "plates.axis",
                             "the plates touch the ring at " + std::to_string(a) + " deg, which is not a hinge of the n = " +
                                 std::to_string(options.n) + " chain (valid: the anchor " + std::to_string(spec.anchor()) +
                                 " deg + 360 k / n)");
}

}  // namespace

void check_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options) {
  // ring.variations: the dense linear modes at rest of the Euler-Bernoulli chain only
  // (linear_model.hpp, LocalChain); the O(n) paths are refused below (banded_modes_lacks).
  if (spec.varies() && spec.rotation.spinning())
    ring::refuse_variations(spec, "the multibody spinning modes (rotation.speed)");
  if (spec.varies() && spec.theory == ring::Theory::timoshenko)
    ring::refuse_variations(spec, "the multibody Timoshenko chain (ring.theory = \"timoshenko\")");
  if (spec.varies() && spec.is_arch()) ring::refuse_variations(spec, "the multibody arch (ring.arc)");
  check_arch(spec, options, "the multibody linear modes", PlasticUse::ignored);
  if (spec.rotation.spinning()) check_spinning(spec, options);
  const bool sparse = backend(options, spec, Analysis::modes) == Backend::banded;
  // What neither O(n) path assembles (backend.hpp, banded_modes_lacks; "auto" keeps it dense).
  if (sparse)
    if (const std::string lacks = banded_modes_lacks(spec); !lacks.empty())
      throw std::invalid_argument("multibody method = \"sparse\" (the O(n) modes path) has no " + lacks +
                                  ": set multibody.method = \"dense\" or \"auto\"");
  // The terms' O(n) path (hinge positions) holds its precision to kPositionModesMaxN only.
  if (sparse && !spec.paper_terms_only() && options.n > kPositionModesMaxN) {
    std::string keys;
    for (const std::string& k : spec.terms_beyond_paper()) keys += (keys.empty() ? "" : ", ") + k;
    throw std::invalid_argument(
        "multibody: the O(n) modes with the terms beyond the paper's ring (" + keys +
        ") hold their precision to multibody.n = " + std::to_string(kPositionModesMaxN) + " (n = " +
        std::to_string(options.n) + "): the refined band solve in hinge positions loses eps (n/2pi)^4 of the low "
        "modes; use a smaller n (the chain's error is order 2 in 1/n: below 1e-8 there)");
  }
  // The paper's dependent angles are chosen for its pin and roller; further constraint rows
  // (pins, a clamp) need the robust null-space basis.
  if (options.dependent == ring::MultibodyOptions::Dependent::paper && !spec.supports.paper_only())
    throw std::invalid_argument(
        "multibody: dependent = \"paper\" takes the paper's pin and roller only; use dependent = \"robust\" with "
        "supports.pins, supports.clamp or supports.springs");
  if (sparse && options.dependent == ring::MultibodyOptions::Dependent::paper)
    throw std::invalid_argument(
        "multibody: method = sparse needs dependent = robust (the paper's dependent angles are "
        "offered on the dense path only)");
  // Forced sparse path: measured right from n = 10 (every support, with and without rotary
  // inertia, against the dense path: tests/multibody/test_modes_sparse.cpp), wrong at n = 8.
  if (sparse && options.method == ring::MultibodyOptions::Method::sparse && options.n < 10)
    throw std::invalid_argument("multibody: method = sparse needs n >= 10 (n = " + std::to_string(options.n) +
                                "); use method = \"dense\" or \"auto\"");
}

void check_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                  const ring::StaticOptions& statics) {
  ring::refuse_variations(spec, "the multibody chain");
  check_arch(spec, options, "the multibody statics", PlasticUse::taken);
  if (statics.displacement) check_drive(spec, options, statics);
  if (statics.plates) check_plates(spec, options, statics);
  // The chain's loads hold the centrifugal force of a spinning spec (loading.hpp), but the
  // statics have no turning frame to report in yet.
  ring::refuse_rotation(spec, "the multibody statics");
  check_arch_loads(spec, statics.loads, "static");
  // The O(n) statics (hinge positions) assemble every term and load; "auto" keeps the rest
  // dense (backend.hpp, banded_statics_lacks): the shear angles (sections.hpp).
  if (backend(options, spec, statics) == Backend::banded) {
    if (const std::string lacks = banded_statics_lacks(spec); !lacks.empty())
      throw std::invalid_argument("multibody method = \"sparse\" (the O(n) statics) has no " + lacks +
                                  ": set multibody.method = \"dense\" or \"auto\"");
    if (statics.path)
      throw std::invalid_argument("static.path = true needs the dense statics (its branch switching takes the tangent's "
                                  "eigenvectors): set multibody.method = \"dense\"");
  }
  if (statics.steps < 1) throw std::invalid_argument("multibody::solve_static: steps must be >= 1");
  check_section_law(spec);  // the fibre law needs the section's shape (bending.hpp)
  // The plastic law acts on the hinge springs' moment (bending.hpp); the Timoshenko chain
  // condenses its springs with the shear into one constant K_c (sections.hpp), which has no
  // hinge moment to return-map.
  if (spec.plastic && spec.theory == ring::Theory::timoshenko)
    throw ring::InputError("", "ring.plastic",
                           "the multibody Timoshenko chain (multibody.theory or ring.theory = \"timoshenko\") takes no plastic law yet: its "
                           "hinge springs are condensed with the shear into one constant stiffness; use multibody.theory = "
                           "\"euler-bernoulli\" or remove ring.plastic");
  // A rigid motion the supports leave makes K singular in it: the dead load then turns the
  // ring until it hangs along its line of action. The tangent stays regular only away from
  // that, so refuse rather than guess.
  // A driven point holds the ring as a pin does (the scene reader's rule).
  const int rigid = ring::static_rigid_modes(spec, statics);
  if (spec.is_arch() && rigid > 0)
    throw std::invalid_argument("multibody::solve_static: the arch (ring.arc) is free to move rigidly (" +
                                std::to_string(rigid) + " rigid motion(s)): pin or clamp its ends (supports.pin, "
                                "supports.pins, supports.clamp)");
  if (!spec.supports.pin && !statics.displacement && rigid > 0)
    throw std::invalid_argument("multibody::solve_static: the ring needs a pin (supports.pin)");
  if (rigid > 0)
    throw std::invalid_argument(
        "multibody::solve_static: needs a roller as well as a pin (supports.roller), "
        "otherwise the ring is free to turn about the pin");
}

void check_preloaded_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                           const ring::StaticOptions& statics) {
  ring::refuse_variations(spec, "the multibody chain");
  ring::refuse_rotation(spec, "the multibody modes under load (modes.preload)");
  // The modes about a driven equilibrium would need the drive's rows in their pencil.
  ring::refuse_displacement(statics, "the multibody modes under load (modes.preload)");
  ring::refuse_plates(statics, "the multibody modes under load (modes.preload)");
  check_modes(spec, options);
  check_static(spec, options, statics);
  if (spec.plastic)
    throw ring::InputError("", "ring.plastic",
                           "the multibody modes under load take the elastic tangent at the loaded equilibrium, which "
                           "a plastic ring does not have: remove modes.preload or ring.plastic");
  if (spec.theory == ring::Theory::timoshenko && spec.supports.free())
    throw std::invalid_argument("multibody modes.preload = \"static\": the Timoshenko chain's modes under load need "
                                "a pinned ring (supports.pin)");
  if (options.method == ring::MultibodyOptions::Method::sparse)
    throw std::invalid_argument("modes.preload = \"static\" is computed on the dense path: set multibody.method = "
                                "\"dense\" or \"auto\"");
}

void check_response(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                    const ring::ResponseOptions& response) {
  ring::refuse_variations(spec, "the multibody chain");
  check_arch(spec, options, "the multibody response", PlasticUse::refused);
  ring::refuse_rotation(spec, "the multibody response");
  if (spec.is_arch()) {
    // The dense angle integrators (newmark, generalized-alpha) on the open chain whose far end
    // is pinned (its rows: the partitioning's dependent angles), under point loads.
    auto refuse = [&](const std::string& key, const std::string& why) {
      throw std::invalid_argument("the multibody response on an arch (ring.arc) does not take " + key + " yet: " + why);
    };
    if (response.integrator == ring::ResponseOptions::Integrator::energy_momentum)
      refuse("response.integrator = \"energy-momentum\"", "its hinge positions close the chain; use \"newmark\" or "
                                                           "\"generalized-alpha\"");
    const double to = spec.arc->to;
    bool to_pinned = false;
    for (double p : spec.supports.pinned()) to_pinned = to_pinned || std::abs(spec.arc->offset(p) - spec.arc->span()) < 1e-9;
    if (!to_pinned) refuse("a free `to` end", "pin the end at " + std::to_string(to) + " deg (supports.pins)");
    if (response.loads.pressure.any()) refuse("response.pressure", "use point loads or gravity");
    if (response.loads.has_gravity() && !ends_pinned(spec))
      refuse("response.gravity without both ends pinned", "pin both ends (supports.pin and supports.pins)");
  }
  // ring.plastic: newmark and generalized-alpha on either angle backend assemble the hinges'
  // law (bending.hpp, newton_backend.hpp), energy-momentum (hinge positions) the discrete
  // gradient of its incremental potential (energy_momentum.hpp); each commits it at accepted
  // steps. What cannot take it refuses by key, saying why and what to use.
  if (spec.plastic) {
    check_section_law(spec);
    if (spec.theory == ring::Theory::timoshenko)
      throw ring::InputError("", "ring.plastic",
                             "the multibody Timoshenko chain (ring.theory = \"timoshenko\") takes no plastic law: "
                             "its hinge springs act on the sections' rotations with constant coefficients "
                             "(sections.hpp); use ring.theory = \"euler-bernoulli\" or remove ring.plastic");
    if (has_point_inertia(spec))
      throw ring::InputError("", "ring.plastic",
                             "the multibody response with point inertias (masses[].inertia > 0) takes no plastic law: "
                             "their hinges' springs are split into constant halves on the hinge's own rotation "
                             "(attachments.hpp, HingeInertias); set the inertias to 0 or remove ring.plastic");
  }
  // The shear angles live on the dense angle path only (sections.hpp); "auto" keeps it dense.
  if (spec.theory == ring::Theory::timoshenko) {
    if (response.integrator == ring::ResponseOptions::Integrator::energy_momentum)
      throw std::invalid_argument(
          "multibody response.integrator = \"energy-momentum\" (hinge positions) has no Timoshenko chain (ring.theory "
          "= \"timoshenko\"): use \"newmark\" or \"generalized-alpha\"");
    if (response.integrator != ring::ResponseOptions::Integrator::energy_momentum &&
        backend(options, spec, response.loads, Analysis::response) == Backend::banded)
      throw std::invalid_argument(
          "multibody method = \"sparse\" (the O(n) response) has no Timoshenko chain (ring.theory = \"timoshenko\"): "
          "set multibody.method = \"dense\" or \"auto\"");
  }
  // The dense path takes every term (a point inertia's hinge rotation on the Timoshenko
  // chain's sections as well: attachments.hpp, HingeInertias); the energy-momentum scheme
  // (hinge positions) every term and load but a point inertia, whose hinge rotation is an
  // unknown of the angle paths only.
  if (response.integrator == ring::ResponseOptions::Integrator::energy_momentum && has_point_inertia(spec))
    throw std::invalid_argument(
        "multibody response.integrator = \"energy-momentum\" (hinge positions) does not take point inertias "
        "(masses[].inertia > 0): use \"newmark\" or \"generalized-alpha\", or inertia = 0");
  // The O(n) angle path: the paper's terms and constant loads (backend.hpp keeps "auto" dense).
  if (response.integrator != ring::ResponseOptions::Integrator::energy_momentum &&
      backend(options, spec, response.loads, Analysis::response) == Backend::banded) {
    if (!spec.paper_terms_only()) ring::refuse_terms_beyond_paper(spec, "multibody method = \"sparse\" (the O(n) response)");
    if (response.loads.shape_dependent())
      throw std::invalid_argument(
          "multibody method = \"sparse\" (the O(n) response) does not take response.pressure of kind \"" +
          ring::to_string(response.loads.pressure.kind) +
          "\" yet (its load stiffness is not diagonal in the angles): set multibody.method = \"dense\" or "
          "\"auto\", or response.integrator = \"energy-momentum\"");
  }
  if (!spec.supports.pin && spec.rigid_modes() > 0)
    throw std::invalid_argument(
        "multibody::respond: the ring needs a pin (supports.pin), or springs or a foundation that hold every rigid "
        "motion");
  if (!(response.dt > 0.0) || !std::isfinite(response.dt))
    throw std::invalid_argument("multibody::respond: dt must be > 0");
  if (!(response.t_end >= response.dt) || !std::isfinite(response.t_end))
    throw std::invalid_argument("multibody::respond: t_end must be >= dt");
  if (!(response.rho_inf >= 0.0 && response.rho_inf <= 1.0))
    throw std::invalid_argument("multibody::respond: rho_inf must lie in [0, 1]");
  if (response.rayleigh_mass < 0 || response.rayleigh_stiffness < 0 || response.hinge_damping < 0)
    throw std::invalid_argument("multibody::respond: damping coefficients must be >= 0");
  if (response.integrator == ring::ResponseOptions::Integrator::midpoint)
    throw std::invalid_argument(
        "multibody::respond: response.integrator = \"midpoint\" is not offered by the multibody chain (accepted: "
        "\"newmark\", \"generalized-alpha\", \"energy-momentum\")");
  if (response.integrator == ring::ResponseOptions::Integrator::energy_momentum &&
      (response.rayleigh_mass > 0 || response.rayleigh_stiffness > 0 || response.hinge_damping > 0))
    throw std::invalid_argument(
        "multibody::respond: response.integrator = \"energy-momentum\" conserves the undamped energy balance and "
        "takes no damping; use \"newmark\" for a damped response");
}

}  // namespace multibody
