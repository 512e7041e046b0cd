// The steps every command shares (run, table, modes, respond, static, converge, bench,
// sweep): a scene checked before anything is computed, the modal columns computed once,
// the comparison table. The commands (commands.cpp, sweep.cpp) only choose and print.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/table.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// Every check a scene gets before any solver runs: each solver's own refusals for the
/// analyses the scene asks of it (check_scene), then the cost guard. Throws
/// ring::InputError (exit 2). Imported columns' files are read and checked here too.
void check_runnable(const ring::Scene& scene, double max_memory_gib, bool force);

/// The solvers whose modes the scene asks for, in column order: the scene's [table]
/// (base, then against), then any other solver of modes.solvers.
std::vector<std::string> table_solvers(const ring::Scene& s);

/// True when the scene asks for modes (a [table] or modes.solvers).
bool modal(const ring::Scene& s);

/// Everything modal the scene needs, each solver computed once.
struct ModalRun {
  std::vector<ring::ModalResult> columns;   ///< in table order, then the imported columns
  std::optional<ring::ModalResult> reference;
};
/// `progress`, if not null, hears one line per solve.
ModalRun compute_modal(const ring::Scene& s, std::ostream* progress);

/// The comparison table of a modal run; with `paper` (or a gate against the paper) the
/// published values.
Table make_table(const ring::Scene& s, const ModalRun& r, bool paper);

}  // namespace cmp
