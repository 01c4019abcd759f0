// Bad fit files are input errors naming file, key and value.
#include "forward/io/input_error.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/experiments/measurement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;
using namespace spifit;

namespace {
std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// The files this test process wrote, removed when it ends (a test that fails early leaves none).
struct WrittenFiles {
  std::vector<fs::path> paths;
  ~WrittenFiles() {
    std::error_code ec;
    for (const fs::path& p : paths) fs::remove(p, ec);
  }
};

std::string write(const std::string& name, const std::string& text) {
  static WrittenFiles written;
  const fs::path p = fs::temp_directory_path() / ("spifit_fitfile_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p) << text;
  written.paths.push_back(p);
  return p.string();
}

std::string base_fit(const std::string& params, const std::string& experiment) {
  return "[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\n" + params + experiment;
}

const std::string kParam = "[parameters.\"swift.K\"]\nlower = 50.0\nupper = 500.0\n";
std::string curve(const std::string& data, const std::string& extra = "") {
  return "[[experiment]]\nname = \"t\"\nscene = \"" + src("experiments/aa3003o/scenes/tensile_00.toml") + "\"\ndata = \"" + data + "\"\n" + extra;
}

void expect_error(const std::string& fit_text, const std::string& key, const std::string& value_part) {
  const std::string path = write("fit.toml", fit_text);
  try {
    inverse::read_fit_file(path);
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_NE(e.key().find(key), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(value_part), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  fs::remove(path);
}
}  // namespace

TEST(FitFile, Errors) {
  const std::string data = write("d.csv", "# synthetic\nstrain [-],stress [MPa]\n0.01,60\n0.02,70\n");
  expect_error(base_fit("[parameters.\"swift.KK\"]\nlower = 1.0\nupper = 2.0\n", curve(data)), "parameters.swift.KK", "unknown parameter");
  expect_error(base_fit("[parameters.\"swift.K\"]\nlower = 500.0\nupper = 50.0\n", curve(data)), "parameters.swift.K.upper", "50");
  expect_error(base_fit("[parameters.\"swift.K\"]\ninitial = 1000.0\nlower = 50.0\nupper = 500.0\n", curve(data)), "parameters.swift.K.initial", "1000");
  expect_error(base_fit("[parameters.\"swift.eps0\"]\nlower = 0.0\nupper = 1.0\nlog = true\n", curve(data)), "parameters.swift.eps0.lower", "0");
  expect_error(base_fit(kParam, curve(data, "y = \"force\"\n")), "experiment[0].y", "force");
  const std::string nocol = write("nocol.csv", "strain [-],stres [MPa]\n0.01,60\n");
  expect_error(base_fit(kParam, curve(nocol)), "column", "stress");
  const std::string outside = write("outside.csv", "strain [-],stress [MPa]\n0.01,60\n0.5,70\n");
  expect_error(base_fit(kParam, curve(outside)), "column strain", "0.5");
  const std::string badnum = write("badnum.csv", "strain [-],stress [MPa]\n0.01,6O\n");
  expect_error(base_fit(kParam, curve(badnum)), "line 2, column stress", "6O");
  expect_error(base_fit(kParam, "[[experiment]]\nscene = \"" + src("experiments/aa3003o/scenes/tensile_00.toml") + "\"\nobservable = \"r_valu\"\nvalue = 0.7\n"),
               "experiment[0].observable", "r_valu");
  expect_error(base_fit("[parameters.\"hill.H\"]\nlower = 0.5\nupper = 1.5\n", curve(data)), "parameters.hill.H", "H = 2 - G");
  // Review 2026-11-21: names that escape the output directory, duplicate names, bounds or
  // fixed values that make the card invalid, negative tolerances, impossible observables.
  expect_error(base_fit(kParam, "[[experiment]]\nname = \"../../escape\"\nscene = \"" + src("experiments/aa3003o/scenes/tensile_00.toml") +
                                    "\"\ndata = \"" + data + "\"\n"),
               "experiment[0].name", "../../escape");
  expect_error(base_fit(kParam, curve(data) + curve(data)), "experiment[1].name", "two experiments");
  expect_error(base_fit(kParam + "[parameters.\"elastic.nu\"]\ninitial = 0.7\nfixed = true\n", curve(data)), "parameters", "elastic.nu");
  expect_error(base_fit("[parameters.\"hill.N\"]\ninitial = 3.0\nlower = -5.0\nupper = 6.0\n", curve(data)), "parameters.hill.N.lower", "-5");
  // G up to 2.5 gives H = -0.5 at the bound, still a convex Hill surface with F = 1.224 (FG + GH
  // + HF = 1.2 > 0): allowed. G up to 3.5 (H = -1.5) is not.
  expect_error(base_fit("[parameters.\"hill.G\"]\nlower = 0.5\nupper = 3.5\n", curve(data)), "parameters.hill.G.upper", "3.5");
  expect_error("[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\nparameter_tolerance = -1.0\n" + kParam + curve(data),
               "fit.parameter_tolerance", "-1");
  expect_error("[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\noffset_tolerance = -0.001\n" + kParam + curve(data),
               "fit.offset_tolerance", "-0.001");
  expect_error("[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\nalgorithm = \"bobyqa\"\noffset_tolerance = 0.001\n" + kParam + curve(data),
               "fit.offset_tolerance", "bobyqa");
  expect_error(base_fit(kParam, "[[experiment]]\nscene = \"" + src("experiments/aa3003o/scenes/tensile_00.toml") +
                                    "\"\nobservable = \"reverse_yield_stress\"\nvalue = -40.0\n"),
               "experiment[0].observable", "reverses");
}

TEST(FitFile, SpreadsheetCsvWithBomAndTrailingCommas) {
  const std::string data = write("bom.csv", "\xEF\xBB\xBFstrain [-],stress [MPa],\r\n0.01,60,\r\n0.02,70,\r\n");
  const auto t = inverse::read_measurement_csv(data);
  EXPECT_EQ(t.names, (std::vector<std::string>{"strain", "stress"}));
  EXPECT_EQ(t.column("stress")[1], 70.0);
}

TEST(FitFile, MeasurementUnitsAndComments) {
  const std::string data = write("units.csv", "# SYNTHETIC\n# seed 3\nstrain [-], stress [MPa]\n0.01, 60.5\n");
  const auto t = inverse::read_measurement_csv(data);
  EXPECT_EQ(t.comments.size(), 2u);
  EXPECT_EQ(t.units.at("stress"), "MPa");
  EXPECT_EQ(t.column("stress")[0], 60.5);
}

// [fit] per_experiment: by default on when every experiment is a material point (each fit alone
// is cheap), off with an FE experiment (each would run the FE scenes again); a stated value wins.
TEST(FitFile, PerExperimentDefaultsToOnWithMaterialPointsOnly) {
  const std::string data = write("pe.csv", "strain [-],stress [MPa]\n0.01,60\n0.02,70\n");
  const std::string head = "[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\n";
  const std::string fe = "[[experiment]]\nname = \"indent\"\nscene = \"" + src("experiments/aa3003o/scenes/indent.toml") +
                         "\"\nobservable = \"peak_fz\"\nvalue = 100.0\n";
  auto per_experiment = [&](const std::string& fit_keys, const std::string& experiments) {
    return inverse::read_fit_file(write("pe.toml", head + fit_keys + kParam + experiments)).per_experiment;
  };
  EXPECT_TRUE(per_experiment("", curve(data)));
  EXPECT_FALSE(per_experiment("per_experiment = false\n", curve(data)));
  EXPECT_FALSE(per_experiment("", fe));
  EXPECT_FALSE(per_experiment("", curve(data) + fe));
  EXPECT_TRUE(per_experiment("per_experiment = true\n", curve(data) + fe));
}

TEST(FitFile, BundledFitClassicLoads) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_classic.toml"));
  EXPECT_EQ(fp.parameters->num_free(), 6);
  ASSERT_EQ(fp.experiments.size(), 5u);  // the r-values are one table
  EXPECT_EQ(fp.experiments[0]->num_residuals(), 3);
  EXPECT_EQ(fp.experiments[0]->kind(), "scalar_table");
}

// The brick identification and its shell twin: the same five parameters, card and data files
// (C.5 renormalised, the indent computed with bricks); only the indent's scene differs.
TEST(FitFile, BundledBrickFitAndItsShellTwinShareTheirData) {
  const auto brick = inverse::read_fit_file(src("experiments/aa3003o/fit_af_indent_brick.toml"));
  const auto shell = inverse::read_fit_file(src("experiments/aa3003o/fit_af_indent_brick_as_shell.toml"));
  EXPECT_EQ(brick.parameters->num_free(), 5);
  EXPECT_EQ(shell.parameters->num_free(), 5);
  ASSERT_EQ(brick.data_files.size(), 3u);
  EXPECT_EQ(brick.data_files, shell.data_files);
  EXPECT_NE(brick.data_files[2].find("indent_line_fz_c5n_brick_synthetic.csv"), std::string::npos);
  auto reads = [](const inverse::FitProblem& fp, const std::string& name) {
    return std::any_of(fp.input_files.begin(), fp.input_files.end(), [&](const std::string& f) { return f.find(name) != std::string::npos; });
  };
  EXPECT_TRUE(reads(brick, "indent_line_c5_af_brick.toml"));
  EXPECT_FALSE(reads(brick, "indent_line_c7_af.toml"));
  EXPECT_TRUE(reads(shell, "indent_line_c7_af.toml"));
  EXPECT_TRUE(reads(brick, "aa3003o_c5n_af_brick.toml") && reads(shell, "aa3003o_c5n_af_brick.toml"));
}

// noise_relative: each point's standard deviation is that fraction of its |y|, so the residual is
// (simulated - measured) / (rel |measured|); not together with noise, not on scalars.
TEST(FitFile, RelativeNoiseDividesEachResidualByItsOwnDeviation) {
  const std::string scene = src("experiments/aa3003o/scenes/tensile_00.toml"), data = src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv");
  const auto problem = inverse::read_fit_file(write("relnoise.toml", base_fit(kParam, "[[experiment]]\nscene = \"" + scene + "\"\ndata = \"" + data +
                                                                               "\"\nnoise_relative = 0.01\n")));
  const auto& e = *problem.experiments.front();
  const auto p = problem.parameters->point(problem.parameters->initial_internal().data());
  std::vector<double> r(static_cast<std::size_t>(e.num_residuals()));
  ASSERT_TRUE(e.residuals(p, r.data()));
  const auto c = e.compare(p);
  ASSERT_EQ(c.simulated.size(), r.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    EXPECT_NEAR(r[i], (c.simulated[i] - c.measured[i]) / (0.01 * std::abs(c.measured[i])), 1e-9 * std::max(1.0, std::abs(r[i]))) << i;
  EXPECT_TRUE(e.noise_given());
  for (const auto& [extra, key] : std::vector<std::pair<std::string, std::string>>{{"noise = 0.5\nnoise_relative = 0.01\n", "noise_relative"},
                                                                                  {"noise_relative = 1.5\n", "noise_relative"}}) {
    const std::string f = write("relnoise_bad.toml", base_fit(kParam, "[[experiment]]\nscene = \"" + scene + "\"\ndata = \"" + data + "\"\n" + extra));
    try {
      inverse::read_fit_file(f);
      ADD_FAILURE() << extra << " accepted";
    } catch (const io::InputError& err) {
      EXPECT_NE(err.key().find(key), std::string::npos) << err.what();
    }
  }
}

// Units in a measurement header: a curve given in % strain and GPa is the same experiment as
// the one in fractions and MPa; a unit spifit does not convert names the file, column and unit.
TEST(FitFile, MeasurementUnitsAreConvertedOrRejected) {
  const std::string plain = write("plain.csv", "strain [-],stress [MPa]\n0.01,60\n0.02,70\n");
  const std::string percent = write("percent.csv", "strain [%],stress [GPa]\n1,0.060\n2,0.070\n");
  const auto a = inverse::read_fit_file(write("a.toml", base_fit(kParam, curve(plain)))).experiments.at(0);
  const auto b = inverse::read_fit_file(write("b.toml", base_fit(kParam, curve(percent)))).experiments.at(0);
  inverse::ParameterPoint p;
  const auto ca = a->compare(p), cb = b->compare(p);
  ASSERT_EQ(ca.x.size(), 2u);
  ASSERT_EQ(cb.x.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(cb.x[i], ca.x[i], 1e-15);
    EXPECT_NEAR(cb.measured[i], ca.measured[i], 1e-12);
  }
  EXPECT_EQ(b->axes().x_unit, "-");
  EXPECT_EQ(b->axes().y_unit, "MPa");
  EXPECT_EQ(b->axes().x_words, "strain ε");  // a tensile scene; shear scenes show γ and τ
  EXPECT_EQ(b->axes().y_words, "true stress σ");
  const std::string odd = write("odd.csv", "strain [furlong],stress [MPa]\n0.01,60\n0.02,70\n");
  expect_error(base_fit(kParam, curve(odd)), "column strain", "does not convert to a fraction");
  const std::string ksi = write("ksi.csv", "strain [-],stress [ksi]\n0.01,60\n0.02,70\n");
  expect_error(base_fit(kParam, curve(ksi)), "column stress", "does not convert to MPa");
}
