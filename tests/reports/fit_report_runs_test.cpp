// The report's forward runs, information shares and FE scalars, each on a bundled material-point
// fit run here into its own directory (fit_classic without its per-experiment sub-fits, and
// fit_n_conflict, whose r45 is a plain scalar).
#include "tests/support/markdown_rows.hpp"
#include "tests/support/temp_files.hpp"
#include "forward/io/output_directory.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_output.hpp"
#include "inverse/fit/run_fit.hpp"
#include "reports/fit_report.hpp"
#include "reports/report_format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace spifit;

namespace {

using spifit::test::md_row;
using spifit::test::slurp;

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// The output of a bundled fit, run into a fresh temporary directory; per_experiment as given;
// whether the fit is usable as expected (fit_n_conflict is not).
fs::path own_fit(const std::string& name, const std::string& fit_file, bool per_experiment, bool usable = true) {
  const fs::path d = test::fresh_temp_path("report_" + name);
  auto problem = inverse::read_fit_file(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/" + fit_file);
  problem.per_experiment = per_experiment;
  const auto result = inverse::run_fit(problem, {"", 2});
  EXPECT_EQ(result.usable, usable) << result.termination;
  inverse::write_fit_outputs(problem, result, io::OutputDirectory::prepare(d.string(), false));
  return d;
}

// The forward runs per experiment (evaluations; a material-point fit has no scene runs) and the
// share of each parameter's Fisher information per experiment, as fit.json gives them (fit_classic
// without the per-experiment sub-fits, whose evaluations forward_runs would count too).
TEST(FitReportRuns, ForwardRunsAndInformationSharesAsInFitJson) {
  const fs::path d = own_fit("runs", "fit_classic.toml", false);
  reports::render_fit_report(d, {false});
  const std::string md = slurp(d / "report.md");
  const json j = json::parse(slurp(d / "fit.json"));
  const std::string runs = test::md_section(md, "## Forward runs"), info = test::md_section(md, "### Which experiment informs which parameter");
  ASSERT_FALSE(runs.empty()) << md;
  ASSERT_FALSE(info.empty()) << md;
  long evaluations = 0;
  for (const auto& e : j["experiments"]) {
    const std::string name = e["name"];
    EXPECT_EQ(e.count("scene_runs"), 0u) << name << ": no FE scene";
    const auto row = md_row(runs, name);
    ASSERT_EQ(row.size(), 4u) << name << "\n" << runs;
    EXPECT_EQ(row[2], std::to_string(e["evaluations"].get<long>())) << name;
    EXPECT_EQ(e["jacobian"], "jets") << name;
    EXPECT_EQ(row[3], "exact (Jets)") << name;
    evaluations += e["evaluations"].get<long>();
    const auto shares = md_row(info, name);
    ASSERT_EQ(shares.size(), 7u) << name << "\n" << info;
    int k = 1;
    for (const auto& q : j["correlation"]["names"]) {
      const double share = e["information_share"][q.get<std::string>()].get<double>();
      EXPECT_EQ(shares[static_cast<std::size_t>(k++)], reports::format_percent(share)) << name << " " << q;
    }
  }
  // Every experiment is evaluated for each of the fit's residual evaluations, and once more at
  // the start (its check): forward_runs counts the former per experiment.
  EXPECT_EQ(evaluations, j["forward_runs"].get<long>() + static_cast<long>(j["experiments"].size()));
  // A column of shares adds up to 1; an r-value does not depend on the hardening law.
  for (const auto& q : j["correlation"]["names"]) {
    double sum = 0.0;
    for (const auto& e : j["experiments"]) sum += e["information_share"][q.get<std::string>()].get<double>();
    EXPECT_NEAR(sum, 1.0, 1e-12) << q;
  }
  for (const auto& e : j["experiments"]) {
    if (e["kind"] == "scalar" || e["kind"] == "scalar_table") {
      EXPECT_LT(e["information_share"]["swift.K"].get<double>(), 1e-12) << e["name"];
    }
  }
}

// An FE scene's scalar observable (kind fe_scalar, e.g. peak_fz in N) is reported like a
// material point's scalar: a row of the scalar table and a bar, no curve plots.
TEST(FitReportRuns, FeScalarsAreScalars) {
  const fs::path d = own_fit("fe_scalar", "fit_n_conflict.toml", false, false);  // the scalar r45 and a shear curve
  json j = json::parse(slurp(d / "fit.json"));
  for (auto& e : j["experiments"]) {
    if (e["name"] != "r45") continue;
    e["kind"] = "fe_scalar";
    e["y"] = "peak_fz";
    e["y_unit"] = "N";
  }
  write(d / "fit.json", j.dump(2));
  reports::render_fit_report(d, {false});
  const std::string md = slurp(d / "report.md");
  const auto row = md_row(test::md_section(md, "### Scalar experiments"), "r45");
  ASSERT_EQ(row.size(), 7u) << md;
  EXPECT_EQ(row[1], "peak_fz [N]");
  EXPECT_EQ(test::md_section(md, "## Curves: data and fit").find("### r45"), std::string::npos);
}

}  // namespace
