// spifit run on the FE forming scenes: the bundled §7.1 indent, and input errors (G-code,
// paths) that exit 2 with one line naming the file, before the output directory is touched.
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using Result = spifit::test::CliResult;
Result run(const std::string& args) { return spifit::test::run_spifit(args); }

using spifit::test::temp_path;

TEST(FormingCli, IndentWritesForceSummaryAndVtu) {
  const fs::path out = temp_path("indent");
  fs::remove_all(out);
  const Result r = run("run " + std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["status"], "ok");
  EXPECT_NEAR(s["final_force"][2].get<double>(), 289.40, 0.05);  // K_p = 1e3 (docs/results/validation.md)
  EXPECT_GT(s["max_penetration"].get<double>(), 0.0);
  std::ifstream f(out / "force.csv");
  int lines = 0;
  for (std::string l; std::getline(f, l);) ++lines;
  EXPECT_EQ(lines, 2 + s["increments"].get<int>());
  EXPECT_TRUE(fs::exists(out / "vtu" / "sheet.pvd"));
  fs::remove_all(out);
}

TEST(FormingCli, MalformedGcodeExitsTwoNamingFileAndLine) {
  const fs::path nc = temp_path("bad.nc");
  std::ofstream(nc) << "G21 G90\nG00 X0 Y0 Z0\nG41 X1\n";
  const fs::path scene = temp_path("bad.toml");
  std::ofstream(scene) << "[scene]\nkind = \"indent\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                       << "[tool]\ngcode = \"" << nc.string() << "\"\n";
  const fs::path out = temp_path("bad_out");
  fs::remove_all(out);
  const Result r = run("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(nc.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("G41"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(nc);
  fs::remove(scene);
}

}  // namespace
