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

}  // namespace
