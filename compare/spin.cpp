#include "compare/spin.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "compare/output.hpp"

namespace cmp {

std::vector<ring::SpinPair> spin_pairs(const ring::ModalResult& r, double speed) {
  std::vector<ring::SpinPair> out;
  if (r.waves.size() != r.omega.size() || speed == 0.0) return out;
  const double w = std::abs(speed);
  std::map<int, std::pair<int, int>> lowest;  // k -> (forward, backward) mode index, -1: none yet
  for (std::size_t i = 0; i < r.omega.size(); ++i) {
    const ring::Wave& v = r.waves[i];
    if (v.number < 1 || v.direction == 0) continue;
    auto& [f, b] = lowest.try_emplace(v.number, -1, -1).first->second;
    int& slot = v.direction > 0 ? f : b;
    if (slot < 0 || r.omega[i] < r.omega[slot]) slot = static_cast<int>(i);
  }
  for (const auto& [k, fb] : lowest) {
    if (fb.first < 0 || fb.second < 0) continue;
    ring::SpinPair p;
    p.wave = k;
    p.forward = r.omega[fb.first];
    p.backward = r.omega[fb.second];
    p.forward_fixed = p.forward + k * w;
    p.backward_fixed = p.backward - k * w;
    p.bryan = 1.0 - (p.backward - p.forward) / (2.0 * k * w);
    out.push_back(p);
  }
  return out;
}

void to_fixed_frame(ring::ModalResult& r, double speed) {
  const double w = std::abs(speed);
  const std::size_t n = r.omega.size();
  if (r.waves.size() != n) throw std::logic_error("to_fixed_frame: a result without its waves");
  for (std::size_t i = 0; i < n; ++i) {
    ring::Wave& v = r.waves[i];
    if (v.direction == 0) continue;
    const double fixed = r.omega[i] + v.direction * v.number * w;
    if (fixed < 0.0) v.direction = -v.direction;
    r.omega[i] = std::abs(fixed);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return r.omega[a] < r.omega[b]; });
  auto permute = [&](auto& v) {
    if (v.size() != n) return;
    auto copy = v;
    for (std::size_t i = 0; i < n; ++i) v[i] = copy[order[i]];
  };
  permute(r.omega);
  permute(r.waves);
  permute(r.shapes);
  r.frame = "fixed";
}

void finish_spin(ring::ModalResult& r, double speed, bool fixed) {
  if (speed == 0.0) return;
  if (r.frame.empty()) r.frame = "rotating";
  if (r.waves.size() != r.omega.size()) {
    r.waves.clear();
    if (fixed)
      throw std::invalid_argument("modes.frame = \"fixed\": " + r.solver +
                                  " reports no travelling direction of its modes, so its frequencies stay in the "
                                  "turning frame; ask for modes.frame = \"rotating\"");
    return;
  }
  r.spin_pairs = spin_pairs(r, speed);
  if (fixed) to_fixed_frame(r, speed);
}

const char* direction_name(int direction) {
  return direction > 0 ? "forward" : direction < 0 ? "backward" : "standing";
}

nlohmann::json spin_pairs_json(const std::vector<ring::SpinPair>& pairs) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& p : pairs)
    j.push_back({{"wave", p.wave}, {"forward", p.forward}, {"backward", p.backward}, {"forward_fixed", p.forward_fixed},
                 {"backward_fixed", p.backward_fixed}, {"bryan", p.bryan}});
  return j;
}

std::string spin_pairs_text(const std::vector<std::pair<std::string, std::vector<ring::SpinPair>>>& pairs,
                            bool markdown) {
  bool any = false;
  for (const auto& [solver, ps] : pairs) any |= !ps.empty();
  if (!any) return "";
  std::ostringstream s;
  s << "\nWave pairs of the spinning ring (rad/s; forward travels with the spin; Bryan's factor: the pattern's "
       "turn in space over the spin's):\n\n";
  const char* head = "solver, wave, forward, backward (turning frame), forward, backward (fixed frame), Bryan";
  if (markdown) s << "| solver | wave | forward | backward | forward (fixed) | backward (fixed) | Bryan |\n|---|---|---|---|---|---|---|\n";
  else s << "  " << head << "\n";
  for (const auto& [solver, ps] : pairs)
    for (const auto& p : ps) {
      if (markdown)
        s << fmt::format("| {} | {} | {} | {} | {} | {} | {:.6f} |\n", solver, p.wave, sig4(p.forward), sig4(p.backward),
                         sig4(p.forward_fixed), sig4(p.backward_fixed), p.bryan);
      else
        s << fmt::format("  {:<10} {:>3}  {:>10}  {:>10}   {:>10}  {:>10}   {:.6f}\n", solver, p.wave, sig4(p.forward),
                         sig4(p.backward), sig4(p.forward_fixed), sig4(p.backward_fixed), p.bryan);
    }
  return s.str();
}

}  // namespace cmp
