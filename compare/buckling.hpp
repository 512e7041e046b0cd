// Linear buckling in the driver: every solver that [buckling] lists, the converged
// reference, and their table (the frequency table's pairing by MAC, differences and errors,
// with load factors in place of frequencies).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "compare/table.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct BucklingRun {
  std::vector<ring::BucklingResult> results;   ///< buckling.solvers, in order
  std::optional<ring::BucklingResult> reference;
};

/// Runs [buckling]'s solvers (`only` non-empty: that solver alone, no reference), saying
/// what it does on `progress` if not null.
BucklingRun run_buckling(const ring::Scene& scene, const std::string& only, std::ostream* progress);

/// A result as a ModalResult whose omega are the load factors (for pairing and tables).
ring::ModalResult as_modal(const ring::BucklingResult& b);

/// The buckling table: the first solver as the base, the others and the reference paired
/// with it by MAC (table.hpp), buckling.count rows.
Table buckling_table(const ring::Scene& scene, const BucklingRun& run);

/// One solver's factors as text: lambda, and for loads that are a uniform pressure alone
/// the critical pressure lambda p and lambda p R^3 / EI (3, 4, 4.5 on the inextensible
/// free ring: ring/closed_form.hpp).
std::string buckling_text(const ring::Scene& scene, const ring::BucklingResult& r);
std::string buckling_json(const ring::BucklingResult& r);

}  // namespace cmp
