// A cone on a pie whose centre is coarsened (sheet.coarse_inside): the floor the tool never
// reaches has half the elements around, and the contour means stay with the regular mesh's
// (two short cone runs, about 30 s: label long).
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
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

}  // namespace
}  // namespace spifit::scene
