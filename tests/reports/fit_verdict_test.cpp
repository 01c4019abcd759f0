// The fit report's verdicts on hand-made records (docs/guide/reading-reports.md "Rules for verdicts and
// findings"): noise and range conditioning, the runs test, bounds, correlations, failures.
#include "reports/fit_document.hpp"
#include "reports/fit_verdict.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace spifit::reports;
using spifit::inverse::FitRecord;

namespace {

FitRecord::Experiment curve(const std::string& name, double rms, bool noise, int points = 20) {
  FitRecord::Experiment e;
  e.name = name;
  e.kind = "curve";
  e.points = points;
  e.rms = rms;
  e.cost = 0.5 * points * rms * rms;
  e.scale = 1.0;
  e.noise_given = noise;
  return e;
}

// points measured values 0..n-1; fitted = measured + residual(i).
template <typename F>
ExperimentData data(int n, F residual) {
  ExperimentData d;
  d.ok = true;
  for (int i = 0; i < n; ++i) {
    d.x.push_back(i);
    d.measured.push_back(i);
    d.initial.push_back(i);
    d.fitted.push_back(i + residual(i));
  }
  return d;
}

bool has(const FitVerdict& v, int level, const std::string& a, const std::string& b = "") {
  return std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
    return f.level == level && f.text.find(a) != std::string::npos && f.text.find(b) != std::string::npos;
  });
}

TEST(FitVerdict, CurvesAgainstTheNoise) {
  const auto alternating = data(20, [](int i) { return i % 2 ? 0.1 : -0.1; });
  EXPECT_EQ(judge_experiment(curve("a", 1.0, true), alternating).level, 0);
  EXPECT_EQ(judge_experiment(curve("a", 1.0, true), alternating).text, "consistent with the noise (rms 1.00 σ)");
  const auto high = judge_experiment(curve("a", 1.6, true), alternating);
  EXPECT_EQ(high.level, 1);
  EXPECT_TRUE(high.above_noise);
  EXPECT_EQ(judge_experiment(curve("a", 0.3, true), alternating).text, "rms 0.30 σ: below the stated noise");
  // Twice the noise and beyond what 20 points of random noise reach once in a million: the fit is
  // not usable (inverse/fit/fit_assessment.hpp); with fewer points the chi-square bound is higher.
  EXPECT_EQ(judge_experiment(curve("a", 2.5, true), alternating).text, "FAR ABOVE THE NOISE: rms 2.5 σ");
  EXPECT_TRUE(judge_experiment(curve("a", 2.5, true), alternating).far_above_noise);
  EXPECT_EQ(judge_experiment(curve("a", 2.1, true, 10), data(10, [](int i) { return i % 2 ? 0.1 : -0.1; })).text, "CONFLICT: rms 2.10 σ");
  // The experiment's weight is taken out: rms 2 at weight 4 is 1 sigma.
  auto weighted = curve("a", 2.0, true);
  weighted.weight = 4.0;
  EXPECT_EQ(judge_experiment(weighted, alternating).text, "consistent with the noise (rms 1.00 σ)");
  EXPECT_EQ(judge_experiment(curve("a", 0.03, false), alternating).text, "rms 3.00 % of the data range");
  EXPECT_EQ(judge_experiment(curve("a", 0.06, false), alternating).level, 2);
  auto failed = curve("a", FitRecord::kNaN, true);
  EXPECT_EQ(judge_experiment(failed, alternating).level, 2);
}

TEST(FitVerdict, NoiseRecognisedFromTheDataOfOlderFiles) {
  auto e = curve("a", 0.01, true);
  e.noise_given.reset();
  e.scale = 19.0;  // the range of the measured values 0..19: no noise was given
  const auto d = data(20, [](int i) { return i % 2 ? 0.1 : -0.1; });
  EXPECT_EQ(judge_experiment(e, d).conditioning, Conditioning::range);
  e.scale = 0.5;
  EXPECT_EQ(judge_experiment(e, d).conditioning, Conditioning::noise);
  EXPECT_EQ(judge_experiment(e, ExperimentData{}).conditioning, Conditioning::unknown);
}

TEST(FitVerdict, RunsTestFindsSystematicDeviations) {
  FitRecord r;
  r.experiments = {curve("bent", 1.0, true, 40)};
  const auto v = judge_fit(r, {data(40, [](int i) { return i < 20 ? 0.2 : -0.2; })});
  EXPECT_EQ(v.experiments[0].sign_changes, 1);
  EXPECT_NEAR(v.experiments[0].expected_sign_changes, 20.0, 1e-12);
  EXPECT_TRUE(has(v, 1, "bent", "systematic"));
}

TEST(FitVerdict, FitLevelFindings) {
  FitRecord r;
  r.usable = false;
  r.termination = "FAILURE";
  r.warnings = {"told by the fit"};
  r.conflicts = {"a and b disagree on hill.N"};
  FitRecord::Parameter p;
  p.name = "swift.K";
  p.value = 400.0;
  p.lower = 50.0;
  p.upper = 400.0;
  r.parameters = {p};
  r.correlation.names = {"x", "y"};
  r.correlation.matrix = {{1.0, 0.995}, {0.995, 1.0}};
  r.experiments = {curve("a", 1.0, true), curve("b", 1.0, true)};
  const auto d = data(20, [](int i) { return i % 2 ? 0.1 : -0.1; });
  const auto v = judge_fit(r, {d, d});
  EXPECT_TRUE(has(v, 2, "The result is NOT USABLE: FAILURE. Its card is written as card_NOT_USABLE.toml"));
  EXPECT_TRUE(has(v, 2, "told by the fit"));
  EXPECT_TRUE(has(v, 2, "Conflict: a and b"));
  EXPECT_TRUE(has(v, 2, "swift.K sits at its upper bound (400)"));
  EXPECT_TRUE(has(v, 2, "x and y are almost perfectly correlated"));
  ASSERT_EQ(v.at_bound.size(), 1u);
  EXPECT_EQ(v.at_bound[0], "upper");
  EXPECT_NEAR(v.experiments[0].share_cost, 0.5, 1e-12);
  // The reasons fit.json gives are the finding.
  r.not_usable = {"swift.K ended at its upper bound (400)", "hill.N is not identifiable from these experiments"};
  EXPECT_TRUE(has(judge_fit(r, {d, d}), 2, "NOT USABLE: swift.K ended at its upper bound (400); hill.N is not identifiable"));
}

TEST(FitVerdict, AScalarFarAboveItsNoise) {
  FitRecord::Experiment e;
  e.name = "r45";
  e.kind = "scalar";
  e.points = 1;
  e.scale = 0.02;
  e.noise_given = true;
  e.rms = 4.0;  // off by 4 sigma: a conflict, not beyond random noise once in a million (4.89)
  EXPECT_EQ(judge_experiment(e, ExperimentData{}).text, "CONFLICT: off by 4.0 σ");
  e.rms = 22.0;
  EXPECT_EQ(judge_experiment(e, ExperimentData{}).text, "FAR ABOVE THE NOISE: rms 22 σ");
}

}  // namespace

namespace {

// The summary table's "result usable" row of a hand-made record.
spifit::reports::Cell usable_cell(const FitRecord& r) {
  FitReportContent c;
  c.record = r;
  c.verdict = judge_fit(r, {});
  const Document d = fit_report_document(c);
  for (const auto& b : d.blocks)
    if (b.kind == Block::Kind::table)
      for (const auto& row : b.table.rows)
        if (row.size() == 2 && row[0].text == "result usable") return row[1];
  ADD_FAILURE() << "no result usable row";
  return {};
}

}  // namespace

// Correlations are shaded by their strength whatever their sign: -0.9 as deep as +0.9; amber from
// |r| = 0.95, red from 0.99.
TEST(FitReportCorrelation, ShadesByTheMagnitude) {
  FitRecord r;
  r.usable = true;
  r.correlation.names = {"a", "b", "c", "d"};
  r.correlation.matrix = {{1.0, -0.9, 0.96, -0.995}, {-0.9, 1.0, 0.0, 0.0}, {0.96, 0.0, 1.0, 0.0}, {-0.995, 0.0, 0.0, 1.0}};
  FitReportContent c;
  c.record = r;
  c.verdict = judge_fit(r, {});
  const Document d = fit_report_document(c);
  const spifit::reports::Table* t = nullptr;
  for (const auto& b : d.blocks)
    if (b.kind == Block::Kind::table && !b.table.rows.empty() && b.table.rows[0].size() == 5 && b.table.rows[0][0].text == "a") t = &b.table;
  ASSERT_NE(t, nullptr);
  EXPECT_DOUBLE_EQ(t->rows[0][2].shade, 0.9);  // r(a, b) = -0.9
  EXPECT_EQ(t->rows[0][3].style, CellStyle::warn);  // 0.96
  EXPECT_EQ(t->rows[0][4].style, CellStyle::bad);   // -0.995
}

// A warning (a conflict between experiments) makes a usable result amber, not green; one that is
// not usable is red and names its card.
TEST(FitReportSummary, AWarningMakesAUsableResultAmber) {
  FitRecord r;
  r.usable = true;
  EXPECT_EQ(usable_cell(r).style, CellStyle::good);
  EXPECT_EQ(usable_cell(r).text, "yes");
  r.conflicts = {"a and b disagree on hill.N"};
  EXPECT_EQ(usable_cell(r).style, CellStyle::warn);
  EXPECT_EQ(usable_cell(r).text, "yes, with 1 warning (see above)");
  r.usable = false;
  EXPECT_EQ(usable_cell(r).style, CellStyle::bad);
  EXPECT_EQ(usable_cell(r).text, "NO (see the warnings): card_NOT_USABLE.toml");
}
