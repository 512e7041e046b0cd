#include "lumped_mass/checks.hpp"

#include "lumped_mass/preload.hpp"
#include "lumped_mass/terms.hpp"
#include "modal/gyroscopic.hpp"
#include "ring/errors.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lumped {
namespace {

/// The points of the loads on hinges (`section`.at for one load, `section`.loads[i].at for
/// several), none at the pin.
void check_loads(const ring::RingSpec& spec, const ring::LumpedOptions& o, const ring::Loads& loads,
                 const std::string& section) {
  const double anchor = spec.anchor();
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const double a = loads.points[i].angle;
    const std::string key =
        loads.points.size() == 1 ? section + ".at" : section + ".loads[" + std::to_string(i + 1) + "].at";
    if (spec.is_arch()) {  // a node of the arch, none at a pinned point (chain.cpp, load_hinges)
      const int k = node_at(spec, a, o.n, key);
      for (double p : spec.supports.pinned())
        if (node_at(spec, p, o.n, "supports.pins") == k)
          throw std::invalid_argument("lumped: " + key + " acts at a pinned point of the arch");
      continue;
    }
    if (!std::isfinite(a) || !ring::on_node(a, anchor, o.n))
      throw std::invalid_argument("lumped: " + key + " (=" + std::to_string(a) + ") is not a hinge of the chain (lumped.n = " +
                                  std::to_string(o.n) + "; valid: anchor " + std::to_string(anchor) + " deg + 360 k / n)");
    if (spec.supports.pin && std::abs(std::remainder(a - anchor, 360.0)) < 1e-9)
      throw std::invalid_argument("lumped: " + key + " acts at the pin");
  }
  // A pressure on an arch (loads.hpp): in linear buckling, the follower kind with both ends
  // pinned, whose potential is the area between the chain and its fixed chord (Timoshenko &
  // Gere's buckling pressures test it); the dead and central kinds wait for their oracle. The
  // statics and the response refuse it: on the pinned semicircle at 1.5 times the critical
  // follower pressure the path went past the bifurcation undetected to a limit point at 0.97
  // (n = 32, measured), which needs looking into before it is offered.
  if (spec.is_arch() && loads.pressure.any() && section != "buckling")
    throw ring::InputError("", "ring.arc",
                           "lumped: " + section + ".pressure on an arch (ring.arc) is not offered by the chain's " +
                               (section == "static" ? "statics" : "response") +
                               " yet (its linear buckling takes a follower pressure); give point loads or gravity");
  if (spec.is_arch() && loads.pressure.any()) {
    if (loads.pressure.kind != ring::Pressure::Kind::follower)
      throw ring::InputError("", "ring.arc",
                             "lumped: " + section + ".pressure.kind = \"" +
                                 (loads.pressure.kind == ring::Pressure::Kind::dead ? "dead" : "central") +
                                 "\" on an arch (ring.arc) is not offered by the chain yet; \"follower\" is, with "
                                 "both ends pinned");
    bool from = false, to = false;
    for (double p : spec.supports.pinned()) {
      const int k = node_at(spec, p, o.n, "supports.pins");
      from = from || k == 0;
      to = to || k == o.n;
    }
    if (!from || !to)
      throw ring::InputError("", "ring.arc",
                             "lumped: " + section + ".pressure (follower) on an arch (ring.arc) needs both ends "
                             "pinned (supports.pin and supports.pins at ring.arc's ends): on a moving end the "
                             "follower load has no potential");
  }
  const std::array<std::pair<const char*, double>, 3> finite{
      {{"pressure", loads.pressure.value}, {"gravity", loads.gravity[0]}, {"gravity", loads.gravity[1]}}};
  for (const auto& [key, v] : finite)
    if (!std::isfinite(v)) throw std::invalid_argument("lumped: " + section + "." + key + " must be finite");
}

/// ring.plastic in the lumped models (bending.hpp): the resultant and the fibre law, in the
/// chain's nonlinear statics (their accepted equilibria commit the states) and its response
/// (its accepted steps commit them); buckling and the modes under load have no plastic state.
/// `what`: the analysis ("statics", "response" take it). ring::InputError naming the key
/// otherwise, and for values the law cannot take (the scene reader's rules, again for callers
/// of the library).
///
/// The frames refuse it: their bending lives in the elements, and the one bending measure an
/// element has that the law can take alone is its mean curvature (th_{j+1} - th_j) / l
/// (bending.hpp). A plastic hinge under a load, which sits on a node, then forms in both
/// elements beside the node: two hinges where the ring has one, and the ring pinched at two
/// points has four, a mechanism at first yield with hardening 0 (the statics end there at a
/// "bifurcation": measured on the pinched ring at n = 64). A hinge at the node needs the
/// node's rotation split in two across it, which the frames do not have yet.
void check_plastic(const ring::RingSpec& spec, const ring::LumpedOptions& o, const std::string& what) {
  if (!spec.plastic) return;
  const ring::Plastic& p = *spec.plastic;
  auto refuse = [](const std::string& key, const std::string& why) {
    throw ring::InputError("", key, "lumped: " + why);
  };
  if (what != "statics" && what != "response")
    refuse(
        "ring.plastic",
        "the lumped " + what +
            " has no elastic–plastic state (only the nonlinear statics and the "
            "chain's response commit one, at every accepted equilibrium or step); remove ring.plastic or run [static] "
            "or [response]");
  if (o.variant != ring::LumpedOptions::Variant::chain)
    refuse(
        "ring.plastic",
        "lumped.variant = \"" + ring::to_string(o.variant) +
            "\" cannot take it yet: a frame's "
            "bending is in its elements, so a plastic hinge at a loaded node would form in the two elements beside it "
            "(two hinges where the ring has one: a mechanism at first yield without hardening); use lumped.variant = "
            "\"chain\" (its hinges take ring.plastic)");
  if (p.law == ring::Plastic::Law::resultant) {
    if (!(p.moment > 0.0) || !std::isfinite(p.moment))
      refuse("ring.plastic.moment",
             "ring.plastic.moment (= " + std::to_string(p.moment) + " N m) must be finite and > 0");
  } else {
    if (!(p.stress > 0.0) || !std::isfinite(p.stress))
      refuse("ring.plastic.stress",
             "ring.plastic.stress (= " + std::to_string(p.stress) + " Pa) must be finite and > 0");
    // The hinge's fibres (ring/section_law.hpp) sit through the section's depth.
    if (spec.section.shape == ring::Section::Shape::general)
      refuse("ring.plastic.stress",
             "the fibre law needs the section's shape to put its fibres through the depth, and "
             "a section given by {area, inertia} has none; give ring.section as a circle or a rectangle, or use the "
             "resultant law (ring.plastic.moment)");
  }
  if (!(p.hardening >= 0.0 && p.hardening < 1.0))
    refuse("ring.plastic.hardening",
           "ring.plastic.hardening (= " + std::to_string(p.hardening) + ") must be in [0, 1)");
}

/// What every nonlinear analysis of the chain (and its linear buckling) needs; `what` is
/// "statics", "response" or "buckling".
/// `held`: [plates] hold the free ring (the statics; no pin needed).
void check_chain(const ring::RingSpec& spec, const ring::LumpedOptions& o, const std::string& what,
                 bool held = false) {
  auto need = [&](bool ok, const std::string& msg) {
    if (!ok) throw std::invalid_argument("lumped " + what + ": " + msg);
  };
  // No ring::refuse_timoshenko: the variant is the model (check_theory). Every variant has a
  // nonlinear model: "chain" (the Euler-Bernoulli chain of either ring.theory; of a Timoshenko
  // ring, its thin-ring model, as for the modes), and the frames as corotational frames
  // (frame.hpp) with their linear element's stiffness. The lumped "frame" has massless
  // rotations: no response (a state without inertia; check_response).
  using Variant = ring::LumpedOptions::Variant;
  // A spin: the chain's linear modes only (check_spin); check_modes below would take it.
  ring::refuse_rotation(spec, "the lumped " + what);
  if (what == "response")
    need(o.variant != Variant::frame,
         "lumped.variant = \"frame\" lumps no rotary inertia (its rotations are massless), so it has no response "
         "here; use \"frame-consistent\", \"timoshenko-frame\" or \"chain\"");
  check_plastic(spec, o, what);
  need(o.n >= 4, "lumped.n (=" + std::to_string(o.n) + ") must be >= 4");
  need(spec.radius > 0 && spec.E > 0 && spec.rho > 0 && spec.A() > 0 && spec.I() > 0,
       "radius, E, rho, area and inertia must be > 0");
  // Every term of the spec is in the nonlinear chain (terms.hpp); its points must be nodes.
  check_modes(spec, o);
  if (spec.supports.roller) {
    need(spec.supports.pin.has_value(), "supports.roller needs supports.pin");
    need(ring::on_node(*spec.supports.roller, *spec.supports.pin, o.n),
         "supports.roller must fall on a hinge (lumped.n = " + std::to_string(o.n) + ")");
    need(std::abs(std::remainder(*spec.supports.roller - *spec.supports.pin, 360.0)) > 1e-9,
         "supports.roller must differ from the pin");
  }
  need(held || spec.supports.pin.has_value() || spec.rigid_modes() == 0,
       "needs a pin (supports.pin), or springs or a foundation that hold every rigid motion: a free ring under "
       "a dead load has no equilibrium");
}

/// A spinning ring (rotation.speed, spin.hpp): the linear modes of the chain and of the
/// Timoshenko frame (lumped masses: the Coriolis term of a point mass) on a closed ring that
/// nothing leaves free to turn, of a size the dense gyroscopic eigensolve takes.
void check_spin(const ring::RingSpec& spec, const ring::LumpedOptions& o) {
  using Variant = ring::LumpedOptions::Variant;
  if (o.variant == Variant::frame)
    throw std::invalid_argument("lumped: lumped.variant = \"frame\" does not take rotation.speed yet (its rotations "
                                "are massless and condensed); use \"chain\" or \"timoshenko-frame\"");
  if (o.variant == Variant::frame_consistent)
    throw std::invalid_argument("lumped: lumped.variant = \"frame-consistent\" does not take rotation.speed yet (the "
                                "Coriolis term of its consistent mass is not derived); use \"chain\" or "
                                "\"timoshenko-frame\"");
  if (spec.is_arch())
    throw std::invalid_argument("lumped: rotation.speed: a spinning arch (ring.arc) is not offered");
  if (!std::isfinite(spec.rotation.speed))
    throw std::invalid_argument("lumped: rotation.speed must be finite");
  if (const int rigid = spec.rigid_modes(); rigid > 0)
    throw std::invalid_argument("lumped: rotation.speed: the spinning ring's stiffness must hold it (" +
                                std::to_string(rigid) + " rigid mode" + (rigid > 1 ? "s" : "") +
                                " left free); add supports, springs or a foundation");
  // The dense eigensolve's bound on its unknowns: about n on the chain's kernel, 3n on the frame.
  const int max_n = o.variant == Variant::chain ? kMaxPreloadHinges
                                                : static_cast<int>(modal::kMaxGyroscopicUnknowns / 3);
  if (o.n > max_n)
    throw std::invalid_argument("lumped: rotation.speed: the spinning " + ring::to_string(o.variant) +
                                "'s modes are dense (O(n^3)): lumped.n (=" + std::to_string(o.n) + ") must be <= " +
                                std::to_string(max_n));
}

/// static.displacement (ring/analysis.hpp) on a closed ring or an arch: a node of the model on no
/// support, finite, with no loads beside it (the scene reader's rules, again for callers of the
/// library). The driven point becomes two constraint rows (chain.hpp, drive(); the frames' the
/// same), so it must not coincide with a pinned point or the roller, whose rows would repeat its
/// own (a singular KKT matrix). ring::InputError naming the key.
void check_displacement(const ring::RingSpec& spec, const ring::LumpedOptions& o, const ring::StaticOptions& statics) {
  const ring::StaticOptions::Displacement& d = *statics.displacement;
  const std::string key = "static.displacement";
  auto refuse = [&](const std::string& k, const std::string& why) { throw ring::InputError("", k, "lumped: " + why); };
  if (!statics.loads.points.empty() || statics.loads.pressure.any() || statics.loads.has_gravity())
    refuse(key, "static.displacement drives the path, and loads would be scaled with it: give the one or the other");
  if (!std::isfinite(d.value[0]) || !std::isfinite(d.value[1]) || !(std::hypot(d.value[0], d.value[1]) > 0.0))
    refuse(key + ".value", "static.displacement.value (= [" + std::to_string(d.value[0]) + ", " +
                               std::to_string(d.value[1]) + "] m) must be finite and not zero");
  // An arch (ring.arc): the open chain's node (node_at: from + span k / n), its supports rows
  // as the ring's are; what the arch refuses (the frames, a roller) check_modes has refused.
  if (spec.is_arch()) {
    const int node = std::isfinite(d.at) ? ring::node_index(spec, d.at, o.n) : -1;
    if (node < 0)
      refuse(key + ".at", "static.displacement.at (= " + std::to_string(d.at) + " deg) is not a node of the n = " +
                              std::to_string(o.n) + " model of the arch (ring.arc = [" +
                              std::to_string(spec.arc->from) + ", " + std::to_string(spec.arc->to) +
                              "]; valid: from + span k / n, k = 0..n)");
    for (double p : spec.supports.pinned())
      if (node_at(spec, p, o.n, "supports") == node)
        refuse(key + ".at", "the point at " + std::to_string(d.at) + " deg is pinned (supports); drive another point");
    return;
  }
  if (!std::isfinite(d.at) || !ring::on_node(d.at, spec.anchor(), o.n))
    refuse(key + ".at", "static.displacement.at (= " + std::to_string(d.at) + " deg) is not a node of the n = " +
                            std::to_string(o.n) + " model (valid: anchor " + std::to_string(spec.anchor()) +
                            " deg + 360 k / n)");
  const int node = node_of(d.at, spec.anchor(), o.n, key + ".at");
  auto same = [&](double a) { return node_of(a, spec.anchor(), o.n, "supports") == node; };
  for (double p : spec.supports.pinned())
    if (same(p))
      refuse(key + ".at", "the point at " + std::to_string(d.at) + " deg is pinned (supports); drive another point");
  if (spec.supports.roller && same(*spec.supports.roller))
    refuse(key + ".at", "the point at " + std::to_string(d.at) + " deg is supports.roller; drive another point");
}

/// [plates] (ring/analysis.hpp, chain.hpp's hold_plates): a closed ring, no loads, no
/// static.displacement, no supports (pin, roller, pins, clamp), both points of first contact
/// nodes, a finite travel in (0, 2 R) and a finite stiffness > 0 (the scene reader's rules,
/// again for callers of the library). ring::InputError naming the key.
///
/// The frames take them elastic and at the end of the path (their statics have neither
/// ring.plastic nor static.path: check_plastic and the static.path refusal here), on their node
/// translations (frame_nonlinear.cpp).
void check_plates(const ring::RingSpec& spec, const ring::LumpedOptions& o, const ring::StaticOptions& statics) {
  const ring::StaticOptions::Plates& p = *statics.plates;
  auto refuse = [&](const std::string& k, const std::string& why) { throw ring::InputError("", k, "lumped: " + why); };
  if (o.variant != ring::LumpedOptions::Variant::chain && statics.path)
    refuse("static.path", "[plates] on lumped.variant = \"" + ring::to_string(o.variant) +
                              "\": the frames' statics have no static.path (the path with its contact lengths at every "
                              "point); give static.path = false (the crushing's end) or use lumped.variant = \"chain\"");
  if (spec.is_arch()) refuse("plates", "[plates] crush a closed ring: an arch (ring.arc) between plates is not offered");
  if (statics.displacement) refuse("plates", "[plates] drive the path already: remove static.displacement");
  if (!statics.loads.points.empty() || statics.loads.pressure.any() || statics.loads.has_gravity())
    refuse("plates", "[plates] drive the path, and loads would be scaled with them: give the one or the other");
  const ring::Supports& sup = spec.supports;
  if (sup.pin || sup.roller || !sup.pins.empty() || sup.clamp)
    refuse("plates", "the plates hold the ring themselves: remove supports.pin, .roller, .pins and .clamp");
  for (double a : {p.axis, p.axis + 180.0})
    if (!std::isfinite(a) || !ring::on_node(a, spec.anchor(), o.n))
      refuse("plates.axis", "the plates touch the ring at " + std::to_string(a) + " deg, which is not a node of the n = " +
                                std::to_string(o.n) + " chain (valid: anchor " + std::to_string(spec.anchor()) +
                                " deg + 360 k / n, with lumped.n even)");
  if (!std::isfinite(p.travel) || !(p.travel > 0.0) || !(p.travel < 2.0 * spec.radius))
    refuse("plates.travel", "plates.travel (= " + std::to_string(p.travel) + " m) must be in (0, 2 R = " +
                                std::to_string(2.0 * spec.radius) + ")");
  if (!std::isfinite(p.stiffness) || !(p.stiffness > 0.0))
    refuse("plates.stiffness", "plates.stiffness (= " + std::to_string(p.stiffness) + " N/m^2) must be finite and > 0");
}

/// What the chain does not take on an arch (ring.arc) yet: ring::InputError naming ring.arc.
void refuse_arch_here(const ring::RingSpec& spec, const std::string& who) {
  if (spec.is_arch())
    throw ring::InputError("", "ring.arc",
                           who + " does not take an arch (ring.arc) yet; the chain's linear modes, linear "
                                 "buckling, nonlinear statics (point loads, gravity, static.path) and response do");
}

}  // namespace

void check_theory(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  // The variant is the model, ring.theory the physics: an Euler-Bernoulli variant on a
  // Timoshenko ring is that ring's thin-ring model (what a thickness study measures), and
  // the Timoshenko frame on an Euler-Bernoulli ring is a richer model of it, as
  // fem.theory = "timoshenko" is. Both are taken; what the Timoshenko frame cannot do
  // without is its shear stiffness, which a section given by {area, inertia} has only
  // with ring.shear_coefficient (the scene reader's rule for ring.theory and fem.theory).
  if (options.variant != ring::LumpedOptions::Variant::timoshenko_frame) return;
  if (!(spec.kGA() > 0.0 && std::isfinite(spec.kGA())))
    throw std::invalid_argument("lumped: lumped.variant = \"" + ring::to_string(options.variant) +
                                "\" needs a shear stiffness kappa G A > 0 (ring.shear_coefficient = " +
                                std::to_string(spec.kappa()) + ", ring.nu = " + std::to_string(spec.nu) +
                                "; a section given by {area, inertia} needs ring.shear_coefficient)");
}

void check_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  // ring.variations: the linear modes at rest of every variant on a closed ring (model.hpp,
  // terms.hpp); the spinning modes (the nonlinear chain's and the corotational frame's
  // uniform pieces, spin.hpp) and an arch's are refused.
  if (spec.varies() && (spec.rotation.spinning() || spec.is_arch()))
    throw std::invalid_argument(std::string("lumped: ring.variations: ") +
                                (spec.is_arch() ? "an arch (ring.arc)" : "a spinning ring (rotation.speed)") +
                                " does not take ring.variations yet; the linear modes at rest of a closed ring do");
  // Every term of the spec is in the linear model (model.hpp); its points must be nodes.
  check_theory(spec, options);
  if (spec.rotation.spinning()) check_spin(spec, options);
  if (options.n < 4) throw std::invalid_argument("lumped.n (=" + std::to_string(options.n) + ") must be >= 4");
  const double anchor = spec.anchor();
  std::vector<std::pair<std::string, double>> points;
  if (spec.supports.clamp) points.emplace_back("supports.clamp", *spec.supports.clamp);  // before pins, which hold it too
  for (double a : spec.supports.pins) points.emplace_back("supports.pins", a);
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i)
    points.emplace_back("supports.springs[" + std::to_string(i + 1) + "]", spec.supports.springs[i].angle);
  for (std::size_t i = 0; i < spec.masses.size(); ++i)
    points.emplace_back("masses[" + std::to_string(i + 1) + "]", spec.masses[i].angle);
  if (spec.is_arch()) {
    // The chain's open form (model.hpp); the frames still close their ring.
    if (options.variant != ring::LumpedOptions::Variant::chain)
      throw ring::InputError("", "ring.arc",
                             "lumped: lumped.variant = \"" + ring::to_string(options.variant) +
                                 "\" does not take an arch (ring.arc) yet; use lumped.variant = \"chain\"");
    if (spec.supports.roller)
      throw ring::InputError("", "ring.arc",
                             "lumped: supports.roller on an arch (ring.arc) is not offered: its ends take pins, "
                             "clamps and springs");
    for (const auto& [key, a] : points) node_at(spec, a, options.n, key);
    if (spec.supports.pin) node_at(spec, *spec.supports.pin, options.n, "supports.pin");
    return;
  }
  for (const auto& [key, a] : points)
    if (!std::isfinite(a) || !ring::on_node(a, anchor, options.n))
      throw std::invalid_argument("lumped: " + key + " (= " + std::to_string(a) + " deg) is not a node of the n = " +
                                  std::to_string(options.n) + " model (valid: anchor " + std::to_string(anchor) +
                                  " deg + 360 k / n)");
}

void check_static(const ring::RingSpec& spec, const ring::LumpedOptions& options, const ring::StaticOptions& statics) {
  ring::refuse_variations(spec, "the lumped-mass model");
  if (statics.plates) check_plates(spec, options, statics);
  check_chain(spec, options, "statics", statics.plates.has_value());
  if (statics.displacement) check_displacement(spec, options, statics);
  check_loads(spec, options, statics.loads, "static");
  // A driven point holds the ring as a pin does (the scene reader's rule).
  if (ring::static_rigid_modes(spec, statics) > 0)
    throw std::invalid_argument(
        "lumped statics: needs a roller as well as the pin (supports.roller), or further pins, a clamp, springs, "
        "a foundation or gravity from which the ring hangs, to keep it from turning about the pin");
  if (statics.steps < 1) throw std::invalid_argument("lumped statics: static.steps must be >= 1");
  if (statics.path && options.variant != ring::LumpedOptions::Variant::chain)
    throw std::invalid_argument("lumped statics: static.path = true (the path through bifurcations to contact) is "
                                "offered by lumped.variant = \"chain\" only; the frames' statics give the "
                                "equilibrium at the full load");
}

void check_preloaded_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                           const ring::StaticOptions& statics) {
  ring::refuse_variations(spec, "the lumped-mass model");
  refuse_arch_here(spec, "the lumped modes under load (modes.preload)");
  // The modes about a driven state would need the driven point's rows in the eigenproblem.
  ring::refuse_displacement(statics, "the lumped modes under load (modes.preload)");
  ring::refuse_plates(statics, "the lumped modes under load (modes.preload)");
  check_plastic(spec, options, "modes under load (modes.preload)");
  if (options.variant == ring::LumpedOptions::Variant::frame)
    throw std::invalid_argument("lumped: modes.preload = \"static\": lumped.variant = \"frame\" lumps no rotary "
                                "inertia (its rotations are massless); use \"frame-consistent\", "
                                "\"timoshenko-frame\" or \"chain\"");
  if (options.n > kMaxPreloadHinges)
    throw std::invalid_argument("lumped: modes.preload = \"static\" solves a dense eigenproblem (O(n^3)): lumped.n (=" +
                                std::to_string(options.n) + ") must be <= " + std::to_string(kMaxPreloadHinges));
  check_static(spec, options, statics);
}

void check_buckling(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                    const ring::BucklingOptions& buckling) {
  ring::refuse_variations(spec, "the lumped-mass model");
  // On an arch the follower pressure alone, which Timoshenko & Gere's pinned arches test; point
  // loads and gravity bend the arch before it buckles and wait for an oracle.
  if (spec.is_arch() && (!buckling.loads.points.empty() || buckling.loads.has_gravity()))
    throw ring::InputError("", "ring.arc",
                           "lumped buckling: an arch (ring.arc) takes a follower pressure (buckling.pressure, both "
                           "ends pinned) only yet; point loads and gravity in [buckling] are not offered on it");
  check_chain(spec, options, "buckling");
  check_loads(spec, options, buckling.loads, "buckling");
  const ring::Loads& l = buckling.loads;
  if (l.points.empty() && !l.pressure.any() && !l.has_gravity())
    throw std::invalid_argument("lumped buckling: buckling.loads has no load (give point loads, a pressure or gravity)");
  if (const int rigid = spec.rigid_modes(); rigid > 0)
    throw std::invalid_argument(
        "lumped buckling: the stiffness at rest (K_0, no load) leaves " + std::to_string(rigid) + " rigid mode" +
        (rigid > 1 ? "s" : "") + " free (a ring that hangs from its pin turns freely at rest); add a roller "
        "(supports.roller), further pins, a clamp, springs or a foundation");
  if (buckling.count < 1)
    throw std::invalid_argument("lumped buckling: buckling.count (=" + std::to_string(buckling.count) +
                                ") must be >= 1");
}

void check_response(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                    const ring::ResponseOptions& r) {
  ring::refuse_variations(spec, "the lumped-mass model");
  check_chain(spec, options, "response");
  check_loads(spec, options, r.loads, "response");
  using Integrator = ring::ResponseOptions::Integrator;
  if (r.integrator == Integrator::energy_momentum)
    throw std::invalid_argument(
        "lumped response: response.integrator = \"energy-momentum\" is not offered by the lumped chain: its "
        "scheme is the implicit midpoint rule, which does not conserve energy; use \"midpoint\" (accepted: "
        "\"midpoint\", \"newmark\")");
  if (r.integrator != Integrator::midpoint && r.integrator != Integrator::newmark)
    throw std::invalid_argument("lumped response: response.integrator = \"" + ring::to_string(r.integrator) +
                                "\" is not offered by the lumped chain (accepted: \"midpoint\", \"newmark\")");
  if (options.variant != ring::LumpedOptions::Variant::chain && r.hinge_damping > 0)
    throw std::invalid_argument("lumped response: response.hinge_damping (a damper on the chain's hinge turning "
                                "rate) is not offered by lumped.variant = \"" + ring::to_string(options.variant) +
                                "\"; use Rayleigh damping (response.rayleigh_mass, response.rayleigh_stiffness)");
  if (!(r.dt > 0) || !(r.t_end >= r.dt))
    throw std::invalid_argument("lumped response: response.dt must be > 0 and <= response.t_end");
}

}  // namespace lumped
