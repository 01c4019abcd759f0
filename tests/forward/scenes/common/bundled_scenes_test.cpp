// Every bundled scene file loads and runs, and its summary matches the stored golden values
// (tests/golden/bundled_scene_summaries.json, a regression guard; correctness is checked
// against closed forms and fine-step references elsewhere). Same input -> identical output.
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

TEST(BundledScenes, RunAndMatchGoldenSummaries) {
  std::ifstream gf(fs::path(SPIFIT_SOURCE_DIR) / "tests" / "golden" / "bundled_scene_summaries.json");
  const auto golden = nlohmann::json::parse(gf)["scenes"];
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(scenes_dir())) {
    // Material-point scenes only (the FE forming and cone scenes have their own tests).
    if (e.path().extension() != ".toml") continue;
    const scene::SceneKind* kind = scene::find_scene_kind(scene::scene_kind_of_file(e.path().string()));
    if (kind && kind->family == "material_point") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 13u);
  const fs::path out = fs::temp_directory_path() / ("spifit_bundled_" + std::to_string(::getpid()));
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    const auto scene = scene::read_material_point_scene(f.string());
    const auto dir = io::OutputDirectory::prepare(out.string(), true);
    const auto rep = scene::run_material_point_scene(scene, scene::RunFiles(dir));
    const auto summary = rep.to_json();
    ASSERT_TRUE(rep.ok()) << summary.dump();
    ASSERT_TRUE(golden.contains(scene.name)) << "no golden summary for " << scene.name;
    for (const auto& [key, value] : golden[scene.name].items()) {
      ASSERT_TRUE(summary.contains(key)) << key;
      const double v = summary[key].get<double>(), g = value.get<double>();
      EXPECT_NEAR(v, g, 1e-9 * std::max(1.0, std::abs(g))) << key;
    }
  }
  fs::remove_all(out);
}

TEST(BundledScenes, SameInputGivesIdenticalCurves) {
  for (const char* name : {"tensile_45_af.toml", "bauschinger_00_ziegler.toml"}) {
    const auto scene = scene::read_material_point_scene((scenes_dir() / name).string());
    const auto a = scene::run_material_point(scene.card.params, scene.setup);
    const auto b = scene::run_material_point(scene.card.params, scene.setup);
    EXPECT_EQ(scene::curve_csv(a), scene::curve_csv(b)) << name;
  }
}
