// The bundled fit files do what experiments/README.md says.
#include "inverse/fit/run_fit.hpp"
#include "inverse/fit/fit_file.hpp"

#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace spifit;

namespace {
std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// Index of a free parameter by name.
int index_of(const inverse::FitProblem& fp, const std::string& name) {
  for (int k = 0; k < fp.parameters->num_free(); ++k) {
    if (fp.parameters->specs()[fp.parameters->free_indices()[k]].name == name) return k;
  }
  return -1;
}
}  // namespace

// fit_kinematic recovers its generating card (C.7 with H = 0.807) within its 95 % intervals.
TEST(BundledFits, KinematicRecoversGeneratingCardWithinIntervals) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_kinematic.toml"));
  const auto r = inverse::run_fit(fp);
  ASSERT_TRUE(r.usable) << r.termination;
  const auto truth = material::load_material_card(src("materials/aa3003o_c7n_af_shell.toml"));
  for (int k = 0; k < fp.parameters->num_free(); ++k) {
    const auto& name = fp.parameters->specs()[fp.parameters->free_indices()[k]].name;
    const double t = inverse::parameter_value(truth, name);
    EXPECT_LE(r.uncertainty.ci95_lower[k], t) << name;
    EXPECT_GE(r.uncertainty.ci95_upper[k], t) << name;
  }
}

// fit_n_conflict: r45 alone and the shear curve alone disagree on N, and the fit says so; the
// joint result is not usable (r45 ends 22 sigma from its measurement).
TEST(BundledFits, NConflictIsReportedPerExperiment) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_n_conflict.toml"));
  const auto r = inverse::run_fit(fp);
  ASSERT_FALSE(r.usable);
  ASSERT_EQ(r.not_usable.size(), 1u);
  EXPECT_EQ(r.not_usable[0].rfind("experiment r45: its residuals are on average 22.", 0), 0u) << r.not_usable[0];
  ASSERT_EQ(r.per_experiment.size(), 2u);
  const int n = index_of(fp, "hill.N");
  ASSERT_GE(n, 0);
  // r45 = (2N - F - G) / (2 (F + G)) with C.3's F, G: N = (F + G)(r45 + 1/2) = 2.9729.
  EXPECT_NEAR(r.per_experiment[0].values[n], (1.224 + 1.193) * (0.73 + 0.5), 1e-4);
  EXPECT_NEAR(r.per_experiment[1].values[n], 4.06, 0.05);  // the generating card's N
  ASSERT_EQ(r.conflicts.size(), 1u);
  EXPECT_NE(r.conflicts[0].find("disagree on hill.N"), std::string::npos);
  // The joint value (close to the shear estimate) lies in the shear interval only.
  EXPECT_NE(r.conflicts[0].find("lies in shear_00's interval only, so r45 is not satisfied"), std::string::npos) << r.conflicts[0];
}

// fit_classic recovers C.2, and its default conflict check (material points only) fits each
// experiment alone and finds the measured r-values and the synthetic C.2 curves agree.
TEST(BundledFits, ClassicFitsNearC2) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_classic.toml"));
  ASSERT_TRUE(fp.per_experiment);
  const auto r = inverse::run_fit(fp);
  ASSERT_TRUE(r.usable);
  const auto truth = material::load_material_card(src("materials/aa3003o_c2.toml"));
  for (const char* name : {"hill.F", "hill.G", "hill.N", "swift.K", "swift.n"}) {
    const int k = index_of(fp, name);
    EXPECT_NEAR(r.values[k] / inverse::parameter_value(truth, name), 1.0, 0.01) << name;
  }
  ASSERT_EQ(r.per_experiment.size(), 5u);
  EXPECT_TRUE(r.conflicts.empty()) << r.conflicts.front();
  // The table of r-values alone fixes Hill by eq. C.3 (H = 2 - G): G = 2 / (1 + r0),
  // F = H / r90, N = (F + G)(r45 + 1/2).
  const auto& alone = r.per_experiment[0];
  EXPECT_EQ(alone.experiment, "r_values");
  const double G = 2.0 / 1.68, F = (2.0 - G) / 0.66, N = (F + G) * 1.23;
  EXPECT_NEAR(alone.values[index_of(fp, "hill.G")], G, 1e-5);
  EXPECT_NEAR(alone.values[index_of(fp, "hill.F")], F, 1e-5);
  EXPECT_NEAR(alone.values[index_of(fp, "hill.N")], N, 1e-5);
}

// Multi-start: random starts inside the bounds all reach the same minimum for fit_kinematic,
// the spread is at the optimiser's tolerance, and the same seed gives the same starts.
TEST(BundledFits, MultiStartFindsTheSameMinimum) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_kinematic.toml"));
  inverse::FitRunOptions o;
  o.multistart = 4;
  o.seed = 7;
  const auto r = inverse::run_fit(fp, o);
  ASSERT_TRUE(r.usable);
  EXPECT_EQ(r.multistart.starts, 4);
  EXPECT_EQ(r.multistart.at_best, 4);
  for (std::size_t k = 0; k < r.values.size(); ++k) {
    EXPECT_LT(r.multistart.spread_max[k] - r.multistart.spread_min[k], 1e-5 * std::abs(r.values[k])) << k;
  }
  const auto again = inverse::run_fit(fp, o);
  for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(again.multistart.solutions[s].start, r.multistart.solutions[s].start);
}

// Same inputs and thread count -> identical results (experiments evaluated in parallel).
TEST(BundledFits, DeterministicWithTwoThreads) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_classic.toml"));
  inverse::FitRunOptions o;
  o.threads = 2;
  const auto a = inverse::run_fit(fp, o);
  const auto b = inverse::run_fit(fp, o);
  ASSERT_TRUE(a.usable && b.usable);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.cost_final, b.cost_final);
  EXPECT_EQ(a.iterations, b.iterations);
}

// fit_yld2000: Yld2000-2d matches the measured r0, r45, r90 and the C.3 shear curve at once,
// the conflict Hill 1948 cannot resolve (NConflictIsReportedPerExperiment).
TEST(BundledFits, Yld2000MatchesRValuesAndShearTogether) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_yld2000.toml"));
  const auto r = inverse::run_fit(fp);
  ASSERT_TRUE(r.usable) << (r.not_usable.empty() ? r.termination : r.not_usable.front());
  const auto& p = r.card.params;
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(material::uniaxial_r_value(p, 0.0), 0.68, 1e-6);
  EXPECT_NEAR(material::uniaxial_r_value(p, pi / 4), 0.73, 1e-6);
  EXPECT_NEAR(material::uniaxial_r_value(p, pi / 2), 0.66, 1e-6);
  // The shear yield stress of card C.3 + C.4, sigma_F(0) / sqrt(N), and its RD yield stress.
  const double s0 = material::hardening_stress(p, 0.0);
  EXPECT_NEAR(s0 / material::shear_yield_factor(p), s0 / std::sqrt(4.06), 0.005 * s0 / std::sqrt(4.06));
  EXPECT_NEAR(material::uniaxial_yield_factor(p, 0.0), 1.0, 0.005);
  EXPECT_TRUE(r.card.params.yield.active());
}

// With every alpha free the same data leave the equibiaxial part of Yld2000-2d open: the fit
// names the X'' alphas (alpha3 to alpha6) not identifiable and is not usable.
TEST(BundledFits, Yld2000EveryAlphaFreeNamesTheUnidentified) {
  std::ifstream in(src("experiments/aa3003o/fit_yld2000.toml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string t = text.str();
  std::string extra;
  for (int i : {3, 4, 6}) extra += "[parameters.\"yld2000.alpha" + std::to_string(i) + "\"]\ninitial = 1.0\nlower = 0.3\nupper = 2.5\n";
  t.insert(t.find("[[experiment]]"), extra + "\n");
  // Paths relative to the bundled file become absolute.
  auto replace_all = [&](const std::string& from, const std::string& to) {
    for (std::size_t at = t.find(from); at != std::string::npos; at = t.find(from, at + to.size())) t.replace(at, from.size(), to);
  };
  replace_all("\"scenes/", "\"" + src("experiments/aa3003o/scenes/"));
  replace_all("\"data/", "\"" + src("experiments/aa3003o/data/"));
  replace_all("\"../../materials/", "\"" + src("materials/"));
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "spifit_yld_all";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "fit_all.toml") << t;
  const auto fp = inverse::read_fit_file((dir / "fit_all.toml").string());
  ASSERT_EQ(fp.parameters->num_free(), 8);
  const auto r = inverse::run_fit(fp);
  EXPECT_FALSE(r.usable);
  std::string all;
  for (const auto& s : r.not_usable) all += s + "\n";
  for (int i : {3, 4, 5, 6}) EXPECT_NE(all.find("yld2000.alpha" + std::to_string(i) + " is not identifiable"), std::string::npos) << all;
  // The data are matched all the same: the r-values to round-off.
  EXPECT_NEAR(material::uniaxial_r_value(r.card.params, std::acos(-1.0) / 4), 0.73, 1e-6);
}
