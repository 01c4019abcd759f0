// spifit run --sensitivities: the tool force's exact parameter derivatives beside force.csv, and
// the refusals (unknown or absent parameters, kinds and options without sensitivities), which
// exit 2 naming the file, the option and its value, before the output directory is touched.
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = spifit::test::CliResult;
Result run(const std::string& args) { return spifit::test::run_spifit(args); }
using spifit::test::slurp;
using spifit::test::temp_path;

const std::string kScenes = std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/";

// The numbers of the ascii DataArray `name` of a VTU file's text; empty when there is none.
std::vector<double> data_array(const std::string& vtu, const std::string& name) {
  const auto at = vtu.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const auto begin = vtu.find('>', at) + 1, end = vtu.find("</DataArray>", begin);
  std::stringstream ss(vtu.substr(begin, end - begin));
  std::vector<double> v;
  for (double x; ss >> x;) v.push_back(x);
  return v;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
  return out;
}

TEST(SensitivityCli, IndentWritesDerivativesBesideUnchangedForces) {
  const fs::path out = temp_path("indent_sens");
  fs::remove_all(out);
  const Result r = run("run " + kScenes + "indent.toml --out " + out.string() + " --sensitivities swift.K,elastic.E");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_NEAR(s["final_force"][2].get<double>(), 289.40, 0.05);  // as without sensitivities
  EXPECT_EQ(s["sensitivities"], nlohmann::json::array({"swift.K", "elastic.E"}));
  // The DDM's solves: one per parameter and increment, by GMRES on Newton's factor unless a
  // factorisation of the exact tangent had to serve.
  const auto& solves = s["sensitivity_solves"];
  EXPECT_EQ(solves["increments"], s["increments"]);
  const int gmres = solves["gmres_solves"].get<int>(), increments = s["increments"].get<int>();
  EXPECT_GT(gmres, 0);
  EXPECT_LE(gmres, 2 * increments);
  EXPECT_GE(solves["gmres_iterations"].get<int>(), gmres);
  if (gmres < 2 * increments) EXPECT_GE(solves["factorisations"].get<int>(), 1);
  EXPECT_GT(solves["seconds"].get<double>(), 0.0);
  std::ifstream f(out / "sensitivities.csv");
  std::vector<std::string> lines;
  for (std::string l; std::getline(f, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 2u + s["increments"].get<std::size_t>());
  const std::vector<std::string> header = split(lines[1]), last = split(lines.back());
  ASSERT_EQ(header.size(), 14u);
  EXPECT_EQ(header[4], "dFz/d(swift.K) [N/MPa]");
  EXPECT_EQ(header[7], "swift.K*dFz/d(swift.K) [N]");
  // Swift's stress scales with K, so K dFz/dK lies just below Fz (289.40 N) at the end: 282.82 N
  // by direct differentiation (checked against central differences in shell_model_sensitivity_test).
  EXPECT_NEAR(std::stod(last[7]), 282.82, 0.01);
  EXPECT_NEAR(std::stod(last[4]) * 180.0, std::stod(last[7]), 1e-9 * std::stod(last[7]));  // K = 180 MPa (card C.4)
  // The terminal says it too, beside the run's line: at the peak Fz, the indent's last increment.
  EXPECT_NE(r.out.find("sensitivities of the peak Fz (289.40 N at t = "), std::string::npos) << r.out;
  const auto k_line = r.out.find("    swift.K ");
  ASSERT_NE(k_line, std::string::npos) << r.out;
  const std::string said = r.out.substr(k_line, r.out.find('\n', k_line) - k_line);
  EXPECT_NE(said.find("N/MPa"), std::string::npos) << said;
  EXPECT_NE(said.find("p dFz/dp      282.8 N"), std::string::npos) << said;
  EXPECT_NE(r.out.find("    elastic.E "), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out / "plots" / "run_sensitivities.svg"));  // the run report's plot
  // The final VTU step carries the displacement's derivatives, raw and scaled by the value.
  const std::string vtu = slurp(out / "vtu" / "sheet_000001.vtu");
  const std::vector<double> u = data_array(vtu, "displacement"), du = data_array(vtu, "d(displacement)/d(swift.K)"),
                            scaled = data_array(vtu, "swift.K*d(displacement)/d(swift.K)");
  ASSERT_EQ(du.size(), u.size());
  ASSERT_EQ(scaled.size(), u.size());
  EXPECT_EQ(data_array(vtu, "d(displacement)/d(elastic.E)").size(), u.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < du.size(); ++i) {
    EXPECT_NEAR(scaled[i], 180.0 * du[i], 1e-12 + 1e-9 * std::abs(scaled[i])) << i;
    largest = std::max(largest, std::abs(du[i]));
  }
  EXPECT_GT(largest, 0.0);  // the sheet's shape around the tool moves with K
  fs::remove_all(out);
}

TEST(SensitivityCli, RefusalsNameFileOptionAndValueBeforeTheOutputDirectory) {
  const fs::path out = temp_path("sens_refused");
  struct Case {
    std::string scene, names, expect;
  } cases[] = {
      {kScenes + "indent.toml", "swift.X", "swift.X is not a material parameter"},
      {kScenes + "indent.toml", "af.CX", "no kinematic hardening"},
      {kScenes + "indent.toml", "swift.K,swift.K", "named twice"},
      {kScenes + "indent.toml", "contact.penalty,contact.penalty", "contact.penalty is named twice"},
      {kScenes + "tensile_00.toml", "swift.K", "FE scenes only"},
      {kScenes + "indent.toml", "tool.radius", "tool.radius has no exact sensitivity"},
      // Found by building the model without running it, still before the output directory.
      {kScenes + "indent_explicit.toml", "swift.K", "the explicit scheme has no exact sensitivities"},
  };
  for (const Case& c : cases) {
    fs::remove_all(out);
    const Result r = run("run " + c.scene + " --out " + out.string() + " --sensitivities " + c.names);
    EXPECT_EQ(r.code, 2) << c.names << ": " << r.err;
    EXPECT_NE(r.err.find(c.scene), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.scene;
  }
}

// A run with sensitivities killed after a checkpoint resumes with the same parameters to the
// uninterrupted run's derivatives; asked for others, the resume is refused naming both and the
// checkpoint, and DIR is left as it was.
TEST(SensitivityCli, AKilledRunResumesWithItsParametersAndRefusesOthers) {
  const fs::path scene = spifit::test::write_tiny_line(temp_path("sens_resume.toml"), "checkpoint_increments = 10\n");
  const fs::path ref = temp_path("sens_resume_ref"), out = temp_path("sens_resume");
  fs::remove_all(ref);
  const auto t0 = std::chrono::steady_clock::now();
  const Result a = run("-q run " + scene.string() + " --out " + ref.string() + " --sensitivities swift.K,contact.penalty");
  const auto ref_time = std::chrono::steady_clock::now() - t0;
  ASSERT_EQ(a.code, 0) << a.err;
  // Killed a fifth of the whole run's time after its first checkpoint (of about 10), as
  // forming_resume_cli_test does.
  fs::remove_all(out);
  const fs::path state = out / "checkpoint" / "state.bin";
  const bool killed = spifit::test::spifit_and_kill(
      {"-q", "run", scene.string(), "--out", out.string(), "--sensitivities", "swift.K,contact.penalty"}, [&] { return fs::exists(state); },
      std::chrono::duration_cast<std::chrono::milliseconds>(ref_time / 5));
  ASSERT_TRUE(killed) << "the run finished before the kill: nothing to resume";
  ASSERT_TRUE(fs::exists(state));
  const std::string before = slurp(out / "sensitivities.csv") + slurp(out / "summary.json");
  const Result other = run("-q run " + scene.string() + " --out " + out.string() + " --resume --sensitivities swift.K");
  EXPECT_EQ(other.code, 2) << other.err;
  EXPECT_NE(other.err.find("checkpoint/state.bin"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("sensitivities swift.K,contact.penalty, not swift.K"), std::string::npos) << other.err;
  EXPECT_EQ(slurp(out / "sensitivities.csv") + slurp(out / "summary.json"), before);
  const Result resumed = run("-q run " + scene.string() + " --out " + out.string() + " --resume --sensitivities swift.K,contact.penalty");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_EQ(slurp(out / "sensitivities.csv"), slurp(ref / "sensitivities.csv"));
  EXPECT_EQ(slurp(out / "force.csv"), slurp(ref / "force.csv"));
  // The solves' counts travel with the checkpoint: those of the whole run.
  const auto solves = spifit::test::read_summary(out)["sensitivity_solves"], ref_solves = spifit::test::read_summary(ref)["sensitivity_solves"];
  for (const char* k : {"increments", "gmres_solves", "gmres_iterations", "factorisations"}) EXPECT_EQ(solves[k], ref_solves[k]) << k;
  EXPECT_GT(solves["increments"].get<int>(), 50);
  fs::remove_all(ref);
  fs::remove_all(out);
  fs::remove(scene);
}

TEST(SensitivityCli, CheckerFindsExactAndCentralDifferencesAgreeOnTheIndent) {
  const Result r = run("-q check-sensitivities " + kScenes + "indent.toml --sensitivities swift.n,contact.penalty");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  std::stringstream ss(r.out);
  std::string line;
  std::getline(ss, line);  // header
  std::getline(ss, line);
  std::stringstream row(line);
  std::string name;
  double value, step, increments, difference, spread;
  row >> name >> value >> step >> increments >> difference >> spread;
  EXPECT_EQ(name, "swift.n");
  EXPECT_DOUBLE_EQ(value, 0.21);
  EXPECT_EQ(increments, 40);
  // Measured 1.0e-8 (exact against central differences with h / 4 = 5.25e-6) and a spread of the
  // central differences of 1.0e-9: the difference is the central differences' error.
  EXPECT_LT(difference, 1e-6);
  std::getline(ss, line);  // the penalty: measured 2.5e-7 against a spread of 2.4e-8
  std::stringstream penalty(line);
  penalty >> name >> value >> step >> increments >> difference >> spread;
  EXPECT_EQ(name, "contact.penalty");
  EXPECT_DOUBLE_EQ(value, 1000.0);
  EXPECT_LT(difference, 1e-6);
  EXPECT_NE(r.out.find("agree within"), std::string::npos) << r.out;
}

// --tolerance converges every run of the checker to it instead of the scene's tolerance: a loose one
// makes the central differences scatter (measured: their spread 5.0e-5 at 1e-3, 1.0e-9 at the scene's).
TEST(SensitivityCli, CheckerToleranceReachesEveryRun) {
  const Result r = run("-q check-sensitivities " + kScenes + "indent.toml --sensitivities swift.n --tolerance 1e-3");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  std::stringstream ss(r.out);
  std::string line, name;
  std::getline(ss, line);  // header
  std::getline(ss, line);
  double value, step, increments, difference, spread;
  std::stringstream(line) >> name >> value >> step >> increments >> difference >> spread;
  EXPECT_EQ(name, "swift.n");
  EXPECT_GT(spread, 1e-6);
  const Result bad = run("-q check-sensitivities " + kScenes + "indent.toml --sensitivities swift.n --tolerance 0.5");
  EXPECT_EQ(bad.code, 2);  // CLI11's range check: outside [0, 1e-3]
  EXPECT_NE(bad.err.find("--tolerance"), std::string::npos) << bad.err;
}

}  // namespace
