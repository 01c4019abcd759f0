// When a fit is usable, and when its data are implausible before it runs (inverse/fit/fit_assessment.hpp,
// inverse/experiments/measurement_plausibility.hpp): chi-square quantiles against published tables, and real
// fits of the bundled tensile data that end at a bound, on a single point, far above a stated
// noise, or start from a data file whose header names the wrong unit.
#include "forward/io/input_error.hpp"
#include "inverse/uncertainty/chi_square.hpp"
#include "inverse/fit/fit_assessment.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/run_fit.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace spifit::inverse {
namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// Quantiles of the chi-square distribution from the published tables (Abramowitz & Stegun,
// table 26.8; NIST/SEMATECH e-Handbook 1.3.6.7.4), printed to 3 decimals.
TEST(ChiSquare, UpperQuantilesMatchThePublishedTables) {
  EXPECT_NEAR(chi_square_upper_quantile(1, 0.001), 10.828, 5e-4);
  EXPECT_NEAR(chi_square_upper_quantile(10, 0.05), 18.307, 5e-4);
  EXPECT_NEAR(chi_square_upper_quantile(100, 0.01), 135.807, 5e-4);
  EXPECT_NEAR(chi_square_upper_quantile(2, 0.5), 1.386, 5e-4);  // 2 ln 2: the exponential's median
  EXPECT_NEAR(chi_square_upper_tail(3, 7.815), 0.0499939029748839, 1e-13);  // mpmath, 30 digits
}

TEST(ChiSquare, FarAboveTheNoiseIsTwiceItOrWhatRandomNoiseReachesOnceInAMillion) {
  // sqrt(q / n) with q the 1e-6 upper quantile: 23.928 for n = 1, 30.665 for n = 3 (mpmath).
  EXPECT_NEAR(far_above_noise_rms(1), 4.8916, 1e-4);
  EXPECT_NEAR(far_above_noise_rms(3), 3.1971, 1e-4);
  EXPECT_NEAR(far_above_noise_rms(10), 2.1648, 1e-4);
  EXPECT_NEAR(far_above_noise_rms(13), 2.01432, 1e-5);
  EXPECT_DOUBLE_EQ(far_above_noise_rms(14), kFarAboveNoiseFloor);
  EXPECT_DOUBLE_EQ(far_above_noise_rms(500), kFarAboveNoiseFloor);
}

// A fit of Swift's K (and n) to the bundled synthetic tensile curve (card C.2, noise 0.5 MPa).
std::string tensile_fit(const std::string& data, const std::string& parameters, double noise) {
  std::ostringstream f;
  f << "[fit]\nname = \"assessment\"\ncard = \"" << src("materials/aa3003o_c2.toml") << "\"\n" << parameters << "[[experiment]]\nname = \"t\"\nscene = \""
    << src("experiments/aa3003o/scenes/tensile_00.toml") << "\"\ndata = \"" << data << "\"\nnoise = " << noise << "\n";
  return test::write_temp_file("fit.toml", f.str()).string();
}

const std::string kKn = "[parameters.\"swift.K\"]\ninitial = 150.0\nlower = 50.0\nupper = 500.0\n"
                        "[parameters.\"swift.n\"]\ninitial = 0.25\nlower = 0.02\nupper = 0.7\n";

std::string slurp_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool mentions(const std::vector<std::string>& reasons, const std::string& what) {
  for (const auto& r : reasons)
    if (r.find(what) != std::string::npos) return true;
  return false;
}

TEST(FitAssessment, TheBundledTensileCurveWithItsOwnNoiseIsUsable) {
  const FitResult r = run_fit(read_fit_file(tensile_fit(src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv"), kKn, 0.5)));
  EXPECT_TRUE(r.usable);
  EXPECT_TRUE(r.not_usable.empty()) << r.not_usable.front();
}

TEST(FitAssessment, ResidualsFarAboveTheStatedNoiseMakeItUnusable) {
  // The same 50 points said to carry 0.05 MPa of noise where they carry 0.5: rms about 10.
  const FitResult r = run_fit(read_fit_file(tensile_fit(src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv"), kKn, 0.05)));
  EXPECT_FALSE(r.usable);
  ASSERT_EQ(r.not_usable.size(), 1u);
  EXPECT_NE(r.not_usable[0].find("experiment t: its residuals are on average"), std::string::npos) << r.not_usable[0];
  EXPECT_NE(r.not_usable[0].find("stays below 2.00 times"), std::string::npos) << r.not_usable[0];
}

TEST(FitAssessment, PointWeightsAreTakenOutOfTheNoiseTest) {
  // The bundled curve with a weight column of 9 on every point: the residuals carry a factor 3,
  // the noise is still the stated 0.5 MPa, and the fit is usable.
  std::ifstream in(src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv"));
  std::stringstream text;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') text << line << "\n";
    else if (line.rfind("strain", 0) == 0) text << line << ",w [-]\n";
    else text << line << ",9\n";
  }
  const auto data = test::write_temp_file("weighted.csv", text.str());
  std::string fit = slurp_text(tensile_fit(data.string(), kKn, 0.5));
  fit += "weight_column = \"w\"\n";
  const FitResult r = run_fit(read_fit_file(test::write_temp_file("weighted_fit.toml", fit).string()));
  EXPECT_TRUE(r.usable) << (r.not_usable.empty() ? r.termination : r.not_usable.front());
  ASSERT_EQ(r.experiment_costs.size(), 1u);
  EXPECT_NEAR(r.experiment_costs[0].rms, 3.0 * r.experiment_costs[0].noise_rms, 1e-9);
  EXPECT_EQ(r.experiment_costs[0].noise_points, 50);
  EXPECT_LT(r.experiment_costs[0].noise_rms, 1.2);
}

TEST(FitAssessment, AParameterAtItsBoundMakesItUnusable) {
  const std::string low_ceiling = "[parameters.\"swift.K\"]\ninitial = 150.0\nlower = 50.0\nupper = 160.0\n";
  const FitResult r = run_fit(read_fit_file(tensile_fit(src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv"), low_ceiling, 0.5)));
  EXPECT_FALSE(r.usable);
  EXPECT_TRUE(mentions(r.not_usable, "swift.K ended at its upper bound (160)"));
}

TEST(FitAssessment, OneDataRowForTwoParametersIsNotIdentifiableAndUnusable) {
  const auto data = test::write_temp_file("one_row.csv", "strain [-],stress [MPa]\n0.1,120\n");
  const FitResult r = run_fit(read_fit_file(tensile_fit(data.string(), kKn, 0.5)));
  EXPECT_FALSE(r.usable);
  EXPECT_TRUE(mentions(r.not_usable, "is not identifiable from these experiments")) << (r.not_usable.empty() ? "" : r.not_usable.front());
}

TEST(FitAssessment, AStressHeaderInGpaOverMpaValuesIsNamedBeforeTheFitRuns) {
  // The bundled curve's numbers (MPa) under a header that says GPa: a thousandfold.
  std::ifstream in(src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv"));
  std::stringstream text;
  for (std::string line; std::getline(in, line);) text << (line == "strain [-],stress [MPa]" ? "strain [-],stress [GPa]" : line) << "\n";
  const auto data = test::write_temp_file("gpa.csv", text.str());
  try {
    read_fit_file(tensile_fit(data.string(), kKn, 0.5));
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), data.string());
    EXPECT_EQ(e.key(), "column stress");
    EXPECT_EQ(e.value(), "[GPa]");
    EXPECT_NE(e.message().find("times more than the start card gives"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("is the unit in the data file's header right?"), std::string::npos) << e.what();
  }
}

TEST(FitAssessment, AnAbsurdScalarValueIsNamedBeforeTheFitRuns) {
  std::ostringstream f;
  f << "[fit]\ncard = \"" << src("materials/aa3003o_c3c4.toml") << "\"\n[parameters.\"hill.N\"]\ninitial = 3.5\nlower = 1.0\nupper = 8.0\n"
    << "[[experiment]]\nname = \"r45\"\nscene = \"" << src("experiments/aa3003o/scenes/tensile_45.toml")
    << "\"\nobservable = \"r_value\"\nvalue = 1e300\nnoise = 0.02\n";
  const auto path = test::write_temp_file("absurd.toml", f.str()).string();
  try {
    read_fit_file(path);
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(e.key().find("value"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("times more than the start card gives"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spifit::inverse
