// Yld2000-2d in a shell scene: the tiny line test with Yld2000-2d at a = 2 and every alpha 1 gives
// the tool forces of the same card with von Mises (Hill 1948 at its defaults), and an
// anisotropic a = 8 card runs to the end.
#include "forward/io/output_directory.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

FormingResult run_with(material::MaterialParams<double> params, const std::string& name) {
  FormingScene s = read_forming_scene(test::write_tiny_line(test::temp_path(name + ".toml")).string());
  s.card.params = params;
  const fs::path dir = test::temp_path(name);
  fs::remove_all(dir);
  return run_forming_scene(s, RunFiles(io::OutputDirectory::prepare(dir.string(), false)), {});
}

material::MaterialParams<double> c3c4() {
  return read_forming_scene(test::write_tiny_line(test::temp_path("c3c4_line.toml")).string()).card.params;
}

TEST(Yld2000Line, ExponentTwoGivesTheVonMisesForces) {
  auto vm = c3c4();
  vm.F = vm.G = vm.H = 1.0;
  vm.L = vm.M = vm.N = 3.0;
  auto yld = vm;
  yld.yield = material::make_yield_function<material::Yld2000_2d>({1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0});
  const FormingResult a = run_with(vm, "vm_line"), b = run_with(yld, "yld_line");
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  const auto& fa = a.force.samples();
  const auto& fb = b.force.samples();
  ASSERT_EQ(fa.size(), fb.size());
  const double scale = a.force.peak().norm();
  ASSERT_GT(scale, 1.0);
  double worst = 0.0;
  for (std::size_t i = 0; i < fa.size(); ++i) worst = std::max(worst, (fa[i].force - fb[i].force).norm());
  // The two return mappings agree to about 1e-12 of the stress; Newton's last iterate of each
  // increment carries that to the forces.
  EXPECT_LT(worst, 1e-6 * scale) << "largest force difference " << worst << " N of peak " << scale << " N";
}

TEST(Yld2000Line, AnisotropicCardRunsToTheEnd) {
  auto p = c3c4();
  p.yield = material::make_yield_function<material::Yld2000_2d>({1.01, 0.909, 1.0, 1.0, 1.015, 1.0, 1.09, 1.41, 8.0});
  const FormingResult r = run_with(p, "yld8_line");
  ASSERT_TRUE(r.ok()) << r.message;
  auto vm = c3c4();
  const FormingResult h = run_with(vm, "hill_line");
  ASSERT_TRUE(h.ok()) << h.message;
  // The same sheet and path: forces of the same size (both cards have the RD yield stress of
  // Table C.4), not the same values.
  const double ry = r.force.peak().norm(), rh = h.force.peak().norm();
  EXPECT_GT(ry, 0.8 * rh);
  EXPECT_LT(ry, 1.2 * rh);
}

}  // namespace
}  // namespace spifit::scene
