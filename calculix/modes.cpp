#include "calculix/modes.hpp"

#include <algorithm>
#include <chrono>
#include <complex>
#include <cmath>
#include <sstream>

#include "calculix/dat.hpp"
#include "modal/gyroscopic.hpp"
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

/// The spinning ring's modes (file comment of modes.hpp): spinning_brick_deck, the complex
/// modes' in-plane ones by the same kinetic-energy rule as at rest on the stations' mean
/// displacements (ccx normalizes a complex mode to
/// Re^T M Re + Im^T M Im = 1), their waves by modal::travelling_mode.
ring::ModalResult spinning_modes(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                                 const Hooks& hooks, const std::string& title,
                                 std::chrono::steady_clock::time_point start) {
  const int nodes = 2 * options.elements;  // the centroid line's stations
  const double node_mass = spec.rhoA() * spec.length() / nodes;
  const int most = 3 * nodes;
  SpinStep step{eigenvalues_for(spec, count), 0};
  for (int attempt = 0;; ++attempt) {
    step.complex = step.eigenvalues;  // the whole basis
    const BrickRing bricks = spinning_brick_deck(spec, options, step, title);
    const Deck& deck = bricks.deck;
    const RunOutput out = run(deck.text, {options.timeout, options.threads}, hooks);
    // K = the tangent with the softening must stay positive definite (modal/gyroscopic.hpp's
    // contract): a negative eigenvalue of the real step is a spin past a divergence, whose
    // complex modes ccx still prints (measured: the ring of tests/calculix/
    // calculix_spin_test.cpp at 12 rad/s, past its k = 1 divergence at 11.3 rad/s).
    const double scale = spec.bending_frequency_scale();
    std::vector<double> real = read_real_eigenvalues(out.dat);
    for (double eig : real)
      if (!(eig > -1e-8 * scale * scale))
        throw ring::NumericalError("calculix: the spinning ring's tangent has the eigenvalue " + std::to_string(eig) +
                                   " rad^2/s^2: the centrifugal softening overcomes a mode's stiffness, a spin past "
                                   "a divergence (rotation.speed = " + std::to_string(spec.rotation.speed) + ")");
    // The centroid line's displacement at each station: the mean of its brick nodes.
    std::vector<DatComplexMode> modes = read_complex_dat(out.dat, bricks.nodes);
    // ccx's complex step may lose modes: measured (the test's ring at 160 elements, 36 real
    // modes) it printed 29 complex ones, the forward partners of k = 11, 12, 13 ... missing
    // (its iteration from each real mode of a nearly degenerate pair finds one of the two). The
    // Coriolis term moves a frequency by at most about the speed, so the i-th complex mode lies
    // within 2 |speed| of the i-th real one while none is lost: the modes are trusted below the
    // first real one without such a partner, less 2 |speed|.
    std::sort(real.begin(), real.end());
    std::sort(modes.begin(), modes.end(), [](const auto& a, const auto& b) { return a.omega < b.omega; });
    const double reach = 2.0 * std::abs(spec.rotation.speed);
    double trusted = INFINITY;
    for (std::size_t i = 0; i < real.size(); ++i) {
      const double w = std::sqrt(std::max(real[i], 0.0));
      if (i >= modes.size() || std::abs(modes[i].omega - w) > reach + 1e-6 * w) {
        trusted = w - reach;
        break;
      }
    }
    modes.erase(std::remove_if(modes.begin(), modes.end(), [&](const auto& m) { return !(m.omega < trusted); }),
                modes.end());
    for (DatComplexMode& m : modes) {
      std::vector<std::complex<double>> ux(nodes), uy(nodes);
      for (int k = 0; k < nodes; ++k) {
        for (int node : bricks.stations[k]) {
          ux[k] += m.ux[node - 1];
          uy[k] += m.uy[node - 1];
        }
        ux[k] /= static_cast<double>(bricks.stations[k].size());
        uy[k] /= static_cast<double>(bricks.stations[k].size());
      }
      m.ux = std::move(ux);
      m.uy = std::move(uy);
    }
    std::vector<const DatComplexMode*> in_plane;
    for (const DatComplexMode& m : modes) {
      double kinetic = 0.0;
      for (int k = 0; k < nodes; ++k) kinetic += node_mass * (std::norm(m.ux[k]) + std::norm(m.uy[k]));
      if (kinetic > 0.5) in_plane.push_back(&m);
    }
    if (static_cast<int>(in_plane.size()) < count) {
      // A larger basis holds more modes, but does not bring back the partners ccx lost
      // (measured: with 72 real modes instead of 36 the same ones are missing): no retry.
      if (!std::isfinite(trusted) && attempt < 3 && step.eigenvalues < most + 10) {
        step.eigenvalues *= 2;
        continue;
      }
      throw ring::NumericalError("calculix: ccx returned " + std::to_string(in_plane.size()) +
                                 " in-plane modes of the spinning ring of the " + std::to_string(count) + " asked (" +
                                 std::to_string(modes.size()) + " complex modes" +
                                 (std::isfinite(trusted) ? ", its complex step losing modes above " +
                                                               std::to_string(trusted) + " rad/s"
                                                         : std::string()) +
                                 ")");
    }
    std::sort(in_plane.begin(), in_plane.end(),
              [](const DatComplexMode* a, const DatComplexMode* b) { return a->omega < b->omega; });
    // A mode at (near) zero: a spin at a divergence (comparison written so that a NaN fails it
    // too).
    if (!(in_plane.front()->omega >= 1e-2 * scale))
      throw ring::NumericalError("calculix: the spinning ring's lowest in-plane mode has omega = " +
                                 std::to_string(in_plane.front()->omega) +
                                 " rad/s: a spin past a divergence (rotation.speed)");

    ring::ModalResult res;
    res.solver = "calculix";
    res.model["elements"] = static_cast<long long>(options.elements);
    // The spinning ring is written as the deck's own C3D20R bricks on the B32R stations, not
    // ccx's expansion of the beam (its Coriolis matrix is wrong across the expansion's MPCs):
    // calculix/README.md, "Spinning rings".
    res.model["element"] = std::string("C3D20R (B32R's stations)");
    res.model["section"] = ring::to_string(options.section);
    res.model["section_width"] = deck.width;
    res.model["section_height"] = deck.height;
    res.model["eigenvalues"] = static_cast<long long>(step.eigenvalues);
    res.model["ccx_seconds"] = out.seconds;
    res.model["ccx_cpu_seconds"] = out.cpu_seconds;
    res.rigid_modes = 0;
    res.frame = "rotating";
    // The sampler of a coordinate vector [ux of the nodes, uy of the nodes].
    const auto sample = [&](const Eigen::VectorXd& v) {
      const std::vector<double> ux(v.data(), v.data() + nodes), uy(v.data() + nodes, v.data() + 2 * nodes);
      return ring::sample_polygon(deck.anchor, ux, uy);
    };
    for (int i = 0; i < count; ++i) {
      const DatComplexMode& m = *in_plane[i];
      Eigen::VectorXcd x(2 * nodes);
      for (int k = 0; k < nodes; ++k) {
        x[k] = m.ux[k];
        x[nodes + k] = m.uy[k];
      }
      auto [shape, wave] = modal::travelling_mode(x, sample, spec.rotation.speed);
      res.omega.push_back(m.omega);
      res.shapes.push_back(std::move(shape));
      res.waves.push_back(wave);
    }
    res.unknowns = equation_count(out.log);
    res.max_residual.reset();
    res.residual_norm = "not reported by ccx";
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
  }
}

}  // namespace

int eigenvalues_for(const ring::RingSpec& spec, int count) {
  return spec.rigid_modes() + count + std::max(10, count / 2);
}

Deck modes_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                const std::string& title) {
  const int n = eigenvalues_for(spec, count);
  if (spec.rotation.spinning()) return spinning_brick_deck(spec, options, SpinStep{n, n}, title).deck;
  return frequency_deck(spec, options, FrequencyStep{n}, title);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                                const Hooks& hooks, const std::string& title) {
  const auto start = std::chrono::steady_clock::now();
  check_deck(spec, options);
  check_spin(spec, options);
  require_ccx();
  if (spec.rotation.spinning()) return spinning_modes(spec, options, count, hooks, title, start);
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
