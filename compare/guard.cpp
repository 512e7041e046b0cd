#include "compare/guard.hpp"

#include <cmath>
#include <cstdio>

#include "compare/registry.hpp"
#include "ring/errors.hpp"

namespace cmp {
namespace {

std::string gib(double bytes) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3g GiB", bytes / double(1ull << 30));
  return b;
}

}  // namespace

Estimate estimate_memory(const ring::Scene& s) {
  Estimate worst;
  auto consider = [&](double bytes, const std::string& key, const std::string& what) {
    if (bytes > worst.bytes) worst = {bytes, key, what};
  };
  for (const SolverEntry& e : registry()) {
    if (e.memory && s.needs(e.name)) consider(e.memory(s, s.modes.count), e.size_key, "the " + e.name + " modes");
    if (e.memory && s.runs_nonlinear(e.name)) consider(e.memory(s, 0), e.size_key, "the " + e.name + " nonlinear solve");
  }
  if (s.response) {
    // The whole history is kept: per step t, 2 values per recorded point, 6 energies and
    // counts; plus six snapshots of every node of the finest model.
    const double steps = std::ceil(s.response->t_end / s.response->dt) + 1.0;
    const double per_step = 8.0 * (7.0 + 2.0 * s.response->record.size());
    consider(steps * per_step * s.response_request.solvers.size(), "response.t_end", "the response history");
  }
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
