// A cone on a pie whose centre is coarsened (sheet.coarse_inside): the key's limits are input
// errors (the contour means against the regular mesh's: coarsened_cone_long_test.cpp).
#include "forward/io/input_error.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

TEST(CoarsenedCone, TheToolsReachAndTheExplicitSchemeAreInputErrors) {
  const std::string head = "[scene]\nkind = \"cone\"\nmaterial = \"" + src("materials/aa3003o_c3c4.toml") +
                           "\"\n[cone]\npreset = \"cone70\"\ncontours = 3\npie_angle = 45.0\n[sheet]\n";
  // The third contour of cone70 touches at 89.45 mm: less the 5 mm tool, 84.45 mm.
  const fs::path reach = test::write_temp_file("coarse_reach.toml", head + "elements_per_45deg = 24\ncoarse_inside = 85.0\n");
  std::string err = test::input_error_of([&] { read_cone_scene(reach.string()); });
  fs::remove(reach);
  EXPECT_NE(err.find("sheet.coarse_inside"), std::string::npos) << err;
  EXPECT_NE(err.find("tool radius"), std::string::npos) << err;
  const fs::path expl = test::write_temp_file("coarse_explicit.toml", head + "elements_per_45deg = 24\ncoarse_inside = 60.0\n[solver]\nscheme = \"explicit\"\n");
  err = test::input_error_of([&] { read_cone_scene(expl.string()); });
  fs::remove(expl);
  EXPECT_NE(err.find("sheet.coarse_inside"), std::string::npos) << err;
  EXPECT_NE(err.find("implicit"), std::string::npos) << err;
  const fs::path odd = test::write_temp_file("coarse_odd.toml", head + "coarse_inside = 60.0\nelements_per_45deg = 22\n");
  err = test::input_error_of([&] { read_cone_scene(odd.string()); });
  fs::remove(odd);
  EXPECT_NE(err.find("sheet.coarse_inside"), std::string::npos) << err;
  EXPECT_NE(err.find("even number"), std::string::npos) << err;
}

}  // namespace
}  // namespace spifit::scene
