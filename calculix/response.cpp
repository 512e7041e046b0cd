#include "calculix/response.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "calculix/dat.hpp"
#include "calculix/deck.hpp"
#include "ring/errors.hpp"

namespace calculix {
namespace {

int node_of(const Deck& d, double angle) {
  for (std::size_t k = 0; k < d.node_angles.size(); ++k) {
    const double x = ring::wrap_degrees(d.node_angles[k] - angle);
    if (std::min(x, 360.0 - x) < 1e-9) return static_cast<int>(k);
  }
  return -1;
}

/// The ITRS column of ccx's .sta, one entry per converged increment (the last attempt's).
std::vector<int> iterations(const std::string& sta) {
  std::istringstream in(sta);
  std::vector<int> v;
  int last_inc = -1;
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    int step, inc, att, itrs;
    if (!(s >> step >> inc >> att >> itrs)) continue;
    if (inc == last_inc && !v.empty()) v.back() = itrs;
    else v.push_back(itrs);
    last_inc = inc;
  }
  return v;
}

}  // namespace

void check_response(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::ResponseOptions& rs) {
  // The deck writes an arch (modes and statics take it); the response's reader and its tests
  // have the closed ring only so far.
  ring::refuse_arch(spec, "the calculix response");
  ring::refuse_variations(spec, "the calculix response");
  check_response_deck(rs);
  if (spec.plastic)
    throw ring::InputError("", "ring.plastic",
                           "the calculix response deck writes an elastic material: the plastic law enters "
                           "calculix's statics only; leave calculix out of a plastic response");
  response_deck(spec, options, rs);  // the load and the recorded points on nodes; O(elements + steps)
  require_ccx();
}

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                          const ring::ResponseOptions& rs, const Hooks& hooks, const std::string& title) {
  const auto start = std::chrono::steady_clock::now();
  check_response(spec, options, rs);
  const Deck deck = response_deck(spec, options, rs, title);
  std::vector<int> nodes;
  for (double a : rs.record) nodes.push_back(node_of(deck, a) + 1);
  const RunOutput out = run(deck.text, {options.timeout, options.threads}, hooks);
  const DatHistory dat = read_history_dat(out.dat, nodes);
  ring::TimeHistory h;
  h.solver = "calculix";
  h.unknowns = equation_count(out.log);
  h.record_angles = rs.record;
  const std::vector<int> its = iterations(out.sta);
  h.t.push_back(0.0);
  h.ux.assign(nodes.size(), {0.0});
  h.uy.assign(nodes.size(), {0.0});
  h.newton_iterations.push_back(0);
  for (std::size_t k = 0; k < dat.t.size(); ++k) {
    h.t.push_back(dat.t[k]);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      h.ux[i].push_back(dat.ux[i][k]);
      h.uy[i].push_back(dat.uy[i][k]);
    }
    h.newton_iterations.push_back(k < its.size() ? its[k] : 0);
  }
  const std::size_t n = h.t.size();
  h.kinetic.assign(n, NAN);
  h.strain.assign(n, NAN);
  h.work.assign(n, NAN);
  h.energy_error.assign(n, NAN);
  h.constraint_residual.assign(n, NAN);
  if (!(std::abs(h.t.back() - rs.t_end) <= 1e-6 * rs.t_end + 1e-12))  // a NaN time fails too
    throw ring::IntegrationFailure(ring::IntegrationFailure::Reason::step_too_small, h.t.back(), h,
                                   "calculix: ccx stopped at t = " + std::to_string(h.t.back()) + " s of " +
                                       std::to_string(rs.t_end) + " s; the last lines of its output:\n" +
                                       tail(out.log, 12));
  h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return h;
}

}  // namespace calculix
