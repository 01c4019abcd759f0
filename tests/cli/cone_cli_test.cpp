// spifit run dispatches kind = "cone" to the cone scene: a one-contour pie runs and
// writes its outputs; a bad scene exits 2 with one line naming file and key, before the output
// directory is touched.
#include "tests/cli/cli_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("spifit_cone_cli_" + std::to_string(::getpid()) + "_" + name); }

fs::path write_scene(const std::string& name, const std::string& body) {
  const fs::path f = temp(name + ".toml");
  std::ofstream(f) << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n" << body;
  return f;
}

TEST(ConeCli, RunDispatchesToTheConeScene) {
  const fs::path scene = write_scene("tiny",
                                     "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = 1\ntop_radius = 20.0\npie_angle = 90.0\n"
                                     "[sheet]\nthickness = 1.0\nelements_per_45deg = 8\nthickness_points = 3\n"
                                     "[solver]\ntravel_per_increment = 0.5\n");
  const fs::path out = temp("tiny_out");
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
  const fs::path out = temp("bad_out");
  fs::remove_all(out);
  const auto r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cone.pie_angle"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(scene);
}

}  // namespace
