// The table's arithmetic, MAC pairing and gates, on results constructed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/gates.hpp"
#include "compare/output.hpp"
#include "compare/registry.hpp"
#include "compare/table.hpp"
#include "modal/modes.hpp"
#include "ring/errors.hpp"
#include "ring/sampling.hpp"

namespace {

/// A result whose mode k (1-based) has the radial shape cos((k+1) a), so that different
/// modes are orthogonal at the stations (MAC 0) and equal modes have MAC 1.
ring::ModalResult fake(const std::string& solver, const std::vector<double>& omega, const std::vector<int>& wave) {
  ring::ModalResult r;
  r.solver = solver;
  r.omega = omega;
  for (int w : wave) {
    ring::ModeShape s;
    for (int i = 0; i < ring::kStations; ++i) {
      const double a = ring::station_angle(i) * M_PI / 180.0;
      s.radial.push_back(std::cos(w * a));
      s.tangential.push_back(-std::sin(w * a) / w);
    }
    r.shapes.push_back(s);
  }
  return r;
}

// Oracle: the paper's definition, difference = (base - other) / other * 100, and error
// = (x - ref) / ref * 100, evaluated here by hand.
TEST(Table, DifferencesFollowThePapersDefinition) {
  const auto base = fake("multibody", {2.0, 4.0}, {2, 3});
  const auto other = fake("lumped", {2.5, 3.0}, {2, 3});
  const auto ref = fake("reference", {2.2, 3.5}, {2, 3});
  const cmp::Table t = cmp::build_table("t", {base, other}, &ref, 2);
  EXPECT_DOUBLE_EQ(t.columns[1].diff_pct[0], (2.0 - 2.5) / 2.5 * 100.0);
  EXPECT_DOUBLE_EQ(t.columns[1].diff_pct[1], (4.0 - 3.0) / 3.0 * 100.0);
  EXPECT_DOUBLE_EQ(t.columns[0].error_pct[1], (4.0 - 3.5) / 3.5 * 100.0);
  EXPECT_DOUBLE_EQ(t.columns[1].error_pct[0], (2.5 - 2.2) / 2.2 * 100.0);
}

// Oracle: shapes built with known wave numbers; the other solver lists them in the
// opposite order, so pairing by order would difference unlike modes.
TEST(Table, PairsByMacNotByOrder) {
  const auto base = fake("multibody", {2.0, 2.1}, {2, 3});
  const auto other = fake("fem", {2.05, 2.02}, {3, 2});
  const auto p = cmp::pair_by_mac(base, other);
  EXPECT_EQ(p[0], 1);
  EXPECT_EQ(p[1], 0);
  const cmp::Table t = cmp::build_table("t", {base, other}, nullptr, 2);
  EXPECT_EQ(t.columns[1].omega[0], 2.02);
  EXPECT_EQ(t.columns[1].mode[0], 2);
  EXPECT_NEAR(t.columns[1].mac[0], 1.0, 1e-12);
  EXPECT_NE(cmp::format_text(t).find("2.020*"), std::string::npos) << cmp::format_text(t);
}

/// A result of modes with radial shapes cos(w (a - phase)), one per (w, phase) (radians).
ring::ModalResult waves(const std::string& solver, const std::vector<double>& omega,
                        const std::vector<std::pair<int, double>>& modes) {
  ring::ModalResult r;
  r.solver = solver;
  r.omega = omega;
  for (const auto& [w, phase] : modes) {
    ring::ModeShape s;
    for (int i = 0; i < ring::kStations; ++i) {
      const double a = ring::station_angle(i) * M_PI / 180.0 - phase;
      s.radial.push_back(std::cos(w * a));
      s.tangential.push_back(-std::sin(w * a) / w);
    }
    r.shapes.push_back(s);
  }
  return r;
}

// Oracle: plane geometry. A double frequency's two modes are any basis of their plane:
// the base returns cos 2a, sin 2a, the other solver the same plane turned by 20 deg.
// Member by member the MAC is cos^2(2 x 20 deg) = 0.587 (what the free ring showed:
// "Lowest MAC 0.5012" for frequencies equal to 1e-12); as a subspace the angle between
// each base mode and the other's plane is 0: MAC 1 (to round-off, 1e-12). A pair split
// by 1e-3 (a pinned ring's) is two modes, compared member by member.
TEST(Table, DoubleFrequenciesArePairedAsSubspaces) {
  const double turn = 20.0 * M_PI / 180.0, quarter = M_PI / 4.0;
  const auto base = waves("multibody", {2.0, 2.0, 3.0}, {{2, 0.0}, {2, quarter}, {3, 0.0}});
  const auto other = waves("lumped", {2.1, 2.1 * (1 + 1e-12), 3.1}, {{2, turn}, {2, turn + quarter}, {3, 0.0}});
  EXPECT_NEAR(ring::mac(base.shapes[0], other.shapes[0]), std::pow(std::cos(2 * turn), 2), 1e-12);
  const cmp::Pairing p = cmp::pair_modes(base, other);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(p.mode[i], i);
    EXPECT_NEAR(p.mac[i], 1.0, 1e-12);
    EXPECT_TRUE(p.subspace[i]);
  }
  EXPECT_EQ(p.mode[2], 2);
  EXPECT_FALSE(p.subspace[2]);
  const cmp::Table t = cmp::build_table("t", {base, other}, nullptr, 3);
  const std::string text = cmp::format_text(t);
  EXPECT_NE(text.find("Lowest MAC of any paired mode: 1.000"), std::string::npos) << text;
  EXPECT_NE(text.find("2.100="), std::string::npos) << text;

  const auto split = waves("lumped", {2.1, 2.1 * (1 + 1e-3), 3.1}, {{2, turn}, {2, turn + quarter}, {3, 0.0}});
  const cmp::Pairing q = cmp::pair_modes(base, split);
  EXPECT_FALSE(q.subspace[0]);
  EXPECT_NEAR(q.mac[0], std::pow(std::cos(2 * turn), 2), 1e-12);
}

// Oracle: the paper prints 4 significant digits: 2.463, 11.30, 101.5, 232.5.
TEST(Table, FourSignificantDigitsLikeThePaper) {
  EXPECT_EQ(cmp::sig4(2.46312), "2.463");
  EXPECT_EQ(cmp::sig4(11.3), "11.30");
  EXPECT_EQ(cmp::sig4(101.54), "101.5");
  EXPECT_EQ(cmp::sig4(9.99996), "10.00");
  EXPECT_EQ(cmp::sig4(1234.6), "1235");
  EXPECT_EQ(cmp::pct2(-0.004), "0.00");
}

// Oracle: a gate bounds |error|: a large negative error must fail (STYLE.md, "avoid").
TEST(Gates, NegativeErrorsFailToo) {
  const auto base = fake("multibody", {1.0, 2.0}, {2, 3});
  const auto ref = fake("reference", {1.0, 2.5}, {2, 3});  // mode 2 is 20 % low
  const cmp::Table t = cmp::build_table("t", {base}, &ref, 2);
  ring::Gate g;
  g.solver = "multibody";
  g.max_pct = 5.0;
  g.last_mode = 0;
  const auto r = cmp::evaluate_gates({g}, t);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].pass);
  EXPECT_EQ(r[0].worst_mode, 2);
  EXPECT_DOUBLE_EQ(r[0].worst_pct, 20.0);
  g.last_mode = 1;
  EXPECT_TRUE(cmp::evaluate_gates({g}, t)[0].pass);
  const std::string xml = cmp::junit_xml("a <b> & \"c\"", cmp::evaluate_gates({g}, t));
  EXPECT_NE(xml.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
}

TEST(Gates, NanFails) {
  const auto base = fake("multibody", {NAN}, {2});
  const auto ref = fake("reference", {1.0}, {2});
  const cmp::Table t = cmp::build_table("t", {base}, &ref, 1);
  ring::Gate g;
  g.solver = "multibody";
  g.max_pct = 5.0;
  EXPECT_FALSE(cmp::evaluate_gates({g}, t)[0].pass);
}

// Oracle: the shipped copy of Table 1 has the paper's 23 modes and the corrections of
// docs/paper.md ("Corrections"): mode 2 MB 3.798, mode 3 FE 8.967, mode 8 MB 35.75.
TEST(Table, EmbeddedPaperTable) {
  const auto rows = cmp::paper_table();
  ASSERT_EQ(rows.size(), 23u);
  EXPECT_EQ(*rows[1].mb_corrected, 3.798);
  EXPECT_EQ(*rows[2].fe_corrected, 8.967);
  EXPECT_EQ(*rows[7].mb_corrected, 35.75);
  EXPECT_FALSE(rows[22].lm_corrected.has_value());
}

}  // namespace

namespace {

// A pairing of unlike shapes (orthogonal at the stations: MAC 0) is marked in the table
// itself, not only in a footnote.
TEST(Table, WeakPairingsAreMarkedInTheTable) {
  const auto base = fake("multibody", {2.0, 4.0}, {2, 3});
  const auto other = fake("fem", {2.1, 4.1}, {4, 5});
  const cmp::Table t = cmp::build_table("t", {base, other}, nullptr, 2);
  const std::string text = cmp::format_text(t);
  EXPECT_NE(text.find("2.100?"), std::string::npos) << text;
  EXPECT_NE(text.find("MAC < 0.5"), std::string::npos) << text;
  const auto good = cmp::build_table("t", {base, fake("fem", {2.1, 4.1}, {2, 3})}, nullptr, 2);
  EXPECT_EQ(cmp::format_text(good).find('?'), std::string::npos);
}

// Oracle: orthogonal shapes (cos 4a against cos 2a: MAC 0) are unlike modes. Their
// "difference" is no datum: the table gives none (NaN in CSV/JSON, "unlike" in the
// cell), an error against a reference paired that weakly is none either, and a gate
// over that mode fails naming the MAC instead of passing on a number that compares
// nothing (the sweep wrote such errors of 28-254 % as data).
TEST(Table, NoDifferenceOrErrorAgainstAWeakPartner) {
  const auto base = fake("multibody", {2.0, 4.0}, {2, 3});
  const auto weak = fake("fem", {2.1, 4.1}, {4, 3});
  const auto ref = fake("reference", {2.05, 4.05}, {2, 5});
  const cmp::Table t = cmp::build_table("t", {base, weak}, &ref, 2);
  EXPECT_TRUE(std::isnan(t.columns[1].diff_pct[0]));
  EXPECT_TRUE(std::isnan(t.columns[0].error_pct[1]));  // the reference's mode 2 is unlike
  EXPECT_NEAR(t.columns[1].diff_pct[1], (4.0 - 4.1) / 4.1 * 100.0, 1e-12);
  EXPECT_NE(cmp::format_text(t).find("unlike"), std::string::npos) << cmp::format_text(t);
  ring::Gate g;
  g.solver = "fem";
  g.against = "reference";
  g.max_pct = 100.0;
  const auto r = cmp::evaluate_gates({g}, t);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].pass);
  EXPECT_EQ(r[0].worst_mode, 1);
  EXPECT_NE(r[0].line().find("paired with MAC"), std::string::npos) << r[0].line();
}

// Found by a robustness probe: the backward-error acceptance passed a NaN. std::max(0, NaN) is 0 and
// std::max_element keeps a small residual ahead of a later NaN, so a pair that broke down
// read as a perfect one. Oracle: IEEE comparisons (NaN is no number below a bound).
TEST(Acceptance, ANanResidualIsNoEigenpairWhereverItStands) {
  EXPECT_TRUE(std::isnan(modal::worst(0.0, NAN)));
  EXPECT_TRUE(std::isnan(modal::worst(NAN, 1e-15)));
  EXPECT_EQ(modal::worst(1e-15, 2e-15), 2e-15);
  for (const std::vector<double>& relative : {std::vector<double>{1e-15, NAN}, std::vector<double>{NAN, 1e-15}}) {
    ring::ModalResult r;
    const Eigen::VectorXd omega2 = Eigen::Vector2d(1.0, 4.0);
    modal::assemble(r, "multibody", omega2, modal::select_modes("multibody", omega2, 1e-3, 2), relative);
    EXPECT_THROW(modal::require_eigenpairs(r), ring::NumericalError) << relative[0] << ", " << relative[1];
  }
}

// Found by a robustness probe: a result holding a value that is not finite is a numerical failure
// (exit 3) naming the value, whatever produced it; a residual the solver does not report
// (ccx, an imported column) is none, not a non-finite value.
TEST(Acceptance, ANonFiniteResultIsANumericalFailureNamingTheValue) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const ring::NumericalError& e) {
      return std::string(e.what());
    }
    return std::string("(no ring::NumericalError)");
  };
  ring::ModalResult m = fake("multibody", {2.0, 3.0}, {2, 3});
  EXPECT_NO_THROW(cmp::require_finite(m));
  m.max_residual.reset();
  EXPECT_NO_THROW(cmp::require_finite(m));
  m.omega[1] = INFINITY;
  EXPECT_NE(message([&] { cmp::require_finite(m); }).find("multibody: the frequency of mode 2 is inf"), std::string::npos);
  m.omega[1] = 3.0;
  m.max_residual = -NAN;
  EXPECT_NE(message([&] { cmp::require_finite(m); }).find("max eigen-residual"), std::string::npos);
  m.max_residual = 0.0;
  m.shapes[0].tangential[90] = NAN;
  EXPECT_NE(message([&] { cmp::require_finite(m); }).find("mode 1's tangential displacement at 90 deg"),
            std::string::npos);

  ring::StaticResult st;
  st.solver = "lumped";
  st.displacements = {{90.0, 0.1, NAN}};
  EXPECT_NE(message([&] { cmp::require_finite(st); }).find("lumped: uy at 90 deg is nan"), std::string::npos);
  ring::BucklingResult b;
  b.solver = "fem";
  b.factors = {3.0, NAN};
  EXPECT_NE(message([&] { cmp::require_finite(b); }).find("critical load factor 2"), std::string::npos);
  ring::TimeHistory h;
  h.solver = "multibody";
  h.record_angles = {0.0};
  h.t = {0.0, 1e-3};
  h.ux = {{0.0, -INFINITY}};
  h.uy = {{0.0, 0.0}};
  EXPECT_NE(message([&] { cmp::require_finite(h); }).find("ux at 0 deg, step 1"), std::string::npos);
}

}  // namespace
