#include "fem_reference/checks.hpp"

#include "fem_reference/buckling.hpp"  // check_buckling: declared with its analysis, checked here

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "ring/errors.hpp"

namespace fem {
namespace {

void need(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("fem: " + what);
}

/// ring.plastic enters the FE beam's nonlinear statics and response (nonlinear.hpp,
/// "Plasticity"): an analysis that would ignore it is refused by the key (this guards the
/// library's callers as well as the driver).
void refuse_plastic(const ring::RingSpec& spec, const std::string& analysis_and_why) {
  if (spec.plastic) throw ring::InputError("", "ring.plastic", "fem: " + analysis_and_why);
}

void check_linear(const ring::RingSpec& spec, const ring::FemOptions& o);

/// Where the vertices are, for a message: the ring's anchor + k 360 / fem.elements, or the
/// arch's from + k span / fem.elements.
std::string vertex_rule(const ring::RingSpec& spec) {
  if (spec.is_arch())
    return std::to_string(spec.arc->from) + " + k * " + std::to_string(spec.arc->span()) + " / fem.elements";
  return std::to_string(spec.anchor()) + " + k * 360 / fem.elements";
}

/// What the arch (ring.arc) needs of the FE model: the Euler-Bernoulli beam on the exact
/// circle (the Timoshenko model and the Reissner beam, and the polygon, keep the closed
/// ring's periodic mesh only), and no roller (a ring's roller moves along the line through
/// the pin; an arch's ends take pins and clamps).
void check_arch(const ring::RingSpec& spec, const ring::FemOptions& o) {
  if (!spec.is_arch()) return;
  if (o.theory.value_or(spec.theory) == ring::Theory::timoshenko)
    throw ring::InputError("", "ring.arc",
                           "fem: the Timoshenko model and the Reissner beam take no arch yet (ring.theory = "
                           "\"euler-bernoulli\" does)");
  if (o.geometry != ring::FemOptions::Geometry::curved)
    throw ring::InputError("", "ring.arc",
                           "fem: fem.geometry = \"polygon\" (the paper's SAP5 frame of the closed ring) takes no arch "
                           "(fem.geometry = \"curved\" does)");
  if (spec.supports.roller)
    throw ring::InputError("", "ring.arc", "fem: an arch takes no supports.roller (pin or clamp its ends)");
}

/// The end vertices of an arch that hold both displacements (a pin or a clamp there).
int held_ends(const ring::RingSpec& spec, int elements) {
  int held = 0;
  for (double end : {spec.arc->from, spec.arc->to}) {
    bool at = false;
    for (double a : spec.supports.pinned())
      at = at || ring::node_index(spec, a, elements) == ring::node_index(spec, end, elements);
    held += at;
  }
  return held;
}

/// The plastic law on the Euler-Bernoulli beam (statics and response): the fibre law needs
/// the section's shape; the Reissner beam takes no law yet (plastic_points.hpp says why).
void check_plastic(const ring::RingSpec& spec, const std::string& analysis) {
  if (!spec.plastic) return;
  if (spec.plastic->law == ring::Plastic::Law::fibre && spec.section.shape == ring::Section::Shape::general)
    throw ring::InputError("", "ring.plastic.stress",
                           "fem: the fibre law integrates the stress over the section's shape, and a section given "
                           "by {area, inertia} has none (give ring.section a circle or a rectangle, or use the "
                           "resultant law ring.plastic.moment)");
  if (spec.theory == ring::Theory::timoshenko)
    throw ring::InputError("", "ring.plastic",
                           "fem: the Reissner (Timoshenko) beam takes no plastic law yet in its " + analysis +
                               ": its bending points over-determine the curvature in a cell, so no plastic hinge "
                               "could form (use ring.theory = \"euler-bernoulli\")");
}

/// What the geometrically exact beam needs of every nonlinear analysis: the terms of the
/// linear modes (check_modes), the curved geometry, and loads that it can place: every
/// point load and record point on a vertex, finite forces, pressure and gravity.
void check_nonlinear(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::Loads& loads,
                     const std::vector<double>& record, const std::string& section) {
  check_linear(spec, o);
  // Only the linear modes take a spin (spin.hpp); the scene reader refuses the rest too.
  ring::refuse_rotation(spec, "the fem " + section + " analysis");
  need(o.geometry == ring::FemOptions::Geometry::curved,
       "the geometrically exact beam needs fem.geometry = \"curved\"");
  auto on_vertex = [&](double a, const std::string& key) {
    need(ring::on_node(spec, a, o.elements), section + "." + key + " (=" + std::to_string(a) +
                                                 ") must fall on an FE vertex: " + vertex_rule(spec));
  };
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const ring::PointLoad& load = loads.points[i];
    const std::string key = loads.points.size() == 1 ? std::string("at") : "loads[" + std::to_string(i + 1) + "].at";
    on_vertex(load.angle, key);
    need(std::isfinite(load.force[0]) && std::isfinite(load.force[1]),
         section + (loads.points.size() == 1 ? std::string(".force") : ".loads[" + std::to_string(i + 1) + "].force") +
             " must be finite");
  }
  for (double a : record) on_vertex(a, "record");
  need(std::isfinite(loads.pressure.value), section + ".pressure.value must be finite");
  need(std::isfinite(loads.gravity[0]) && std::isfinite(loads.gravity[1]), section + ".gravity must be finite");
  // The follower pressure's potential -p (A - A0) (A swept from the centre) has the follower
  // load as its gradient up to the ends' term [x cross dx] / 2: exact where neither end moves.
  if (spec.is_arch() && loads.pressure.any() && loads.pressure.kind == ring::Pressure::Kind::follower &&
      held_ends(spec, o.elements) < 2)
    throw ring::InputError("", "ring.arc",
                           "fem: a follower pressure on an arch needs both ends pinned or clamped (its potential "
                           "holds only where the ends do not move)");
}

/// The supports, springs, masses and foundation of linear modes: finite, >= 0, every point
/// on an FE vertex (anchor + k 360 / fem.elements), pins and clamp with a pin.
void check_terms(const ring::RingSpec& spec, const ring::FemOptions& o) {
  const ring::Supports& s = spec.supports;
  auto on_vertex = [&](double a, const std::string& key) {
    need(std::isfinite(a), key + " must be finite");
    need(ring::on_node(spec, a, o.elements), key + " (=" + std::to_string(a) +
                                                 ") must fall on an FE vertex: " + vertex_rule(spec));
  };
  auto non_negative = [&](double v, const std::string& key) {
    need(std::isfinite(v) && v >= 0.0, key + " (=" + std::to_string(v) + ") must be finite and >= 0");
  };
  need(s.pins.empty() || s.pin, "supports.pins needs supports.pin (the first pinned point)");
  // The clamp is one of the pinned points (the scene reader puts it there): named as itself.
  for (double a : s.pins)
    on_vertex(a, s.clamp && ring::wrap_degrees(a - *s.clamp + 1e-9) < 2e-9 ? "supports.clamp" : "supports.pins");
  if (s.clamp) {
    need(s.pin.has_value(), "supports.clamp needs supports.pin");
    bool pinned = false;
    for (double a : s.pinned()) pinned = pinned || ring::wrap_degrees(a - *s.clamp + 1e-9) < 2e-9;
    need(pinned, "supports.clamp (=" + std::to_string(*s.clamp) + ") must be supports.pin or one of supports.pins");
  }
  for (const ring::Spring& k : s.springs) {
    on_vertex(k.angle, "supports.springs.at");
    non_negative(k.kx, "supports.springs.kx");
    non_negative(k.ky, "supports.springs.ky");
    non_negative(k.kr, "supports.springs.kr");
  }
  for (const ring::PointMass& m : spec.masses) {
    on_vertex(m.angle, "masses.at");
    non_negative(m.mass, "masses.mass");
    non_negative(m.inertia, "masses.inertia");
  }
  non_negative(spec.foundation.radial, "foundation.radial");
  non_negative(spec.foundation.tangential, "foundation.tangential");
  // The polygon (the paper's SAP5 frame) is the check of the paper's ring: its chords'
  // radial and tangential directions are not the undeformed point's, so it takes none of
  // the terms beyond the paper.
  if (o.geometry == ring::FemOptions::Geometry::polygon && !spec.paper_terms_only()) {
    std::string keys;
    for (const std::string& k : spec.terms_beyond_paper()) keys += (keys.empty() ? "" : ", ") + k;
    need(false, "fem.geometry = \"polygon\" (the paper's SAP5 frame) does not take " + keys +
                    " (fem.geometry = \"curved\" does)");
  }
}

/// The linear terms every analysis of the FE beam shares (the public check_modes adds the
/// eigen-solve's precision limit).
void check_linear(const ring::RingSpec& spec, const ring::FemOptions& o) {
  need(spec.theory != ring::Theory::timoshenko || o.geometry == ring::FemOptions::Geometry::curved,
       "ring.theory = \"timoshenko\" needs fem.geometry = \"curved\" (the polygon is the paper's Euler-Bernoulli "
       "SAP5 frame)");
  need(spec.theory != ring::Theory::timoshenko || spec.kappa() > 0.0,
       "ring.theory = \"timoshenko\" needs a shear coefficient > 0 (ring.shear_coefficient)");
  need(spec.radius > 0 && std::isfinite(spec.radius), "ring.radius must be > 0");
  need(spec.E > 0 && spec.rho > 0, "ring.E and ring.rho must be > 0");
  need(spec.A() > 0 && spec.I() > 0, "the section's area and inertia must be > 0");
  need(o.elements >= 4, "fem.elements (=" + std::to_string(o.elements) + ") must be >= 4");
  need(o.degree >= kMinDegree && o.degree <= kMaxDegree, "fem.degree (=" + std::to_string(o.degree) +
                                                              ") must be in " + std::to_string(kMinDegree) + ".." +
                                                              std::to_string(kMaxDegree));
  need(!o.reference || (o.tolerance > 0 && o.tolerance < 1), "fem.tolerance must be in (0, 1)");
  need(!o.reference || (o.response_tolerance > 0 && o.response_tolerance < 1), "fem.response_tolerance must be in (0, 1)");
  need(!spec.supports.roller || spec.supports.pin, "supports.roller needs supports.pin");
  check_arch(spec, o);
  check_terms(spec, o);
  if (spec.supports.roller) {
    need(ring::wrap_degrees(*spec.supports.roller - *spec.supports.pin) > 1e-9 &&
             ring::wrap_degrees(*spec.supports.pin - *spec.supports.roller) > 1e-9,
         "supports.roller must differ from supports.pin");
    need(ring::on_node(*spec.supports.roller, *spec.supports.pin, o.elements),
         "supports.roller (=" + std::to_string(*spec.supports.roller) +
             ") must fall on an FE vertex: pin + k * 360 / fem.elements");
  }
}

}  // namespace

double precision_ratio_bound(int elements, int degree) {
  // Lower envelope of the measured ratios (table above kPrecisionLimit's doc): 2.0e4 at
  // 10^4 cells of degree 6, times cells^4, times p^7 above p = 6 (measured p^7.2 from 6 to
  // 8, p^7.5 from 8 to 12) and p^8 below it (the steepest growth measured, so the bound
  // falls fastest towards low p). It stays 7 to 35 % under every measured ratio:
  // 1000 x 12: 256 (340), 3000 x 12: 2.1e4 (2.8e4), 10^4 x 8: 1.5e5 (1.6e5), 5000 x 12:
  // 1.6e5 (2.1e5), 7000 x 12: 6.1e5 (8.2e5), 10^4 x 12: 2.6e6 (3.4e6).
  const double cells = elements / 1e4, p = degree / 6.0;
  return 2.0e4 * std::pow(cells, 4) * std::pow(p, degree >= 6 ? 7.0 : 8.0);
}

/// The modes of a spinning ring (spin.hpp): what their path cannot take, by key.
static void check_spin(const ring::RingSpec& spec, const ring::FemOptions& o) {
  need(std::isfinite(spec.rotation.speed), "rotation.speed must be finite");
  need(!spec.is_arch(), "rotation.speed: an arch (ring.arc) does not spin here (rotation is the closed ring's)");
  need(o.geometry == ring::FemOptions::Geometry::curved,
       "fem.geometry = \"polygon\" does not take a spinning ring (rotation.speed): the spin's terms are the "
       "geometrically exact beam's, on the curved geometry");
  need(spec.rigid_modes() == 0,
       "rotation.speed: a spinning ring needs its rigid motions held in the turning frame (" +
           std::to_string(spec.rigid_modes()) + " left free): supports, springs or a foundation");
  refuse_plastic(spec, "the modes of a spinning ring take the elastic tangent at the spin's equilibrium (remove "
                       "ring.plastic or rotation.speed)");
}

void check_modes(const ring::RingSpec& spec, const ring::FemOptions& o) {
  // ring.variations: the Euler-Bernoulli ring's linear modes take them (RingModel's local
  // section, ring_model.hpp); the Timoshenko model's one cell matrix and the spinning ring's
  // geometrically exact terms do not yet.
  if (spec.varies() && (o.theory.value_or(spec.theory) == ring::Theory::timoshenko || spec.rotation.spinning()))
    ring::refuse_variations(spec, spec.rotation.spinning() ? "the fem modes of a spinning ring"
                                                           : "the fem Timoshenko ring");
  check_linear(spec, o);
  if (spec.rotation.spinning()) check_spin(spec, o);
  // The eigen-solve's precision limit, from fem.elements and fem.degree alone: refused
  // here, before any assembly, where the bound already exceeds the limit (the model's own
  // ratio, measured after assembly in modes.cpp, catches the rest). 10^4 elements of
  // degree 12 were refused only after 10 s and 707 MB of assembly (issue 46). The bound is
  // the Euler-Bernoulli ring's bending, which no other term lowers; a Timoshenko model's
  // high end grows like cells^2 (shear), so only the assembled ratio judges it.
  const ring::Theory theory = o.theory.value_or(spec.theory);
  if (theory == ring::Theory::euler_bernoulli && o.geometry == ring::FemOptions::Geometry::curved) {
    const double bound = precision_ratio_bound(o.elements, o.degree);
    if (!(bound <= kPrecisionLimit)) {
      // The bound grows like cells^4: this many cells of the degree reach the limit.
      const int most = static_cast<int>(o.elements * std::pow(kPrecisionLimit / bound, 0.25));
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.3g", bound);
      need(false, "fem.elements (=" + std::to_string(o.elements) + ") with fem.degree (=" + std::to_string(o.degree) +
                      ") are too fine for double precision: the stiffness spans at least eps lambda_max / |sigma| = " +
                      ratio + " (limit " + std::to_string(static_cast<int>(kPrecisionLimit)) +
                      "), and the lowest frequencies would be wrong; use at most about " + std::to_string(most) +
                      " elements of this degree, or a lower degree");
    }
  }
}

/// static.displacement (static_path.cpp, "the driven point"): a vertex of the beam that no
/// support holds, a finite displacement, no loads with it (they would be scaled with the
/// displacement). The scene reader checks the same; this guards the library's callers.
static void check_displacement(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  if (!st.displacement) return;
  const ring::StaticOptions::Displacement& d = *st.displacement;
  const std::string key = "static.displacement";
  auto refuse = [&](const std::string& sub, const std::string& why) {
    throw ring::InputError("", key + sub, "fem: " + why);
  };
  if (!std::isfinite(d.at) || !ring::on_node(spec, d.at, o.elements))
    refuse(".at", "the driven point (=" + std::to_string(d.at) + ") must fall on an FE vertex: " + vertex_rule(spec));
  if (!std::isfinite(d.value[0]) || !std::isfinite(d.value[1]) || std::hypot(d.value[0], d.value[1]) == 0.0)
    refuse(".value", "the displacement must be finite and not zero");
  const int at = ring::node_index(spec, d.at, o.elements);
  std::vector<double> held = spec.supports.pinned();
  if (spec.supports.roller) held.push_back(*spec.supports.roller);
  for (const ring::Spring& k : spec.supports.springs) held.push_back(k.angle);
  for (double a : held)
    if (ring::node_index(spec, a, o.elements) == at)
      refuse(".at", "the driven point (=" + std::to_string(d.at) +
                        " deg) has a support (pin, roller or spring) on its vertex; drive another point");
  if (!st.loads.points.empty() || st.loads.pressure.any() || st.loads.has_gravity())
    refuse("", "static.displacement drives the path, and loads would be scaled with it: give the one or the other");
}

/// [plates] (static_path.cpp, BeamPotential): the closed ring on the curved geometry, both
/// points of first contact on vertices, no loads and no supports, a finite approach and a
/// positive stiffness. The scene reader checks the same; this guards the library's callers.
/// Refused: the inextensible extrapolation and the reference refinement (their results are
/// combinations of paths whose contact lengths are not a smooth function of EA or of the mesh:
/// the extent jumps by the quadrature and sample spacing; untested, so refused).
static void check_plates(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  if (!st.plates) return;
  const ring::StaticOptions::Plates& p = *st.plates;
  auto refuse = [](const std::string& sub, const std::string& why) { throw ring::InputError("", "plates" + sub, "fem: " + why); };
  if (spec.is_arch()) refuse("", "the plates crush a closed ring (remove ring.arc)");
  if (o.geometry != ring::FemOptions::Geometry::curved)
    refuse("", "the plates' penalty is integrated on the curved geometry (fem.geometry = \"curved\")");
  if (!std::isfinite(p.axis) || !ring::on_node(spec, p.axis, o.elements) || !ring::on_node(spec, p.axis + 180.0, o.elements))
    refuse(".axis", "the points of first contact (=" + std::to_string(p.axis) + " and " + std::to_string(p.axis + 180.0) +
                        " deg) must fall on FE vertices: " + vertex_rule(spec) + " (an even fem.elements)");
  if (!(std::isfinite(p.travel) && p.travel > 0.0 && p.travel < 2.0 * spec.radius))
    refuse(".travel", "the plates' approach (=" + std::to_string(p.travel) + " m) must lie in (0, 2 R)");
  if (!(std::isfinite(p.stiffness) && p.stiffness > 0.0))
    refuse(".stiffness", "the penalty (=" + std::to_string(p.stiffness) + " N/m^2) must be positive and finite");
  if (!st.loads.points.empty() || st.loads.pressure.any() || st.loads.has_gravity())
    refuse("", "the plates drive the path, and loads would be scaled with them: give the one or the other");
  if (st.displacement) refuse("", "the plates drive the path: remove static.displacement");
  if (spec.supports.pin || spec.supports.roller || !spec.supports.pins.empty() || spec.supports.clamp)
    refuse("", "the plates hold the ring (and its two no-slide rows): remove the pin, roller, pins and clamp");
  if (!o.extensible)
    refuse("", "fem.extensible = false (the extrapolation from two paths) is not offered with the plates: its contact "
               "lengths, extents on sampled points, are not smooth in 1/EA; use fem.extensible = true");
  if (o.reference)
    refuse("", "fem.reference = true is not offered with the plates (untested: the contact's extent moves between "
               "the quadrature points as the mesh refines); choose fem.elements and fem.degree");
}

void check_static(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  ring::refuse_variations(spec, "the fem beam");
  check_nonlinear(spec, o, st.loads, st.record, "static");
  check_displacement(spec, o, st);
  check_plates(spec, o, st);
  if (spec.is_arch() && spec.plastic)
    throw ring::InputError("", "ring.arc", "fem: the plastic statics take no arch yet (remove ring.plastic)");
  check_plastic(spec, "statics");
  // An equilibrium from rest needs a regular tangent there: nothing of the ring may move
  // freely, unless gravity holds a ring that hangs from its pin (ring::static_rigid_modes).
  // A driven point holds the ring as a pin does (its two multipliers, static_path.cpp); the
  // plates hold it along their normal, and their no-slide rows along them and its turning.
  need(ring::static_rigid_modes(spec, st) == 0,
       "statics need supports that hold every rigid motion (" + std::to_string(spec.rigid_modes()) +
           " left free): a pin and supports.roller, supports.pins, supports.clamp, supports.springs or a foundation");
  // static.path follows one discretization's path to its end (contact as a result): the
  // reference refinement and the inextensible extrapolation (two paths combined) have no
  // one path to report.
  need(!st.path || !o.reference,
       "static.path = true traces one discretization: fem.reference = true is not offered with it");
  need(!st.path || o.extensible,
       "static.path = true traces one path: fem.extensible = false (an extrapolation from two paths) is not offered "
       "with it");
}

void check_buckling(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::BucklingOptions& b) {
  ring::refuse_variations(spec, "the fem beam");
  refuse_plastic(spec, "linear buckling is about the undeformed, elastic ring and would ignore the plastic law "
                       "(follow the equilibrium path with static.path = true instead)");
  check_nonlinear(spec, o, b.loads, {}, "buckling");
  need(b.count >= 1, "buckling.count (=" + std::to_string(b.count) + ") must be >= 1");
  need(!b.loads.points_only() || !b.loads.points.empty(),
       "buckling.loads has no load: give a point load, a pressure or gravity");
  // Buckling about a state that exists: the tangent at rest must be regular.
  need(ring::static_rigid_modes(spec, b.loads) == 0,
       "linear buckling needs supports that hold every rigid motion (" + std::to_string(spec.rigid_modes()) +
           " left free): a pin and supports.roller, supports.pins, supports.clamp, supports.springs or a foundation");
}

void check_preloaded_modes(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  ring::refuse_variations(spec, "the fem beam");
  ring::refuse_arch(spec, "the fem modes under load");
  refuse_plastic(spec, "the modes under load take the elastic tangent at the loaded equilibrium, which the plastic "
                       "statics do not provide yet (remove modes.preload)");
  // static.path shapes the path's report, not the equilibrium at the full load.
  ring::StaticOptions at_full_load = st;
  at_full_load.path = false;
  check_static(spec, o, at_full_load);
  // The loaded modes keep the rounding of the assembled tangent (preload.hpp, "Accuracy"):
  // a refinement that stops on the change between discretizations would stall there.
  need(!o.reference, "fem.reference = true is not offered with modes.preload = \"static\": the frequencies under load "
                     "keep the rounding of the assembled tangent (1e-10 to 3e-7 of omega, growing with fem.degree and "
                     "fem.elements), at or above fem.tolerance, so a refinement until they stop changing would stall; "
                     "choose fem.elements and fem.degree (16 elements of degree 6 are converged to ~2e-8 on the paper's ring)");
  need(!o.rotary_inertia, "fem.rotary_inertia = true is not offered with modes.preload = \"static\" (the geometrically "
                          "exact beam has no cross-section rotary inertia; linear modes only)");
}

void check_response(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::ResponseOptions& rs) {
  ring::refuse_variations(spec, "the fem beam");
  check_nonlinear(spec, o, rs.loads, rs.record, "response");
  check_plastic(spec, "response");
  need(spec.supports.pin || spec.rigid_modes() == 0,
       "needs a pin (supports.pin), or springs or a foundation that hold every rigid motion: a free ring under a "
       "load drifts away");
  need(!o.rotary_inertia, "fem.rotary_inertia = true is not offered for the nonlinear response (linear modes only)");
  need(rs.hinge_damping == 0.0, "response.hinge_damping: the FE beam has no hinges (use rayleigh_* damping)");
  need(rs.integrator == ring::ResponseOptions::Integrator::newmark ||
           rs.integrator == ring::ResponseOptions::Integrator::generalized_alpha,
       "response.integrator = \"" + ring::to_string(rs.integrator) +
           "\" is not offered by the FE beam (accepted: \"newmark\", \"generalized-alpha\")");
  need(rs.dt > 0 && rs.t_end >= rs.dt, "response.dt must be > 0 and <= response.t_end");
}

}  // namespace fem
