#include "calculix/statics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "calculix/dat.hpp"
#include "calculix/deck.hpp"
#include "ring/errors.hpp"

namespace calculix {
namespace {

/// The node (0-based) of the model at `angle`, or -1.
int node_of(const Deck& d, double angle) {
  for (std::size_t k = 0; k < d.node_angles.size(); ++k) {
    const double x = ring::wrap_degrees(d.node_angles[k] - angle);
    if (std::min(x, 360.0 - x) < 1e-9) return static_cast<int>(k);
  }
  return -1;
}

/// The sum of the ITRS column of ccx's .sta ("STEP INC ATT ITRS TOT TIME STEP TIME INC TIME").
int newton_iterations(const std::string& sta) {
  std::istringstream in(sta);
  int total = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    int step, inc, att, itrs;
    if (s >> step >> inc >> att >> itrs) total += itrs;
  }
  return total;
}

}  // namespace

void check_static(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::StaticOptions& st) {
  ring::refuse_variations(spec, "the calculix statics");
  // [plates]: the deck's springs (plates_block); what it cannot write is refused there
  // (check_plates: an arch, loads or supports beside them, an element other than B32R).
  // static.displacement is the driven node's *BOUNDARY (static_deck); the resultant law stays
  // refused by the deck (ring.plastic.moment), with loads or driven.
  // An arch takes point loads (held to the elastica of DaDeppo & Schmidt's deep arch,
  // tests/calculix/calculix_arch_test.cpp). Distributed loads on an arch are refused until
  // validated: under a uniform pressure a pinned arch is membrane-dominated, its bending driven
  // by the O(r^2/R^2) coupling of extension and curvature that beam theories treat differently
  // (measured on a pinned semicircle, R/h = 100: ccx B31 converges to the curved-bar theory's
  // crown deflection, 4 % from the thin-ring kinematics of the other solvers, and B32R drifts
  // from B31 by 0.4 % at 160 elements instead of converging).
  if (spec.arc && st.loads.pressure.any())
    throw ring::InputError("", "static.pressure",
                           "the calculix column does not take a pressure on an arch (ring.arc) yet: its brick "
                           "expansion differs from the thin-ring kinematics of the other solvers by percents on a "
                           "membrane-dominated arch (calculix/README.md, \"Arches\"); use point loads");
  if (spec.arc && st.loads.has_gravity())
    throw ring::InputError("", "static.gravity",
                           "the calculix column does not take gravity on an arch (ring.arc) yet (not validated); use "
                           "point loads");
  const Deck d = static_deck(spec, options, st, "check");  // the loads on nodes, what ccx cannot load; O(elements)
  for (double a : st.record)
    if (node_of(d, a) < 0)
      throw ring::InputError("", "static.record", "angle " + number(a) + " is not a node of the calculix model");
  require_ccx();
}

namespace {

/// The load factor at ccx's total time t of a deck whose step k (1-based) runs over total
/// time (k - 1, k] from legs[k - 2] (0 for the first) to legs[k - 1].
double load_factor(const std::vector<double>& legs, double t) {
  const int k = std::clamp(static_cast<int>(std::ceil(t - 1e-9)), 1, static_cast<int>(legs.size()));
  const double from = k == 1 ? 0.0 : legs[k - 2];
  return from + (t - (k - 1)) * (legs[k - 1] - from);
}

}  // namespace

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                                const ring::StaticOptions& st, const Hooks& hooks, const std::string& title) {
  const auto start = std::chrono::steady_clock::now();
  check_static(spec, options, st);
  const Deck deck = static_deck(spec, options, st, title);
  const RunOutput out = run(deck.text, {options.timeout, options.threads}, hooks);
  const int nodes = node_count(spec, options);
  const DatStatic dat = read_static_dat(out.dat, nodes);
  const std::vector<double> legs = st.history.empty() ? std::vector<double>{1.0} : st.history;
  const double end = static_cast<double>(legs.size());
  if (!(std::abs(dat.time - end) <= 1e-6))  // written so that a NaN time fails too
    throw ring::NumericalError(
        "calculix: ccx stopped at load factor " + std::to_string(load_factor(legs, dat.time)) +
        (legs.size() > 1 ? " in leg " + std::to_string(static_cast<int>(std::ceil(dat.time - 1e-9))) + " of " +
                               std::to_string(legs.size()) + " (static.history)"
                         : std::string(" of 1")) +
        "; the last lines of its output:\n" + tail(out.log, 12));
  if (st.displacement)
    for (const auto& inc : dat.all)
      if (std::isnan(inc.force[0]))
        throw ring::NumericalError("calculix: ccx printed no reaction of the driven node at total time " +
                                   std::to_string(inc.time) + " (*NODE PRINT RF)");
  if (st.plates)
    for (const auto& inc : dat.all)
      if (std::isnan(inc.plates[0][0]) || std::isnan(inc.plates[1][0]))
        throw ring::NumericalError("calculix: ccx printed no total force of the plates at total time " +
                                   std::to_string(inc.time) + " (*NODE PRINT, TOTALS=ONLY RF)");
  std::optional<ring::PlatePair> pair;
  if (st.plates) pair.emplace(spec, *st.plates);
  // The contact lengths on the deformed beam nodes in order around the ring (every node, not
  // the path's strided shape). ccx prints the displacements with 7 significant digits, and a
  // touching node's gap is the penalty's sinking, -F / (k w) (~1e-10 m): below the print's
  // resolution, so that read back it comes out either side of 0 (measured: a crushed ring's
  // contact length 0 at half its increments). A gap within the print's rounding, 1e-6 of the
  // largest displacement (twice the rounding of 7 digits), counts as touching: the plates'
  // position shifted by it, the load factor s + 2 tol / travel in PlatePair::contact_lengths.
  // It lengthens a contact by sqrt(2 tol R) or less at each end (the ring curving away from
  // the plate), ~1e-2 m at a travel of R on R = 10 m.
  auto contact = [&](const std::vector<double>& ux, const std::vector<double>& uy, double s) {
    std::vector<double> x(nodes), y(nodes);
    double largest = 0.0;
    for (int k = 0; k < nodes; ++k) {
      const double t = deck.node_angles[k] * M_PI / 180.0;
      x[k] = spec.radius * std::cos(t) + ux[k];
      y[k] = spec.radius * std::sin(t) + uy[k];
      largest = std::max(largest, std::hypot(ux[k], uy[k]));
    }
    const double tol = 1e-6 * largest;
    return pair->contact_lengths(x, y, s + 2.0 * tol / pair->travel);
  };
  ring::StaticResult r;
  r.solver = "calculix";
  r.unknowns = equation_count(out.log);
  r.steps = dat.increments;
  r.newton_iterations = newton_iterations(out.sta);
  // The recorded points and the deformed ring of one increment.
  auto point = [&](const DatStatic::Increment& inc) {
    ring::PathPoint p;
    p.load_factor = load_factor(legs, inc.time);
    for (double a : st.record) {
      const int k = node_of(deck, a);
      p.displacements.push_back({a, inc.ux[k], inc.uy[k]});
    }
    const int stride = ring::path_shape_stride(nodes);
    for (int k = 0; k < nodes; k += stride) {
      const double t = deck.node_angles[k] * M_PI / 180.0;
      p.node_x.push_back(spec.radius * std::cos(t) + inc.ux[k]);
      p.node_y.push_back(spec.radius * std::sin(t) + inc.uy[k]);
    }
    // (largest - smallest distance between opposite nodes) / R, the chains' definition
    // (multibody/statics.cpp); 0 for an arch and for an odd node count (B31), which have no
    // opposite nodes.
    if (!spec.arc && nodes % 2 == 0) {
      double most = 0.0, least = INFINITY;
      for (int k = 0; k < nodes / 2; ++k) {
        const int j = k + nodes / 2;
        const double tk = deck.node_angles[k] * M_PI / 180.0, tj = deck.node_angles[j] * M_PI / 180.0;
        const double d = std::hypot(spec.radius * (std::cos(tk) - std::cos(tj)) + inc.ux[k] - inc.ux[j],
                                    spec.radius * (std::sin(tk) - std::sin(tj)) + inc.uy[k] - inc.uy[j]);
        most = std::max(most, d);
        least = std::min(least, d);
      }
      p.ovalisation = (most - least) / spec.radius;
    }
    if (st.displacement) p.reaction = inc.force;
    // The force of plate 0 on the ring: the total RF of its plate nodes, the force its
    // boundary puts on them, which their springs pass on to the ring whole (a plate node has
    // no other load; its tie along e carries ~0, the springs lying along d_p).
    if (st.plates) {
      p.reaction = inc.plates[0];
      p.contact_length = contact(inc.ux, inc.uy, p.load_factor);
    }
    if (spec.plastic) p.dissipated = p.plastic_curvature = std::nan("");
    return p;
  };
  const ring::PathPoint last = point(dat.all.back());
  r.displacements = last.displacements;
  r.reaction = last.reaction;
  r.contact_length = last.contact_length;
  for (int k = 0; k < nodes; ++k) {
    const double t = deck.node_angles[k] * M_PI / 180.0;
    r.node_x.push_back(spec.radius * std::cos(t) + dat.ux[k]);
    r.node_y.push_back(spec.radius * std::sin(t) + dat.uy[k]);
  }
  if (st.path) {
    // Every converged increment from rest (ccx's load stepping: no arc length, so no limit
    // point is passed or located, no branch switched and no contact found; a load-controlled
    // run past a limit point stops, exit 3, as above).
    ring::PathPoint rest;
    rest.displacements = last.displacements;
    for (auto& d : rest.displacements) d.ux = d.uy = 0.0;
    const int stride = ring::path_shape_stride(nodes);
    for (int k = 0; k < nodes; k += stride) {
      const double t = deck.node_angles[k] * M_PI / 180.0;
      rest.node_x.push_back(spec.radius * std::cos(t));
      rest.node_y.push_back(spec.radius * std::sin(t));
    }
    if (spec.plastic) rest.dissipated = rest.plastic_curvature = std::nan("");
    if (st.plates) rest.contact_length = contact(std::vector<double>(nodes, 0.0), std::vector<double>(nodes, 0.0), 0.0);
    r.path.push_back(rest);
    for (const auto& inc : dat.all) r.path.push_back(point(inc));
    r.end = st.history.empty() ? "full load" : "end of the history";
    r.end_load = legs.back();
  }
  if (spec.plastic) {
    // ccx prints no plastic work by itself (its ENER is the whole internal energy, elastic and
    // plastic alike) and has no plastic curvature (its bricks have plastic strains at the
    // integration points): not read, as the response's energies.
    r.dissipated = std::nan("");
    r.plastic_curvature = std::nan("");
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace calculix
