// spifit run --resume on a forming scene (docs/cli.md): a line run killed with SIGKILL after
// its first checkpoint and resumed ends with the force.csv, energies.csv and sections of an
// uninterrupted run, byte for byte.
#include "tests/cli/cli_support.hpp"
#include "forward/io/text_file.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("spifit_forming_resume_cli_" + std::to_string(::getpid()) + "_" + name); }

std::string slurp(const fs::path& f) { return fs::exists(f) ? spifit::io::read_text_file(f.string()) : std::string("(missing)"); }

TEST(FormingResumeCli, AKilledLineRunResumesToTheUninterruptedResult) {
  const fs::path scene = spifit::test::write_tiny_line(temp("line.toml"), "checkpoint_increments = 5\n");
  const fs::path ref = temp("ref"), out = temp("killed");
  fs::remove_all(ref);
  fs::remove_all(out);
  auto r = spifit::test::run_spifit("-q run " + scene.string() + " --out " + ref.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path state = out / "checkpoint" / "state.bin";
  const bool killed = spifit::test::run_and_kill(scene, out, state, std::chrono::milliseconds(300));
  ASSERT_TRUE(fs::exists(state)) << "no checkpoint appeared";
  std::printf("line run %s; force.csv then had %zu bytes (uninterrupted: %zu)\n", killed ? "killed by SIGKILL" : "finished before the kill",
              slurp(out / "force.csv").size(), slurp(ref / "force.csv").size());
  r = spifit::test::run_spifit("run " + scene.string() + " --out " + out.string() + " --resume");
  ASSERT_EQ(r.code, 0) << r.err;
  spifit::test::expect_same_run(ref, out, {"force.csv", "energies.csv", "sections/section_C.csv", "sections/section_E.csv", "vtu/sheet.pvd"},
                                {"status", "increments", "newton_iterations", "cutbacks", "peak_force", "final_force", "max_penetration", "energies"});
  fs::remove_all(ref);
  fs::remove_all(out);
  fs::remove(scene);
}

}  // namespace
