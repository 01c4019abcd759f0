// spifit run dispatches kind = "cone" to the cone scene: a one-contour pie runs and
// writes its outputs; a bad scene exits 2 with one line naming file and key, before the output
// directory is touched.
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using spifit::test::temp_path;

fs::path write_scene(const std::string& name, const std::string& body) {
  const fs::path f = temp_path(name + ".toml");
  std::ofstream(f) << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n" << body;
  return f;
}

TEST(ConeCli, RunDispatchesToTheConeScene) {
  const fs::path scene = spifit::test::write_tiny_cone(temp_path("tiny.toml"));
  const fs::path out = temp_path("tiny_out");
  fs::remove_all(out);
  const auto r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1/1 contours"), std::string::npos) << r.out;
  const auto s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["status"], "ok");
  EXPECT_EQ(s["kind"], "cone");
  EXPECT_TRUE(fs::exists(out / "force.csv"));
  EXPECT_TRUE(fs::exists(out / "contours.csv"));
  EXPECT_TRUE(fs::exists(out / "vtu" / "sheet.pvd"));
  fs::remove_all(out);
  fs::remove(scene);
}

TEST(ConeCli, BadPieAngleExitsTwoNamingFileAndKey) {
  const fs::path scene = write_scene("bad", "[cone]\npreset = \"cone70\"\npie_angle = 0.0\n");
  const fs::path out = temp_path("bad_out");
  fs::remove_all(out);
  const auto r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cone.pie_angle"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(scene);
}

// spifit fit with a cone experiment whose contour range lies beyond the scene's path: exit 2 at
// read time, one line naming the fit file, key and value; nothing runs, --out is not made.
TEST(ConeCli, FitWithAContourRangeBeyondThePathExits2) {
  const fs::path scene = spifit::test::write_tiny_cone(temp_path("cone.toml"), "", spifit::test::small_tiny_cone(2));
  const fs::path fit = temp_path("fit.toml"), out = temp_path("fit_out");
  fs::remove_all(out);
  std::ofstream(fit) << "[fit]\ncard = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                     << "[parameters.\"contact.friction\"]\ninitial = 0.1\nlower = 0.0\nupper = 0.5\n"
                     << "[[experiment]]\nscene = \"" << scene.string() << "\"\nobservable = \"steady_ftheta_over_fz\"\nvalue = -0.2\ncontours = [1, 3]\n";
  const auto r = spifit::test::run_spifit("fit " + fit.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("spifit: " + fit.string() + ": experiment[0].contours = [1, 3]: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("contours = [1, 3]: beyond the path of scene " + scene.string() + ": it has 2 contours (numbers 1 to 2)"), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(fit);
  fs::remove(scene);
}

}  // namespace
