#include "compare/report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "compare/files.hpp"
#include "compare/output.hpp"
#include "compare/pairs.hpp"
#include "compare/spin.hpp"
#include "compare/plot.hpp"
#include "compare/response.hpp"

namespace cmp {
namespace {

nlohmann::json model_json(const ring::ModalResult& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : m.model) std::visit([&, k = k](const auto& x) { j[k] = x; }, v);
  return j;
}

nlohmann::json modes_json_value(const ring::ModalResult& m, bool with_shapes) {
  nlohmann::json j;
  j["solver"] = m.solver;
  j["model"] = model_json(m);
  j["rigid_modes"] = m.rigid_modes;
  j["omega"] = m.omega;
  j["seconds"] = m.seconds;
  j["unknowns"] = m.unknowns;
  j["max_residual"] = m.max_residual ? nlohmann::json(*m.max_residual) : nlohmann::json();  // null: none reported
  j["residual_norm"] = m.residual_norm;
  if (m.error_estimate > 0) j["error_estimate"] = m.error_estimate;
  // The pairs the scene's terms split (their frequencies, split and orientation).
  if (const auto pairs = split_pairs(m); !pairs.empty()) j["pairs"] = split_pairs_json(pairs);
  // A spinning ring: the frame of omega, each mode's wave and the wave pairs with Bryan's factor.
  if (!m.frame.empty()) j["frame"] = m.frame;
  if (!m.waves.empty()) {
    nlohmann::json wave = nlohmann::json::array(), direction = nlohmann::json::array();
    for (const auto& w : m.waves) wave.push_back(w.number), direction.push_back(direction_name(w.direction));
    j["wave"] = wave;
    j["direction"] = direction;
  }
  if (!m.spin_pairs.empty()) j["wave_pairs"] = spin_pairs_json(m.spin_pairs);
  if (with_shapes) {
    nlohmann::json shapes = nlohmann::json::array();
    for (const auto& s : m.shapes) shapes.push_back({{"radial", s.radial}, {"tangential", s.tangential}});
    j["stations_deg"] = [] {
      std::vector<double> a;
      for (int i = 0; i < ring::kStations; ++i) a.push_back(ring::station_angle(i));
      return a;
    }();
    j["shapes"] = shapes;
  }
  return j;
}

}  // namespace

std::string modal_json(const ring::ModalResult& m, bool with_shapes) { return modes_json_value(m, with_shapes).dump(2) + "\n"; }

std::string modal_csv(const ring::ModalResult& m) {
  std::ostringstream s;
  s.precision(17);
  s << "mode,omega_rad_s,frequency_hz\n";
  for (std::size_t i = 0; i < m.omega.size(); ++i) s << i + 1 << "," << m.omega[i] << "," << m.omega[i] / (2 * M_PI) << "\n";
  return s.str();
}

std::string shapes_csv(const ring::ModalResult& m) {
  std::ostringstream s;
  s.precision(10);
  s << "angle_deg";
  for (std::size_t k = 0; k < m.shapes.size(); ++k) s << ",radial_" << k + 1 << ",tangential_" << k + 1;
  s << "\n";
  for (int i = 0; i < ring::kStations; ++i) {
    s << ring::station_angle(i);
    for (const auto& sh : m.shapes) s << "," << sh.radial[i] << "," << sh.tangential[i];
    s << "\n";
  }
  return s.str();
}


void write_report(const std::string& dir, const RunReport& r) {
  const ring::Scene& s = *r.scene;
  std::ostringstream md;
  md << "# " << (s.title.empty() ? s.file : s.title) << "\n\n"
     << "Made by `ringvib run " << s.file << "`. Frequencies are angular (rad/s).\n\n";
  for (const auto& w : s.warnings) md << "> warning: " << w << "\n\n";
  std::vector<std::string> files;
  auto put = [&](const std::string& name, const std::string& content) {
    write_file(dir + "/" + name, content);
    files.push_back(name);
  };
  if (r.table) {
    md << "## Natural frequencies\n\n" << format_markdown(*r.table) << "\n";
    put("table.txt", format_text(*r.table));
    put("table.md", format_markdown(*r.table));
    put("table.csv", format_csv(*r.table));
    put("table.json", format_json(*r.table));
  }
  if (!r.gates.empty()) {
    md << "## Accuracy gates\n\n";
    for (const auto& g : r.gates) md << "- " << g.line() << "\n";
    md << "\n";
  }
  std::vector<ring::ModalResult> all = r.modal;
  if (r.reference) all.push_back(*r.reference);
  if (!all.empty()) {
    // One residual per row, in the norm that row's solver names (ring/results.hpp).
    md << "## Models\n\nmax eigen-residual: the largest relative residual (K x - w^2 M x) / (K x + w^2 M x) of the "
          "returned modes, each term measured in the norm of the next column (ring::ModalResult::max_residual).\n\n"
       << "| solver | model | rigid modes | unknowns | solve time (s) | max eigen-residual | residual norm |\n"
       << "|---|---|---:|---:|---:|---:|---|\n";
    for (const auto& m : all) {
      std::ostringstream model;
      for (const auto& [k, v] : m.model) model << k << "=" << model_value(v) << " ";
      md << fmt::format("| {} | {}| {} | {} | {:.3g} | {} | {} |\n", m.solver, model.str(), m.rigid_modes,
                        m.unknowns, m.seconds, residual_cell(m), m.residual_norm);
      put("modes_" + m.solver + ".json", modal_json(m, true));
      put("modes_" + m.solver + ".csv", modal_csv(m));
      if (!m.shapes.empty()) put("shapes_" + m.solver + ".csv", shapes_csv(m));
    }
    md << "\n";
  }
  if (!r.modal.empty() && !r.modal.front().shapes.empty()) {
    // The paper's Figure 3: base solver first, the others overlaid.
    // Imported columns without shapes are left out of the figure.
    std::vector<ring::ModalResult> with_shapes;
    for (const auto& m : r.modal)
      if (!m.shapes.empty()) with_shapes.push_back(m);
    plot_mode_shapes(dir, with_shapes, s.ring, 9);
    files.push_back("mode_shapes.png");
    md << "## Mode shapes (the paper's Figure 3)\n\n![mode shapes](mode_shapes.png)\n\n";
  }
  if (r.table && r.table->columns.size() > 1) {
    std::vector<Series> diff;
    for (std::size_t c = 1; c < r.table->columns.size(); ++c) {
      Series x{r.table->columns[0].solver + " vs " + r.table->columns[c].solver, {}, r.table->columns[c].diff_pct};
      for (int i = 0; i < r.table->rows; ++i) x.x.push_back(i + 1);
      diff.push_back(x);
    }
    plot_series(dir, "difference", "Difference between solvers, (base - other) / other", "mode number",
                "difference (%)", diff);
    files.push_back("difference.png");
    md << "## Differences\n\n![differences](difference.png)\n\n";
  }
  if (r.table && r.table->reference) {
    std::vector<Series> err;
    for (const auto& c : r.table->columns) {
      Series x{c.solver, {}, c.error_pct};
      for (int i = 0; i < r.table->rows; ++i) x.x.push_back(i + 1);
      err.push_back(x);
    }
    plot_series(dir, "error", "Error against the converged FE reference", "mode number", "error (%)", err);
    files.push_back("error.png");
    md << "## Errors against the converged reference\n\n![errors](error.png)\n\n";
  }
  if (r.history) {
    md << "## Forced response\n\n";
    // response.csv is the first solver's history; with several solvers each has its own.
    put("response.csv", history_csv(*r.history));
    const auto& histories = r.nonlinear ? r.nonlinear->histories : std::vector<ring::TimeHistory>{*r.history};
    if (histories.size() > 1)
      for (const auto& h : histories) put("response_" + h.solver + ".csv", history_csv(h));
    if (r.nonlinear && r.nonlinear->history_reference)
      put("response_reference.csv", history_csv(*r.nonlinear->history_reference));
    if (r.response_table) {
      md << format_markdown(*r.response_table) << "\n";
      put("response_table.txt", format_text(*r.response_table));
      put("response_table.md", format_markdown(*r.response_table));
      put("response_table.csv", format_csv(*r.response_table));
      put("response_table.json", format_json(*r.response_table));
    }
    if (histories.size() > 1) plot_histories(dir, histories, s.ring);
    else plot_response(dir, *r.history, s.ring);
    files.push_back("response_history.png");
    md << "![time histories](response_history.png)\n\n";
    if (!r.history->snapshot_t.empty()) {
      files.push_back("response_shapes.png");
      md << "![deformed ring](response_shapes.png)\n\n";
    }
  }
  if (r.statics) {
    md << "## Nonlinear statics\n\n";
    put("static.json", static_json(*r.statics));
    if (r.static_table) {
      md << format_markdown(*r.static_table) << "\n";
      if (r.nonlinear && r.nonlinear->statics.size() > 1)
        for (const auto& x : r.nonlinear->statics) put("static_" + x.solver + ".json", static_json(x));
      if (r.nonlinear && r.nonlinear->static_reference)
        put("static_reference.json", static_json(*r.nonlinear->static_reference));
      put("static_table.txt", format_text(*r.static_table));
      put("static_table.md", format_markdown(*r.static_table));
      put("static_table.csv", format_csv(*r.static_table));
      put("static_table.json", format_json(*r.static_table));
    } else {
      md << "```\n" << static_text(*r.statics) << "```\n\n";
    }
    std::vector<ring::StaticResult> all = r.nonlinear ? r.nonlinear->statics : std::vector<ring::StaticResult>{*r.statics};
    if (r.nonlinear && r.nonlinear->static_reference) all.push_back(*r.nonlinear->static_reference);
    plot_static_shapes(dir, all, s.ring);
    files.push_back("static_shapes.png");
    md << "![deformed ring under the static load](static_shapes.png)\n\n";
    if (!all.front().path.empty()) {
      for (const auto& x : all) {
        put("static_path_" + x.solver + ".csv", static_path_csv(x));
        md << "- " << x.solver << ": " << x.path.size() << " equilibria; ended at load factor " << x.end_load << ": "
           << x.end << "\n";
      }
      std::optional<std::array<double, 2>> drive;
      if (s.statics->displacement) drive = s.statics->displacement->value;
      // The plate at plates.axis moves along -d_0 (ring/analysis.hpp, PlatePair): its force
      // along that is the crushing force, against the plates' approach.
      if (const auto& pl = s.statics->plates)
        drive = {-pl->travel * std::cos(pl->axis * M_PI / 180.0), -pl->travel * std::sin(pl->axis * M_PI / 180.0)};
      plot_static_paths(dir, all, s.ring, drive);
      files.push_back("static_path.png");
      md << "\n![equilibrium paths](static_path.png)\n\n";
      if (!s.statics->history.empty()) {
        plot_static_history(dir, all, drive);
        files.push_back("static_history.png");
        md << "![the load history](static_history.png)\n\n";
      }
      plot_path_shapes(dir, all.front(), s.ring);
      files.push_back("static_path_shapes.png");
      md << "![the ring along its path](static_path_shapes.png)\n\n";
    }
  }
  if (r.buckling) {
    md << "## Linear buckling\n\n";
    for (const auto& b : r.buckling->results) put("buckling_" + b.solver + ".json", buckling_json(b));
    if (r.buckling->reference) put("buckling_reference.json", buckling_json(*r.buckling->reference));
    if (r.buckling_table) {
      md << format_markdown(*r.buckling_table) << "\n";
      put("buckling_table.txt", format_text(*r.buckling_table));
      put("buckling_table.md", format_markdown(*r.buckling_table));
      put("buckling_table.csv", format_csv(*r.buckling_table));
      put("buckling_table.json", format_json(*r.buckling_table));
    } else {
      md << "```\n" << buckling_text(s, r.buckling->results.front()) << "```\n\n";
    }
    std::vector<ring::ModalResult> shapes;
    for (const auto& b : r.buckling->results) shapes.push_back(as_modal(b));
    if (r.buckling->reference) shapes.push_back(as_modal(*r.buckling->reference));
    plot_mode_shapes(dir, shapes, s.ring, std::min(9, s.buckling->count),
                     {"buckling_shapes", "Buckling modes", "buckling mode ", "lambda = ", ""});
    files.push_back("buckling_shapes.png");
    md << "![buckling modes](buckling_shapes.png)\n\n";
  }
  md << "## Scene (after --set overrides)\n\n```toml\n" << s.resolved_toml << "\n```\n\n## Files\n\n";
  for (const auto& f : files) md << "- `" << f << "`\n";
  md << "\nEach figure NAME.png has NAME.gp (gnuplot script) and NAME.dat (data) beside it.\n";
  write_file(dir + "/report.md", md.str());
}

}  // namespace cmp
