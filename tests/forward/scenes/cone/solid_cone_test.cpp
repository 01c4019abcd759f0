// Cones with solid sheets (docs/design/numerics-solid.md, "Cones"): the tiny cone (one contour,
// 45 deg wall on a 90 deg pie, 1 mm sheet) with solid-shells and with bricks against the shell:
// the pie's cyclic ties, virtual tools and rim act on 3-DOF node columns, sections read the
// columns' mid-surface, and the rim holds the mid-surface only (or the whole column with
// clamp_rotations). The reader refuses what solids do not have, naming file, key and value.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "tests/support/csv_rows.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

struct Outcome {
  nlohmann::json summary;
  std::vector<std::vector<double>> contours, section;
};

// The tiny cone with `element` (and `extra` after its [solver] table), run into a fresh directory.
Outcome run_tiny(const std::string& name, const std::string& element, int layers = 0, const std::string& extra = "") {
  test::TinyCone c;
  c.element = element;
  c.layers = layers;
  const fs::path file = test::write_tiny_cone(test::temp_path(name + ".toml"), extra, c);
  const ConeScene scene = read_cone_scene(file.string());
  const fs::path dir = test::temp_path(name);
  fs::remove_all(dir);
  const ConeResult r = run_cone_scene(scene, RunFiles(io::OutputDirectory::prepare(dir.string(), false)));
  Outcome o{r.to_json(), {}, {}};
  EXPECT_TRUE(r.ok()) << o.summary.dump();
  if (r.ok()) {
    o.contours = test::read_csv_rows(dir / "contours.csv");
    o.section = test::read_csv_rows(dir / "sections" / "section_s1_c001.csv");
  }
  std::printf("tiny cone, %s: %d increments, %d iterations, %.2f s; contour mean Fz %.2f N, centre depth %.4f mm\n", name.c_str(),
              o.summary.value("increments", 0), o.summary.value("newton_iterations", 0), o.summary.value("wall_seconds", 0.0),
              o.contours.empty() ? 0.0 : o.contours[0][5], o.section.empty() ? 0.0 : -o.section[0][3]);
  fs::remove_all(dir);
  fs::remove(file);
  return o;
}

// Section columns (file-formats.md): r0, r, theta, z, thickness, r_top, z_top, r_bottom, z_bottom.
constexpr std::size_t kR0 = 0, kR = 1, kZ = 3, kThickness = 4, kRTop = 5, kZTop = 6, kRBottom = 7, kZBottom = 8;

// The solid sheet against the shell, each on the same tiny cone: the contour's mean Fz, the
// centre depth and every section point's thickness. The families differ in physics (the solids'
// through-thickness stress and transverse shear, the one-point brick's bending) and in how they
// sample the thickness (nodal column against nodal average of element thicknesses), not by more.
void expect_near_the_shell(const Outcome& solid, const Outcome& shell, double force_share, double depth_mm, double thickness_mm) {
  ASSERT_EQ(solid.section.size(), shell.section.size());
  ASSERT_FALSE(solid.contours.empty());
  EXPECT_NEAR(solid.contours[0][5], shell.contours[0][5], force_share * shell.contours[0][5]);
  EXPECT_NEAR(solid.section[0][kZ], shell.section[0][kZ], depth_mm);
  double worst = 0.0;
  for (std::size_t i = 0; i < shell.section.size(); ++i) {
    EXPECT_DOUBLE_EQ(solid.section[i][kR0], shell.section[i][kR0]);  // the same mid-surface line
    worst = std::max(worst, std::abs(solid.section[i][kThickness] - shell.section[i][kThickness]));
  }
  std::printf("  against the shell: Fz %+.2f %%, centre depth %+.4f mm, largest thickness difference %.4f mm\n",
              100.0 * (solid.contours[0][5] / shell.contours[0][5] - 1.0), shell.section[0][kZ] - solid.section[0][kZ], worst);
  EXPECT_LE(worst, thickness_mm);
}

TEST(SolidCone, SolidShellsAndBricksFormTheTinyConeAsTheShellDoes) {
  const Outcome shell = run_tiny("shell", "shell");
  const Outcome solid_shell = run_tiny("solid_shell", "solid_shell");
  ASSERT_FALSE(shell.section.empty());
  ASSERT_FALSE(solid_shell.section.empty());
  EXPECT_EQ(solid_shell.summary["model"]["element"], "solid_shell");
  EXPECT_EQ(solid_shell.summary["model"]["elements"], shell.summary["model"]["elements"]);
  EXPECT_EQ(solid_shell.summary["model"]["nodes"].get<int>(), 2 * shell.summary["model"]["nodes"].get<int>());
  // Measured: Fz -6.5 %, centre 0.033 mm deeper, thickness within 0.016 mm.
  expect_near_the_shell(solid_shell, shell, 0.10, 0.06, 0.03);

  // The rim (r0 = 21.5 mm): its mid-surface stays where it was, the column turns about it.
  const std::vector<double>& rim = solid_shell.section.back();
  ASSERT_DOUBLE_EQ(rim[kR0], 21.5);
  EXPECT_NEAR(rim[kR], 21.5, 1e-12);
  EXPECT_NEAR(rim[kZ], 0.0, 1e-12);
  EXPECT_LT(rim[kRTop], 21.5 - 0.1);  // turned: the wall pulls the top inwards
  EXPECT_GT(rim[kZTop], 0.4);         // and lifts it

  // Four one-point layers (two: Fz +19 %, the centre 0.52 mm deeper; one: Fz +85 %, as a single
  // layer of one-point bricks bends stiffly, M/M_p 11 in the plastic strip test).
  const Outcome bricks = run_tiny("brick", "brick", 4);
  ASSERT_FALSE(bricks.section.empty());
  EXPECT_EQ(bricks.summary["model"]["layers"].get<int>(), 4);
  EXPECT_FALSE(bricks.summary["model"].contains("thickness_points"));
  EXPECT_EQ(bricks.summary["model"]["nodes"].get<int>(), 5 * shell.summary["model"]["nodes"].get<int>());
  // Measured: Fz +1.7 %, centre 0.18 mm deeper, thickness within 0.02 mm.
  expect_near_the_shell(bricks, shell, 0.05, 0.25, 0.04);
}

TEST(SolidCone, ClampRotationsHoldsEveryNodeOfTheRimColumns) {
  test::TinyCone c = test::small_tiny_cone(1);
  c.element = "solid_shell";
  const fs::path file = test::write_tiny_cone(test::temp_path("clamped.toml"), "", c);
  // clamp_rotations into [sheet], before its element key.
  std::string text = test::slurp(file);
  text.replace(text.find("element = "), 0, "clamp_rotations = true\n");
  std::ofstream(file) << text;
  const ConeScene scene = read_cone_scene(file.string());
  ASSERT_TRUE(scene.clamp_rotations);
  const fs::path dir = test::temp_path("clamped");
  fs::remove_all(dir);
  const ConeResult r = run_cone_scene(scene, RunFiles(io::OutputDirectory::prepare(dir.string(), false)));
  ASSERT_TRUE(r.ok()) << r.to_json().dump();
  const auto section = test::read_csv_rows(dir / "sections" / "section_s1_c001.csv");
  const std::vector<double>& rim = section.back();
  ASSERT_DOUBLE_EQ(rim[kR0], 13.5);
  EXPECT_NEAR(rim[kRTop], 13.5, 1e-12);
  EXPECT_NEAR(rim[kRBottom], 13.5, 1e-12);
  EXPECT_NEAR(rim[kZTop], 0.5, 1e-12);
  EXPECT_NEAR(rim[kZBottom], -0.5, 1e-12);
  EXPECT_GT(std::abs(section[section.size() - 2][kZ]), 1e-3);  // its neighbour moved
  fs::remove_all(dir);
  fs::remove(file);
}

// An InputError naming the scene file, this key and value.
void expect_refused(const std::string& name, const std::string& sheet, const std::string& extra, const std::string& key,
                    const std::string& value) {
  test::TinyCone c;
  c.element = "solid_shell";
  const fs::path file = test::write_tiny_cone(test::temp_path(name + ".toml"), extra, c);
  std::string text = test::slurp(file);
  text.replace(text.find("element = "), 0, sheet);
  std::ofstream(file) << text;
  try {
    read_cone_scene(file.string());
    ADD_FAILURE() << name << ": read";
  } catch (const io::InputError& e) {
    std::printf("%s\n", e.what());
    EXPECT_EQ(e.file(), file.string()) << name;
    EXPECT_EQ(e.key(), key) << name;
    EXPECT_EQ(e.value(), value) << name;
  }
  fs::remove(file);
}

TEST(SolidCone, ReaderRefusesWhatSolidSheetsDoNotHave) {
  expect_refused("history", "", "[output]\nhistory_element = { r = 18.0, theta = 45.0 }\n", "output.history_element", "");
  expect_refused("layers", "layers = 2\n", "", "sheet.layers", "2");
  expect_refused("hourglass", "hourglass_stiffness = 0.05\n", "", "sheet.hourglass_stiffness", "0.05");
  expect_refused("explicit", "", "scheme = \"explicit\"\n", "solver.scheme", "\"explicit\"");
  expect_refused("phong", "", "[contact]\nsurface = \"phong\"\n", "contact.surface", "\"phong\"");
}

}  // namespace
}  // namespace spifit::scene
