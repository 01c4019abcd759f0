// Every parameter class of the card through an FE run (docs/design/sensitivities.md): the
// derivative checker on the bundled indent (thesis §7.1) with card C.7 (Hill + Swift +
// Armstrong-Frederick), C.8 (von Mises + Swift + Ziegler) and C.3 + C.4 (Hill), for the Hill
// coefficients, Swift's eps0, Poisson's ratio and the kinematic laws' coefficients (Swift's K and
// n, Young's modulus, hill.G, the penalty and friction are checked by the model's and the cones'
// tests). Converged to 1e-10 so that the central differences follow the exact solution: at the
// scene's own tolerance ziegler.CA lies 1.5e-6 off them, the solver's, not the derivative's.
#include "forward/scenes/common/sensitivity_check.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

// The bundled indent (or its solid twins) with another card and 20 increments of 0.1 mm instead
// of 40 of 0.05 mm (and elements x elements instead of 10 x 10, when given).
std::unique_ptr<Scene> indent_with(const std::string& card, const std::string& scene = "indent.toml", const std::string& friction = "",
                                   int elements = 0) {
  std::string text = test::slurp(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + scene);
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("\"../../../materials/aa3003o_c3c4.toml\"", "\"" + std::string(SPIFIT_SOURCE_DIR) + "/materials/" + card + "\"");
  replace("travel_per_increment = 0.05", "travel_per_increment = 0.1");
  if (!friction.empty()) replace("friction = 0.0", friction);
  if (elements > 0) replace("elements = 10", "elements = " + std::to_string(elements));
  const fs::path file = test::temp_path("indent_" + card);
  std::ofstream(file) << text;
  auto s = read_scene(file.string());
  fs::remove(file);
  return s;
}

void expect_agreement(const std::string& card, const std::vector<std::string>& names, const std::string& scene_file = "indent.toml",
                      const std::string& friction = "", int elements = 0) {
  const auto scene = indent_with(card, scene_file, friction, elements);
  const SensitivityCheck c = check_sensitivities(*scene, names, 1e-4, 1e-10, {});
  std::printf("%s\n%s", card.c_str(), format_sensitivity_check(c).c_str());
  ASSERT_EQ(c.rows.size(), names.size());
  for (const SensitivityCheckRow& r : c.rows) {
    EXPECT_GE(r.increments, 20) << r.name;  // every increment (a few more where 1e-10 cuts one back)
    // Measured: 5e-10 to 1.7e-7 of the run's largest derivative, within the spread of cd(h) and cd(h/4).
    EXPECT_TRUE(r.agrees()) << r.name << ": " << r.difference << " against a spread of " << r.spread;
    EXPECT_LT(r.difference, 1e-6) << r.name;
  }
}

TEST(SensitivityCheck, ArmstrongFrederickSwiftEps0AndPoissonOnTheIndent) {
  expect_agreement("aa3003o_c7_af_shell.toml", {"af.CX", "af.Xsat", "swift.eps0", "elastic.nu"});
}

TEST(SensitivityCheck, ZieglerOnTheIndent) { expect_agreement("aa3003o_c8_ziegler_shell.toml", {"ziegler.CA", "ziegler.GA"}); }

TEST(SensitivityCheck, HillCoefficientsOnTheIndent) { expect_agreement("aa3003o_c3c4.toml", {"hill.F", "hill.H", "hill.N"}); }

// The one-point brick in three layers with card C.5 (its centre's 3D return mapping, the hourglass
// forces and the stabilisation on the consistent tangent) with the tool on its top faces and
// friction (mu = 0.1: the stick history there). E, nu and Swift's n: the element's test.
TEST(SensitivityCheck, BricksWithFrictionOnTheIndent) {
  expect_agreement("aa3003o_c5_af_brick.toml", {"swift.K", "af.CX", "hill.G", "contact.penalty", "contact.friction"}, "indent_brick.toml",
                   "friction = 0.1");
}

// The solid-shell with card C.7 (the back-stress makes its condensed blocks non-symmetric) and
// friction (mu = 0.1) on a 6 x 6 mesh: the enhanced thickness strains and the levels' mean
// dilatation carry the derivatives (Swift's K and n, E and nu: the element's test; the penalty's
// load on the top faces: the bricks'). The checker converges the enhanced strains to 1e-13 with the runs'
// 1e-10; at their own 1e-8, E, hill.G and the penalty lay 1.2e-6 to 6e-6 off central differences
// whose spread was 3e-8 (the 10 x 10 mesh), the committed points' states carrying errors of that order.
TEST(SensitivityCheck, SolidShellsWithFrictionOnTheIndent) {
  expect_agreement("aa3003o_c7_af_shell.toml", {"af.CX", "hill.G", "contact.friction"}, "indent_solid_shell.toml", "friction = 0.1", 6);
}

// A disagreement at the scene's own tolerance, or one looser than 1e-10, also points to
// --tolerance (the runs' own error); one at 1e-10 points to smaller steps alone.
TEST(SensitivityCheck, ADisagreementSaysWhatMaySettleIt) {
  SensitivityCheck c;
  SensitivityCheckRow row;
  row.name = "contact.friction";
  row.difference = 1e-4;
  row.spread = 1e-8;
  c.rows.push_back(row);
  const std::string own = format_sensitivity_check(c);
  EXPECT_NE(own.find("DIFFERS"), std::string::npos) << own;
  EXPECT_NE(own.find("--relative-step"), std::string::npos) << own;
  EXPECT_NE(own.find("--tolerance 1e-10"), std::string::npos) << own;
  c.tolerance = 1e-8;
  EXPECT_NE(format_sensitivity_check(c).find("--tolerance 1e-10"), std::string::npos);
  c.tolerance = 1e-10;
  const std::string tight = format_sensitivity_check(c);
  EXPECT_NE(tight.find("--relative-step"), std::string::npos) << tight;
  EXPECT_EQ(tight.find("--tolerance"), std::string::npos) << tight;
  c.rows[0].difference = 1e-9;
  EXPECT_NE(format_sensitivity_check(c).find("agree"), std::string::npos);
}

}  // namespace
}  // namespace spifit::scene
