// Reading a material-point scene file without [scene] material: the default card C.3 + C.4 as
// for the FE scenes (../../../materials/aa3003o_c3c4.toml from the scene's folder), or no card
// at all for a fit, whose card replaces the scene's.
#include "forward/io/input_error.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace spifit;

namespace {
const char* kNoCard = "[scene]\nkind = \"tensile\"\nangle = 45.0\n";
}  // namespace

// A tree like the bundled one: ROOT/materials/aa3003o_c3c4.toml and ROOT/a/b/c/scene.toml.
TEST(MaterialPointFile, WithoutMaterialTheDefaultCardIsUsed) {
  const fs::path root = test::fresh_temp_path("tree");
  fs::create_directories(root / "materials");
  fs::create_directories(root / "a" / "b" / "c");
  fs::copy_file(fs::path(SPIFIT_SOURCE_DIR) / "materials" / "aa3003o_c3c4.toml", root / "materials" / "aa3003o_c3c4.toml");
  const fs::path file = root / "a" / "b" / "c" / "scene.toml";
  std::ofstream(file) << kNoCard;
  const auto s = scene::read_material_point_scene(file.string());
  EXPECT_EQ(s.card.name, "aa3003o_c3c4");
  EXPECT_EQ(s.card.params.N, 4.06);  // Bouffioux's N of card C.3
  EXPECT_EQ(s.setup.angle_deg, 45.0);
  const auto fit = scene::read_material_point_scene(file.string(), scene::AbsentMaterial::no_card);
  EXPECT_EQ(fit.card.name, "");
  EXPECT_EQ(fit.card.file, "");
  EXPECT_EQ(fit.name, "scene");
  EXPECT_EQ(fit.setup.angle_deg, 45.0);
  fs::remove_all(root);
}

// Where no default card lies, a run fails on the key, naming the file and where it looked.
TEST(MaterialPointFile, WithoutMaterialOrDefaultCardARunFailsOnTheKey) {
  const fs::path dir = test::fresh_temp_path("lone");
  fs::create_directories(dir);
  const fs::path file = dir / "scene.toml";
  std::ofstream(file) << kNoCard;
  try {
    scene::read_material_point_scene(file.string());
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    EXPECT_EQ(e.key(), "scene.material");
    const std::string looked = fs::absolute(dir / "../../../materials/aa3003o_c3c4.toml").lexically_normal().string();
    EXPECT_EQ(e.message(), "not given, and the default card C.3 + C.4 is not at " + looked +
                               " (../../../materials/aa3003o_c3c4.toml from the scene's folder): give the scene's card");
  }
  // For a fit the same file reads without a card; a card the file names must exist in both.
  EXPECT_NO_THROW(scene::read_material_point_scene(file.string(), scene::AbsentMaterial::no_card));
  std::ofstream(file) << kNoCard << "material = \"nope.toml\"\n";
  for (const auto absent : {scene::AbsentMaterial::default_card, scene::AbsentMaterial::no_card}) {
    try {
      scene::read_material_point_scene(file.string(), absent);
      ADD_FAILURE() << "no error";
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.key(), "scene.material");
      EXPECT_EQ(e.value(), "\"nope.toml\"");
      EXPECT_EQ(e.message(), "material card not found at " + (dir / "nope.toml").string());
    }
  }
  fs::remove_all(dir);
}
