#include "calculix/modes.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "calculix/dat.hpp"
#include "ring/errors.hpp"
#include "ring/sampling.hpp"

namespace calculix {
namespace {

/// The node (0-based) of the deck at a point mass's angle (check_deck put it on one).
int point_mass_node(const Deck& d, double angle) {
  for (std::size_t k = 0; k < d.node_angles.size(); ++k) {
    const double x = ring::wrap_degrees(d.node_angles[k] - angle);
    if (std::min(x, 360.0 - x) < 1e-9) return static_cast<int>(k);
  }
  return 0;
}

}  // namespace

int eigenvalues_for(const ring::RingSpec& spec, int count) {
  return spec.rigid_modes() + count + std::max(10, count / 2);
}

Deck modes_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                const std::string& title) {
  return frequency_deck(spec, options, FrequencyStep{eigenvalues_for(spec, count)}, title);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                                const Hooks& hooks, const std::string& title) {
  const auto start = std::chrono::steady_clock::now();
  check_deck(spec, options);
  require_ccx();
  const int nodes = node_count(spec, options);
  const int rigid = spec.rigid_modes();
  const double length = spec.length();
  const double node_mass = spec.rhoA() * length / nodes;
  const int most = 3 * nodes;  // the beam nodes' in-plane degrees of freedom bound the in-plane modes
  FrequencyStep step{eigenvalues_for(spec, count)};
  for (int attempt = 0;; ++attempt) {
    const Deck deck = frequency_deck(spec, options, step, title);
    const RunOutput out = run(deck.text, {options.timeout, options.threads}, hooks);
    const std::vector<DatMode> modes = read_frequency_dat(out.dat, nodes);
    std::vector<const DatMode*> in_plane;
    for (const DatMode& m : modes) {
      double kinetic = 0.0;
      for (int k = 0; k < nodes; ++k) kinetic += node_mass * (m.ux[k] * m.ux[k] + m.uy[k] * m.uy[k]);
      for (const ring::PointMass& pm : spec.masses) {  // the point masses' share of the unit modal mass
        const int k = point_mass_node(deck, pm.angle);
        kinetic += pm.mass * (m.ux[k] * m.ux[k] + m.uy[k] * m.uy[k]);
      }
      if (kinetic > 0.5) in_plane.push_back(&m);
    }
    if (static_cast<int>(in_plane.size()) < rigid + count) {
      if (attempt < 3 && step.eigenvalues < most + 10) {
        step.eigenvalues *= 2;
        continue;
      }
      throw ring::NumericalError("calculix: ccx returned " + std::to_string(in_plane.size()) +
                                 " in-plane modes of the " + std::to_string(rigid + count) + " asked (" +
                                 std::to_string(modes.size()) + " eigenvalues)");
    }
    // The rigid modes the supports leave must be ccx's lowest, near zero (each comparison
    // written so that a NaN frequency fails it).
    const double scale = spec.bending_frequency_scale();
    for (int r = 0; r < rigid; ++r)
      if (!(in_plane[r]->omega <= 1e-2 * scale))
        throw ring::NumericalError("calculix: the supports leave " + std::to_string(rigid) +
                                   " rigid modes, but ccx's in-plane mode " + std::to_string(r + 1) + " has omega = " +
                                   std::to_string(in_plane[r]->omega) + " rad/s");
    if (!(in_plane[rigid]->omega >= 1e-2 * scale))
      throw ring::NumericalError("calculix: more zero modes than the supports leave (" + std::to_string(rigid) + ")");

    ring::ModalResult res;
    res.solver = "calculix";
    res.model["elements"] = static_cast<long long>(options.elements);
    res.model["element"] = ring::to_string(options.element);
    res.model["section"] = ring::to_string(options.section);
    res.model["section_width"] = deck.width;
    res.model["section_height"] = deck.height;
    res.model["eigenvalues"] = static_cast<long long>(step.eigenvalues);
    res.model["ccx_seconds"] = out.seconds;
    res.model["ccx_cpu_seconds"] = out.cpu_seconds;
    res.rigid_modes = rigid;
    for (int i = rigid; i < rigid + count; ++i) {
      const DatMode& m = *in_plane[i];
      res.omega.push_back(m.omega);
      res.shapes.push_back(spec.arc ? ring::sample_arc(*spec.arc, m.ux, m.uy)
                                    : ring::sample_polygon(deck.anchor, m.ux, m.uy));
    }
    res.unknowns = equation_count(out.log);
    // ccx reports no residual: none (JSON null), not a perfect 0.
    res.max_residual.reset();
    res.residual_norm = "not reported by ccx";
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
  }
}

}  // namespace calculix
