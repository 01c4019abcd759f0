// The worked example of docs/design/architecture.md: a scene kind defined in a folder of its own
// (strip_press.hpp), registered, read from a scene file, run through the registry, and swept
// over one of its named inputs with its new observable.
#include "tests/forward/scenes/example/strip_press.hpp"

#include "forward/scenes/scene_registry.hpp"
#include "inverse/sweeps/sweep.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

using test::temp_path;

void register_once() {
  if (!scene::find_scene_kind("strip_press")) scene::register_scene_kind(example::strip_press_kind());
}

fs::path write_scene(const std::string& extra = "") {
  const fs::path f = temp_path("strip.toml");
  std::ofstream(f) << "[scene]\nkind = \"strip_press\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                   << "[strip]\nlength = 40.0\nelements = 20\n[tool]\ndepth = 1.5\n" << extra;
  return f;
}

TEST(ExampleKind, RunsThroughTheRegistryAndItsObservableReadsTheResult) {
  register_once();
  const fs::path file = write_scene();
  const auto scene = scene::read_scene(file.string());
  ASSERT_EQ(scene->kind(), "strip_press");
  EXPECT_EQ(scene->input("tool.depth"), 1.5);
  EXPECT_EQ(scene->input("swift.K"), 180.0);  // the card's parameters are inputs too
  const auto r = scene->run(scene::RunFiles(), {});
  ASSERT_TRUE(r->ok()) << r->message;
  const scene::SceneKind* k = scene::find_scene_kind("strip_press");
  const double fz = k->find_observable("peak_fz")->value(*r, {});
  const double w = k->find_observable("mid_deflection")->value(*r, {});
  std::printf("strip_press: %s\n", r->brief_report().c_str());
  EXPECT_GT(fz, 0.0);  // the strip pushes the tool up
  // The mid-span follows the tool down to its depth less the contact penetration.
  const double pen = r->to_json()["max_penetration"].get<double>();
  EXPECT_NEAR(w, 1.5 - pen, 0.02);
  fs::remove(file);
}

TEST(ExampleKind, ASweepVariesItsNamedInputs) {
  register_once();
  const fs::path scene = write_scene("[solver]\ntravel_per_increment = 0.25\n"), sweep = temp_path("sweep.toml");
  std::ofstream(sweep) << "[sweep]\nscene = \"" << scene.string() << "\"\nmetrics = [\"mid_deflection\", \"peak_fz\"]\n"
                       << "[inputs.\"tool.depth\"]\nvalues = [0.5, 1.0]\n";
  const auto spec = inverse::read_sweep_file(sweep.string());
  const auto r = inverse::run_sweep(spec, {1, nullptr, {}});
  ASSERT_EQ(r.points.size(), 2u);
  ASSERT_TRUE(r.points[0].ok && r.points[1].ok);
  EXPECT_LT(r.points[0].metrics[0], r.points[1].metrics[0]);  // deeper tool, deeper strip
  EXPECT_LT(r.points[0].metrics[1], r.points[1].metrics[1]);  // and a larger force
  // An unknown input of the kind is an input error naming the key.
  std::ofstream(sweep) << "[sweep]\nscene = \"" << scene.string() << "\"\nmetrics = [\"peak_fz\"]\n[inputs.\"tool.dept\"]\nvalues = [1.0]\n";
  EXPECT_THROW(inverse::read_sweep_file(sweep.string()), io::InputError);
  fs::remove(scene);
  fs::remove(sweep);
}

}  // namespace
