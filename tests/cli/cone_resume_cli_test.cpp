// spifit run --resume (docs/cli.md; docs/cone-scene.md, "Checkpoints and resume"): a cone run
// killed with SIGKILL after its first checkpoint and resumed ends with the force.csv and
// contours.csv of an uninterrupted run, byte for byte; --resume refuses other scene kinds, a
// missing directory or checkpoint, and --force, with exit code 2 and one line naming the
// file or option.
#include "tests/cli/cli_support.hpp"
#include "forward/io/text_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("spifit_resume_cli_" + std::to_string(::getpid()) + "_" + name); }

// A smaller cousin of the tiny cone of cone_tests (top radius 12 mm, 6 elements per 45 deg: 72
// elements, about 2.5 s for two contours).
fs::path write_scene(const std::string& name, int contours, const std::string& extra = "") {
  const fs::path f = temp(name + ".toml");
  std::ofstream(f) << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                   << "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = " << contours << "\ntop_radius = 12.0\npie_angle = 90.0\n"
                   << "[sheet]\nthickness = 1.0\nelements_per_45deg = 6\nthickness_points = 3\n[solver]\ntravel_per_increment = 0.5\n"
                   << extra;
  return f;
}

std::string slurp(const fs::path& f) { return spifit::io::read_text_file(f.string()); }

TEST(ConeResumeCli, RefusesWhatItCannotResume) {
  const std::string tensile = std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/tensile_00.toml";
  const fs::path out = temp("refused");
  fs::remove_all(out);
  auto r = spifit::test::run_spifit("run " + tensile + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not supported for scene kind tensile"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  const fs::path scene = write_scene("nockpt", 1, "[output]\ncheckpoint_every = 0\n");
  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--out = " + out.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume --force");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("excludes"), std::string::npos) << r.err;

  // A finished run without checkpoints.
  r = spifit::test::run_spifit("-q run " + scene.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "checkpoint"));
  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find((out / "checkpoint" / "state.bin").string() + ": cannot resume: no checkpoint"), std::string::npos) << r.err;
  fs::remove_all(out);
  fs::remove(scene);
}

TEST(ConeResumeCli, AKilledRunResumesToTheUninterruptedResult) {
  const fs::path scene = write_scene("two", 2);
  const fs::path ref = temp("ref"), out = temp("killed");
  fs::remove_all(ref);
  fs::remove_all(out);
  auto r = spifit::test::run_spifit("-q run " + scene.string() + " --out " + ref.string());
  ASSERT_EQ(r.code, 0) << r.err;

  // Start the same run and kill it (SIGKILL) a little after its first checkpoint appears.
  const fs::path state = out / "checkpoint" / "state.bin";
  const bool killed = spifit::test::run_and_kill(scene, out, state, std::chrono::milliseconds(700));  // into contour 2
  ASSERT_TRUE(fs::exists(state)) << "no checkpoint appeared";
  std::printf("run %s; force.csv then had %zu bytes (uninterrupted: %zu)\n", killed ? "killed by SIGKILL" : "finished before the kill",
              slurp(out / "force.csv").size(), slurp(ref / "force.csv").size());
  if (killed) {
    const auto s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
    EXPECT_EQ(s["status"], "running");
  }

  // An existing directory is not replaced without --force or --resume.
  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2/2 contours"), std::string::npos) << r.out;
  spifit::test::expect_same_run(ref, out, {"force.csv", "contours.csv", "sections/section_s1_c001.csv", "sections/section_s1_c002.csv", "vtu/sheet.pvd"},
                                {"status", "increments", "newton_iterations", "cutbacks", "factorisations", "peak_force", "final_force", "max_penetration"});
  fs::remove_all(ref);
  fs::remove_all(out);
  fs::remove(scene);
}

}  // namespace
