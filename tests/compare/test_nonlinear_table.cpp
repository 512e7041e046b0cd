// The nonlinear comparison's arithmetic and gates, on histories and equilibria built by
// hand: peaks of known closed-form signals, the paper's difference, errors against a
// reference, the pinned point left out, and gates bounding |error| (a large negative
// error fails).
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "compare/gates.hpp"
#include "compare/nonlinear.hpp"
#include "compare/registry.hpp"
#include "ring/errors.hpp"

namespace {

/// A history of two recorded points: the loaded one moves as a (1 - cos) step response
/// of amplitude `a` and angular frequency `w` (peak 2a at t = pi/w), the pin not at all.
ring::TimeHistory step_response(const std::string& solver, double a, double w) {
  ring::TimeHistory h;
  h.solver = solver;
  h.record_angles = {0.0, 180.0};
  h.ux.resize(2);
  h.uy.resize(2);
  for (int k = 0; k <= 2000; ++k) {
    const double t = k * 1e-3;
    h.t.push_back(t);
    h.ux[0].push_back(-a * (1.0 - std::cos(w * t)) * 0.6);
    h.uy[0].push_back(a * (1.0 - std::cos(w * t)) * 0.8);
    h.ux[1].push_back(0.0);
    h.uy[1].push_back(0.0);
  }
  return h;
}

ring::StaticResult equilibrium(const std::string& solver, double ux, double uy) {
  ring::StaticResult r;
  r.solver = solver;
  r.displacements = {{0.0, ux, uy}, {180.0, 0.0, 0.0}};
  return r;
}

const cmp::NonlinearRow& row(const cmp::NonlinearTable& t, double angle, const std::string& q) {
  for (const auto& r : t.rows)
    if (r.angle == angle && r.quantity == q) return r;
  throw std::runtime_error("no row " + q);
}

// Oracle: 1 - cos(w t) peaks at 2 at t = pi / w; |(-0.6, 0.8)| = 1. The time grid
// (1 ms) bounds the sampled peak time to within half a step of pi / w.
TEST(NonlinearTable, PeaksOfAKnownSignal) {
  const auto t = cmp::response_table("t", {step_response("multibody", 1.5, 2.0)}, nullptr);
  EXPECT_NEAR(row(t, 0.0, "peak_u").value[0], 3.0, 1e-6);
  EXPECT_NEAR(row(t, 0.0, "t_peak").value[0], M_PI / 2.0, 0.5e-3);
  EXPECT_EQ(row(t, 180.0, "peak_u").value[0], 0.0);
}

// Oracle: the paper's definition (base - other) / |other| * 100 and the error
// (x - ref) / |ref| * 100, evaluated by hand on the peaks 2a.
TEST(NonlinearTable, DifferencesAndErrorsFollowTheirDefinitions) {
  const auto mb = step_response("multibody", 1.0, 2.0), lm = step_response("lumped", 1.1, 2.0);
  const auto ref = step_response("reference", 1.05, 2.0);
  const auto t = cmp::response_table("t", {mb, lm}, &ref);
  const auto& r = row(t, 0.0, "peak_u");
  EXPECT_NEAR(r.diff_pct[1], (2.0 - 2.2) / 2.2 * 100.0, 1e-9);
  EXPECT_NEAR(r.error_pct[0], (2.0 - 2.1) / 2.1 * 100.0, 1e-9);
  EXPECT_NEAR(r.error_pct[1], (2.2 - 2.1) / 2.1 * 100.0, 1e-9);
  // The pin does not move: no relative value there.
  EXPECT_TRUE(std::isnan(row(t, 180.0, "peak_u").error_pct[0]));
  const auto j = nlohmann::json::parse(cmp::format_json(t));
  EXPECT_EQ(j["analysis"], "response");
  EXPECT_EQ(j["base"], "multibody");
  EXPECT_TRUE(j["rows"][0].contains("lumped_diff_pct"));
  EXPECT_TRUE(j["rows"][0].contains("multibody_error_pct"));
  EXPECT_TRUE(j["rows"][2]["multibody_error_pct"].is_null());  // the pin
}

// A plastic response: where each point ends (|u| at the last step, the residual once the
// load is gone) and the plastic work at the end; an elastic history beside it has no work
// (an empty cell). Oracle: 1 - cos(w t) at t = 2 s, w = 2, times a; the works by hand.
TEST(NonlinearTable, APlasticResponseAddsTheEndDisplacementAndThePlasticWork) {
  auto mb = step_response("multibody", 1.0, 2.0), lm = step_response("lumped", 1.1, 2.0);
  mb.dissipated.assign(mb.t.size(), 0.0);
  mb.dissipated.back() = 3.0;
  const auto elastic = step_response("fem", 1.0, 2.0);
  const auto t = cmp::response_table("t", {mb, lm, elastic}, nullptr);
  EXPECT_NEAR(row(t, 0.0, "u_end").value[0], 1.0 * (1.0 - std::cos(4.0)), 1e-12);
  EXPECT_NEAR(row(t, 0.0, "u_end").value[1], 1.1 * (1.0 - std::cos(4.0)), 1e-12);
  const auto& d = row(t, cmp::NonlinearRow::kWholeRing, "dissipated");
  EXPECT_EQ(d.value[0], 3.0);
  EXPECT_TRUE(std::isnan(d.value[1]) && std::isnan(d.value[2]));
  EXPECT_NE(cmp::format_text(t).find("dissipated: plastic work (J)"), std::string::npos);
  // An elastic comparison has neither row.
  const auto plain = cmp::response_table("t", {step_response("multibody", 1.0, 2.0)}, nullptr);
  for (const auto& r : plain.rows) EXPECT_TRUE(r.quantity == "peak_u" || r.quantity == "t_peak") << r.quantity;
}

// Oracle: |u| = hypot(ux, uy) = 5 for (3, 4); errors by hand.
TEST(NonlinearTable, StaticsCompareComponentsAndMagnitude) {
  const auto ref = equilibrium("reference", -3.0, 4.0);
  const auto t = cmp::static_table("t", {equilibrium("multibody", -3.3, 4.0)}, &ref);
  EXPECT_DOUBLE_EQ(row(t, 0.0, "u").value[0], std::hypot(3.3, 4.0));
  EXPECT_NEAR(row(t, 0.0, "ux").error_pct[0], (-3.3 + 3.0) / 3.0 * 100.0, 1e-12);
  EXPECT_NEAR(row(t, 0.0, "uy").error_pct[0], 0.0, 1e-12);
}

// A gate bounds |error|: -10 % fails a 5 % gate, the pin is not evaluated, a gate
// against another solver uses (solver - other) / |other|.
TEST(NonlinearGates, BoundAbsoluteErrorsAtMovingPoints) {
  const auto ref = step_response("reference", 1.0, 2.0);
  const auto t = cmp::response_table("t", {step_response("multibody", 0.9, 2.0), step_response("lumped", 0.95, 2.0)},
                                     &ref);
  ring::Gate g;
  g.solver = "multibody";
  g.analysis = "response";
  g.max_pct = 5.0;
  auto r = cmp::evaluate_nonlinear_gates({g}, t);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].pass);
  EXPECT_NEAR(r[0].worst_pct, 10.0, 1e-9);
  EXPECT_EQ(r[0].worst_point, 0.0);
  g.max_pct = 10.5;
  EXPECT_TRUE(cmp::evaluate_nonlinear_gates({g}, t)[0].pass);
  g.against = "lumped";
  g.max_pct = 5.3;  // |1.8 - 1.9| / 1.9 = 5.26 %
  r = cmp::evaluate_nonlinear_gates({g}, t);
  EXPECT_NEAR(r[0].worst_pct, std::abs(0.9 - 0.95) / 0.95 * 100.0, 1e-9);
  EXPECT_TRUE(r[0].pass);
  // A modal gate is not a response gate.
  g.analysis = "modes";
  EXPECT_TRUE(cmp::evaluate_nonlinear_gates({g}, t).empty());
}

// The registry is the one list of solvers: the scene schema, the names and the entries
// agree, each entry's analyses are callable, and an unknown name is an input error.
TEST(Registry, OneListOfSolvers) {
  const auto names = cmp::solver_names();
  ASSERT_FALSE(names.empty());
  const auto& schema = cmp::scene_schema();
  ASSERT_EQ(schema.solvers.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(schema.solvers[i].name, names[i]);
    const auto& e = cmp::solver(names[i]);
    EXPECT_TRUE(e.modes) << names[i];
    EXPECT_EQ(schema.solvers[i].statics, bool(e.statics)) << names[i];
    EXPECT_EQ(schema.solvers[i].response, bool(e.response)) << names[i];
  }
  EXPECT_NE(schema.find(schema.default_solver), nullptr);
  EXPECT_NE(schema.find(schema.reference_solver), nullptr);
  EXPECT_THROW(cmp::solver("sap5"), ring::InputError);
}

}  // namespace
