// `ringvib run --out DIR`: report.md with the table, the figures and the resolved scene,
// CSV and JSON of every result, gnuplot figures. Every file is written atomically.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/gates.hpp"
#include "compare/nonlinear.hpp"
#include "compare/buckling.hpp"
#include "compare/table.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct RunReport {
  const ring::Scene* scene = nullptr;
  std::vector<ring::ModalResult> modal;          ///< table columns, base first
  std::optional<ring::ModalResult> reference;
  std::optional<Table> table;
  std::vector<GateResult> gates;
  std::optional<ring::TimeHistory> history;      ///< the first response solver's
  std::optional<ring::StaticResult> statics;     ///< the first statics solver's
  std::optional<NonlinearRun> nonlinear;         ///< every nonlinear result
  std::optional<NonlinearTable> response_table, static_table;  ///< with several solvers or a reference
  std::optional<BucklingRun> buckling;           ///< [buckling]'s results
  std::optional<Table> buckling_table;           ///< with several solvers or a reference
};

/// Writes every file of the report into `dir` (which exists). Lists what it wrote in
/// report.md. Throws std::runtime_error if a file or a figure cannot be written.
void write_report(const std::string& dir, const RunReport& r);

/// JSON/CSV forms shared with the subcommands.
std::string modal_json(const ring::ModalResult& m, bool with_shapes);
std::string modal_csv(const ring::ModalResult& m);
std::string shapes_csv(const ring::ModalResult& m);

}  // namespace cmp
