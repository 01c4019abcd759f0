// A cone on a pie whose centre is coarsened (sheet.coarse_inside): the floor the tool never
// reaches has half the elements around, and the contour means stay with the regular mesh's; the
// key's limits are input errors.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

ConeResult run(const ConeScene& s, const std::string& name) {
  const fs::path d = test::fresh_temp_path(name);
  ConeResult r = run_cone_scene(s, RunFiles(io::OutputDirectory::prepare(d.string(), false)));
  fs::remove_all(d);
  return r;
}

TEST(CoarsenedCone, ShortConeContourMeansStayWithTheRegularMesh) {
  const ConeScene regular = read_cone_scene(src("experiments/aa3003o/scenes/cone70_pie45_short.toml"));
  ConeScene coarse = regular;
  coarse.mesh.coarse_inside = 70.0;
  const ConeResult a = run(regular, "regular"), b = run(coarse, "coarse");
  ASSERT_TRUE(a.ok());
  ASSERT_TRUE(b.ok());
  ASSERT_EQ(a.contours.size(), 3u);
  ASSERT_EQ(b.contours.size(), 3u);
  // Measured: 312 elements against 528 and 12 hanging nodes; contour 1 and 3 mean Fz within
  // 0.2 % (822.9 / 1 015.9 N regular), the barely touched contour 2 +4.3 % (246.0 N).
  EXPECT_EQ(b.elements, 312);
  EXPECT_EQ(b.to_json()["model"]["hanging_nodes"].get<int>(), 12);
  for (std::size_t k = 0; k < 3; ++k) {
    const double fa = a.contours[k].force.z(), fb = b.contours[k].force.z();
    std::printf("contour %zu mean Fz regular %.2f N, coarsened centre %.2f N (%+.2f %%)\n", k + 1, fa, fb, 100.0 * (fb / fa - 1.0));
    EXPECT_NEAR(fb / fa, 1.0, k == 1 ? 0.06 : 0.005) << "contour " << k + 1;
  }
}

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
