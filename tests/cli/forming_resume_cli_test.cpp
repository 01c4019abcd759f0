// spifit run --resume on a forming scene (docs/reference/cli.md): a line run killed with SIGKILL after
// its first checkpoint and resumed ends with the force.csv, energies.csv and sections of an
// uninterrupted run, byte for byte.
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

TEST(FormingResumeCli, AKilledLineRunResumesToTheUninterruptedResult) {
  const fs::path scene = spifit::test::write_tiny_line(temp_path("line.toml"), "checkpoint_increments = 5\n");
  const fs::path ref = temp_path("ref"), out = temp_path("killed");
  fs::remove_all(ref);
  fs::remove_all(out);
  const auto t0 = std::chrono::steady_clock::now();
  auto r = spifit::test::run_spifit("-q run " + scene.string() + " --out " + ref.string());
  const auto ref_time = std::chrono::steady_clock::now() - t0;
  ASSERT_EQ(r.code, 0) << r.err;
  const auto ref_rows = spifit::test::read_csv_rows(ref / "force.csv").size();

  // The first checkpoint comes after 5 of about 100 increments; the kill a fifth of the whole
  // run's time later, about a quarter into the path, whatever the machine's speed (the run
  // would have to go 4 times faster than the reference run to finish first).
  const fs::path state = out / "checkpoint" / "state.bin";
  const auto delay = std::chrono::duration_cast<std::chrono::milliseconds>(ref_time / 5);
  const bool killed = spifit::test::run_and_kill(scene, out, state, delay);
  ASSERT_TRUE(fs::exists(state)) << "no checkpoint appeared";
  const auto partial_rows = spifit::test::read_csv_rows(out / "force.csv").size();
  std::printf("line run of %.2f s %s %lld ms after its first checkpoint; force.csv then had %zu rows (uninterrupted: %zu)\n",
              std::chrono::duration<double>(ref_time).count(), killed ? "killed by SIGKILL" : "finished before the kill",
              static_cast<long long>(delay.count()), partial_rows, ref_rows);
  ASSERT_TRUE(killed) << "the run finished before the kill: nothing was resumed";
  EXPECT_LT(partial_rows, ref_rows);
  EXPECT_EQ(spifit::test::read_summary(out)["status"], "running");

  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GE(spifit::test::read_summary(out)["resumed_at_mark"].get<int>(), 0);
  spifit::test::expect_same_run(ref, out, {"force.csv", "energies.csv", "sections/section_C.csv", "sections/section_E.csv", "vtu/sheet.pvd"},
                                {"status", "increments", "newton_iterations", "cutbacks", "peak_force", "final_force", "max_penetration", "energies"});
  fs::remove_all(ref);
  fs::remove_all(out);
  fs::remove(scene);
}

// README: `spifit run SCENE --out DIR --resume` into the directory of another scene names both
// scenes (exit 2), with a checkpoint there or without one.
TEST(FormingResumeCli, ResumeIntoTheDirectoryOfAnotherSceneNamesBoth) {
  const fs::path line = spifit::test::write_tiny_line(temp_path("line.toml"), "checkpoint_increments = 5\n");
  const fs::path out = spifit::test::fresh_temp_path("line_out");
  auto r = spifit::test::run_spifit("-q run " + line.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_TRUE(fs::exists(out / "checkpoint" / "state.bin"));
  const std::string indent = std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml";
  r = spifit::test::run_spifit("run " + indent + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("state.bin: cannot resume: the checkpoint is of scene " + line.string() + " (kind line), not of scene " + indent +
                       " (kind indent): resume with that scene, or run this one in another output directory\n"),
            std::string::npos)
      << r.err;
  // Another scene of the same kind: compared by contents (a copy with the same contents resumes).
  std::string text = spifit::test::slurp(line);
  const fs::path other = spifit::test::write_temp_file("other_line.toml", text.replace(text.find("z = -5.0"), 8, "z = -4.0"));
  r = spifit::test::run_spifit("run " + other.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("written with another scene: the contents of " + other.string() + " differ from those of " + line.string()), std::string::npos)
      << r.err;

  // A directory without a checkpoint, of a tensile run.
  const std::string tensile = std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/tensile_00.toml";
  fs::remove_all(out);
  ASSERT_EQ(spifit::test::run_spifit("-q run " + tensile + " --out " + out.string()).code, 0);
  r = spifit::test::run_spifit("run " + line.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("state.bin: cannot resume: no checkpoint, and the run in " + out.string() + " is of scene " + tensile +
                       " (kind tensile), not of scene " + line.string() + " (kind line): run this one in another output directory\n"),
            std::string::npos)
      << r.err;
  fs::remove_all(out);
  fs::remove(line);
  fs::remove(other);
}

}  // namespace
