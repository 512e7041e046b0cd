// [plates] in the CalculiX column through the binary: `ringvib static SCENE --solver calculix
// --json` on a scene written here prints the plates' force ("reaction") and the contact
// lengths ("contact_length") of the elastic crushing's closed form, and what the column does
// not take with plates is exit 2 naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/cli.hpp"
#include "support/paper.hpp"

namespace {

using ringtest::ringvib;

bool ccx_absent() { return ringtest::shell("command -v ccx").empty(); }

/// The paper ring (R = 10 m, circle d = 0.12 m as its equivalent rectangle), no supports,
/// crushed along the vertical by 1e-3 m (1e-4 R) at 40 B32R elements; `extra` appended.
std::string plates_scene(const std::string& extra = "") {
  return "title = \"plates, calculix\"\n" + ringtest::paper_ring_toml() + R"([calculix]
elements = 40
[plates]
axis = 90.0
travel = 1e-3
[static]
solvers = ["calculix"]
record = [90.0, 180.0]
steps = 2
)" + extra;
}

struct Scene {
  std::string dir = ringtest::temp_dir(), path = dir + "/scene.toml";
  explicit Scene(const std::string& text) { ringtest::write(path, text); }
  ~Scene() { std::system(("rm -rf " + dir).c_str()); }
};

TEST(CalculixPlatesCli, TheJsonHoldsThePinchingForceAndAPointContact) {
  if (ccx_absent()) GTEST_SKIP() << "ccx is not on the PATH (Debian package calculix-ccx; scripts/install-deps.sh)";
  Scene s(plates_scene());
  const auto r = ringvib("static " + s.path + " --solver calculix --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("reaction") && j.contains("contact_length")) << r.out;
  // The thin ring's pinching force c / ((pi/4 - 2/pi) R^3 / EI) (Roark's ring case 1): within
  // 1.5e-3, the column's error at 40 elements (measured 8.0e-4 against the thick ring's form,
  // 1.2e-4 below the thin one, calculix_plates_test) and NLGEOM's 7e-5 at c = 1e-4 R.
  const double d = 0.12, EI = 2.1e11 * M_PI * std::pow(d, 4) / 64.0, R = 10.0, c = 1e-3;
  const double P = c / ((M_PI / 4.0 - 2.0 / M_PI) * R * R * R / EI);
  EXPECT_NEAR(j["reaction"][1].get<double>() / -P, 1.0, 1.5e-3) << r.out;
  EXPECT_NEAR(j["reaction"][0].get<double>(), 0.0, 1e-9 * P) << r.out;
  // The elastic ring touches each plate at its first contact node only: a contact length far
  // below the node spacing (pi R / 40 = 0.785 m), the same on both plates.
  EXPECT_LT(j["contact_length"][0].get<double>(), 1e-3) << r.out;
  EXPECT_NEAR(j["contact_length"][0].get<double>(), j["contact_length"][1].get<double>(), 1e-6) << r.out;
  // The first contact point went down with its plate (c / 2, less the sinking of 1e-10 m); the
  // side at 180 deg out by the closed form's widening, (2/pi - 1/2) / (pi/4 - 2/pi) c / 2,
  // within the column's 1e-3.
  EXPECT_NEAR(j["displacements"][0]["uy"].get<double>(), -0.5 * c, 1e-6 * c) << r.out;
  const double widening = (2.0 / M_PI - 0.5) / (M_PI / 4.0 - 2.0 / M_PI) * 0.5 * c;
  EXPECT_NEAR(j["displacements"][1]["ux"].get<double>() / -widening, 1.0, 1e-3) << r.out;
}

TEST(CalculixPlatesCli, WhatTheColumnDoesNotTakeWithPlatesIsExit2NamingTheKey) {
  // B31 (not validated with plates) and a history that draws the plates back (ccx's return
  // diverges): refused before ccx runs, so no ccx is needed.
  {
    Scene s(plates_scene() + "");
    const auto r = ringvib("static " + s.path + " --solver calculix --json --set calculix.element=\"B31\"");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("calculix.element"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("plates"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
  {
    Scene s(plates_scene("history = [1.0, 0.9]\n"));
    const auto r = ringvib("static " + s.path + " --solver calculix --json");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("static.history"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("plates"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
}

}  // namespace
