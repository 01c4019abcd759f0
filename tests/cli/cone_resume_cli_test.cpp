// spifit run --resume (docs/reference/cli.md; docs/design/architecture.md, "Checkpoints and resume"): a cone run
// killed with SIGKILL after its first checkpoint and resumed ends with the force.csv and
// contours.csv of an uninterrupted run, byte for byte; --resume refuses other scene kinds, a
// missing directory or checkpoint, and --force, with exit code 2 and one line naming the
// file or option.
#include "tests/cli/cli_support.hpp"
#include "tests/support/csv_rows.hpp"
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using spifit::test::temp_path;

// The small tiny cone (top radius 12 mm, 6 elements per 45 deg: 72 elements, about 2.5 s for two
// contours).
fs::path write_scene(const std::string& name, int contours, const std::string& extra = "") {
  return spifit::test::write_tiny_cone(temp_path(name + ".toml"), extra, spifit::test::small_tiny_cone(contours));
}

TEST(ConeResumeCli, RefusesWhatItCannotResume) {
  const std::string tensile = std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/tensile_00.toml";
  const fs::path out = temp_path("refused");
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

  // A finished run (here without checkpoints): complete, nothing to resume.
  r = spifit::test::run_spifit("-q run " + scene.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "checkpoint"));
  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("the run in this directory is complete (summary.json: status ok): nothing to resume"), std::string::npos) << r.err;
  fs::remove_all(out);
  fs::remove(scene);
}

TEST(ConeResumeCli, AKilledRunResumesToTheUninterruptedResult) {
  const fs::path scene = write_scene("two", 2);
  const fs::path ref = temp_path("ref"), out = temp_path("killed");
  fs::remove_all(ref);
  fs::remove_all(out);
  const auto t0 = std::chrono::steady_clock::now();
  auto r = spifit::test::run_spifit("-q run " + scene.string() + " --out " + ref.string());
  const auto ref_time = std::chrono::steady_clock::now() - t0;
  ASSERT_EQ(r.code, 0) << r.err;
  const auto ref_rows = spifit::test::read_csv_rows(ref / "force.csv").size();

  // Start the same run and kill it (SIGKILL) after its first checkpoint (the end of contour 1,
  // about half way) appears, a fifth of the whole run's time later: into contour 2, whatever
  // the machine's speed (the run would have to go 2.5 times faster than the reference run to
  // finish first).
  const fs::path state = out / "checkpoint" / "state.bin";
  const auto delay = std::chrono::duration_cast<std::chrono::milliseconds>(ref_time / 5);
  const bool killed = spifit::test::run_and_kill(scene, out, state, delay);
  ASSERT_TRUE(fs::exists(state)) << "no checkpoint appeared";
  const auto partial_rows = spifit::test::read_csv_rows(out / "force.csv").size();
  std::printf("run of %.2f s %s %lld ms after its first checkpoint; force.csv then had %zu rows (uninterrupted: %zu)\n",
              std::chrono::duration<double>(ref_time).count(), killed ? "killed by SIGKILL" : "finished before the kill",
              static_cast<long long>(delay.count()), partial_rows, ref_rows);
  ASSERT_TRUE(killed) << "the run finished before the kill: nothing was resumed";
  EXPECT_LT(partial_rows, ref_rows);
  EXPECT_EQ(spifit::test::read_summary(out)["status"], "running");

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
