// The fit report: a real fit (fit_classic) is run once, written like `spifit fit --out DIR`
// does, and rendered; the report must show what fit.json says, the HTML must be well formed,
// plots must exist when gnuplot is there, and a broken gnuplot or fit.json is handled.
#include "tests/support/markdown_rows.hpp"
#include "tests/support/temp_files.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "inverse/fit/run_fit.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_output.hpp"
#include "reports/fit_report.hpp"
#include "reports/plot.hpp"
#include "reports/report_format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace spifit;

namespace {

using spifit::test::md_row;
using spifit::test::slurp;

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

bool have_gnuplot() { return !reports::find_executable("gnuplot").empty(); }

double rel_diff(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// Every element of the HTML is closed in order (void elements excepted).
bool html_well_formed(const std::string& html, std::string* why) {
  std::vector<std::string> stack;
  static const std::regex tag(R"(<(/?)([a-zA-Z][a-zA-Z0-9]*)[^>]*>)");
  const std::vector<std::string> void_tags{"meta", "img", "br", "hr", "link", "input"};
  for (std::sregex_iterator it(html.begin(), html.end(), tag), end; it != end; ++it) {
    const bool closing = (*it)[1] == "/";
    const std::string name = (*it)[2];
    if (std::find(void_tags.begin(), void_tags.end(), name) != void_tags.end()) continue;
    if (!closing) {
      stack.push_back(name);
    } else if (stack.empty() || stack.back() != name) {
      *why = "</" + name + "> closes " + (stack.empty() ? std::string("nothing") : "<" + stack.back() + ">");
      return false;
    } else {
      stack.pop_back();
    }
  }
  if (!stack.empty()) *why = "<" + stack.back() + "> is never closed";
  return stack.empty();
}

// The text of the element <table id="ID"> ... </table>.
std::string html_table(const std::string& html, const std::string& id) {
  const auto a = html.find("<table id=\"" + id + "\">");
  if (a == std::string::npos) return {};
  const auto b = html.find("</table>", a);
  return b == std::string::npos ? std::string() : html.substr(a, b - a);
}

class FitReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("spifit_report_test_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fit_dir_ = root_ / "fit";
    const auto problem = inverse::read_fit_file(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/fit_classic.toml");
    const auto result = inverse::run_fit(problem, {"", 2});
    ASSERT_TRUE(result.usable) << result.termination;
    const auto out = io::OutputDirectory::prepare(fit_dir_.string(), false);
    inverse::write_fit_outputs(problem, result, out);
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  // A copy of the fit output to modify.
  static fs::path copy_of_fit(const std::string& name) {
    const fs::path d = root_ / name;
    fs::remove_all(d);
    fs::copy(fit_dir_, d, fs::copy_options::recursive);
    return d;
  }
  static fs::path root_, fit_dir_;
};
fs::path FitReportTest::root_, FitReportTest::fit_dir_;

TEST_F(FitReportTest, MarkdownShowsTheNumbersOfFitJson) {
  const fs::path d = copy_of_fit("md");
  const auto s = reports::render_fit_report(d, {false});
  ASSERT_TRUE(fs::exists(d / "report.md"));
  EXPECT_EQ(s.markdown, d / "report.md");
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_TRUE(s.plots.empty());
  EXPECT_FALSE(fs::exists(d / "plots"));
  const std::string md = slurp(d / "report.md");
  const json j = json::parse(slurp(d / "fit.json"));

  EXPECT_NE(md.find("# Fit report: fit_classic"), std::string::npos);
  EXPECT_NE(md.find(j["fit_file"].get<std::string>()), std::string::npos);
  EXPECT_NE(md.find("levenberg_marquardt"), std::string::npos);
  EXPECT_NE(md.find("| iterations | " + std::to_string(j["iterations"].get<int>()) + " |"), std::string::npos);
  EXPECT_NE(md.find("| forward runs | " + std::to_string(j["forward_runs"].get<long>()) + " |"), std::string::npos);
  EXPECT_NE(md.find("No warnings"), std::string::npos) << "fit_classic has no warnings";
  EXPECT_EQ(md.find("WARNING"), std::string::npos);

  // Parameters: every one, with initial, value, std error and interval as in fit.json.
  ASSERT_EQ(j["parameters"].size(), 6u);
  for (const auto& [name, p] : j["parameters"].items()) {
    const auto row = md_row(md, name);
    ASSERT_GE(row.size(), 10u) << name << "\n" << md;
    EXPECT_EQ(row[1], name.rfind("swift.K", 0) == 0 ? "MPa" : "-") << name;  // the card's unit of K; Hill and n are ratios
    EXPECT_LT(rel_diff(std::stod(row[2]), p["initial"].get<double>()), 1e-5) << name;
    EXPECT_LT(rel_diff(std::stod(row[3]), p["value"].get<double>()), 1e-5) << name << ": " << row[3];
    EXPECT_LT(rel_diff(std::stod(row[4]), p["std_error"].get<double>()), 1e-3) << name;
    EXPECT_LT(rel_diff(std::stod(row[5].substr(1)), p["ci95"][0].get<double>()), 1e-5) << name;
    EXPECT_LT(rel_diff(std::stod(row[6]), p["lower"].get<double>()), 1e-5) << name;
    EXPECT_LT(rel_diff(std::stod(row[7]), p["upper"].get<double>()), 1e-5) << name;
    EXPECT_EQ(row[8], "yes") << name;
  }
  // Parameters in the order of the fit file (hill.F first), not alphabetical.
  EXPECT_LT(md.find("| hill.F |"), md.find("| swift.K |"));

  // Experiments: points, cost, rms and the share of the total cost.
  double total = 0.0;
  for (const auto& e : j["experiments"]) total += e["cost"].get<double>();
  EXPECT_LT(rel_diff(total, j["cost_final"].get<double>()), 1e-9);
  for (const auto& e : j["experiments"]) {
    const std::string name = e["name"];
    const auto row = md_row(md, name);
    ASSERT_GE(row.size(), 11u) << name;
    EXPECT_EQ(row[2], std::to_string(e["points"].get<int>())) << name;
    EXPECT_LT(rel_diff(std::stod(row[6]), e["cost"].get<double>()), 1e-3) << name;
    EXPECT_LT(rel_diff(std::stod(row[9]), e["rms"].get<double>()), 1e-3) << name;
    const double share = 100.0 * e["cost"].get<double>() / total;
    if (share >= 0.1) {
      EXPECT_NEAR(std::stod(row[7]), share, 0.051) << name;
    }
    // Synthetic data fitted with the generating model: everyone agrees with the noise.
    EXPECT_EQ(row[10].find("CONFLICT"), std::string::npos) << name << ": " << row[10];
  }
  EXPECT_NE(md.find("noise σ = 0.5 MPa"), std::string::npos);

  // Correlation matrix and singular values.
  EXPECT_NE(md.find("## Correlation of the parameters"), std::string::npos);
  const auto pos = md.find("## Correlation of the parameters");
  const auto row_k = md_row(md.substr(pos), "swift.K");
  ASSERT_EQ(row_k.size(), 7u);
  EXPECT_NEAR(std::stod(row_k[6]), j["correlation"]["matrix"][3][5].get<double>(), 5e-4);
  EXPECT_EQ(row_k[4], "1.000");
  const double sv1 = j["uncertainty"]["singular_values_scaled"][0].get<double>();
  EXPECT_LT(rel_diff(std::stod(md_row(md.substr(md.find("## Singular values")), "1")[1]), sv1), 1e-3);
}

TEST_F(FitReportTest, HtmlIsWellFormedWithTheTables) {
  const fs::path d = copy_of_fit("html");
  reports::render_fit_report(d, {false});
  const std::string html = slurp(d / "report.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  std::string why;
  EXPECT_TRUE(html_well_formed(html, &why)) << why;
  const json j = json::parse(slurp(d / "fit.json"));
  const std::string experiments = html_table(html, "experiments");
  ASSERT_FALSE(experiments.empty());
  for (const auto& e : j["experiments"]) {
    EXPECT_NE(experiments.find("<td>" + e["name"].get<std::string>() + "</td>"), std::string::npos) << e["name"];
  }
  const std::string params = html_table(html, "parameters");
  for (const auto& [name, p] : j["parameters"].items()) EXPECT_NE(params.find("<td>" + name + "</td>"), std::string::npos) << name;
  EXPECT_FALSE(html_table(html, "correlation").empty());
  EXPECT_FALSE(html_table(html, "singular-values").empty());
  EXPECT_EQ(html.find("<img"), std::string::npos) << "no plots were asked for";
}

TEST_F(FitReportTest, PlotsAreSvgFilesReferencedByTheReport) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not on PATH";
  const fs::path d = copy_of_fit("plots");
  const auto s = reports::render_fit_report(d, {});
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  // 4 curves and the table of r-values x (fit + residuals) + convergence; no scalar experiment.
  ASSERT_EQ(s.plots.size(), 11u);
  const std::string md = slurp(d / "report.md"), html = slurp(d / "report.html");
  for (const auto& p : s.plots) {
    ASSERT_TRUE(fs::exists(p)) << p;
    EXPECT_EQ(p.parent_path(), d / "plots");
    EXPECT_EQ(p.extension(), ".svg");
    const std::string svg = slurp(p);
    EXPECT_GT(svg.size(), 1000u) << p;
    EXPECT_NE(svg.find("<svg"), std::string::npos) << p;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << p;
    const std::string rel = "plots/" + p.filename().string();
    EXPECT_NE(md.find("](" + rel + ")"), std::string::npos) << rel;
    EXPECT_NE(html.find("<img src=\"" + rel + "\""), std::string::npos) << rel;
    EXPECT_TRUE(fs::exists(d / "plots" / "src" / (p.stem().string() + ".gp"))) << p;
  }
  EXPECT_TRUE(fs::exists(d / "plots" / "convergence.svg"));
  EXPECT_TRUE(fs::exists(d / "plots" / "02_tensile_00_fit.svg"));
  EXPECT_TRUE(fs::exists(d / "plots" / "02_tensile_00_residuals.svg"));
  EXPECT_NE(slurp(d / "plots" / "02_tensile_00_fit.svg").find("measured"), std::string::npos);
  std::string why;
  EXPECT_TRUE(html_well_formed(html, &why)) << why;
}

TEST_F(FitReportTest, WithoutGnuplotTheReportIsStillWritten) {
  const fs::path d = copy_of_fit("nognuplot");
  reports::ReportOptions o;
  o.gnuplot = (root_ / "no-such-gnuplot").string();
  const auto s = reports::render_fit_report(d, o);
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings.front().find("gnuplot"), std::string::npos);
  EXPECT_TRUE(s.plots.empty());
  EXPECT_TRUE(fs::exists(d / "report.md"));
  EXPECT_TRUE(fs::exists(d / "report.html"));
  EXPECT_EQ(slurp(d / "report.md").find("plots/"), std::string::npos);
}

TEST_F(FitReportTest, FailingGnuplotGivesWarningsNotACrash) {
  const fs::path d = copy_of_fit("badgnuplot");
  const fs::path fake = root_ / "fake-gnuplot";
  write(fake, "#!/bin/sh\necho 'fake gnuplot: refusing' >&2\nexit 3\n");
  fs::permissions(fake, fs::perms::owner_all);
  reports::ReportOptions o;
  o.gnuplot = fake.string();
  const auto s = reports::render_fit_report(d, o);
  EXPECT_TRUE(s.plots.empty());
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings.front().find("status 3"), std::string::npos) << s.warnings.front();
  EXPECT_NE(s.warnings.front().find("refusing"), std::string::npos) << s.warnings.front();
  EXPECT_LE(s.warnings.size(), 3u) << "stops trying after gnuplot failed twice";
  EXPECT_TRUE(fs::exists(d / "report.html"));
  EXPECT_FALSE(fs::exists(d / "plots" / "convergence.svg"));
}

TEST_F(FitReportTest, MissingOrCorruptFitJsonIsAnInputErrorNamingIt) {
  const fs::path empty = root_ / "empty";
  fs::create_directories(empty);
  try {
    reports::render_fit_report(empty, {});
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), (empty / "fit.json").string());
    EXPECT_NE(std::string(e.what()).find("fit.json"), std::string::npos);
  }
  EXPECT_THROW(reports::render_fit_report(root_ / "does-not-exist", {}), io::InputError);
  EXPECT_FALSE(fs::exists(root_ / "does-not-exist"));

  const fs::path d = copy_of_fit("corrupt");
  write(d / "fit.json", "{\"parameters\": {\"a\": ");
  try {
    reports::render_fit_report(d, {});
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), (d / "fit.json").string());
    EXPECT_NE(std::string(e.what()).find("JSON"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  write(d / "fit.json", "{\"parameters\": {\"a\": {\"value\": \"x\"}}, \"experiments\": []}");
  try {
    reports::render_fit_report(d, {});
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "parameters.a.value");
  }
  write(d / "fit.json", "[1, 2]");
  EXPECT_THROW(reports::render_fit_report(d, {}), io::InputError);
  EXPECT_FALSE(fs::exists(d / "report.md"));
}

TEST_F(FitReportTest, ConflictsAndBoundsArePlainWarnings) {
  const fs::path d = copy_of_fit("conflict");
  json j = json::parse(slurp(d / "fit.json"));
  for (auto& e : j["experiments"]) {
    ASSERT_TRUE(e.contains("noise_rms")) << e["name"];  // noise given: the weights taken out
    if (e["name"] == "tensile_45") e["rms"] = e["noise_rms"] = 4.5;   // residuals 4.5 times the stated noise
    if (e["name"] == "r_values") e["rms"] = e["noise_rms"] = 6.0;     // the table of r-values 6 sigma off
  }
  j["parameters"]["hill.N"]["value"] = j["parameters"]["hill.N"]["upper"];
  j["warnings"] = json::array({"swift.eps0 is not identifiable from the chosen experiments"});
  j["parameters"]["swift.eps0"]["identifiable"] = false;
  write(d / "fit.json", j.dump(2));
  const auto s = reports::render_fit_report(d, {false});
  const std::string md = slurp(d / "report.md");

  auto finding = [&](const std::string& a, const std::string& b) {
    for (const auto& f : s.findings) {
      if (f.find(a) != std::string::npos && f.find(b) != std::string::npos) return true;
    }
    return false;
  };
  // Both far above their noise (50 points at 4.5 sigma, 3 at 6 sigma: beyond 2 and 3.20).
  EXPECT_TRUE(finding("tensile_45", "4.5 times its stated noise over 50 points"));
  EXPECT_TRUE(finding("tensile_45", "so the fit is not usable"));
  EXPECT_TRUE(finding("r_values", "6 times its stated noise over 3 points"));
  EXPECT_TRUE(finding("hill.N", "upper bound"));
  EXPECT_TRUE(finding("swift.eps0", "not identifiable"));
  EXPECT_FALSE(finding("tensile_00", ""));
  // Prominent: the warnings box comes before the summary table, every finding is in it.
  const auto box = md.find("> **WARNING: 4 problems need attention**");
  ASSERT_NE(box, std::string::npos) << md.substr(0, 2000);
  EXPECT_LT(box, md.find("## Summary"));
  for (const auto& f : s.findings) EXPECT_NE(md.find(f.substr(0, 30)), std::string::npos) << f;
  EXPECT_NE(md_row(md, "tensile_45").at(10).find("FAR ABOVE THE NOISE"), std::string::npos);
  EXPECT_EQ(md_row(md, "swift.eps0").at(8), "**NO**");
  EXPECT_NE(md_row(md, "hill.N").at(9).find("AT upper BOUND"), std::string::npos);
  const std::string html = slurp(d / "report.html");
  EXPECT_NE(html.find("<div class=\"callout warn\">"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"bad\">FAR ABOVE THE NOISE"), std::string::npos);
}

TEST_F(FitReportTest, BoundWarningOfFitJsonIsNotRepeated) {
  const fs::path d = copy_of_fit("bound");
  json j = json::parse(slurp(d / "fit.json"));
  j["parameters"]["hill.N"]["value"] = j["parameters"]["hill.N"]["lower"];
  j["warnings"] = json::array({"hill.N ended at its bound (1): the data push it further"});
  write(d / "fit.json", j.dump(2));
  const auto s = reports::render_fit_report(d, {false});
  ASSERT_EQ(s.findings.size(), 1u);
  EXPECT_EQ(s.findings[0], "hill.N ended at its bound (1): the data push it further");
  EXPECT_NE(md_row(slurp(d / "report.md"), "hill.N").at(9).find("AT lower BOUND"), std::string::npos);
}

TEST_F(FitReportTest, MultiStartSectionAndSpreadNote) {
  const fs::path d = copy_of_fit("multistart");
  json j = json::parse(slurp(d / "fit.json"));
  const double k = j["parameters"]["swift.K"]["value"];
  j["multistart"] = {{"starts", 3}, {"best_start", 1}, {"starts_at_best_cost", 2},
                     {"spread_at_best_cost", {{"swift.K", {{"min", k - 5.0}, {"max", k}}}}},
                     {"solutions", json::array({{{"usable", true}, {"cost", 99.0}, {"values", {1, 1, 3, 170, 0.001, 0.2}}},
                                                {{"usable", true}, {"cost", 87.0}, {"values", {1, 1, 3, k, 0.001, 0.2}}},
                                                {{"usable", false}, {"cost", nullptr}, {"values", json::array()}}})}};
  write(d / "fit.json", j.dump(2));
  const auto s = reports::render_fit_report(d, {false});
  const std::string md = slurp(d / "report.md");
  EXPECT_NE(md.find("### Multi-start"), std::string::npos);
  EXPECT_NE(md.find("| 1 (best) | yes | 87 |"), std::string::npos) << md;
  EXPECT_NE(md.find("give swift.K from"), std::string::npos);
  EXPECT_TRUE(s.findings.empty()) << "notes are not warnings";
}

// A fit.json of an older spifit, without the runs and shares: the report says so, no tables.
TEST_F(FitReportTest, OlderFitJsonWithoutRunsOrShares) {
  const fs::path d = copy_of_fit("older");
  json j = json::parse(slurp(d / "fit.json"));
  for (auto& e : j["experiments"]) {
    e.erase("evaluations");
    e.erase("information_share");
  }
  write(d / "fit.json", j.dump(2));
  reports::render_fit_report(d, {false});
  const std::string md = slurp(d / "report.md");
  EXPECT_EQ(test::md_section(md, "## Forward runs"),
            "## Forward runs\n\nfit.json does not count the forward runs per experiment (written by an older spifit).\n");
  EXPECT_EQ(md.find("Which experiment informs which parameter"), std::string::npos);
}

// A real conflict (fit_n_conflict: r45 and the shear curve disagree on Hill's N; each
// experiment is also fitted alone): the report names it as a warning and shows both fits; the
// joint fit is not usable (r45 ends 22 sigma off).
TEST(FitReportConflict, RealConflictOnHillN) {
  const fs::path dir = fs::temp_directory_path() / ("spifit_report_conflict_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto problem = inverse::read_fit_file(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/fit_n_conflict.toml");
  const auto result = inverse::run_fit(problem, {"", 2});
  ASSERT_FALSE(result.usable) << result.termination;
  ASSERT_EQ(result.not_usable.size(), 1u);
  EXPECT_EQ(result.not_usable[0].rfind("experiment r45: its residuals are on average 22.", 0), 0u) << result.not_usable[0];
  inverse::write_fit_outputs(problem, result, io::OutputDirectory::prepare(dir.string(), false));
  const auto s = reports::render_fit_report(dir, {false});
  const std::string md = slurp(dir / "report.md"), html = slurp(dir / "report.html");
  fs::remove_all(dir);

  bool named = false, r45 = false;
  for (const auto& f : s.findings) {
    named = named || (f.find("Conflict") == 0 && f.find("hill.N") != std::string::npos);
    r45 = r45 || f.find("Experiment r45: its residuals are 22.") == 0;
  }
  EXPECT_TRUE(named) << md;
  EXPECT_TRUE(r45) << md;
  EXPECT_NE(md_row(md, "r45").at(10).find("FAR ABOVE THE NOISE"), std::string::npos);
  EXPECT_NE(md.find("### Each experiment fitted alone"), std::string::npos);
  const auto alone = md.substr(md.find("### Each experiment fitted alone"));
  const auto row = md_row(alone, "r45");
  ASSERT_EQ(row.size(), 2u);
  EXPECT_NEAR(std::stod(row[1].substr(row[1].find_first_not_of('*'))), result.per_experiment.at(0).values.at(0), 1e-3);
  EXPECT_NE(html_table(html, "per-experiment").find("<td>shear_00</td>"), std::string::npos);
  // Simple shear is labelled with its own quantities, not an axial strain and stress.
  EXPECT_EQ(md_row(md, "shear_00").at(3), "shear stress τ [MPa] vs shear strain γ");
  std::string why;
  EXPECT_TRUE(html_well_formed(html, &why)) << why;
}

TEST_F(FitReportTest, HostileExperimentNamesAreEscapedEverywhere) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not on PATH";
  const fs::path d = copy_of_fit("hostile");
  const std::string marker = (root_ / "pwned").string();
  const std::string name = "a'b\"<i>|`$(touch " + marker + ")`'; system('touch " + marker + "')";
  json j = json::parse(slurp(d / "fit.json"));
  for (auto& e : j["experiments"]) {
    if (e["name"] == "tensile_00") {
      e["name"] = name;
      e["data_file"] = "experiments/hostile.csv";
    }
  }
  fs::rename(d / "experiments" / "tensile_00.csv", d / "experiments" / "hostile.csv");
  write(d / "fit.json", j.dump(2));
  const auto s = reports::render_fit_report(d, {});
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  EXPECT_EQ(s.plots.size(), 11u);
  for (const auto& p : s.plots) {
    for (char c : p.filename().string()) EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.') << p;
  }
  const std::string html = slurp(d / "report.html");
  EXPECT_EQ(html.find("<i>"), std::string::npos);
  EXPECT_NE(html.find("a&#39;b&quot;&lt;i&gt;|"), std::string::npos);
  std::string why;
  EXPECT_TRUE(html_well_formed(html, &why)) << why;
  EXPECT_NE(slurp(d / "report.md").find("| a'b\"&lt;i>\\|\\`$(touch " + marker + ")\\`'; system('touch " + marker + "') |"), std::string::npos);
  // A data_file pointing outside DIR is not read.
  j["experiments"][1]["data_file"] = "../../etc/passwd";  // the renamed tensile_00
  write(d / "fit.json", j.dump(2));
  const auto s2 = reports::render_fit_report(d, {false});
  EXPECT_FALSE(s2.warnings.empty());
}

TEST(GnuplotQuote, DoublesQuotesAndDropsControlCharacters) {
  EXPECT_EQ(reports::gnuplot_quote("it's"), "'it''s'");
  EXPECT_EQ(reports::gnuplot_quote("a\nb`c`"), "'a b`c`'");
  EXPECT_EQ(reports::safe_file_stem("../x y'"), "___x_y_");
  EXPECT_EQ(reports::safe_file_stem(""), "plot");
}

}  // namespace
