// --force removes only what spifit wrote: the entries DIR/.spifit-manifest lists (or, in a
// directory of an older spifit without one, the entries with spifit's output names); a user's
// own files stay, with a warning (docs/reference/file-formats.md, "Output directories").
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using spifit::test::run_spifit;

std::string scene(const std::string& name) { return std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + name; }

TEST(ForceManifestCli, ForceKeepsAUsersFile) {
  const fs::path out = spifit::test::fresh_temp_path("force_keeps");
  auto r = run_spifit("-q run " + scene("tensile_45.toml") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string manifest = spifit::test::slurp(out / ".spifit-manifest");
  EXPECT_NE(manifest.find("\nsummary.json\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\ncurve.csv\n"), std::string::npos) << manifest;

  // The user's notes beside the results, and a directory of their own.
  std::ofstream(out / "notes.txt") << "my notes";
  fs::create_directories(out / "mine");
  std::ofstream(out / "mine" / "plot.py") << "print(1)";
  r = run_spifit("run " + scene("tensile_00.toml") + " --out " + out.string() + " --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(spifit::test::slurp(out / "notes.txt"), "my notes");
  EXPECT_TRUE(fs::exists(out / "mine" / "plot.py"));
  EXPECT_NE(r.err.find("spifit: warning: --out = " + out.string() + ": kept mine, notes.txt (not written by spifit"), std::string::npos) << r.err;
  EXPECT_EQ(spifit::test::read_summary(out)["angle_deg"].get<double>(), 0.0);
  // The kept files stay out of the new manifest: a third run keeps them too.
  EXPECT_EQ(spifit::test::slurp(out / ".spifit-manifest").find("notes.txt"), std::string::npos);
  r = run_spifit("-q run " + scene("tensile_45.toml") + " --out " + out.string() + " --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << "-q: no warning: " << r.err;
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  fs::remove_all(out);
}

// An FE run lists the directories it writes by other means than one file at a time (vtu/).
TEST(ForceManifestCli, DirectoriesOfAnFeRunAreListed) {
  const fs::path out = spifit::test::fresh_temp_path("force_fe");
  auto r = run_spifit("-q run " + std::string(SPIFIT_SOURCE_DIR) + "/experiments/benchmarks/cantilever_shear.toml --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(spifit::test::slurp(out / ".spifit-manifest").find("\nvtu/\n"), std::string::npos);
  std::ofstream(out / "notes.txt") << "my notes";
  r = run_spifit("-q run " + std::string(SPIFIT_SOURCE_DIR) + "/experiments/benchmarks/cantilever_shear.toml --out " + out.string() + " --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_TRUE(fs::exists(out / "vtu"));
  fs::remove_all(out);
}

// A directory of an older spifit (summary.json, no manifest): its outputs go, the rest stays.
TEST(ForceManifestCli, WithoutAManifestOnlySpifitNamesAreRemoved) {
  const fs::path out = spifit::test::fresh_temp_path("force_old");
  fs::create_directories(out / "vtu");
  std::ofstream(out / "summary.json") << "{}";
  std::ofstream(out / "curve.csv") << "x\n";
  std::ofstream(out / "vtu" / "shell.pvd") << "<pvd/>";
  std::ofstream(out / "notes.txt") << "my notes";
  auto r = run_spifit("run " + scene("tensile_00.toml") + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("pass --force to replace it"), std::string::npos) << r.err;
  r = run_spifit("run " + scene("tensile_00.toml") + " --out " + out.string() + " --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "vtu"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_NE(r.err.find("kept notes.txt"), std::string::npos) << r.err;
  fs::remove_all(out);

  // Neither a manifest nor a summary: not spifit's, refused as before.
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "my notes";
  r = run_spifit("run " + scene("tensile_00.toml") + " --out " + out.string() + " --force");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("only a spifit output directory (one with .spifit-manifest or summary.json) is replaced"), std::string::npos) << r.err;
  fs::remove_all(out);
}

// A manifest line never reaches outside the directory.
TEST(ForceManifestCli, ManifestLinesStayInsideTheDirectory) {
  const fs::path base = spifit::test::fresh_temp_path("force_escape");
  const fs::path out = base / "out";
  fs::create_directories(out);
  std::ofstream(base / "outside.txt") << "keep";
  std::ofstream(out / ".spifit-manifest") << "# spifit\n../outside.txt\n..\n/\nsummary.json\n";
  std::ofstream(out / "summary.json") << "{}";
  const auto r = run_spifit("-q run " + scene("tensile_00.toml") + " --out " + out.string() + " --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(base / "outside.txt"));
  fs::remove_all(base);
}

}  // namespace
