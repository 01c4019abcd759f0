// spifit run on the bundled shell benchmarks (experiments/benchmarks): every summary within
// 2 % of its reference; bad settings exit 2 with one line; a failed run keeps its outputs.
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
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using Result = spifit::test::CliResult;
Result run(const std::string& args) { return spifit::test::run_spifit(args); }

fs::path fresh_dir(const std::string& name) { return spifit::test::fresh_temp_path(name); }

std::string write_temp(const std::string& name, const std::string& text) { return spifit::test::write_temp_file(name, text).string(); }

nlohmann::json summary(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "summary.json")); }

TEST(ShellBenchmarkCli, EveryBundledBenchmarkIsWithinTwoPercent) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SPIFIT_SOURCE_DIR) / "experiments/benchmarks")) {
    if (entry.path().extension() != ".toml") continue;
    const fs::path out = fresh_dir(entry.path().stem().string());
    const Result r = run("run " + entry.path().string() + " --out " + out.string());
    ASSERT_EQ(r.code, 0) << entry.path() << "\n" << r.err;
    const auto s = summary(out);
    EXPECT_EQ(s["status"], "ok");
    EXPECT_LT(std::abs(s["relative_error"].get<double>()), 0.02) << entry.path();
    EXPECT_NEAR(s["value"].get<double>() / s["reference"].get<double>() - 1.0, s["relative_error"].get<double>(), 1e-12);
    EXPECT_TRUE(fs::exists(out / "increments.csv"));
    EXPECT_TRUE(fs::exists(out / "vtu" / "shell.pvd"));
    fs::remove_all(out);
    ++count;
  }
  EXPECT_GE(count, 11);
}

TEST(ShellBenchmarkCli, BadSettingsExitTwoNamingFileKeyAndValue) {
  struct Case { std::string text, must_contain; };
  const Case cases[] = {
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"scordelis\"\n", "benchmark"},
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"scordelis_lo\"\nthickness_points = 12\n", "thickness_points"},
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"scordelis_lo\"\nmesh = 0\n", "mesh"},
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"rollup\"\nmesh = 7\n", "even number"},
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"rollup\"\n[solver]\nmax_increment = 2\n", "max_increment"},
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"rollup\"\n[solver]\nlinear_solver = \"lu\"\n", "linear_solver"},
      {"[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"rollup\"\nmeshes = 4\n", "meshes"},
  };
  for (const auto& c : cases) {
    const std::string file = write_temp("bad.toml", c.text);
    const fs::path out = fresh_dir("bad");
    const Result r = run("run " + file + " --out " + out.string());
    EXPECT_EQ(r.code, 2) << c.text;
    EXPECT_NE(r.err.find(c.must_contain), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
    fs::remove(file);  // the scene files are written to the shared temp directory
  }
}

TEST(ShellBenchmarkCli, NonConvergenceStopsWithWhereAndWhyAndKeepsOutputs) {
  // One Newton iteration per increment cannot follow the plastic strip: the increment is cut
  // back to the minimum and the run stops, keeping the increments and VTU files written.
  const std::string file = write_temp("stuck.toml",
                                      "[scene]\nkind = \"shell_benchmark\"\nbenchmark = \"limit_moment\"\nmesh = 4\n"
                                      "[solver]\ninitial_increment = 0.01\nmin_increment = 0.001\nmax_iterations = 2\n"
                                      "[output]\nvtu_every = 1\n");
  const fs::path out = fresh_dir("stuck");
  const Result r = run("run " + file + " --out " + out.string());
  EXPECT_EQ(r.code, 1) << r.err;
  const auto s = summary(out);
  EXPECT_EQ(s["status"], "failed");
  const std::string msg = s["message"];
  EXPECT_NE(msg.find("minimum increment"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no convergence in 2 iterations"), std::string::npos) << msg;
  EXPECT_NE(r.err.find("minimum increment"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "increments.csv"));
  EXPECT_TRUE(fs::exists(out / "vtu" / "shell.pvd"));
  fs::remove_all(out);
  fs::remove(file);
}

}  // namespace
