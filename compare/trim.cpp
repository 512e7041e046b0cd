#include "compare/trim.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "compare/files.hpp"
#include "compare/pairs.hpp"
#include "compare/registry.hpp"
#include "compare/runner.hpp"
#include "ring/errors.hpp"
#include "ring/scene.hpp"

namespace cmp {
namespace {

constexpr int kMaxSteps = 12;  ///< chord-Newton steps before the trim gives up (exit 3)

/// The scene's masses and `extra` at the trim angles, as the override of `masses`.
std::string masses_override(const ring::Scene& s, const std::vector<double>& at, const std::vector<double>& extra) {
  std::ostringstream o;
  o.precision(17);
  o << "masses=[";
  bool first = true;
  auto put = [&](double angle, double mass, double inertia) {
    o << (first ? "" : ", ") << "{at = " << angle << ", mass = " << mass << ", inertia = " << inertia << "}";
    first = false;
  };
  for (const auto& m : s.ring.masses) put(m.angle, m.mass, m.inertia);
  for (std::size_t j = 0; j < at.size(); ++j)
    if (extra[j] != 0.0) put(at[j], extra[j], 0.0);
  o << "]";
  return o.str();
}

struct Probe {
  SplitPair pair;
  std::complex<double> z;  ///< relative split e^{i 2k phi}
};

}  // namespace

TrimResult run_trim(const std::string& text, const std::string& name, const std::vector<std::string>& overrides,
                    const TrimArgs& t) {
  const ring::Scene s = parse_scene(text, name, overrides);
  const std::string solver = !t.solver.empty() ? t.solver : s.modes.solvers.empty() ? "" : s.modes.solvers.front();
  if (solver.empty()) throw ring::InputError(name, "--solver", "the scene lists no modal solver: name one");
  if (s.ring.is_arch())
    throw ring::InputError(name, "ring.arc", "an arch's modes come in no degenerate pairs: trimming is for closed rings");
  const SolverEntry& entry = cmp::solver(solver);
  if (t.at.empty() || t.at.size() > 2)
    throw ring::InputError("", "--at", "one or two angles (degrees): a pair's split has two components");
  for (double x : t.at)
    if (!std::isfinite(x)) throw ring::InputError("", "--at", "angles must be finite numbers of degrees");
  if (!(t.tolerance > 0.0 && t.tolerance < 1.0)) throw ring::InputError("", "--tolerance", "must be in (0, 1)");
  const int count = std::max(s.modes.count, t.mode + 1);
  if (t.mode < 1 || count > entry.elastic_modes(s))
    throw ring::InputError("", "--mode", "a mode number from 1 to " + std::to_string(entry.elastic_modes(s) - 1) +
                                             " of the " + solver + " model");
  const double ring_mass = s.ring.rhoA() * 2.0 * M_PI * s.ring.radius;
  // The trial masses must sit on every model's nodes: checked by the scene reader on a
  // scene that holds them, before anything is computed.
  auto scene_with = [&](const std::vector<double>& extra) {
    std::vector<std::string> o = overrides;
    o.push_back(masses_override(s, t.at, extra));
    return parse_scene(text, name, o);
  };
  try {
    const ring::Scene probe = scene_with(std::vector<double>(t.at.size(), 1e-3 * ring_mass));
    check_modes_of(probe, entry);
  } catch (const ring::InputError& e) {
    throw ring::InputError("", "--at", std::string("a trim mass there is refused: ") + e.what());
  }

  auto measure = [&](const std::vector<double>& extra, int wave) -> Probe {
    const ring::Scene sc = scene_with(extra);
    const ring::ModalResult m = entry.modes(sc, count);
    for (const auto& p : split_pairs(m))
      if (wave == 0 ? (p.lower == t.mode || p.upper == t.mode) : p.wave == wave)
        return {p, std::polar(p.relative(), 2.0 * p.wave * p.orientation * M_PI / 180.0)};
    // No split pair of that wave number left: split below kSplit (wave 0, z = 0).
    return {SplitPair{}, 0.0};
  };
  const std::vector<double> zero(t.at.size(), 0.0);
  const Probe before = measure(zero, 0);
  if (before.pair.wave == 0)
    throw ring::InputError("", "--mode", "mode " + std::to_string(t.mode) + " of the " + solver +
                                             " model is in no split pair: nothing to trim (ringvib modes lists the pairs)");
  const int k = before.pair.wave;
  if (t.at.size() == 2) {
    const double turn = std::fmod(std::abs(2.0 * k * (t.at[1] - t.at[0])), 180.0);
    if (turn < 1e-6 || 180.0 - turn < 1e-6)
      throw ring::InputError("", "--at", fmt::format("the two angles act alike on pair k = {} (they differ by a multiple of "
                                                     "{:g} degrees); choose angles {:g} degrees apart",
                                                     k, 90.0 / k, 45.0 / k));
  }
  // Each angle's effect per kg, measured with a probe of 1e-4 of the ring's mass.
  const double probe = 1e-4 * ring_mass;
  std::vector<std::complex<double>> J;
  for (std::size_t j = 0; j < t.at.size(); ++j) {
    std::vector<double> e = zero;
    e[j] = probe;
    J.push_back((measure(e, k).z - before.z) / probe);
  }
  std::vector<double> m = zero;
  Probe now = before;
  int steps = 0;
  while (std::abs(now.z) > t.tolerance) {
    if (++steps > kMaxSteps)
      throw ring::NumericalError(fmt::format("trim: the split of pair k = {} is still {:.3g} after {} steps (tolerance "
                                             "{:g})",
                                             k, std::abs(now.z), kMaxSteps, t.tolerance));
    // J dm = -z: two real equations; one angle: least squares along its direction.
    std::vector<double> dm(t.at.size());
    if (t.at.size() == 1) {
      dm[0] = -std::real(now.z * std::conj(J[0])) / std::norm(J[0]);
    } else {
      const double a11 = J[0].real(), a12 = J[1].real(), a21 = J[0].imag(), a22 = J[1].imag();
      const double det = a11 * a22 - a12 * a21;
      dm[0] = (-now.z.real() * a22 + now.z.imag() * a12) / det;
      dm[1] = (-now.z.imag() * a11 + now.z.real() * a21) / det;
    }
    for (std::size_t j = 0; j < m.size(); ++j) {
      m[j] += dm[j];
      // A mass within round-off of zero (the split lies along the other angle's direction
      // alone: 1e-12 of the ring's mass, far below any probe's 1e-4) is none, not a removal.
      if (std::abs(m[j]) <= 1e-12 * ring_mass) m[j] = 0.0;
      if (m[j] < 0.0)
        throw ring::NumericalError(fmt::format(
            "trim: pair k = {} needs {:.4g} kg at {:g} degrees, a removal; a mass at {:g} degrees acts as one: give "
            "that angle instead",
            k, m[j], t.at[j], std::fmod(t.at[j] + 90.0 / k, 360.0)));
    }
    const Probe next = measure(m, k);
    if (t.at.size() == 1 && std::abs(next.z) >= std::abs(now.z))
      throw ring::NumericalError(fmt::format("trim: one mass at {:g} degrees cannot bring the split of pair k = {} below "
                                             "{:.3g} (it lies off the mass's direction); give two angles",
                                             t.at[0], k, std::abs(now.z)));
    now = next;
  }

  TrimResult r;
  r.solver = solver;
  r.mode = t.mode;
  r.wave = k;
  r.steps = steps;
  r.at = t.at;
  r.masses = m;
  r.before = before.pair;
  r.after = now.pair;
  std::ostringstream scene;
  scene.precision(17);
  scene << text << (text.empty() || text.back() == '\n' ? "" : "\n")
        << fmt::format("\n# Trimmed by ringvib trim (pair k = {} of {}: relative split {:.3g} -> {:.3g}).\n", k, solver,
                       before.pair.relative(), std::abs(now.z));
  for (std::size_t j = 0; j < m.size(); ++j)
    if (m[j] != 0.0) scene << "[[masses]]\nat = " << t.at[j] << "\nmass = " << m[j] << "\n";
  r.trimmed_scene = scene.str();
  // The trimmed text must read back as the trimmed scene (an inline `masses = [...]` would not).
  parse_scene(r.trimmed_scene, name, overrides);
  return r;
}

int cmd_trim(const CommonArgs& a, const TrimArgs& t) {
  const std::string text = ring::read_scene_text(a.scene);
  check_runnable(parse_scene(text, a.scene, a.set), a.max_memory_gib, a.force);
  Outputs files;
  if (!t.out.empty()) files.file(t.out, "--out", a.scene);  // checked before computing
  const TrimResult r = run_trim(text, a.scene, a.set, t);
  if (!t.out.empty()) {
    files.open();
    files.stage_file(t.out, r.trimmed_scene);
    files.publish();
  }
  if (t.json) {
    nlohmann::json j;
    j["mode"] = r.mode;
    j["wave"] = r.wave;
    j["solver"] = r.solver;
    j["masses"] = nlohmann::json::array();
    for (std::size_t i = 0; i < r.masses.size(); ++i) j["masses"].push_back({{"at", r.at[i]}, {"mass", r.masses[i]}});
    j["split_before"] = r.before.relative();
    j["split_after"] = r.after.wave ? r.after.relative() : 0.0;
    j["orientation_before"] = r.before.orientation;
    j["steps"] = r.steps;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << fmt::format("{}: pair k = {} (modes {}, {}): relative split {:.4g} at {:.2f} deg\n", r.solver, r.wave,
                             r.before.lower, r.before.upper, r.before.relative(), r.before.orientation);
    for (std::size_t i = 0; i < r.masses.size(); ++i)
      std::cout << fmt::format("  trim mass {:+.6g} kg at {:g} deg\n", r.masses[i], r.at[i]);
    std::cout << fmt::format("relative split after: {:.3g} ({} steps; tolerance {:g})\n",
                             r.after.wave ? r.after.relative() : 0.0, r.steps, t.tolerance);
  }
  return 0;
}

}  // namespace cmp
