#include "compare/nonlinear.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "compare/grid.hpp"
#include "compare/output.hpp"
#include "compare/plot.hpp"
#include "compare/files.hpp"
#include "compare/progress.hpp"
#include "compare/registry.hpp"
#include "ring/errors.hpp"

namespace cmp {

NonlinearRun run_nonlinear(const ring::Scene& scene, const std::string& only, std::ostream* progress) {
  NonlinearRun run;
  auto listed = [&](const ring::NonlinearRequest& q) {
    std::vector<std::string> v;
    for (const auto& name : q.solvers)
      if (only.empty() || name == only) v.push_back(name);
    if (!only.empty() && v.empty()) v.push_back(only);  // --solver NAME not listed: run it anyway
    return v;
  };
  // A response longer than ProgressLine::kDelay shows the fraction of t_end on a
  // terminal: the solver's time loop reports it through ResponseOptions::progress.
  // The same callback carries the thread's interruption check (interrupt_check(): the
  // Python module's Ctrl-C), which throws to end the run.
  std::optional<ProgressLine> line;
  auto with_progress = [&](const std::string& who) {
    ring::Scene s = scene;
    const std::function<void()>& check = interrupt_check();
    if (!progress && !check) return s;
    line.reset();
    if (progress) line.emplace("response " + who, "", progress);
    s.response->progress = [&line, check](double f) {
      if (line) line->fraction(f);
      if (check) check();
    };
    return s;
  };
  auto say = [&](const std::string& what) {
    line.reset();  // ends the previous response's line, if it was drawn
    if (progress) *progress << "ringvib: " << what << "\n";
  };
  if (scene.response) {
    for (const auto& name : listed(scene.response_request)) {
      const SolverEntry& e = solver(name);
      if (!e.response) throw ring::InputError(scene.file, "response.solvers", "the " + name + " solver has no forced response");
      say("integrating the forced response with " + name);
      run.histories.push_back(e.response(with_progress(name)));
    }
    if (scene.response_request.reference && only.empty()) {
      say("integrating the converged reference response");
      // The reference halves dt until it converges: the fraction restarts with each run.
      run.history_reference = reference_response(with_progress("reference"));
    }
  }
  if (scene.statics) {
    for (const auto& name : listed(scene.static_request)) {
      const SolverEntry& e = solver(name);
      if (!e.statics) throw ring::InputError(scene.file, "static.solvers", "the " + name + " solver has no statics");
      say("solving the nonlinear statics with " + name);
      run.statics.push_back(e.statics(scene));
    }
    if (scene.static_request.reference && only.empty()) {
      say("solving the converged reference statics");
      run.static_reference = reference_static(scene);
    }
  }
  return run;
}

namespace {

/// Fills the differences against the base (column 0) and the errors against the
/// reference, leaving NaN where the value compared with is ~0 for that quantity.
void fill_relative(NonlinearTable& t) {
  std::map<std::string, double> scale;
  for (const auto& r : t.rows)
    for (double v : r.value) scale[r.quantity] = std::max(scale[r.quantity], std::abs(v));
  auto rel = [&](double a, double b, const std::string& q) {
    return std::abs(b) > 1e-9 * scale[q] ? (a - b) / std::abs(b) * 100.0 : NAN;
  };
  for (auto& r : t.rows) {
    r.diff_pct.assign(r.value.size(), NAN);
    for (std::size_t c = 1; c < r.value.size(); ++c) r.diff_pct[c] = rel(r.value[0], r.value[c], r.quantity);
    if (r.reference) {
      r.error_pct.clear();
      for (double v : r.value) r.error_pct.push_back(rel(v, *r.reference, r.quantity));
    }
  }
}

struct Peak {
  double u = 0.0, t = 0.0;
};

Peak peak(const ring::TimeHistory& h, std::size_t point) {
  Peak p;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    const double u = std::hypot(h.ux[point][k], h.uy[point][k]);
    if (u > p.u) p = {u, h.t[k]};
  }
  return p;
}

/// Index of the recorded point at `angle` (degrees), or -1.
int point_index(const std::vector<double>& angles, double angle) {
  for (std::size_t i = 0; i < angles.size(); ++i)
    if (std::abs(angles[i] - angle) < 1e-9) return static_cast<int>(i);
  return -1;
}

/// 4 significant digits, exponent form for very small or large values; "n/a" if undefined.
std::string number_or_na(double v, bool pct) {
  if (!std::isfinite(v)) return "n/a";
  if (pct) return pct2(v);
  return fmt::format("{:.4g}", v);
}

Cells cells(const NonlinearTable& t) {
  Cells out;
  std::vector<std::string> head = {"point deg", "quantity"};
  for (std::size_t c = 0; c < t.solvers.size(); ++c) {
    head.push_back(t.solvers[c]);
    if (c > 0) head.push_back("diff %");
    if (t.has_reference()) head.push_back("error %");
  }
  if (t.has_reference()) head.push_back("reference");
  out.push_back(head);
  for (const auto& r : t.rows) {
    std::vector<std::string> row = {r.whole_ring() ? "ring" : number_or_na(r.angle, false), r.quantity};
    for (std::size_t c = 0; c < r.value.size(); ++c) {
      row.push_back(number_or_na(r.value[c], false));
      if (c > 0) row.push_back(number_or_na(r.diff_pct[c], true));
      if (r.reference) row.push_back(number_or_na(r.error_pct[c], true));
    }
    if (r.reference) row.push_back(number_or_na(*r.reference, false));
    out.push_back(row);
  }
  return out;
}

std::string units_note(const NonlinearTable& t) {
  const bool plastic = std::any_of(t.rows.begin(), t.rows.end(), [](const NonlinearRow& r) { return r.whole_ring(); });
  return t.analysis == "response"
             ? std::string("peak_u: largest |u| over the history (m); t_peak: when it occurs (s)") +
                   (plastic ? "; u_end: |u| at the end (m); dissipated: plastic work (J)" : "")
             : "ux, uy: displacement (m, ring-centred frame); u: its magnitude; dissipated: plastic work (J); "
               "limit_load: the load factor at the path's first limit point; reaction_x, reaction_y: the force at the "
               "driven point at the end (N; with [plates], of the plate at plates.axis); peak_reaction: its largest magnitude "
               "along the path (N); contact_length, contact_length_opposite: on each plate at the end (m)";
}

}  // namespace

NonlinearTable response_table(const std::string& title, const std::vector<ring::TimeHistory>& histories,
                              const ring::TimeHistory* reference) {
  NonlinearTable t;
  t.title = title;
  t.analysis = "response";
  if (histories.empty()) return t;
  for (const auto& h : histories) t.solvers.push_back(h.solver);
  for (std::size_t p = 0; p < histories.front().record_angles.size(); ++p) {
    const double angle = histories.front().record_angles[p];
    NonlinearRow u{angle, "peak_u", {}, {}, std::nullopt, {}}, tp{angle, "t_peak", {}, {}, std::nullopt, {}};
    for (const auto& h : histories) {
      const int i = point_index(h.record_angles, angle);
      const Peak pk = i < 0 ? Peak{NAN, NAN} : peak(h, i);
      u.value.push_back(pk.u);
      tp.value.push_back(pk.t);
    }
    if (reference) {
      const int i = point_index(reference->record_angles, angle);
      const Peak pk = i < 0 ? Peak{NAN, NAN} : peak(*reference, i);
      u.reference = pk.u;
      tp.reference = pk.t;
    }
    t.rows.push_back(u);
    t.rows.push_back(tp);
  }
  // A plastic ring: where each point ends (the residual displacement once the load is gone)
  // and the plastic work done over the history, J.
  const auto plastic = [](const ring::TimeHistory& h) { return !h.dissipated.empty(); };
  if (std::any_of(histories.begin(), histories.end(), plastic) || (reference && plastic(*reference))) {
    const auto end_u = [](const ring::TimeHistory& h, double angle) {
      const int i = point_index(h.record_angles, angle);
      return i < 0 || h.t.empty() ? NAN : std::hypot(h.ux[i].back(), h.uy[i].back());
    };
    for (const double angle : histories.front().record_angles) {
      NonlinearRow e{angle, "u_end", {}, {}, std::nullopt, {}};
      for (const auto& h : histories) e.value.push_back(end_u(h, angle));
      if (reference) e.reference = end_u(*reference, angle);
      t.rows.push_back(e);
    }
    const auto work = [&](const ring::TimeHistory& h) { return plastic(h) ? h.dissipated.back() : NAN; };
    NonlinearRow d{NonlinearRow::kWholeRing, "dissipated", {}, {}, std::nullopt, {}};
    for (const auto& h : histories) d.value.push_back(work(h));
    if (reference) d.reference = work(*reference);
    t.rows.push_back(d);
  }
  fill_relative(t);
  return t;
}

NonlinearTable static_table(const std::string& title, const std::vector<ring::StaticResult>& results,
                            const ring::StaticResult* reference) {
  NonlinearTable t;
  t.title = title;
  t.analysis = "static";
  if (results.empty()) return t;
  for (const auto& r : results) t.solvers.push_back(r.solver);
  auto find = [](const ring::StaticResult& r, double angle) -> const ring::PointDisplacement* {
    for (const auto& d : r.displacements)
      if (std::abs(d.angle - angle) < 1e-9) return &d;
    return nullptr;
  };
  for (const auto& d0 : results.front().displacements) {
    NonlinearRow rows[3] = {{d0.angle, "ux", {}, {}, std::nullopt, {}},
                            {d0.angle, "uy", {}, {}, std::nullopt, {}},
                            {d0.angle, "u", {}, {}, std::nullopt, {}}};
    auto values = [](const ring::PointDisplacement* d) {
      return d ? std::array<double, 3>{d->ux, d->uy, std::hypot(d->ux, d->uy)} : std::array<double, 3>{NAN, NAN, NAN};
    };
    for (const auto& r : results) {
      const auto v = values(find(r, d0.angle));
      for (int q = 0; q < 3; ++q) rows[q].value.push_back(v[q]);
    }
    if (reference) {
      const auto v = values(find(*reference, d0.angle));
      for (int q = 0; q < 3; ++q) rows[q].reference = v[q];
    }
    for (auto& r : rows) t.rows.push_back(r);
  }
  // A plastic ring: the plastic work done along the whole history, J (after unloading, the
  // displacements above are the residual ones).
  const auto dissipates = [](const ring::StaticResult& r) { return r.dissipated > 0.0; };
  if (std::any_of(results.begin(), results.end(), dissipates) || (reference && dissipates(*reference))) {
    NonlinearRow row{NonlinearRow::kWholeRing, "dissipated", {}, {}, std::nullopt, {}};
    for (const auto& r : results) row.value.push_back(r.dissipated);
    if (reference) row.reference = reference->dissipated;
    t.rows.push_back(row);
  }
  // A driven path (static.displacement): the force at the driven point at the end, x and y,
  // and the largest force along the path (a crushing test's peak load), N.
  const auto driven = [](const ring::StaticResult& r) { return r.driven; };
  if (std::any_of(results.begin(), results.end(), driven) || (reference && driven(*reference))) {
    const auto peak = [](const ring::StaticResult& r) {
      double m = std::hypot(r.reaction[0], r.reaction[1]);
      for (const auto& p : r.path) m = std::max(m, std::hypot(p.reaction[0], p.reaction[1]));
      return m;
    };
    // A component below 1e-9 of the peak is round-off (a drive along an axis): 0, so that the
    // table says n/a rather than compare two round-offs.
    const auto component = [peak](int i) {
      return [peak, i](const ring::StaticResult& r) {
        return std::abs(r.reaction[i]) <= 1e-9 * peak(r) ? 0.0 : r.reaction[i];
      };
    };
    using Quantity = std::pair<const char*, std::function<double(const ring::StaticResult&)>>;
    std::vector<Quantity> quantities = {{"reaction_x", component(0)}, {"reaction_y", component(1)}, {"peak_reaction", peak}};
    // [plates]: the contact length on each plate at the end (m).
    const auto plates = [](const ring::StaticResult& r) { return r.plates; };
    if (std::any_of(results.begin(), results.end(), plates) || (reference && plates(*reference))) {
      quantities.push_back({"contact_length", [](const ring::StaticResult& r) { return r.contact_length[0]; }});
      quantities.push_back({"contact_length_opposite", [](const ring::StaticResult& r) { return r.contact_length[1]; }});
    }
    for (const auto& [name, value] : quantities) {
      NonlinearRow row{NonlinearRow::kWholeRing, name, {}, {}, std::nullopt, {}};
      for (const auto& r : results) row.value.push_back(value(r));
      if (reference) row.reference = value(*reference);
      t.rows.push_back(row);
    }
  }
  // A path through a limit point (an arch's snap, a ring's collapse): the first limit load.
  const auto limit = [](const ring::StaticResult& r) { return r.limit_points.empty() ? NAN : r.limit_points.front().load_factor; };
  const auto has_limit = [](const ring::StaticResult& r) { return !r.limit_points.empty(); };
  if (std::any_of(results.begin(), results.end(), has_limit) || (reference && has_limit(*reference))) {
    NonlinearRow row{NonlinearRow::kWholeRing, "limit_load", {}, {}, std::nullopt, {}};
    for (const auto& r : results) row.value.push_back(limit(r));
    if (reference) row.reference = limit(*reference);
    t.rows.push_back(row);
  }
  fill_relative(t);
  return t;
}

std::string format_text(const NonlinearTable& t) {
  std::ostringstream s;
  if (!t.title.empty()) s << t.title << "\n";
  s << (t.analysis == "response" ? "Forced response" : "Nonlinear statics") << " at the recorded points, "
    << units_note(t) << "\n\n"
    << text_grid(cells(t));
  s << "\ndiff % = (" << (t.solvers.empty() ? "base" : t.solvers[0])
    << " - other) / |other| * 100 (the paper's definition)";
  if (t.has_reference()) s << "; error % = (x - reference) / |reference| * 100";
  s << "; n/a where the value compared with is ~0.\n";
  return s.str();
}

std::string format_markdown(const NonlinearTable& t) {
  std::ostringstream s;
  s << markdown_grid(cells(t), 2) << "\n" << units_note(t) << ". diff % = (base - other) / |other| * 100";
  if (t.has_reference()) s << "; error % against the converged reference";
  s << ".\n";
  return s.str();
}

std::string format_csv(const NonlinearTable& t) {
  std::ostringstream s;
  s.precision(17);
  s << "point,quantity";
  for (std::size_t c = 0; c < t.solvers.size(); ++c) {
    s << "," << t.solvers[c];
    if (c > 0) s << "," << t.solvers[c] << "_diff_pct";
    if (t.has_reference()) s << "," << t.solvers[c] << "_error_pct";
  }
  if (t.has_reference()) s << ",reference";
  s << "\n";
  auto num = [](double v) {
    if (!std::isfinite(v)) return std::string();
    std::ostringstream o;
    o.precision(17);
    o << v;
    return o.str();
  };
  for (const auto& r : t.rows) {
    if (r.whole_ring()) s << "ring," << r.quantity;
    else s << r.angle << "," << r.quantity;
    for (std::size_t c = 0; c < r.value.size(); ++c) {
      s << "," << num(r.value[c]);
      if (c > 0) s << "," << num(r.diff_pct[c]);
      if (r.reference) s << "," << num(r.error_pct[c]);
    }
    if (r.reference) s << "," << num(*r.reference);
    s << "\n";
  }
  return s.str();
}

std::string format_json(const NonlinearTable& t) {
  nlohmann::json j;
  j["title"] = t.title;
  j["analysis"] = t.analysis;
  j["base"] = t.solvers.empty() ? "" : t.solvers[0];
  j["rows"] = nlohmann::json::array();
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  for (const auto& r : t.rows) {
    nlohmann::json row;
    if (r.whole_ring()) row["point"] = "ring";
    else row["point"] = r.angle;
    row["quantity"] = r.quantity;
    for (std::size_t c = 0; c < r.value.size(); ++c) {
      row[t.solvers[c]] = num(r.value[c]);
      if (c > 0) row[t.solvers[c] + "_diff_pct"] = num(r.diff_pct[c]);
      if (r.reference) row[t.solvers[c] + "_error_pct"] = num(r.error_pct[c]);
    }
    if (r.reference) row["reference"] = num(*r.reference);
    j["rows"].push_back(row);
  }
  return j.dump(2) + "\n";
}

void plot_histories(const std::string& dir, const std::vector<ring::TimeHistory>& histories, const ring::RingSpec& ring) {
  std::vector<Series> series;
  for (std::size_t s = 0; s < histories.size(); ++s) {
    const auto& h = histories[s];
    for (std::size_t p = 0; p < h.record_angles.size(); ++p) {
      Series x{h.solver + ": |u| at " + sig4(h.record_angles[p]) + " deg", h.t, {}, static_cast<int>(p), 1 + static_cast<int>(s % 4)};
      double largest = 0.0;
      for (std::size_t k = 0; k < h.t.size(); ++k) {
        x.y.push_back(std::hypot(h.ux[p][k], h.uy[p][k]));
        largest = std::max(largest, x.y.back());
      }
      if (largest > 0.0) series.push_back(x);  // the pin does not move
    }
  }
  plot_series(dir, "response_history", "Forced response, |u| of the recorded points (solid: the base solver; dashed, dotted: the others in order)", "t (s)",
              "|displacement| (m)", series);
  std::vector<Series> shapes = {undeformed_ring(ring)};
  for (std::size_t s = 0; s < histories.size(); ++s) {
    const auto& h = histories[s];
    for (std::size_t k = 0; k < h.snapshot_t.size(); ++k)
      shapes.push_back(deformed_line(h.solver + ", t = " + sig4(h.snapshot_t[k]) + " s", h.snapshot_x[k], h.snapshot_y[k],
                                     ring, static_cast<int>(k), 1 + static_cast<int>(s % 4)));
  }
  if (shapes.size() > 1)
    plot_series(dir, "response_shapes", "Deformed ring at several instants (solid: the base solver; dashed, dotted, dash-dotted: the others in order)",
                "x (m)", "y (m)", shapes, false, false, true);
}

void plot_static_shapes(const std::string& dir, const std::vector<ring::StaticResult>& results, const ring::RingSpec& ring) {
  std::vector<Series> shapes = {undeformed_ring(ring)};
  for (std::size_t s = 0; s < results.size(); ++s)
    if (!results[s].node_x.empty())
      shapes.push_back(deformed_line(results[s].solver, results[s].node_x, results[s].node_y, ring, static_cast<int>(s)));
  if (shapes.size() > 1)
    plot_series(dir, "static_shapes", "Deformed ring under the static load, every solver", "x (m)", "y (m)", shapes,
                false, false, true);
}

}  // namespace cmp
