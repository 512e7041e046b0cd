// Scene parsing and validation. Every key is checked for type and range here, once;
// solvers receive validated options and never re-check user input.
#include "ring/scene.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <sstream>

#include <toml++/toml.h>

#include "ring/errors.hpp"
#include "ring/toml_reader.hpp"

namespace ring {
namespace {

using toml_input::Reader;
using toml_input::fmt_num;

/// Angular distance of two angles on the circle, degrees in [0, 180].
double circular_distance(double a, double b) {
  const double d = wrap_degrees(a - b);
  return std::min(d, 360.0 - d);
}



/// ring.plastic: { moment = Mp } (the resultant law) or { stress = sigma_y } (the fibre law,
/// on a section with a shape), hardening in [0, 1), rule kinematic or isotropic.
std::optional<Plastic> read_plastic(const Reader& r, const toml::table& ring_t, const Section& section) {
  const toml::table* t = r.table(ring_t, "ring", "plastic");
  if (!t) return std::nullopt;
  const std::string sec = "ring.plastic";
  r.known_keys(*t, sec, {"moment", "stress", "hardening", "rule"});
  Plastic p;
  if (t->contains("moment") == t->contains("stress"))
    r.fail(sec, t, "give one of 'moment' (N m: the resultant law, moment against curvature) or 'stress' (Pa: the "
                   "fibre law, stress against strain over the section's shape)");
  if (t->contains("moment")) {
    p.law = Plastic::Law::resultant;
    p.moment = r.number(*t, sec, "moment", 0.0, 0.0, HUGE_VAL, true);
  } else {
    p.law = Plastic::Law::fibre;
    p.stress = r.number(*t, sec, "stress", 0.0, 0.0, HUGE_VAL, true);
    if (section.shape == Section::Shape::general)
      r.fail(sec + ".stress", t->get("stress"),
             "the fibre law integrates over the section's shape, and a section given by {area, inertia} has none "
             "(give ring.section a circle or a rectangle, or use the resultant law 'moment')");
  }
  p.hardening = r.number(*t, sec, "hardening", 0.0, 0.0, 1.0);
  if (!(p.hardening < 1.0))
    r.fail(sec + ".hardening", t->get("hardening"), "expected a number in [0, 1): the tangent past yield over EI");
  p.rule = r.choice(*t, sec, "rule", "kinematic", {"kinematic", "isotropic"}) == "kinematic" ? Plastic::Rule::kinematic
                                                                                            : Plastic::Rule::isotropic;
  return p;
}

Section read_section(const Reader& r, const toml::table& ring_t) {
  Section s;
  const toml::table* t = r.table(ring_t, "ring", "section");
  if (!t) {  // the paper's ring: solid circle, 0.12 m
    s.diameter = 0.12;
    return s;
  }
  const std::string sec = "ring.section";
  r.known_keys(*t, sec, {"shape", "diameter", "width", "height", "area", "inertia"});
  std::string shape = r.choice(*t, sec, "shape", "", {"circle", "rectangle", "general"});
  if (shape.empty()) shape = t->contains("area") || t->contains("inertia") ? "general"
                            : t->contains("width") || t->contains("height") ? "rectangle" : "circle";
  auto need = [&](const std::string& key, double& out) {
    if (!t->contains(key))
      r.fail(sec + "." + key, t, "a " + shape + " section needs '" + key + "' (m" +
                                      (key == "area" ? "^2" : key == "inertia" ? "^4" : "") + ")");
    out = r.number(*t, sec, key, 0.0, 0.0, HUGE_VAL, true);
  };
  auto forbid = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (t->contains(k)) r.fail(sec + "." + k, t->get(k), "not used by a " + shape + " section");
  };
  if (shape == "circle") {
    s.shape = Section::Shape::circle;
    need("diameter", s.diameter);
    forbid({"width", "height", "area", "inertia"});
  } else if (shape == "rectangle") {
    s.shape = Section::Shape::rectangle;
    need("width", s.width);
    need("height", s.height);
    forbid({"diameter", "area", "inertia"});
  } else {
    s.shape = Section::Shape::general;
    need("area", s.area_);
    need("inertia", s.inertia_);
    forbid({"diameter", "width", "height"});
  }
  return s;
}

/// The key of point load i in messages: "static.at" for the one-load shorthand,
/// "static.loads[2].at" (1-based) in a list.
std::string point_load_key(const std::string& sec, const Loads& loads, std::size_t i) {
  return loads.points.size() == 1 ? sec + ".at" : sec + ".loads[" + std::to_string(i + 1) + "].at";
}

/// One point load: `at` (degrees) and `force` ([Fx, Fy], N) of the table `t` named `name`.
PointLoad read_point_load(const Reader& r, const toml::table& t, const std::string& name) {
  PointLoad p;
  if (!t.contains("at")) r.fail(Reader::dotted(name, "at"), &t, "missing: the angle (degrees) of the loaded point");
  if (!t.contains("force")) r.fail(Reader::dotted(name, "force"), &t, "missing: the force [Fx, Fy] in N");
  p.angle = wrap_degrees(r.number(t, name, "at", 0.0, -360.0, 360.0));
  const auto f = r.numbers(t, name, "force", {}, 2);
  p.force = {f[0], f[1]};
  return p;
}

/// static.displacement = {at, value = [ux, uy]}: the driven point (ring/analysis.hpp).
StaticOptions::Displacement read_displacement(const Reader& r, const toml::table& t, const RingSpec& ring) {
  const std::string name = "static.displacement";
  r.known_keys(t, name, {"at", "value"});
  if (!t.contains("at")) r.fail(name + ".at", &t, "missing: the angle (degrees) of the driven point");
  if (!t.contains("value")) r.fail(name + ".value", &t, "missing: the displacement [ux, uy] in m at load factor 1");
  StaticOptions::Displacement d;
  d.at = wrap_degrees(r.number(t, name, "at", 0.0, -360.0, 360.0));
  const auto v = r.numbers(t, name, "value", {}, 2);
  // Beyond a few radii no model here holds (the inextensible ring spans 2 R at most); the
  // bound keeps 1e300 from reaching a solver.
  const double reach = 4.0 * ring.radius;
  if (!(std::hypot(v[0], v[1]) > 0.0) || std::hypot(v[0], v[1]) > reach)
    r.fail(name + ".value", t.get("value"),
           "expected a displacement of length in (0, " + fmt_num(reach) + "] m (4 radii), got [" + fmt_num(v[0]) + ", " +
               fmt_num(v[1]) + "]");
  d.value = {v[0], v[1]};
  for (double p : ring.supports.pinned())
    if (circular_distance(d.at, p) < 1e-6)
      r.fail(name + ".at", t.get("at"), "the point at " + fmt_num(d.at) + " deg is pinned (supports); drive another point");
  if (ring.supports.roller && circular_distance(d.at, *ring.supports.roller) < 1e-6)
    r.fail(name + ".at", t.get("at"), "the point at " + fmt_num(d.at) + " deg is supports.roller; drive another point");
  for (const auto& sp : ring.supports.springs)
    if (circular_distance(d.at, sp.angle) < 1e-6)
      r.fail(name + ".at", t.get("at"), "the point at " + fmt_num(d.at) + " deg has a support spring; drive another point");
  return d;
}

/// [plates] axis = DEG, travel = METRES, stiffness = N/m^2: the plates that drive [static]
/// (ring/analysis.hpp, StaticOptions::Plates and PlatePair).
StaticOptions::Plates read_plates(const Reader& r, const toml::table& t, const RingSpec& ring) {
  const std::string name = "plates";
  r.known_keys(t, name, {"axis", "travel", "stiffness"});
  if (!t.contains("travel"))
    r.fail(name + ".travel", &t, "missing: the plates' approach in m at load factor 1 (they crush the ring by it)");
  StaticOptions::Plates p;
  p.axis = wrap_degrees(r.number(t, name, "axis", 90.0, -360.0, 360.0));
  // Two plates an approach of 2 R apart have flattened the ring (its wall is not modelled
  // through its thickness): the approach stays below the diameter.
  const double diameter = 2.0 * ring.radius;
  p.travel = r.number(t, name, "travel", 0.0, 0.0, diameter);
  if (!(p.travel > 0.0) || !(p.travel < diameter))
    r.fail(name + ".travel", t.get("travel"),
           "expected an approach in (0, " + fmt_num(diameter) + ") m (below the diameter), got " + fmt_num(p.travel));
  // E A^2 / (12 I): E b / h for a b x h rectangle, the wall's own stiffness through its depth.
  const double wall = ring.E * ring.A() * ring.A() / (12.0 * ring.I());
  p.stiffness = r.number(t, name, "stiffness", wall, 0.0, 1e6 * wall);
  if (!(p.stiffness > 0.0))
    r.fail(name + ".stiffness", t.get("stiffness"), "expected a penalty stiffness > 0 N/m^2 (default E A^2 / (12 I) = " +
                                                        fmt_num(wall) + ")");
  return p;
}

/// The loads of [static] or [response]: point loads (`loads = [{at, force}, ...]`, or the
/// one-load shorthand `at`/`force`), `pressure = {value, kind}` and `gravity = [gx, gy]`;
/// at least one of them.
Loads read_loads(const Reader& r, const toml::table& t, const std::string& sec) {
  Loads loads;
  const bool shorthand = t.contains("at") || t.contains("force");
  if (shorthand && t.contains("loads"))
    r.fail(sec + ".loads", t.get("loads"), "give the point loads either as " + sec + ".at/force or as " + sec +
                                               ".loads = [{at, force}, ...], not both");
  if (shorthand) loads.points.push_back(read_point_load(r, t, sec));
  for (const auto& [name, lt] : r.tables(t, sec, "loads")) {
    r.known_keys(*lt, name, {"at", "force"});
    loads.points.push_back(read_point_load(r, *lt, name));
  }
  for (std::size_t i = 0; i < loads.points.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (circular_distance(loads.points[i].angle, loads.points[j].angle) < 1e-6)
        r.fail(sec + ".loads[" + std::to_string(i + 1) + "].at", t.get("loads"),
               "acts at the point of " + sec + ".loads[" + std::to_string(j + 1) + "]; add the forces into one load");
  if (const toml::table* pt = r.table(t, sec, "pressure")) {
    const std::string name = sec + ".pressure";
    r.known_keys(*pt, name, {"value", "kind"});
    if (!pt->contains("value")) r.fail(name + ".value", pt, "missing: the pressure in N/m (positive inward)");
    loads.pressure.value = r.number(*pt, name, "value", 0.0, -HUGE_VAL, HUGE_VAL);
    const std::string kind = r.choice(*pt, name, "kind", "follower", {"follower", "dead", "central"});
    loads.pressure.kind = kind == "dead" ? Pressure::Kind::dead
                        : kind == "central" ? Pressure::Kind::central : Pressure::Kind::follower;
  }
  if (t.contains("gravity")) {
    const auto g = r.numbers(t, sec, "gravity", {}, 2);
    loads.gravity = {g[0], g[1]};
  }
  if (loads.points.empty() && !loads.pressure.any() && !loads.has_gravity())
    r.fail(sec, &t, "has no load: give " + sec + ".at and " + sec + ".force, " + sec + ".loads, " + sec +
                        ".pressure or " + sec + ".gravity");
  return loads;
}

LoadHistory read_history(const Reader& r, const toml::table& t, const std::string& sec) {
  LoadHistory h;
  const std::string kind = r.choice(t, sec, "history", "step", {"step", "ramp", "half-sine", "harmonic"});
  h.kind = kind == "ramp" ? LoadHistory::Kind::ramp
         : kind == "half-sine" ? LoadHistory::Kind::half_sine
         : kind == "harmonic" ? LoadHistory::Kind::harmonic : LoadHistory::Kind::step;
  h.period = r.number(t, sec, "period", 1.0, 0.0, HUGE_VAL, true);
  return h;
}

std::vector<double> read_record(const Reader& r, const toml::table& t, const std::string& sec) {
  std::vector<double> rec = r.numbers(t, sec, "record", {0.0, 90.0, 180.0, 270.0});
  for (double& a : rec) {
    if (a < -360.0 || a > 360.0) r.fail(sec + ".record", t.get("record"), "angles must lie in [-360, 360] degrees");
    a = wrap_degrees(a);
  }
  return rec;
}

/// A path of the scene resolved against the scene file's folder (absolute paths as given).
std::string beside_scene(const std::string& scene, const std::string& path) {
  if (path.empty() || path.front() == '/') return path;
  const auto slash = scene.find_last_of('/');
  return slash == std::string::npos ? path : scene.substr(0, slash + 1) + path;
}

/// [[table.import]]: label, file, shapes. The files themselves are read by the driver
/// (compare/imports.hpp), which names their lines.
std::vector<ImportedColumn> read_imports(const Reader& r, const toml::table& t, const SceneSchema& schema) {
  std::vector<ImportedColumn> out;
  const toml::node* n = t.get("import");
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    r.fail("table.import", n, "expected [[table.import]] tables with label and file");
  for (const auto& e : *a) {
    const toml::table& it = *e.as_table();
    const std::string sec = "table.import";
    r.known_keys(it, sec, {"label", "file", "shapes"});
    auto text = [&](const std::string& key, bool required) {
      const toml::node* v = it.get(key);
      if (!v) {
        if (required) r.fail(sec + "." + key, &it, "missing: " + std::string(key == "label" ? "the column's name" : "the CSV file (mode, omega or mode, hz)"));
        return std::string();
      }
      auto str = v->value_exact<std::string>();
      if (!str || str->empty()) r.fail(sec + "." + key, v, "expected a non-empty string");
      return *str;
    };
    ImportedColumn c;
    c.label = text("label", true);
    const bool word = std::all_of(c.label.begin(), c.label.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
    });
    if (!word || c.label.size() > 40)
      r.fail(sec + ".label", it.get("label"), "expected up to 40 letters, digits, '_' or '-' (it names a column and a gate)");
    if (schema.find(c.label) || c.label == "reference" || c.label == "paper" || c.label == "mode")
      r.fail(sec + ".label", it.get("label"), "\"" + c.label + "\" names a solver or a column of the table already");
    for (const auto& o : out)
      if (o.label == c.label) r.fail(sec + ".label", it.get("label"), "\"" + c.label + "\" is imported twice");
    c.file = beside_scene(r.file(), text("file", true));
    c.shapes = beside_scene(r.file(), text("shapes", false));
    out.push_back(c);
  }
  return out;
}

void read_gates(const Reader& r, const toml::table& t, Scene& s, const SceneSchema& schema) {
  std::vector<std::string> names = schema.names();
  for (const auto& c : s.table.imports) names.push_back(c.label);
  r.known_keys(t, "gates", names);
  for (const auto& [k, node] : t) {
    const std::string solver(k.str());
    const std::string key = "gates." + solver;
    auto one = [&](const toml::node& n) {
      Gate g;
      g.solver = solver;
      if (n.is_number()) {
        g.max_pct = n.value<double>().value();
        r.check_range(key, &n, g.max_pct, 0.0, HUGE_VAL, true);
      } else if (const toml::table* gt = n.as_table()) {
        r.known_keys(*gt, key, {"max", "modes", "against", "analysis"});
        g.analysis = r.choice(*gt, key, "analysis", "modes", {"modes", "response", "static"});
        if (g.analysis != "modes" && gt->contains("modes"))
          r.fail(key + ".modes", gt->get("modes"), "a mode range gates frequencies (analysis = \"modes\")");
        if (!gt->contains("max")) r.fail(key + ".max", gt, "missing: the largest allowed |error| in percent");
        g.max_pct = r.number(*gt, key, "max", 0.0, 0.0, HUGE_VAL, true);
        std::vector<std::string> against = {"reference", "paper"};
        for (const auto& o : names)
          if (o != solver) against.push_back(o);
        if (g.analysis != "modes") against.erase(against.begin() + 1);  // no published nonlinear values
        g.against = r.choice(*gt, key, "against", "reference", against);
        const auto m = r.numbers(*gt, key, "modes", {1.0, 0.0}, 2);
        g.first_mode = static_cast<int>(m[0]);
        g.last_mode = static_cast<int>(m[1]);
        if (m[0] != g.first_mode || m[1] != g.last_mode || g.first_mode < 1 ||
            (g.last_mode != 0 && g.last_mode < g.first_mode) || g.last_mode > s.modes.count)
          r.fail(key + ".modes", gt->get("modes"),
                 "expected [first, last] mode numbers with 1 <= first <= last <= modes.count (" +
                     std::to_string(s.modes.count) + ")");
      } else {
        r.fail(key, &n, "expected a number (max |error| in %) or a table {max, modes, against}");
      }
      s.gates.push_back(g);
    };
    if (const toml::array* a = node.as_array()) {
      for (const auto& e : *a) one(e);
    } else {
      one(node);
    }
  }
}

/// The angle of a point key, wrapped to [0, 360).
double read_angle(const Reader& r, const toml::table& t, const std::string& sec, const std::string& key) {
  if (!t.contains(key)) r.fail(Reader::dotted(sec, key), &t, "missing: the angle (degrees) of the point");
  return wrap_degrees(r.number(t, sec, key, 0.0, -360.0, 360.0));
}

/// ring.arc = [from, to]: an arch (degrees, counter-clockwise), from in [-360, 360] and
/// 0 < to - from < 360; absent: the closed ring.
/// ring.variations = [{harmonic, thickness, density, phase}, ...] (ring/spec.hpp, Variation).
/// Each model's resolution of the harmonics is checked with the nodes (check_nodes).
std::vector<Variation> read_variations(const Reader& r, const toml::table& ring_t, const Section& section) {
  std::vector<Variation> out;
  double thick = 0.0, dense = 0.0;
  for (const auto& [name, vt] : r.tables(ring_t, "ring", "variations")) {
    r.known_keys(*vt, name, {"harmonic", "thickness", "density", "phase"});
    Variation v;
    if (!vt->contains("harmonic")) r.fail(name + ".harmonic", vt, "missing: the wave number K >= 1 of cos(K theta)");
    v.harmonic = static_cast<int>(r.integer(*vt, name, "harmonic", 1, 1, 1000000));
    v.thickness = r.number(*vt, name, "thickness", 0.0, -1.0, 1.0);
    v.density = r.number(*vt, name, "density", 0.0, -1.0, 1.0);
    v.phase = r.number(*vt, name, "phase", 0.0, -360.0, 360.0);
    if (v.thickness == 0.0 && v.density == 0.0)
      r.fail(name, vt, "a variation needs a thickness or a density amplitude (relative, in (-1, 1))");
    if (v.thickness != 0.0 && section.shape == Section::Shape::general)
      r.fail(name + ".thickness", vt->get("thickness"),
             "a section given by {area, inertia} has no radial depth to vary: give its shape (circle or rectangle), "
             "or vary the density alone");
    thick += std::abs(v.thickness), dense += std::abs(v.density);
    if (thick >= 1.0)
      r.fail(name + ".thickness", vt->get("thickness"),
             "the thickness amplitudes add up to " + fmt_num(thick) + ": a depth of 0 or less somewhere (keep the sum of "
             "|thickness| below 1)");
    if (dense >= 1.0)
      r.fail(name + ".density", vt->get("density"),
             "the density amplitudes add up to " + fmt_num(dense) + ": a density of 0 or less somewhere (keep the sum of "
             "|density| below 1)");
    out.push_back(v);
  }
  return out;
}

std::optional<Arc> read_arc(const Reader& r, const toml::table& ring_t) {
  if (!ring_t.contains("arc")) return std::nullopt;
  const toml::node* n = ring_t.get("arc");
  const std::vector<double> v = r.numbers(ring_t, "ring", "arc", {}, 2);
  Arc arc{v[0], v[1]};
  if (arc.from < -360.0 || arc.from > 360.0)
    r.fail("ring.arc", n, "the first angle (from) must lie in [-360, 360] degrees, got " + fmt_num(arc.from));
  if (!(arc.span() > 0.0))
    r.fail("ring.arc", n, "expected [from, to] with to > from (degrees, counter-clockwise), got [" + fmt_num(arc.from) +
                              ", " + fmt_num(arc.to) + "]");
  if (arc.span() >= 360.0)
    r.fail("ring.arc", n, "the arch spans " + fmt_num(arc.span()) +
                              " degrees; an arch spans less than 360 (a closed ring: leave ring.arc out)");
  return arc;
}

/// [supports]: pin, pins, clamp, roller, springs. `pin` is the first pinned point (the
/// models' anchor): given, else the clamp, else the first of `pins`.
void read_supports(const Reader& r, const toml::table& root, RingSpec& ring) {
  const toml::table* t = r.table(root, "", "supports");
  if (!t) return;
  r.known_keys(*t, "supports", {"pin", "pins", "clamp", "roller", "springs"});
  Supports& sup = ring.supports;
  std::vector<double> pinned;
  if (t->contains("pin")) pinned.push_back(read_angle(r, *t, "supports", "pin"));
  if (t->contains("clamp")) {
    sup.clamp = read_angle(r, *t, "supports", "clamp");
    pinned.insert(pinned.begin() + (pinned.empty() ? 0 : 1), *sup.clamp);
  }
  for (double a : r.numbers(*t, "supports", "pins", {})) {
    if (a < -360.0 || a > 360.0) r.fail("supports.pins", t->get("pins"), "angles must lie in [-360, 360] degrees");
    pinned.push_back(wrap_degrees(a));
  }
  // A clamp at the pin is the pin clamped; any other coincidence is a mistake. Sorted
  // neighbours (and the last with the first across 360) find every pair closer than 1e-6
  // degrees: O(n log n), where comparing every pair took 48 s for 100 000 pins (issue 46).
  if (sup.clamp && t->contains("pin") && circular_distance(pinned[0], pinned[1]) < 1e-6)
    pinned.erase(pinned.begin() + 1);
  std::vector<double> sorted = pinned;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size() && sorted.size() > 1; ++i) {
    const double next = i + 1 < sorted.size() ? sorted[i + 1] : sorted.front();
    if (circular_distance(sorted[i], next) < 1e-6)
      r.fail("supports.pins", t->get("pins") ? t->get("pins") : t,
             "two supports at " + fmt_num(next) + " degrees: list every pinned point once");
  }
  if (!pinned.empty()) {
    sup.pin = pinned.front();
    sup.pins.assign(pinned.begin() + 1, pinned.end());
  }
  if (t->contains("roller")) {
    if (!sup.pin) r.fail("supports.roller", t->get("roller"), "a roller needs a pin");
    sup.roller = read_angle(r, *t, "supports", "roller");
    for (double p : pinned)
      if (circular_distance(*sup.roller, p) < 1e-6)
        r.fail("supports.roller", t->get("roller"), "the roller must be at a different angle from every pin");
  }
  for (const auto& [name, st] : r.tables(*t, "supports", "springs")) {
    r.known_keys(*st, name, {"at", "kx", "ky", "kr"});
    Spring sp;
    sp.angle = read_angle(r, *st, name, "at");
    sp.kx = r.number(*st, name, "kx", 0.0, 0.0, HUGE_VAL);
    sp.ky = r.number(*st, name, "ky", 0.0, 0.0, HUGE_VAL);
    sp.kr = r.number(*st, name, "kr", 0.0, 0.0, HUGE_VAL);
    if (sp.kx == 0.0 && sp.ky == 0.0 && sp.kr == 0.0) r.fail(name, st, "a spring needs kx, ky or kr > 0");
    sup.springs.push_back(sp);
  }
}

/// masses = [{at, mass, inertia}, ...] and [foundation] {radial, tangential}.
void read_attachments(const Reader& r, const toml::table& root, RingSpec& ring) {
  for (const auto& [name, mt] : r.tables(root, "", "masses")) {
    r.known_keys(*mt, name, {"at", "mass", "inertia"});
    PointMass pm;
    pm.angle = read_angle(r, *mt, name, "at");
    pm.mass = r.number(*mt, name, "mass", 0.0, 0.0, HUGE_VAL);
    pm.inertia = r.number(*mt, name, "inertia", 0.0, 0.0, HUGE_VAL);
    if (pm.mass == 0.0 && pm.inertia == 0.0) r.fail(name, mt, "a point mass needs mass or inertia > 0");
    ring.masses.push_back(pm);
  }
  if (const toml::table* ft = r.table(root, "", "foundation")) {
    r.known_keys(*ft, "foundation", {"radial", "tangential"});
    ring.foundation.radial = r.number(*ft, "foundation", "radial", 0.0, 0.0, HUGE_VAL);
    ring.foundation.tangential = r.number(*ft, "foundation", "tangential", 0.0, 0.0, HUGE_VAL);
  }
}

/// Every model that the scene uses must have a node at every support, load and record point.
void check_nodes(const Reader& r, const Scene& s, const toml::table& root, const SceneSchema& schema) {
  struct Model { std::string name, key; int n; };
  std::vector<Model> models;
  for (const auto& m : schema.solvers)
    if (s.needs(m.name) || s.runs_nonlinear(m.name) || s.runs_buckling(m.name)) models.push_back({m.name, m.size_key, m.size(s)});
  // A harmonic K of ring.variations needs more than 2 K pieces around the ring (its Nyquist
  // limit) in every model that computes it.
  for (std::size_t i = 0; i < s.ring.variations.size(); ++i)
    for (const auto& m : models)
      if (2 * s.ring.variations[i].harmonic >= m.n)
        r.fail("ring.variations[" + std::to_string(i + 1) + "].harmonic", root.at_path("ring.variations").node(),
               "the harmonic " + std::to_string(s.ring.variations[i].harmonic) + " is not resolved by " + m.key + " = " +
                   std::to_string(m.n) + " pieces: a harmonic K needs more than 2 K (raise " + m.key + ")");
  const auto& sup = s.ring.supports;
  const double anchor = s.ring.anchor();
  struct Point { std::string key; double angle; };
  std::vector<Point> points;
  if (sup.roller) points.push_back({"supports.roller", *sup.roller});
  // The clamp is one of the pinned points (read_supports): it is named as itself.
  if (sup.clamp) points.push_back({"supports.clamp", *sup.clamp});
  for (double p : sup.pins)
    if (!sup.clamp || circular_distance(p, *sup.clamp) >= 1e-6) points.push_back({"supports.pins", p});
  for (std::size_t i = 0; i < sup.springs.size(); ++i)
    points.push_back({"supports.springs[" + std::to_string(i + 1) + "]", sup.springs[i].angle});
  for (std::size_t i = 0; i < s.ring.masses.size(); ++i)
    points.push_back({"masses[" + std::to_string(i + 1) + "]", s.ring.masses[i].angle});
  if (s.response) {
    for (std::size_t i = 0; i < s.response->loads.points.size(); ++i)
      points.push_back({point_load_key("response", s.response->loads, i), s.response->loads.points[i].angle});
    for (double a : s.response->record) points.push_back({"response.record", a});
  }
  if (s.statics) {
    for (std::size_t i = 0; i < s.statics->loads.points.size(); ++i)
      points.push_back({point_load_key("static", s.statics->loads, i), s.statics->loads.points[i].angle});
    for (double a : s.statics->record) points.push_back({"static.record", a});
    if (s.statics->displacement) points.push_back({"static.displacement.at", s.statics->displacement->at});
    if (const auto& pl = s.statics->plates) {
      points.push_back({"plates.axis", pl->axis});
      points.push_back({"plates.axis", wrap_degrees(pl->axis + 180.0)});
    }
  }
  if (s.buckling)
    for (std::size_t i = 0; i < s.buckling->loads.points.size(); ++i)
      points.push_back({point_load_key("buckling", s.buckling->loads, i), s.buckling->loads.points[i].angle});
  auto node_of = [&](const Point& p) -> const toml::node* {
    const auto dot = p.key.find('.');
    return root.at_path(p.key.substr(0, dot)).as_table() ? root.at_path(p.key).node() : nullptr;
  };
  if (const auto& arc = s.ring.arc) {
    if (sup.pin) points.push_back({"supports.pin", *sup.pin});
    for (const auto& p : points)
      if (!arc->contains(p.angle))
        r.fail(p.key, node_of(p), "angle " + fmt_num(p.angle) + " lies outside the arch (ring.arc = [" +
                                      fmt_num(arc->from) + ", " + fmt_num(arc->to) + "])");
    for (const auto& p : points)
      for (const auto& m : models)
        if (!on_node(s.ring, p.angle, m.n))
          r.fail(p.key, node_of(p),
                 "angle " + fmt_num(p.angle) + " is not a node of the " + m.name + " model (" + m.key + " = " +
                     std::to_string(m.n) + " cuts the arch into pieces of " + fmt_num(arc->span() / m.n) +
                     " degrees from " + fmt_num(arc->from) + ")");
    return;
  }
  for (const auto& p : points) {
    for (const auto& m : models) {
      if (on_node(p.angle, anchor, m.n)) continue;
      const bool opposite = std::abs(wrap_degrees(p.angle - anchor) - 180.0) < 1e-9;
      std::string what = "angle " + fmt_num(p.angle) + " is not a node of the " + m.name + " model (" + m.key +
                         " = " + std::to_string(m.n) + " puts nodes every " + fmt_num(360.0 / m.n) +
                         " degrees from " + fmt_num(anchor) + ")";
      if (opposite) what += "; " + m.key + " must be even so that a node lies opposite";
      r.fail(p.key, node_of(p), what);
    }
  }
}

/// Every model that the scene uses must keep unknowns that the supports do not hold: an
/// over-constrained ring (constraint rows + rigid modes >= the model's unknowns, so no
/// elastic mode is left) is refused naming the supports, not modes.count.
void check_constraints(const Reader& r, const Scene& s, const toml::table& root, const SceneSchema& schema) {
  const Supports& sup = s.ring.supports;
  const std::string key = !sup.pins.empty() ? "supports.pins"
                          : sup.clamp       ? "supports.clamp"
                          : sup.roller      ? "supports.roller"
                                            : "supports.pin";
  if (sup.constraint_rows() == 0) return;
  const long long held = sup.constraint_rows() + s.ring.rigid_modes();
  for (const auto& m : schema.solvers) {
    if (!(s.needs(m.name) || s.runs_nonlinear(m.name) || s.runs_buckling(m.name))) continue;
    const long long elastic = m.elastic_modes(s);
    if (elastic > 0) continue;
    const long long unknowns = elastic + held;
    const toml::node* n = root.at_path(key).node();
    r.fail(key, n ? n : &root,
           "the supports impose " + std::to_string(sup.constraint_rows()) +
               " constraints (2 per pinned point, 1 for a roller, 1 for a clamp) against the " +
               std::to_string(unknowns) + " unknowns of the " + m.name + " model (" + m.size_key + " = " +
               std::to_string(m.size(s)) + "), which leaves it no elastic mode: pin fewer points or refine " +
               m.size_key);
  }
}

/// [response].solvers / [static].solvers / [buckling].solvers (default: the schema's
/// default solver) and .reference; each listed solver must offer the analysis.
NonlinearRequest read_request(const Reader& r, const toml::table& t, const std::string& sec,
                              const SceneSchema& schema, bool SolverSchema::*offers) {
  const std::string what = sec == "static" ? "nonlinear statics" : sec == "buckling" ? "linear buckling" : "a forced response";
  NonlinearRequest q;
  q.solvers = r.strings(t, sec, "solvers", schema.names());
  if (t.contains("solvers") && q.solvers.empty()) r.fail(sec + ".solvers", t.get("solvers"), "expected at least one solver");
  if (q.solvers.empty()) q.solvers.push_back(schema.default_solver);
  for (const auto& name : q.solvers)
    if (!(schema.find(name)->*offers))
      r.fail(sec + ".solvers", t.get("solvers"),
             "the " + name + " solver does not offer " + what);
  q.reference = r.boolean(t, sec, "reference", false);
  if (q.reference && !(schema.find(schema.reference_solver)->*offers))
    r.fail(sec + ".reference", t.get("reference"), "the reference solver " + schema.reference_solver + " does not offer it");
  return q;
}

/// `section`.`key` as a beam theory, or nothing when the key is absent (a solver's model
/// theory then follows ring.theory).
std::optional<Theory> read_theory(const Reader& r, const toml::table& t, const std::string& section,
                                  const std::string& key = "theory") {
  if (!t.contains(key)) return std::nullopt;
  return r.choice(t, section, key, "euler-bernoulli", {"euler-bernoulli", "timoshenko"}) == "timoshenko"
             ? Theory::timoshenko : Theory::euler_bernoulli;
}

/// A solver's model theory (`section`.`key`) of "timoshenko" needs the shear stiffness
/// kappa G A that ring.theory = "timoshenko" needs: a shear coefficient for a section
/// without a shape.
void check_model_theory(const Reader& r, const toml::table& t, const std::string& section, const std::string& key,
                        const RingSpec& ring) {
  if (!t.contains(key)) return;
  if (read_theory(r, t, section, key) == Theory::timoshenko && !(ring.kappa() > 0.0))
    r.fail(section + "." + key, t.get(key),
           "\"timoshenko\" needs the ring's shear coefficient, which is missing: a section given by {area, inertia} "
           "has no shape, so give ring.shear_coefficient (or use \"euler-bernoulli\")");
}

/// One solver's section checked against its option schema: unknown keys (with the nearest
/// known one), then its theory keys against the ring, then every key in the schema's order,
/// each with its type and range (SolverSchema::integer_ranges replacing a declared range).
/// An absent section, or key, takes the schema's defaults. Every key a solver takes is
/// declared in its folder (multibody/options.cpp, ...): this function names none.
OptionValues read_solver_section(const Reader& r, const toml::table& root, const SolverSchema& solver,
                                 const RingSpec& ring) {
  const OptionSchema& schema = solver.options;
  const toml::table* t = r.table(root, "", solver.name);
  if (!t) return defaults(schema);
  const std::string& sec = solver.name;
  r.known_keys(*t, sec, schema.keys());
  for (const OptionEntry& e : schema.entries())
    if (e.type == OptionEntry::Type::theory) check_model_theory(r, *t, sec, e.key, ring);
  OptionValues v;
  for (const OptionEntry& e : schema.entries()) {
    switch (e.type) {
      case OptionEntry::Type::integer: {
        std::pair<long long, long long> range{e.int_min, e.int_max};
        if (const auto it = solver.integer_ranges.find(e.key); it != solver.integer_ranges.end()) range = it->second;
        v.set(e.key, r.integer(*t, sec, e.key, std::get<long long>(*e.value), range.first, range.second));
        break;
      }
      case OptionEntry::Type::number:
        v.set(e.key, r.number(*t, sec, e.key, std::get<double>(*e.value), e.min, e.max, e.min_open));
        break;
      case OptionEntry::Type::boolean: v.set(e.key, r.boolean(*t, sec, e.key, std::get<bool>(*e.value))); break;
      case OptionEntry::Type::choice:
        v.set(e.key, r.choice(*t, sec, e.key, std::get<std::string>(*e.value), e.choices));
        break;
      case OptionEntry::Type::theory:
        if (t->contains(e.key)) v.set(e.key, to_string(*read_theory(r, *t, sec, e.key)));
        break;
    }
  }
  return v;
}

/// [rotation] {speed, tension}: read after the analyses, which it checks. A spinning ring has
/// its modes (the gyroscopic eigenproblem in the frame that turns with it); the other analyses
/// and the shapes it cannot spin refuse it here, naming rotation.speed.
void read_rotation(const Reader& r, const toml::table& t, Scene& s) {
  r.known_keys(t, "rotation", {"speed", "tension"});
  Rotation& rot = s.ring.rotation;
  // A bound far above any ring that holds together (a steel ring's hoop stress rho (speed R)^2
  // reaches its yield stress at a rim speed of ~200 m/s) and far below the doubles' range.
  rot.speed = r.number(t, "rotation", "speed", 0.0, -1e12, 1e12);
  rot.tension = r.choice(t, "rotation", "tension", "spin", {"spin", "none"}) == "spin" ? Rotation::Tension::spin
                                                                                      : Rotation::Tension::none;
  if (!rot.spinning()) return;
  const toml::node* at = t.get("speed");
  const double rim = std::abs(rot.speed) * s.ring.radius, wave = std::sqrt(s.ring.E / s.ring.rho);
  if (rim >= wave)
    r.fail("rotation.speed", at,
           "the rim speed " + fmt_num(rim) + " m/s reaches the ring's wave speed sqrt(E/rho) = " + fmt_num(wave) +
               " m/s: the hoop strain of the spin would exceed 1 and no model here holds");
  if (s.ring.arc) r.fail("rotation.speed", at, "an arch (ring.arc) does not spin here: rotation is the closed ring's");
  if (s.ring.rigid_modes() > 0)
    r.fail("rotation.speed", at,
           "a spinning ring needs its rigid motions held in the turning frame (supports, springs or a foundation); "
           "this one has " + std::to_string(s.ring.rigid_modes()) + " rigid modes");
  for (const auto& [sec, there] : {std::pair{"static", s.statics.has_value()}, std::pair{"response", s.response.has_value()},
                                    std::pair{"buckling", s.buckling.has_value()}})
    if (there)
      r.fail("rotation.speed", at,
             std::string("the [") + sec + "] analysis of a spinning ring is not implemented: its modes are ([modes], [table])");
  if (s.modes.preload_static)
    r.fail("rotation.speed", at, "modes.preload = \"static\" and a spin: the modes of a spinning ring take the spin's own "
                                 "prestress (rotation.tension) and no other load");
}

Scene build(const toml::table& root, const Reader& r, const SceneSchema& schema) {
  Scene s;
  s.reference_solver = schema.reference_solver;
  std::vector<std::string> sections = {"title", "ring", "supports", "masses", "foundation", "rotation"};
  const std::vector<std::string> analyses = {"modes", "table", "gates", "response", "static", "buckling", "plates"};
  for (const auto& m : schema.solvers) {
    if (std::find(sections.begin(), sections.end(), m.name) != sections.end() ||
        std::find(analyses.begin(), analyses.end(), m.name) != analyses.end())
      throw std::logic_error("scene schema: the solver \"" + m.name + "\" takes the name of a scene section");
    sections.push_back(m.name);  // its option section
  }
  sections.insert(sections.end(), analyses.begin(), analyses.end());
  r.known_keys(root, "", sections);
  if (const toml::node* n = root.get("title")) {
    auto t = n->value_exact<std::string>();
    if (!t) r.fail("title", n, "expected a string");
    s.title = *t;
  }

  // [ring]
  const toml::table* rt = r.table(root, "", "ring");
  if (!rt) r.fail("ring", &root, "missing: the [ring] section (radius, E, rho, section)");
  r.known_keys(*rt, "ring",
               {"radius", "E", "rho", "section", "theory", "nu", "shear_coefficient", "plastic", "arc", "variations"});
  s.ring.radius = r.number(*rt, "ring", "radius", 10.0, 0.0, HUGE_VAL, true);
  s.ring.E = r.number(*rt, "ring", "E", 2.1e11, 0.0, HUGE_VAL, true);
  s.ring.rho = r.number(*rt, "ring", "rho", 7.8e3, 0.0, HUGE_VAL, true);
  s.ring.section = read_section(r, *rt);
  s.ring.theory = read_theory(r, *rt, "ring").value_or(Theory::euler_bernoulli);
  s.ring.plastic = read_plastic(r, *rt, s.ring.section);
  s.ring.arc = read_arc(r, *rt);
  s.ring.variations = read_variations(r, *rt, s.ring.section);
  if (s.ring.arc && s.ring.varies())
    r.fail("ring.variations", rt->get("variations"), "an arch (ring.arc) is not an imperfect ring here: vary a closed ring");
  s.ring.nu = r.number(*rt, "ring", "nu", 0.3, -1.0, 0.5);
  if (s.ring.nu <= -1.0 || s.ring.nu >= 0.5)
    r.fail("ring.nu", rt->get("nu"), "Poisson's ratio must lie in (-1, 0.5), got " + fmt_num(s.ring.nu));
  s.ring.shear_coefficient = r.number(*rt, "ring", "shear_coefficient", 0.0, 0.0, HUGE_VAL);
  if (rt->contains("shear_coefficient") && !(s.ring.shear_coefficient > 0.0))
    r.fail("ring.shear_coefficient", rt->get("shear_coefficient"), "must be > 0 (omit it for Cowper's value)");
  if (s.ring.theory == Theory::timoshenko && !(s.ring.kappa() > 0.0))
    r.fail("ring.shear_coefficient", rt,
           "missing: a section given by {area, inertia} has no shape, so the Timoshenko theory needs its shear "
           "coefficient (Cowper's values: 10 (1 + nu)/(12 + 11 nu) for a rectangle, 6 (1 + nu)/(7 + 6 nu) for a circle)");
  // Sizes that are positive but whose area or second moment under- or overflows a double
  // (a diameter of 1e-300 m gives A = 0) leave nothing to compute with.
  const double area = s.ring.section.area(), inertia = s.ring.section.inertia();
  if (!std::isnormal(area) || !std::isnormal(inertia))
    r.fail("ring.section", rt->get("section"),
           "area " + fmt_num(area) + " m^2 and inertia " + fmt_num(inertia) +
               " m^4 are not positive normal doubles: the section's sizes under- or overflow");
  const double depth_ratio = s.ring.section.depth() / s.ring.radius;
  if (depth_ratio >= 1.0)
    r.fail("ring.section", rt->get("section"),
           "section depth " + fmt_num(s.ring.section.depth()) + " m is not small against the radius " +
               fmt_num(s.ring.radius) + " m (a ring needs depth/radius < 1)");
  if (depth_ratio > 0.1 && s.ring.theory == Theory::euler_bernoulli)
    s.warnings.push_back("ring.section: depth/radius = " + fmt_num(depth_ratio) +
                         " > 0.1 stretches the thin-ring (Euler-Bernoulli) assumption (ring.theory = \"timoshenko\" has shear)");

  read_supports(r, root, s.ring);
  read_attachments(r, root, s.ring);

  // Solver sections: each optional, read against its solver's option schema (SolverSchema::
  // options; the scene reference, docs/scenes.md, is printed from the same schemas), then
  // handed to the solver's option struct (SolverSchema::store).
  for (const auto& m : schema.solvers) {
    OptionValues& v = s.options[m.name] = read_solver_section(r, root, m, s.ring);
    if (m.store) m.store(s, v);
  }

  // [modes]: solvers default to those whose section the scene has (multibody if none).
  if (const toml::table* t = r.table(root, "", "modes")) {
    r.known_keys(*t, "modes", {"count", "solvers", "preload", "frame"});
    s.modes.count = static_cast<int>(r.integer(*t, "modes", "count", 23, 1, 100000));
    s.modes.fixed_frame = r.choice(*t, "modes", "frame", "rotating", {"rotating", "fixed"}) == "fixed";
    if (t->contains("frame") && !root.get("rotation"))
      r.fail("modes.frame", t->get("frame"), "names the frame of a spinning ring's frequencies, and the scene has no [rotation]");
    s.modes.preload_static = r.choice(*t, "modes", "preload", "none", {"none", "static"}) == "static";
    s.modes.solvers = r.strings(*t, "modes", "solvers", schema.names());
    if (t->contains("solvers") && s.modes.solvers.empty())
      r.fail("modes.solvers", t->get("solvers"), "expected at least one solver");
    if (!t->contains("solvers")) {
      for (const auto& m : schema.solvers)
        if (root.get(m.name)) s.modes.solvers.push_back(m.name);
      if (s.modes.solvers.empty()) s.modes.solvers.push_back(schema.default_solver);
    }
  }

  // A scene that lists no analysis at all: the modes of the solver sections present
  // (docs/scenes.md, modes.solvers), rather than nothing.
  if (!root.get("modes") && !root.get("table") && !root.get("response") && !root.get("static") && !root.get("buckling"))
    for (const auto& m : schema.solvers)
      if (root.get(m.name)) s.modes.solvers.push_back(m.name);

  // [table]
  if (const toml::table* t = r.table(root, "", "table")) {
    r.known_keys(*t, "table", {"base", "against", "reference", "import"});
    s.table.present = true;
    s.table.base = r.choice(*t, "table", "base", schema.default_solver, schema.names());
    s.table.against = r.strings(*t, "table", "against", schema.names());
    if (std::find(s.table.against.begin(), s.table.against.end(), s.table.base) != s.table.against.end())
      r.fail("table.against", t->get("against"), "lists the base solver \"" + s.table.base + "\" again");
    s.table.reference = r.boolean(*t, "table", "reference", false);
    s.table.imports = read_imports(r, *t, schema);
    if (s.modes.solvers.empty()) s.modes.count = 23;  // a table without [modes]: the paper's 23
  }

  if (const toml::table* t = r.table(root, "", "gates")) read_gates(r, *t, s, schema);

  // [response], [static]: need a pin, or terms that hold every rigid motion (a free ring
  // under a dead load has no equilibrium and drifts away under a dynamic one).
  if (const toml::table* t = r.table(root, "", "response")) {
    const std::string sec = "response";
    r.known_keys(*t, sec, {"solvers", "reference", "at", "force", "loads", "pressure", "gravity", "history", "period",
                           "dt", "t_end", "integrator",
                           "rho_inf", "record", "rayleigh_mass", "rayleigh_stiffness", "hinge_damping"});
    // A free ring held by springs or a foundation responds about its rest position; one
    // that nothing holds drifts away under the load.
    if (!s.ring.supports.pin && s.ring.rigid_modes() > 0)
      r.fail("supports.pin", &root,
             "a forced response needs a pin, or springs or a foundation that hold every rigid motion: the ring is "
             "free (" + std::to_string(s.ring.rigid_modes()) + " rigid modes)");
    ResponseOptions o;
    o.loads = read_loads(r, *t, sec);
    o.history = read_history(r, *t, sec);
    o.dt = r.number(*t, sec, "dt", 0.01, 0.0, HUGE_VAL, true);
    o.t_end = r.number(*t, sec, "t_end", 5.0, 0.0, HUGE_VAL, true);
    if (o.dt > o.t_end)
      r.fail(t->contains("dt") ? "response.dt" : "response.t_end", t->contains("dt") ? t->get("dt") : t->get("t_end"),
             "the time step " + fmt_num(o.dt) + " s is longer than response.t_end = " + fmt_num(o.t_end) + " s");
    if (o.t_end / o.dt > 1e8)
      r.fail(t->contains("t_end") ? "response.t_end" : "response.dt", t->contains("t_end") ? t->get("t_end") : t->get("dt"),
             "t_end/dt = " + fmt_num(o.t_end / o.dt) + " steps exceeds 1e8");
    const std::string integrator =
        r.choice(*t, sec, "integrator", "newmark", {"newmark", "generalized-alpha", "energy-momentum", "midpoint"});
    o.integrator = integrator == "newmark"             ? ResponseOptions::Integrator::newmark
                 : integrator == "generalized-alpha" ? ResponseOptions::Integrator::generalized_alpha
                 : integrator == "energy-momentum"   ? ResponseOptions::Integrator::energy_momentum
                                                      : ResponseOptions::Integrator::midpoint;
    o.rho_inf = r.number(*t, sec, "rho_inf", 0.8, 0.0, 1.0);
    o.record = read_record(r, *t, sec);
    o.rayleigh_mass = r.number(*t, sec, "rayleigh_mass", 0.0, 0.0, HUGE_VAL);
    o.rayleigh_stiffness = r.number(*t, sec, "rayleigh_stiffness", 0.0, 0.0, HUGE_VAL);
    o.hinge_damping = r.number(*t, sec, "hinge_damping", 0.0, 0.0, HUGE_VAL);
    s.response = o;
    s.response_request = read_request(r, *t, sec, schema, &SolverSchema::response);
  }
  if (const toml::table* t = r.table(root, "", "static")) {
    const std::string sec = "static";
    r.known_keys(*t, sec, {"solvers", "reference", "at", "force", "loads", "pressure", "gravity", "steps", "record", "path", "branch",
                           "history", "displacement"});
    StaticOptions o;
    const toml::table* plates = r.table(root, "", "plates");
    if (plates) {
      o.plates = read_plates(r, *plates, s.ring);
      for (const char* key : {"at", "force", "loads", "pressure", "gravity"})
        if (t->contains(key))
          r.fail(sec + "." + key, t->get(key), "[plates] drive the path, and loads would be scaled with them: give the one or the other");
      if (t->contains("displacement"))
        r.fail("static.displacement", t->get("displacement"), "[plates] drive the path already: give the one or the other");
      if (s.ring.arc) r.fail("plates", plates, "crush a closed ring: an arch (ring.arc) between plates is not implemented");
      const auto& sup = s.ring.supports;
      if (sup.pin || sup.roller || !sup.pins.empty() || sup.clamp)
        r.fail("plates", plates,
               "the plates hold the ring themselves (along their axis, and at the two points of first contact along "
               "them): remove supports.pin, .roller, .pins and .clamp");
    } else if (const toml::table* dt = r.table(*t, sec, "displacement")) {
      o.displacement = read_displacement(r, *dt, s.ring);
      for (const char* key : {"at", "force", "loads", "pressure", "gravity"})
        if (t->contains(key))
          r.fail(sec + "." + key, t->get(key),
                 "static.displacement drives the path, and loads would be scaled with it: give the one or the other");
    } else {
      o.loads = read_loads(r, *t, sec);
    }
    // A dead load has an equilibrium only when nothing is left to move rigidly (gravity may
    // hold the rotation of a ring that hangs from its pin); a driven point holds as a pin
    // does, and plates hold a free ring.
    if (const int rigid = static_rigid_modes(s.ring, o); rigid > 0)
      r.fail(s.ring.supports.pin ? "supports.roller" : "supports.pin", &root,
             s.ring.supports.pin
                 ? "a static analysis needs a roller as well as the pin (or a second pin, a clamp, springs, a "
                   "foundation, or gravity from which the ring hangs): without it the ring can turn about the pin"
                 : "a static analysis needs a pin (or springs or a foundation that hold the ring): the ring is free (" +
                       std::to_string(rigid) + " rigid modes)");
    o.steps = static_cast<int>(r.integer(*t, sec, "steps", 20, 1, 1000000));
    o.record = read_record(r, *t, sec);
    o.history = r.numbers(*t, sec, "history", {});
    if (t->contains("history")) {
      if (o.history.empty()) r.fail("static.history", t->get("history"), "expected at least one load factor");
      if (o.history.size() > 10000) r.fail("static.history", t->get("history"), "expected at most 10000 load factors");
      for (double f : o.history)
        if (std::abs(f) > 1e6)
          r.fail("static.history", t->get("history"), "load factors must lie in [-1e6, 1e6], got " + fmt_num(f));
    }
    // A history is a path by nature: its equilibria are the result (static_path_<solver>.csv).
    o.path = r.boolean(*t, sec, "path", !o.history.empty());
    o.branch_side = r.choice(*t, sec, "branch", "positive", {"positive", "negative"}) == "positive" ? 1 : -1;
    if (t->contains("branch") && !o.path)
      r.fail("static.branch", t->get("branch"),
             "chooses the side a path takes at a branch point, and only static.path = true switches branches");
    s.statics = o;
    s.static_request = read_request(r, *t, sec, schema, &SolverSchema::statics);
  }
  if (const toml::table* t = r.table(root, "", "buckling")) {
    const std::string sec = "buckling";
    r.known_keys(*t, sec, {"solvers", "reference", "count", "at", "force", "loads", "pressure", "gravity"});
    BucklingOptions o;
    const bool own = t->contains("at") || t->contains("force") || t->contains("loads") || t->contains("pressure") ||
                     t->contains("gravity");
    if (own) o.loads = read_loads(r, *t, sec);
    else if (s.statics && s.statics->driven())
      r.fail("buckling.loads", t, "has no load: [static] is driven (static.displacement or [plates]), not loaded; give "
                                  "buckling.loads, .at/.force, .pressure or .gravity");
    else if (s.statics) o.loads = s.statics->loads;
    else r.fail("buckling.loads", t, "has no load: give buckling.loads, .at/.force, .pressure or .gravity, or a [static] "
                                     "section whose loads it takes");
    // Buckling about a state that exists: nothing left to move rigidly under the loads.
    if (const int rigid = static_rigid_modes(s.ring, o.loads); rigid > 0)
      r.fail(s.ring.supports.pin ? "supports.roller" : "supports.pin", &root,
             "linear buckling needs the ring held, and it has " + std::to_string(rigid) + " rigid mode" +
                 (rigid > 1 ? "s" : "") + " that the loads do not restrain: add " +
                 (s.ring.supports.pin ? "a roller (or a second pin, a clamp, springs or a foundation)"
                                      : "a pin and a roller (or springs or a foundation)"));
    o.count = static_cast<int>(r.integer(*t, sec, "count", 4, 1, 1000));
    s.buckling = o;
    s.buckling_request = read_request(r, *t, sec, schema, &SolverSchema::buckling);
  }
  for (const auto& [sec, loads] : {std::pair{"response", s.response ? &s.response->loads : nullptr},
                                    std::pair{"static", s.statics ? &s.statics->loads : nullptr},
                                    std::pair{"buckling", s.buckling ? &s.buckling->loads : nullptr}}) {
    if (!loads) continue;
    for (std::size_t i = 0; i < loads->points.size(); ++i)
      for (double p : s.ring.supports.pinned())
        if (circular_distance(loads->points[i].angle, p) < 1e-6)
          r.fail(point_load_key(sec, *loads, i), &root,
                 "the load acts at the pin at " + fmt_num(p) + " deg, where it does nothing; load another point");
    if (loads->has_gravity() && !s.ring.supports.pin && s.ring.rigid_modes() > 0)
      r.fail(std::string(sec) + ".gravity", &root,
             "gravity on a ring that is free to move rigidly has no equilibrium and no meaning here: add a pin, a "
             "clamp, springs or a foundation");
  }

  if (const toml::table* t = r.table(root, "", "rotation")) read_rotation(r, *t, s);
  if (root.get("plates") && !s.statics)
    r.fail("plates", root.get("plates"), "[plates] drive a static path: the scene needs a [static] section");

  if (s.modes.preload_static && s.statics && s.statics->driven())
    r.fail("modes.preload", root.at_path("modes.preload").node(),
           "\"static\" takes the loads of [static], and its path is driven (static.displacement or [plates]): the "
           "modes about a driven state are not implemented");
  if (s.modes.preload_static && !s.statics)
    r.fail("modes.preload", root.at_path("modes.preload").node(),
           "\"static\" takes the equilibrium of [static], and the scene has no [static] section");

  // The elastic–plastic law enters the nonlinear statics and the forced response, each
  // solver refusing by key what it cannot integrate (its checks); the analyses about the
  // undeformed ring (buckling, the preloaded modes' elastic tangent) would ignore it silently.
  if (s.ring.plastic) {
    const toml::node* at = root.at_path("ring.plastic").node();
    if (s.buckling)
      r.fail("ring.plastic", at,
             "linear buckling is about the undeformed, elastic ring and would ignore the plastic law: follow the "
             "equilibrium path with [static] path = true instead");
    if (s.modes.preload_static)
      r.fail("ring.plastic", at,
             "modes.preload = \"static\" takes the elastic tangent at the loaded equilibrium, which a plastic ring "
             "does not have yet: remove modes.preload");
  }

  for (const auto& g : s.gates) {
    const std::string key = "gates." + g.solver;
    if (g.analysis != "modes") {
      const bool has = g.analysis == "response" ? s.response.has_value() : s.statics.has_value();
      const NonlinearRequest& q = g.analysis == "response" ? s.response_request : s.static_request;
      auto runs = [&](const std::string& n) { return std::find(q.solvers.begin(), q.solvers.end(), n) != q.solvers.end(); };
      if (!has) r.fail(key + ".analysis", root.at_path("gates").node(), "the scene has no [" + g.analysis + "] section");
      if (!runs(g.solver))
        r.fail(key, root.at_path("gates").node(), "gates a solver that " + g.analysis + ".solvers does not list");
      if (g.against == "reference" && !q.reference)
        r.fail(key + ".against", root.at_path("gates").node(),
               "compares with the reference, but " + g.analysis + ".reference is not true");
      if (g.against != "reference" && !runs(g.against))
        r.fail(key + ".against", root.at_path("gates").node(),
               "compares with \"" + g.against + "\", which " + g.analysis + ".solvers does not list");
      continue;
    }
    if (!s.column(g.solver) && !s.imported(g.solver))
      r.fail(key, root.at_path("gates").node(),
             "gates a solver the scene does not run (add it to modes.solvers or table.against)");
    if (g.against != "reference" && g.against != "paper" && !s.column(g.against) && !s.imported(g.against))
      r.fail(key + ".against", root.at_path("gates").node(),
             "compares with \"" + g.against + "\", which the scene does not run");
  }
  // One anchor for every model of every analysis (RingSpec::free_anchor).
  for (const Loads* loads : {s.statics ? &s.statics->loads : nullptr, s.response ? &s.response->loads : nullptr,
                             s.buckling ? &s.buckling->loads : nullptr})
    if (loads && !loads->points.empty()) {
      s.ring.free_anchor = loads->points.front().angle;
      break;
    }
  check_nodes(r, s, root, schema);
  check_constraints(r, s, root, schema);
  // Cross checks, each naming the key that causes it: nodes at the points, supports that
  // leave the models something to move, then the modes asked for.
  for (const auto& m : schema.solvers) {
    if (!s.needs(m.name)) continue;
    const long long most = m.elastic_modes(s);
    if (s.modes.count > most)
      r.fail("modes.count", root.at_path("modes.count").node(),
             std::to_string(s.modes.count) + " modes asked, but the " + m.name + " model (" + m.size_key +
                 ") has only " + std::to_string(most) + " elastic modes");
  }
  if (s.buckling)
    for (const auto& m : schema.solvers) {
      if (!s.runs_buckling(m.name)) continue;
      const long long most = m.elastic_modes(s);
      if (s.buckling->count > most)
        r.fail("buckling.count", root.at_path("buckling.count").node(),
               std::to_string(s.buckling->count) + " critical loads asked, but the " + m.name + " model (" +
                   m.size_key + ") has only " + std::to_string(most) + " elastic modes");
    }
  return s;
}

}  // namespace

// The TOML parser (and the printing and freeing of what it built) recurses once per level
// of nesting, and overflows the stack somewhere past 20,000 levels; toml++ itself stops
// nested arrays and inline tables at 256 levels, but not tables made by dotted keys. So the
// text is scanned once, as the parser will read it, and refused where a point lies deeper
// than kMaxNesting levels: the parts of the current [table] header or of a dotted key, plus
// the arrays and inline tables open around it (and the dotted keys that opened them). Dots
// and brackets inside strings and comments, and the dots of numbers, do not nest: a record
// list of 1001 angles is two levels deep. The scan is linear and keeps no recursion of its
// own; on malformed text it may be less exact, but only up to where the parser fails too.
void check_nesting(const std::string& text, const std::string& name) {
  struct Frame {
    char open;          // '[' an array, '{' an inline table
    std::size_t level;  // the level of its elements (an inline table: of its keys' base)
  };
  std::vector<Frame> open;
  std::size_t line = 1;
  std::size_t header = 0;  // parts of the current [table] header
  std::size_t parts = 0;   // parts of the key being read (0: none started)
  std::size_t here = 0;    // level of the value being read
  bool key = true;         // reading a key (else a value)
  bool in_header = false;
  auto refuse = [&](const std::string& what) {
    throw InputError(name, "line " + std::to_string(line),
                     what + " more than " + std::to_string(kMaxNesting) + " levels deep; a scene does not nest that deep");
  };
  auto base = [&]() -> std::size_t { return in_header ? 0 : open.empty() ? header : open.back().level; };
  // Skips the string that starts at text[i] (a quote); returns the index after it. A
  // single-line string ends at its closing quote or before a newline (where the parser
  // fails); a multi-line one ("""...""" or '''...''', up to two more quotes belong to it)
  // counts the lines it spans.
  auto skip_string = [&](std::size_t i, bool multi_allowed) {
    const char q = text[i];
    const bool multi = multi_allowed && text.compare(i, 3, std::string(3, q)) == 0;
    std::size_t j = i + (multi ? 3 : 1);
    while (j < text.size()) {
      const char c = text[j];
      if (c == '\\' && q == '"') {
        if (j + 1 < text.size() && text[j + 1] == '\n') {
          if (!multi) return j + 1;
          ++line;
        }
        j += 2;
      } else if (c == '\n') {
        if (!multi) return j;
        ++line;
        ++j;
      } else if (c == q && (!multi || text.compare(j, 3, std::string(3, q)) == 0)) {
        j += multi ? 3 : 1;
        for (int extra = 0; multi && extra < 2 && j < text.size() && text[j] == q; ++extra) ++j;
        return j;
      } else {
        ++j;
      }
    }
    return j;
  };
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      if (open.empty()) {  // a statement ends (inside an array, the value goes on)
        key = true;
        in_header = false;
        parts = 0;
      }
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '"' || c == '\'') {
      if (key) parts = std::max<std::size_t>(parts, 1);
      i = skip_string(i, !key);
    } else if (key) {
      if (c == '[' && open.empty() && !in_header && parts == 0) {  // [table] or [[array of tables]]
        in_header = true;
        i += text.compare(i, 2, "[[") == 0 ? 2 : 1;
        continue;
      }
      if (c == ']' && in_header) {
        header = parts;
        in_header = false;
        parts = 0;
        i += text.compare(i, 2, "]]") == 0 ? 2 : 1;
        continue;
      }
      if (c == '}' && !open.empty() && open.back().open == '{') {  // {} or a trailing comma
        open.pop_back();
        key = false;
        here = open.empty() ? here : open.back().level;
      } else if (c == '=') {
        here = base() + std::max<std::size_t>(parts, 1);
        key = false;
        parts = 0;
      } else if (c == '.') {
        parts = std::max<std::size_t>(parts, 1) + 1;
      } else if (c == ',' && !open.empty() && open.back().open == '{') {
        parts = 0;
      } else {
        parts = std::max<std::size_t>(parts, 1);
      }
      if (base() + parts > kMaxNesting) refuse(in_header ? "a [table] header" : "a dotted key");
      ++i;
    } else {  // a value: only arrays and inline tables nest
      if (c == '[' || c == '{') {
        open.push_back({c, here + 1});
        if (open.back().level > kMaxNesting) refuse("an array or inline table");
        if (c == '{') {
          key = true;
          parts = 0;
        } else {
          here = open.back().level;
        }
      } else if ((c == ']' || c == '}') && !open.empty()) {
        open.pop_back();
        if (!open.empty()) here = open.back().level;
      } else if (c == ',' && !open.empty() && open.back().open == '{') {
        key = true;
        parts = 0;
      }
      ++i;
    }
  }
}

namespace {

/// Applies one "a.b.c=value" override to the parsed document.
std::string apply_override(toml::table& root, const std::string& spec, const std::string& file) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(file, "--set " + spec, "expected section.key=value");
  const std::string path = spec.substr(0, eq), value = spec.substr(eq + 1);
  toml::table parsed;
  if (value.find_first_of("\n\r") != std::string::npos)
    throw InputError(file, "--set " + path, "the value spans several lines; give one key=value per --set");
  try {
    check_nesting("v = " + value, file);
  } catch (const InputError&) {
    throw InputError(file, "--set " + path,
                     "the value nests more than " + std::to_string(kMaxNesting) + " levels deep (dotted keys, arrays, tables)");
  }
  try {
    parsed = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    // A bare word (--set lumped.variant=frame) is a string.
    if (value.empty() || value.find_first_of("\"'[]{}=\n\r") != std::string::npos)
      throw InputError(file, "--set " + path, "the value '" + value + "' is not valid TOML");
    parsed.insert_or_assign("v", value);
  }
  std::vector<std::string> parts;
  std::stringstream ps(path);
  for (std::string p; std::getline(ps, p, '.');) parts.push_back(p);
  toml::table* t = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n) n = &t->insert_or_assign(parts[i], toml::table{}).first->second;
    if (!n->is_table()) throw InputError(file, "--set " + path, "'" + parts[i] + "' is not a section");
    t = n->as_table();
  }
  if (parts.empty() || parts.back().empty()) throw InputError(file, "--set " + spec, "expected section.key=value");
  t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
  return path;
}

/// A TOML string as a basic string ("..." with escapes): one line, whatever it holds.
void append_quoted(std::string& o, std::string_view s) {
  o += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\b': o += "\\b"; break;
      case '\t': o += "\\t"; break;
      case '\n': o += "\\n"; break;
      case '\f': o += "\\f"; break;
      case '\r': o += "\\r"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          char u[8];
          std::snprintf(u, sizeof u, "\\u%04X", static_cast<unsigned>(c));
          o += u;
        } else {
          o += ch;  // UTF-8 as the parser validated it
        }
    }
  }
  o += '"';
}

void append_toml(std::string& o, const toml::node& n) {
  if (const auto* v = n.as_string()) {
    append_quoted(o, v->get());
  } else if (const auto* v = n.as_integer()) {
    o += std::to_string(v->get());
  } else if (const auto* v = n.as_floating_point()) {
    const double x = v->get();
    if (std::isnan(x)) {
      o += "nan";
    } else if (std::isinf(x)) {
      o += x > 0 ? "inf" : "-inf";
    } else {
      // The shortest digits that read back to the same double (0.1, 1e-300, 5e-324).
      char buf[64];
      const auto r = std::to_chars(buf, buf + sizeof buf, x);
      const std::string t(buf, r.ptr);
      o += t;
      if (t.find_first_of(".e") == std::string::npos) o += ".0";  // stays a float
    }
  } else if (const auto* v = n.as_boolean()) {
    o += v->get() ? "true" : "false";
  } else if (const auto* v = n.as_array()) {
    o += '[';
    for (std::size_t i = 0; i < v->size(); ++i) {
      if (i) o += ", ";
      append_toml(o, *v->get(i));
    }
    o += ']';
  } else if (const auto* v = n.as_table()) {
    o += '{';
    bool first = true;
    for (const auto& [k, x] : *v) {
      o += first ? " " : ", ";
      first = false;
      const std::string_view key = k.str();
      const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
      });
      if (bare) o += key;
      else append_quoted(o, key);
      o += " = ";
      append_toml(o, x);
    }
    o += first ? "}" : " }";
  } else {  // a date, a time or a date-time: toml++ prints them as TOML does
    std::ostringstream t;
    if (const auto* d = n.as_date()) t << *d;
    else if (const auto* d = n.as_time()) t << *d;
    else if (const auto* d = n.as_date_time()) t << *d;
    o += t.str();
  }
}

/// The same TOML value (type and value; NaN equals NaN, 0.0 and -0.0 differ).
bool same_value(const toml::node& a, const toml::node& b) {
  if (a.type() != b.type()) return false;
  if (const auto* x = a.as_floating_point()) {
    const double p = x->get(), q = b.as_floating_point()->get();
    return (std::isnan(p) && std::isnan(q)) || (p == q && std::signbit(p) == std::signbit(q));
  }
  if (const auto* x = a.as_array()) {
    const auto* y = b.as_array();
    if (x->size() != y->size()) return false;
    for (std::size_t i = 0; i < x->size(); ++i)
      if (!same_value(*x->get(i), *y->get(i))) return false;
    return true;
  }
  if (const auto* x = a.as_table()) {
    const auto* y = b.as_table();
    if (x->size() != y->size()) return false;
    for (const auto& [k, v] : *x) {
      const toml::node* w = y->get(k.str());
      if (!w || !same_value(v, *w)) return false;
    }
    return true;
  }
  if (const auto* x = a.as_string()) return x->get() == b.as_string()->get();
  if (const auto* x = a.as_integer()) return x->get() == b.as_integer()->get();
  if (const auto* x = a.as_boolean()) return x->get() == b.as_boolean()->get();
  if (const auto* x = a.as_date()) return x->get() == b.as_date()->get();
  if (const auto* x = a.as_time()) return x->get() == b.as_time()->get();
  if (const auto* x = a.as_date_time()) return x->get() == b.as_date_time()->get();
  return false;
}

std::string toml_text(const toml::node& value) {
  std::string o;
  append_toml(o, value);
  return o;
}

}  // namespace

std::vector<std::string> toml_array_items(const std::string& text, const std::string& where) {
  const std::string doc = "v = " + text;
  try {
    check_nesting(doc, "");
  } catch (const InputError&) {
    throw InputError("", where, "the values nest more than " + std::to_string(kMaxNesting) + " levels deep");
  }
  toml::table parsed;
  try {
    parsed = toml::parse(doc);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    const auto column = b.line == 1 && b.column > 4 ? b.column - 4 : b.column;  // without "v = "
    throw InputError("", where,
                     "expected [v1, v2, ...], a TOML array (strings in quotes): " + std::string(e.description()) +
                         " (line " + std::to_string(b.line) + ", column " + std::to_string(column) + " of the list)");
  }
  const toml::array* list = parsed.size() == 1 ? parsed.get_as<toml::array>("v") : nullptr;
  if (!list) throw InputError("", where, "expected [v1, v2, ...], one TOML array and nothing after it");
  if (list->empty()) throw InputError("", where, "expected a non-empty list of values");
  std::vector<std::string> items;
  for (const auto& element : *list) {
    std::string item = toml_text(element);
    // Every item is read back as an override will read it: the same value, or a refusal.
    bool same = false;
    try {
      const toml::table back = toml::parse("v = " + item);
      same = back.size() == 1 && back.get("v") && same_value(element, *back.get("v"));
    } catch (const toml::parse_error&) {
    }
    if (!same) throw InputError("", where, "the value " + item.substr(0, 80) + " does not read back as itself from TOML text");
    items.push_back(std::move(item));
  }
  return items;
}

bool Scene::column(const std::string& solver) const {
  auto in = [&](const std::vector<std::string>& v) { return std::find(v.begin(), v.end(), solver) != v.end(); };
  return in(modes.solvers) || (table.present && (table.base == solver || in(table.against)));
}

bool Scene::imported(const std::string& label) const {
  for (const auto& c : table.imports)
    if (c.label == label) return true;
  return false;
}

bool Scene::needs_reference() const {
  if (table.present && table.reference) return true;
  for (const auto& g : gates)
    if (g.analysis == "modes" && g.against == "reference") return true;
  return false;
}

bool Scene::needs(const std::string& solver) const {
  if (column(solver)) return true;
  return solver == reference_solver && needs_reference();
}

bool Scene::runs_nonlinear(const std::string& solver) const {
  auto in = [&](const NonlinearRequest& q) {
    return std::find(q.solvers.begin(), q.solvers.end(), solver) != q.solvers.end() ||
           (q.reference && solver == reference_solver);
  };
  return (response && in(response_request)) || (statics && in(static_request));
}

bool Scene::runs_buckling(const std::string& solver) const {
  const NonlinearRequest& q = buckling_request;
  return buckling && (std::find(q.solvers.begin(), q.solvers.end(), solver) != q.solvers.end() ||
                      (q.reference && solver == reference_solver));
}

const SolverSchema* SceneSchema::find(const std::string& name) const {
  for (const auto& m : solvers)
    if (m.name == name) return &m;
  return nullptr;
}

std::vector<std::string> SceneSchema::names() const {
  std::vector<std::string> v;
  for (const auto& m : solvers) v.push_back(m.name);
  return v;
}

Scene parse_scene(const std::string& toml_text, const std::string& name, const std::vector<std::string>& overrides,
                  const SceneSchema& schema) {
  check_nesting(toml_text, name);
  toml::table root;
  try {
    root = toml::parse(toml_text, name);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw InputError(name, "line " + std::to_string(b.line) + ", column " + std::to_string(b.column),
                     "malformed TOML: " + std::string(e.description()));
  }
  std::set<std::string> overridden;
  for (const auto& o : overrides) overridden.insert(apply_override(root, o, name));
  Reader r(name, overridden);
  Scene s = build(root, r, schema);
  s.file = name;
  std::ostringstream out;
  out << root;
  s.resolved_toml = out.str();
  return s;
}

std::string read_scene_text(const std::string& path) {
  // A scene may come down a pipe (/dev/stdin, a FIFO: docs/commands.md, "ringvib sweep"): the user
  // named it on the command line; the cap bounds an endless device.
  return read_input_file(path, kMaxSceneBytes, "the scene file", InputKind::stream);
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, const SceneSchema& schema) {
  return parse_scene(read_scene_text(path), path, overrides, schema);
}

std::string toml_quoted(std::string_view s) {
  std::string o;
  append_quoted(o, s);
  return o;
}

}  // namespace ring
