// The option schemas (ring/options_schema.hpp) of the four solvers: each default is
// written once, in the solver's schema, and the option structs of ring/spec.hpp agree with
// it (a default-constructed struct equals the struct read from an empty section); the
// reader fills the structs through the schema (values given reach the struct); the schema
// vocabulary refuses a key declared twice and prints its Markdown table.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "calculix/options.hpp"
#include "compare/registry.hpp"
#include "fem_reference/options.hpp"
#include "lumped_mass/options.hpp"
#include "multibody/options.hpp"

namespace {

void expect_same(const ring::MultibodyOptions& a, const ring::MultibodyOptions& b) {
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.rotary_inertia, b.rotary_inertia);
  EXPECT_EQ(a.dependent, b.dependent);
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.theory, b.theory);
}

void expect_same(const ring::FemOptions& a, const ring::FemOptions& b) {
  EXPECT_EQ(a.elements, b.elements);
  EXPECT_EQ(a.degree, b.degree);
  EXPECT_EQ(a.geometry, b.geometry);
  EXPECT_EQ(a.extensible, b.extensible);
  EXPECT_EQ(a.rotary_inertia, b.rotary_inertia);
  EXPECT_EQ(a.reference, b.reference);
  EXPECT_EQ(a.tolerance, b.tolerance);
  EXPECT_EQ(a.response_tolerance, b.response_tolerance);
  EXPECT_EQ(a.theory, b.theory);
}

void expect_same(const ring::LumpedOptions& a, const ring::LumpedOptions& b) {
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.variant, b.variant);
}

void expect_same(const ring::CalculixOptions& a, const ring::CalculixOptions& b) {
  EXPECT_EQ(a.elements, b.elements);
  EXPECT_EQ(a.element, b.element);
  EXPECT_EQ(a.section, b.section);
  EXPECT_EQ(a.timeout, b.timeout);
  EXPECT_EQ(a.threads, b.threads);
}

TEST(OptionSchemas, TheStructDefaultsAreTheSchemaDefaults) {
  expect_same(multibody::read_options(ring::defaults(multibody::option_schema())), ring::MultibodyOptions{});
  expect_same(fem::read_options(ring::defaults(fem::option_schema())), ring::FemOptions{});
  expect_same(lumped::read_options(ring::defaults(lumped::option_schema())), ring::LumpedOptions{});
  expect_same(calculix::read_options(ring::defaults(calculix::option_schema())), ring::CalculixOptions{});
}

TEST(OptionSchemas, ASceneWithoutSolverSectionsHasTheDefaults) {
  const ring::Scene s = cmp::parse_scene("[ring]\n", "t.toml");
  expect_same(s.multibody, ring::MultibodyOptions{});
  expect_same(s.fem, ring::FemOptions{});
  expect_same(s.lumped, ring::LumpedOptions{});
  expect_same(s.calculix, ring::CalculixOptions{});
  for (const auto& e : cmp::registry()) EXPECT_EQ(s.options.count(e.name), 1u) << e.name;
}

TEST(OptionSchemas, GivenValuesReachTheStructs) {
  const ring::Scene s = cmp::parse_scene(
      "[ring]\n[multibody]\nn = 64\nmethod = \"sparse\"\ndependent = \"paper\"\nrotary_inertia = false\n"
      "theory = \"timoshenko\"\n[fem]\ndegree = 5\ngeometry = \"polygon\"\ntolerance = 1e-8\n"
      "[lumped]\nvariant = \"frame-consistent\"\n[calculix]\nelement = \"B31\"\ntimeout = 60\nthreads = 2\n",
      "t.toml");
  EXPECT_EQ(s.multibody.n, 64);
  EXPECT_EQ(s.multibody.method, ring::MultibodyOptions::Method::sparse);
  EXPECT_EQ(s.multibody.dependent, ring::MultibodyOptions::Dependent::paper);
  EXPECT_FALSE(s.multibody.rotary_inertia);
  EXPECT_EQ(s.multibody.theory, ring::Theory::timoshenko);
  EXPECT_EQ(s.fem.degree, 5);
  EXPECT_EQ(s.fem.geometry, ring::FemOptions::Geometry::polygon);
  EXPECT_EQ(s.fem.tolerance, 1e-8);
  EXPECT_FALSE(s.fem.theory.has_value());
  EXPECT_EQ(s.lumped.variant, ring::LumpedOptions::Variant::frame_consistent);
  EXPECT_EQ(s.calculix.element, ring::CalculixOptions::Element::b31);
  EXPECT_EQ(s.calculix.timeout, 60.0);  // an integer is taken as a number
  EXPECT_EQ(s.calculix.threads, 2);
  EXPECT_EQ(s.options.at("multibody").choice("method"), "sparse");
}

TEST(OptionSchemas, EverySolverOfTheRegistryHasItsSectionsSchema) {
  for (const auto& e : cmp::registry()) {
    EXPECT_EQ(e.options.section(), e.name);
    EXPECT_FALSE(e.options.entries().empty()) << e.name;
    EXPECT_TRUE(e.store) << e.name;
  }
}

TEST(OptionSchemaVocabulary, AKeyIsDeclaredOnce) {
  ring::OptionSchema s("x", "");
  s.declare_integer("n", 4, 1, 9, "pieces");
  EXPECT_THROW(s.declare_boolean("n", true, "again"), std::logic_error);
}

TEST(OptionSchemaVocabulary, ValuesOfAnotherTypeAreABug) {
  ring::OptionSchema s("x", "");
  s.declare_integer("n", 4, 1, 9, "pieces");
  s.declare_theory("theory", "model");
  const ring::OptionValues v = ring::defaults(s);
  EXPECT_EQ(v.integer("n"), 4);
  EXPECT_FALSE(v.theory("theory").has_value());  // absent: the ring's theory
  EXPECT_THROW(v.number("n"), std::logic_error);
  EXPECT_THROW(v.integer("m"), std::logic_error);
}

TEST(OptionSchemaVocabulary, TheMarkdownTable) {
  ring::OptionSchema s("x", "One line.");
  s.declare_integer("n", 40, 4, 100000000, "pieces");
  s.declare_integer("p", 3, 2, 16, "degree");
  s.declare_number("tol", 1e-9, 1e-14, 1e-2, "a | b");
  s.declare_number("t", 600.0, 0.0, HUGE_VAL, "time", true).unit = "s";
  s.declare_boolean("b", false, "flag");
  s.declare_choice("c", "a", {"a", "b"}, "pick");
  s.declare_theory("theory", "model");
  EXPECT_EQ(ring::markdown(s),
            "### `[x]`\n\nOne line.\n\n"
            "| key | unit | default | valid | meaning |\n|---|---|---|---|---|\n"
            "| `x.n` | | 40 | >= 4 | pieces |\n"
            "| `x.p` | | 3 | [2, 16] | degree |\n"
            "| `x.tol` | | 1e-9 | [1e-14, 0.01] | a \\| b |\n"
            "| `x.t` | s | 600 | > 0 | time |\n"
            "| `x.b` | | false | `true`, `false` | flag |\n"
            "| `x.c` | | `\"a\"` | `\"a\"`, `\"b\"` | pick |\n"
            "| `x.theory` | | `ring.theory` | `\"euler-bernoulli\"`, `\"timoshenko\"` | model |\n");
}

}  // namespace
