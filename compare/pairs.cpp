#include "compare/pairs.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "compare/grid.hpp"

namespace cmp {
namespace {

/// The harmonics k = 0 .. kStations/2 - 1 of a radial shape: (a_k, b_k) with
/// w ~ sum a_k cos k theta + b_k sin k theta (up to a common factor).
struct Harmonics {
  std::vector<double> a, b;
  double energy(int k) const { return a[k] * a[k] + b[k] * b[k]; }
};

Harmonics harmonics(const std::vector<double>& w) {
  const int n = ring::kStations, kmax = n / 2;
  // cos and sin of 2 pi k s / n depend on k s mod n alone: one table of the stations' angles.
  static const auto table = [] {
    std::vector<std::pair<double, double>> cs(ring::kStations);
    for (int j = 0; j < ring::kStations; ++j)
      cs[j] = {std::cos(2.0 * M_PI * j / ring::kStations), std::sin(2.0 * M_PI * j / ring::kStations)};
    return cs;
  }();
  Harmonics h;
  h.a.assign(kmax, 0.0);
  h.b.assign(kmax, 0.0);
  for (int k = 0; k < kmax; ++k)
    for (int s = 0; s < n; ++s) {
      const auto& [c, si] = table[(k * s) % n];
      h.a[k] += w[s] * c;
      h.b[k] += w[s] * si;
    }
  for (int k = 1; k < kmax; ++k) {  // cos and sin carry half the energy of the constant
    h.a[k] *= std::sqrt(0.5);
    h.b[k] *= std::sqrt(0.5);
  }
  return h;
}

/// The wave number carrying most of the radial energy and its share; k = 0 for none.
std::pair<int, double> wave_of(const Harmonics& h) {
  double total = 0.0, best = 0.0;
  int k = 0;
  for (std::size_t i = 0; i < h.a.size(); ++i) {
    const double e = h.energy(static_cast<int>(i));
    total += e;
    if (e > best) {
      best = e;
      k = static_cast<int>(i);
    }
  }
  return {k, total > 0.0 ? best / total : 0.0};
}

}  // namespace

std::vector<SplitPair> split_pairs(const ring::ModalResult& r) {
  std::vector<SplitPair> out;
  // A spinning ring's pairs are travelling waves that the Coriolis term splits: compare/spin.hpp.
  if (r.arch || r.shapes.size() != r.omega.size() || !r.waves.empty()) return out;
  const std::size_t m = r.omega.size();
  std::vector<Harmonics> h;
  std::vector<int> wave(m, 0);
  for (std::size_t i = 0; i < m; ++i) {
    if (static_cast<int>(r.shapes[i].radial.size()) != ring::kStations) return out;
    h.push_back(harmonics(r.shapes[i].radial));
    const auto [k, share] = wave_of(h.back());
    wave[i] = share >= kPairShare ? k : 0;
  }
  std::vector<bool> used(m, false);
  for (std::size_t i = 0; i < m; ++i) {
    if (used[i] || wave[i] < 1) continue;
    for (std::size_t j = i + 1; j < m; ++j) {
      if (used[j] || wave[j] != wave[i]) continue;
      used[i] = used[j] = true;
      SplitPair p;
      p.wave = wave[i];
      p.lower = static_cast<int>(i) + 1;
      p.upper = static_cast<int>(j) + 1;
      p.omega_lower = r.omega[i];
      p.omega_upper = r.omega[j];
      // w ~ A cos(k (theta - phi)) = A (cos k phi cos k theta + sin k phi sin k theta).
      const int k = p.wave;
      const double period = 180.0 / k;
      double phi = std::atan2(h[i].b[k], h[i].a[k]) * 180.0 / M_PI / k;
      phi = std::fmod(std::fmod(phi, period) + period, period);
      p.orientation = phi >= period - 1e-9 * period ? 0.0 : phi;
      if (p.relative() > kSplit) out.push_back(p);
      break;
    }
  }
  return out;
}

nlohmann::json split_pairs_json(const std::vector<SplitPair>& pairs) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : pairs)
    a.push_back({{"wave", p.wave},
                 {"modes", {p.lower, p.upper}},
                 {"omega", {p.omega_lower, p.omega_upper}},
                 {"split", p.split()},
                 {"relative_split", p.relative()},
                 {"orientation_deg", p.orientation}});
  return a;
}

std::string split_pairs_text(const std::vector<SolverSplits>& splits, bool markdown) {
  // One row per wave number, one column per solver: the relative split (%) and the
  // orientation (deg); empty where that solver's modes hold no such pair.
  std::map<int, std::vector<std::string>> rows;
  for (std::size_t c = 0; c < splits.size(); ++c)
    for (const auto& p : splits[c].pairs) {
      auto& row = rows[p.wave];
      row.resize(splits.size());
      row[c] = fmt::format("{:.4g} % at {:.2f}", 100.0 * p.relative(), p.orientation);
    }
  if (rows.empty()) return "";
  Cells cells{{"k"}};
  for (const auto& s : splits) cells[0].push_back(s.solver);
  for (auto& [k, row] : rows) {
    row.resize(splits.size());
    cells.push_back({std::to_string(k)});
    for (const auto& cell : row) cells.back().push_back(cell);
  }
  return std::string("\n") + (markdown ? "**Split pairs**" : "Split pairs") +
         " of wave number k: the relative split (upper - lower) / mean, % at the lower mode's\n"
         "radial antinode (degrees in [0, 180/k)).\n\n" +
         (markdown ? markdown_grid(cells, 1) : text_grid(cells));
}

}  // namespace cmp
