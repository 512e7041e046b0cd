// The [calculix] section and the calculix entry as the scene reader sees them: defaults,
// ranges and names in messages, and which analyses the entry offers.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "compare/registry.hpp"
#include "ring/errors.hpp"

namespace {

const std::string kRing = R"([ring]
radius = 10.0
[supports]
pin = 180.0
roller = 0.0
)";

std::string error_of(const std::string& toml) {
  try {
    cmp::parse_scene(toml, "s.toml");
  } catch (const ring::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CalculixScene, DefaultsAndValues) {
  ring::Scene s = cmp::parse_scene(kRing + "[calculix]\n", "s.toml");
  EXPECT_EQ(s.calculix.elements, 160);
  EXPECT_EQ(s.calculix.element, ring::CalculixOptions::Element::b32r);
  EXPECT_EQ(s.calculix.section, ring::CalculixOptions::Section::equivalent_rectangle);
  EXPECT_EQ(s.calculix.timeout, 600.0);
  EXPECT_EQ(s.calculix.threads, 1);
  EXPECT_TRUE(s.column("calculix"));  // a section present and no [modes]: its modes
  s = cmp::parse_scene(kRing + "[calculix]\nelements = 80\nelement = \"B31\"\nsection = \"as-given\"\ntimeout = 5.5\n"
                               "threads = 2\n",
                       "s.toml");
  EXPECT_EQ(s.calculix.elements, 80);
  EXPECT_EQ(s.calculix.element, ring::CalculixOptions::Element::b31);
  EXPECT_EQ(s.calculix.section, ring::CalculixOptions::Section::as_given);
  EXPECT_EQ(s.calculix.timeout, 5.5);
  EXPECT_EQ(s.calculix.threads, 2);
}

TEST(CalculixScene, BadValuesNameTheKey) {
  EXPECT_NE(error_of(kRing + "[calculix]\nelement = \"B33\"\n").find("calculix.element"), std::string::npos);
  EXPECT_NE(error_of(kRing + "[calculix]\nelements = 3\n").find("calculix.elements"), std::string::npos);
  EXPECT_NE(error_of(kRing + "[calculix]\ntimeout = 0\n").find("calculix.timeout"), std::string::npos);
  EXPECT_NE(error_of(kRing + "[calculix]\nelemnts = 40\n").find("did you mean 'elements'"), std::string::npos);
  // The roller must be a node of the model (nodes every 360/elements degrees from the pin).
  EXPECT_NE(error_of("[ring]\nradius = 10.0\n[supports]\npin = 0.0\nroller = 100.0\n[calculix]\nelements = 12\n")
                .find("calculix.elements"),
            std::string::npos);
}

TEST(CalculixScene, OffersModesStaticsAndNewmarksResponseWithoutDamping) {
  const std::string stat = "[static]\nsolvers = [\"calculix\"]\nat = 0.0\nforce = [-1.0, 0.0]\n";
  EXPECT_EQ(error_of(kRing + "[calculix]\n" + stat), "");
  const std::string resp = "[response]\nsolvers = [\"calculix\"]\nat = 0.0\nforce = [-1.0, 0.0]\n";
  EXPECT_EQ(error_of(kRing + "[calculix]\n" + resp), "");
  // What the deck cannot write is refused by the entry's check, naming the key.
  for (const auto& [extra, key] : std::vector<std::pair<std::string, std::string>>{
           {"integrator = \"generalized-alpha\"\n", "response.integrator"},
           {"rayleigh_mass = 0.1\n", "response.rayleigh_mass"},
           {"hinge_damping = 1.0\n", "response.hinge_damping"}}) {
    const ring::Scene s = cmp::parse_scene(kRing + "[calculix]\n" + resp + extra, "s.toml");
    try {
      cmp::check_scene(s);
      ADD_FAILURE() << extra << " was accepted";
    } catch (const ring::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

}  // namespace
