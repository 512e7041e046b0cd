#include "compare/response.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "compare/output.hpp"
#include "compare/plot.hpp"
#include "ring/errors.hpp"

namespace cmp {

namespace {
std::string deg_label(double a) {
  std::ostringstream s;
  s << a;
  return s.str();
}
}  // namespace

std::string history_csv(const ring::TimeHistory& h) {
  std::ostringstream s;
  s.precision(12);
  s << "t";
  for (double a : h.record_angles) s << ",ux_" << deg_label(a) << ",uy_" << deg_label(a);
  // A plastic ring's plastic work (J) after the energies; `strain` is then the elastic part.
  const bool plastic = !h.dissipated.empty();
  s << ",kinetic,strain," << (plastic ? "dissipated," : "") << "work,energy_error,constraint_residual,newton_iterations\n";
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    s << h.t[k];
    for (std::size_t p = 0; p < h.record_angles.size(); ++p) s << "," << h.ux[p][k] << "," << h.uy[p][k];
    s << "," << h.kinetic[k] << "," << h.strain[k] << ",";
    if (plastic) s << h.dissipated[k] << ",";
    s << h.work[k] << "," << h.energy_error[k] << "," << h.constraint_residual[k] << "," << h.newton_iterations[k]
      << "\n";
  }
  return s.str();
}

namespace {
nlohmann::json displacements_json(const std::vector<ring::PointDisplacement>& v) {
  nlohmann::json d = nlohmann::json::array();
  for (const auto& x : v) d.push_back({{"angle", x.angle}, {"ux", x.ux}, {"uy", x.uy}});
  return d;
}
}  // namespace

std::string static_json(const ring::StaticResult& r) {
  nlohmann::json j;
  j["displacements"] = displacements_json(r.displacements);
  j["steps"] = r.steps;
  j["newton_iterations"] = r.newton_iterations;
  j["solver"] = r.solver;
  j["unknowns"] = r.unknowns;
  j["seconds"] = r.seconds;
  if (!r.path.empty()) {
    j["end"] = r.end;
    j["end_load"] = r.end_load;
    j["branch_points"] = r.branch_points;
    j["limit_points"] = nlohmann::json::array();
    for (const auto& p : r.limit_points) {
      j["limit_points"].push_back({{"load_factor", p.load_factor}, {"displacements", displacements_json(p.displacements)}});
      if (r.driven) j["limit_points"].back()["reaction"] = p.reaction;
      if (r.plates) j["limit_points"].back()["contact_length"] = p.contact_length;
    }
    j["path_points"] = r.path.size();
    // Every accepted equilibrium: the load factor, the recorded points' displacements and,
    // for a plastic ring, the plastic work done so far and the largest plastic curvature.
    j["path"] = nlohmann::json::array();
    for (const auto& p : r.path) {
      j["path"].push_back({{"load_factor", p.load_factor},
                           {"displacements", displacements_json(p.displacements)},
                           {"ovalisation", p.ovalisation},
                           {"dissipated", p.dissipated},
                           {"plastic_curvature", p.plastic_curvature}});
      if (r.driven) j["path"].back()["reaction"] = p.reaction;
      if (r.plates) j["path"].back()["contact_length"] = p.contact_length;
    }
  }
  j["dissipated"] = r.dissipated;
  j["plastic_curvature"] = r.plastic_curvature;
  // static.displacement: the force [Fx, Fy] (N) the ring needs at the driven point; [plates]:
  // the force of the plate at plates.axis, and the contact length on each plate (m).
  if (r.driven) j["reaction"] = r.reaction;
  if (r.plates) j["contact_length"] = r.contact_length;
  return j.dump(2) + "\n";
}

std::string static_text(const ring::StaticResult& r) {
  std::ostringstream s;
  s << (r.solver.empty() ? "" : r.solver + ": ") << "static equilibrium after " << r.steps << " load steps, " << r.newton_iterations << " Newton iterations\n";
  if (!r.path.empty()) {
    const std::string line = path_summary({r});
    s << "path: " << line.substr(line.find(": ") + 2)
      << (r.end == "full load" ? "at the full load:\n" : r.end == "end of the history" ? "at its end:\n" : "at the touch:\n");
  }
  s << "   angle deg        ux m        uy m\n";
  for (const auto& d : r.displacements) s << fmt::format("  {:10.4g}  {:10.4e}  {:10.4e}\n", d.angle, d.ux, d.uy);
  if (r.plates)
    s << fmt::format("force of the plate at plates.axis: Fx {:.6e} N, Fy {:.6e} N; contact lengths {:.6e} m, {:.6e} m\n",
                     r.reaction[0], r.reaction[1], r.contact_length[0], r.contact_length[1]);
  else if (r.driven)
    s << fmt::format("reaction at the driven point: Fx {:.6e} N, Fy {:.6e} N\n", r.reaction[0], r.reaction[1]);
  return s.str();
}

std::string path_summary(const std::vector<ring::StaticResult>& results) {
  std::ostringstream s;
  for (const auto& r : results) {
    if (r.path.empty()) continue;
    s << r.solver << ": " << r.path.size() << " equilibria from rest";
    for (const auto& l : r.limit_points) s << "; a limit point at load factor " << sig4(l.load_factor);
    for (double b : r.branch_points) s << "; onto a branch at load factor " << sig4(b);
    s << "; ended at load factor " << fmt::format("{:.6g}", r.end_load) << ": " << r.end << "\n";
  }
  return s.str();
}

std::string static_path_csv(const ring::StaticResult& r) {
  std::ostringstream s;
  s.precision(12);
  s << "load_factor,ovalisation";
  if (!r.path.empty())
    for (const auto& d : r.path.front().displacements) s << ",ux_" << deg_label(d.angle) << ",uy_" << deg_label(d.angle);
  s << ",dissipated,plastic_curvature" << (r.driven ? ",reaction_x,reaction_y" : "")
    << (r.plates ? ",contact_length,contact_length_opposite" : "") << "\n";
  for (const auto& p : r.path) {
    s << p.load_factor << "," << p.ovalisation;
    for (const auto& d : p.displacements) s << "," << d.ux << "," << d.uy;
    // A value the solver does not report (ccx's plastic work: NaN) is an empty cell.
    for (double v : {p.dissipated, p.plastic_curvature}) {
      s << ",";
      if (std::isfinite(v)) s << v;
    }
    if (r.driven) s << "," << p.reaction[0] << "," << p.reaction[1];
    if (r.plates) s << "," << p.contact_length[0] << "," << p.contact_length[1];
    s << "\n";
  }
  return s.str();
}

namespace {

/// A driven path (static.displacement = `drive` at load factor 1) drawn as a test machine
/// draws it: the reaction's component along the drive against the driven point's travel.
void plot_driven_paths(const std::string& dir, const std::string& name, const std::vector<ring::StaticResult>& results,
                       const std::array<double, 2>& drive) {
  const double length = std::hypot(drive[0], drive[1]);
  std::vector<Series> series;
  for (const auto& r : results) {
    Series x{r.solver, {}, {}};
    for (const auto& p : r.path) {
      x.x.push_back(p.load_factor * length);
      x.y.push_back((p.reaction[0] * drive[0] + p.reaction[1] * drive[1]) / length);
    }
    if (!x.x.empty()) series.push_back(x);
  }
  if (!results.empty() && results.front().plates)
    plot_series(dir, name, "Crushed between plates: the force on a plate against the plates' approach",
                "approach of the plates (m)", "force on each plate (N)", series);
  else
    plot_series(dir, name, "Driven path: the force at the driven point against its travel",
                "travel of the driven point along static.displacement.value (m)", "reaction along it (N)", series);
}

}  // namespace

void plot_static_paths(const std::string& dir, const std::vector<ring::StaticResult>& results, const ring::RingSpec& ring,
                       const std::optional<std::array<double, 2>>& drive) {
  if (drive) return plot_driven_paths(dir, "static_path", results, *drive);
  std::vector<Series> series;
  if (!ring.arc) {
    for (const auto& r : results) {
      if (r.path.empty()) continue;
      Series x{r.solver, {}, {}};
      for (const auto& p : r.path) {
        x.x.push_back(p.ovalisation);
        x.y.push_back(p.load_factor);
      }
      series.push_back(x);
    }
    plot_series(dir, "static_path", "Equilibrium paths: load factor against ovalisation", "(largest - smallest diameter) / R",
                "load factor", series);
    return;
  }
  // An arch: the load factor against both displacements of the first recorded point (the
  // loaded point, as DaDeppo & Schmidt and Simo & Vu-Quoc draw the deep arch).
  double angle = 0.0;
  for (std::size_t s = 0; s < results.size(); ++s) {
    const auto& r = results[s];
    if (r.path.empty() || r.path.front().displacements.empty()) continue;
    angle = r.path.front().displacements[0].angle;
    Series x{r.solver + ": ux", {}, {}, static_cast<int>(s), 2}, y{r.solver + ": uy", {}, {}, static_cast<int>(s), 1};
    for (const auto& p : r.path) {
      x.x.push_back(p.displacements[0].ux);
      y.x.push_back(p.displacements[0].uy);
      x.y.push_back(p.load_factor);
      y.y.push_back(p.load_factor);
    }
    series.push_back(y);
    series.push_back(x);
  }
  plot_series(dir, "static_path", "Equilibrium paths: load factor against the displacement of the first recorded point",
              "displacement at " + deg_label(angle) + " deg (m)", "load factor", series);
}

void plot_static_history(const std::string& dir, const std::vector<ring::StaticResult>& results,
                         const std::optional<std::array<double, 2>>& drive) {
  if (drive) return plot_driven_paths(dir, "static_history", results, *drive);
  if (results.empty() || results.front().path.empty() || results.front().path.front().displacements.empty()) return;
  // The component of the first recorded point that moves most along the first path.
  double range[2] = {0.0, 0.0};
  for (const auto& p : results.front().path) {
    range[0] = std::max(range[0], std::abs(p.displacements.front().ux));
    range[1] = std::max(range[1], std::abs(p.displacements.front().uy));
  }
  const bool y = range[1] >= range[0];
  const double angle = results.front().path.front().displacements.front().angle;
  std::vector<Series> series;
  for (const auto& r : results) {
    Series x{r.solver, {}, {}};
    for (const auto& p : r.path) {
      if (p.displacements.empty()) continue;
      x.x.push_back(y ? p.displacements.front().uy : p.displacements.front().ux);
      x.y.push_back(p.load_factor);
    }
    if (!x.x.empty()) series.push_back(x);
  }
  plot_series(dir, "static_history", "Load history: load factor against displacement",
              std::string(y ? "uy" : "ux") + " at " + deg_label(angle) + " deg, m", "load factor", series);
}

void plot_path_shapes(const std::string& dir, const ring::StaticResult& r, const ring::RingSpec& ring) {
  if (r.path.empty()) return;
  // Five equilibria, nearest to 0, 1/4, ..., 1 of the path's largest ovalisation (a ring) or
  // displacement of the first recorded point (an arch, which has no opposite points).
  const auto progress = [&](const ring::PathPoint& p) {
    if (!ring.arc) return p.ovalisation;
    return p.displacements.empty() ? 0.0 : std::hypot(p.displacements[0].ux, p.displacements[0].uy);
  };
  double most = 0.0;
  for (const auto& p : r.path) most = std::max(most, progress(p));
  std::vector<std::size_t> chosen;
  for (int i = 0; i <= 4; ++i) {
    const double target = most * i / 4.0;
    std::size_t best = 0;
    for (std::size_t k = 1; k < r.path.size(); ++k)
      if (std::abs(progress(r.path[k]) - target) < std::abs(progress(r.path[best]) - target)) best = k;
    if (std::find(chosen.begin(), chosen.end(), best) == chosen.end()) chosen.push_back(best);
  }
  std::vector<Series> series;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const ring::PathPoint& p = r.path[chosen[i]];
    if (p.node_x.empty()) continue;
    series.push_back(deformed_line("load factor " + fmt::format("{:.4g}", p.load_factor) +
                                       (ring.arc ? "" : ", ovalisation " + fmt::format("{:.3f}", p.ovalisation)),
                                   p.node_x, p.node_y, ring, static_cast<int>(i)));
  }
  if (series.empty()) return;
  plot_series(dir, "static_path_shapes", r.solver + ": the ring along its equilibrium path", "x (m)", "y (m)", series,
              false, false, true);
}

void plot_response(const std::string& dir, const ring::TimeHistory& h, const ring::RingSpec& ring) {
  std::vector<Series> series;
  for (std::size_t p = 0; p < h.record_angles.size(); ++p) {
    const int color = static_cast<int>(p);
    series.push_back({"u_x at " + deg_label(h.record_angles[p]) + " deg", h.t, h.ux[p], color, 1});
    series.push_back({"u_y at " + deg_label(h.record_angles[p]) + " deg", h.t, h.uy[p], color, 2});
  }
  plot_series(dir, "response_history", "Forced response: displacements of the recorded points", "t (s)",
              "displacement (m)", series);
  if (h.snapshot_t.empty()) return;
  // Deformed ring at the snapshots, node positions (the paper's Figure 5 shows one half;
  // for its symmetric load the other half is the mirror image).
  std::vector<Series> shapes = {undeformed_ring(ring)};
  for (std::size_t k = 0; k < h.snapshot_t.size(); ++k)
    shapes.push_back(deformed_line("t = " + sig4(h.snapshot_t[k]) + " s", h.snapshot_x[k], h.snapshot_y[k], ring));
  plot_series(dir, "response_shapes", "Deformed ring at several instants (node positions)", "x (m)", "y (m)", shapes,
              false, false, true);
}

}  // namespace cmp
