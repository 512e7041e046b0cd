#include "compare/buckling.hpp"

#include <fmt/format.h>

#include <cmath>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "compare/output.hpp"
#include "compare/registry.hpp"
#include "ring/errors.hpp"

namespace cmp {

BucklingRun run_buckling(const ring::Scene& scene, const std::string& only, std::ostream* progress) {
  BucklingRun run;
  if (!scene.buckling) return run;
  std::vector<std::string> names;
  for (const auto& name : scene.buckling_request.solvers)
    if (only.empty() || name == only) names.push_back(name);
  if (!only.empty() && names.empty()) names.push_back(only);
  for (const auto& name : names) {
    const SolverEntry& e = solver(name);
    if (!e.buckling)
      throw ring::InputError(scene.file, "buckling.solvers",
                             "the " + name + " solver has no buckling" +
                                 (e.no_buckling_because.empty() ? "" : ": " + e.no_buckling_because));
    if (progress) *progress << "ringvib: linear buckling with " << name << "\n";
    run.results.push_back(e.buckling(scene));
  }
  if (scene.buckling_request.reference && only.empty()) {
    if (progress) *progress << "ringvib: the converged reference buckling\n";
    run.reference = reference_buckling(scene);
  }
  return run;
}

ring::ModalResult as_modal(const ring::BucklingResult& b) {
  ring::ModalResult m;
  m.solver = b.solver;
  m.model = b.model;
  m.omega = b.factors;
  m.shapes = b.shapes;
  m.unknowns = b.unknowns;
  m.seconds = b.seconds;
  m.error_estimate = b.error_estimate;
  return m;
}

Table buckling_table(const ring::Scene& scene, const BucklingRun& run) {
  std::vector<ring::ModalResult> columns;
  for (const auto& r : run.results) columns.push_back(as_modal(r));
  const std::optional<ring::ModalResult> ref =
      run.reference ? std::optional<ring::ModalResult>(as_modal(*run.reference)) : std::nullopt;
  Table t = build_table(scene.title.empty() ? "Linear buckling" : scene.title + ": linear buckling", columns,
                        ref ? &*ref : nullptr, scene.buckling->count);
  t.unit = "Critical load factors lambda (lambda = 1: the loads as given)";
  return t;
}

namespace {

/// The uniform pressure, when it is the only load.
std::optional<ring::Pressure> pressure_alone(const ring::Loads& loads) {
  if (!loads.points.empty() || loads.has_gravity() || !loads.pressure.any()) return std::nullopt;
  return loads.pressure;
}

}  // namespace

std::string buckling_text(const ring::Scene& scene, const ring::BucklingResult& r) {
  std::ostringstream s;
  s << r.solver << ":";
  for (const auto& [k, v] : r.model) s << " " << k << "=" << model_value(v);
  const auto p = pressure_alone(scene.buckling->loads);
  const double unit = scene.ring.EI() / std::pow(scene.ring.radius, 3);
  s << "\n\n  mode        lambda";
  if (p) s << "   p_cr N/m   p_cr R^3/EI";
  s << "\n";
  for (std::size_t i = 0; i < r.factors.size(); ++i) {
    s << fmt::format("  {:4d}  {:>12}", i + 1, sig4(r.factors[i]));
    if (p) s << fmt::format("  {:>9}  {:>12}", sig4(r.factors[i] * p->value), sig4(r.factors[i] * p->value / unit));
    s << "\n";
  }
  s << fmt::format("\n{} unknowns, solved in {:.3g} s\n", r.unknowns, r.seconds);
  if (p)
    s << "closed forms of the inextensible ring, p_cr R^3/EI: follower 3, central 4.5, dead 4 (free) or 3.271 on a pin "
         "and a roller opposite (ring/closed_form.hpp)\n";
  return s.str();
}

std::string buckling_json(const ring::BucklingResult& r) {
  nlohmann::json j;
  j["solver"] = r.solver;
  for (const auto& kv : r.model) std::visit([&](const auto& x) { j["model"][kv.first] = x; }, kv.second);
  j["factors"] = r.factors;
  j["unknowns"] = r.unknowns;
  j["seconds"] = r.seconds;
  if (r.error_estimate > 0.0) j["error_estimate"] = r.error_estimate;
  return j.dump(2) + "\n";
}

}  // namespace cmp
