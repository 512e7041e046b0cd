#include "compare/guard.hpp"

#include <cmath>

#include <fmt/format.h>

#include "compare/registry.hpp"
#include "ring/errors.hpp"

namespace cmp {
namespace {

std::string gib(double bytes) { return fmt::format("{:.3g} GiB", bytes / double(1ull << 30)); }

}  // namespace

// The process itself, measured as the peak RSS of `ringvib modes` / `respond` / `static`
// on the smallest models: 7.8-8.8 MiB. The code a solver loads on first use
// (SolverEntry::code_bytes) and the solvers' own memory (SolverEntry::memory) come on top.
constexpr double kProcessBytes = 9.5 * (1 << 20);

Estimate estimate_memory(const ring::Scene& s) {
  Estimate worst;
  auto consider = [&](double bytes, const std::string& key, const std::string& what) {
    if (bytes > worst.bytes) worst = {bytes, key, what};
  };
  // The whole history is kept by every solver of the response: per step t, 2 values per
  // recorded point and 6 energies and counts, 8 bytes each, held 4.7-5.6 times over
  // (vector growth, the copies of the comparison, the CSV text): measured 49, 124 and
  // 205 MB above the process for 10^5, 3 10^5 and 5 10^5 steps of 11 values (multibody,
  // n = 40, dt = 1e-5 s). Used: 6 times.
  double history = 0.0;
  if (s.response) {
    const double steps = std::ceil(s.response->t_end / s.response->dt) + 1.0;
    history = steps * 48.0 * (7.0 + 2.0 * s.response->record.size());
  }
  double code = 0.0;
  for (const SolverEntry& e : registry()) {
    const bool modes = s.needs(e.name), nonlinear = s.runs_nonlinear(e.name), buckling = s.runs_buckling(e.name);
    if (modes || nonlinear || buckling) code += e.code_bytes;
    if (e.buckling_memory && buckling) consider(e.buckling_memory(s), e.size_key, "the " + e.name + " buckling");
    if (e.memory && modes) consider(e.memory(s, s.modes.count), e.size_key, "the " + e.name + " modes");
    if (e.memory && nonlinear) {
      // Every response solver's history is kept until the comparison is written.
      const double solve = e.memory(s, 0);
      const double histories = history * std::max<std::size_t>(1, s.response_request.solvers.size());
      consider(solve + histories, histories > solve ? "response.t_end" : e.size_key,
               "the " + e.name + " nonlinear solve" + (histories > solve ? " and its response history" : ""));
    }
  }
  if (s.response) consider(history * s.response_request.solvers.size(), "response.t_end", "the response history");
  worst.bytes += kProcessBytes + code;
  return worst;
}

void check_cost(const ring::Scene& s, const Budget& budget) {
  if (budget.force) return;
  const Estimate e = estimate_memory(s);
  if (e.bytes > budget.max_bytes)
    throw ring::InputError(s.file, e.key,
                           e.what + " would need about " + gib(e.bytes) + " of memory, more than the budget of " +
                               gib(budget.max_bytes) + " (--max-memory GiB to raise it, --force to go ahead)");
}

}  // namespace cmp
