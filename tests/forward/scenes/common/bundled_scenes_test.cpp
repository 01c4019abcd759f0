// Same input -> identical output (the golden outputs of every bundled scene:
// golden_outputs_test.cpp).
#include "forward/io/output_directory.hpp"
#include "forward/scenes/material_point/material_point_scene.hpp"
#include "forward/scenes/scene_registry.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace spifit;

namespace {
fs::path scenes_dir() { return fs::path(SPIFIT_SOURCE_DIR) / "experiments" / "aa3003o" / "scenes"; }
}  // namespace

TEST(BundledScenes, SameInputGivesIdenticalCurves) {
  for (const char* name : {"tensile_45_af.toml", "bauschinger_00_ziegler.toml"}) {
    const auto scene = scene::read_material_point_scene((scenes_dir() / name).string());
    const auto a = scene::run_material_point(scene.card.params, scene.setup);
    const auto b = scene::run_material_point(scene.card.params, scene.setup);
    EXPECT_EQ(scene::curve_csv(a), scene::curve_csv(b)) << name;
  }
}
