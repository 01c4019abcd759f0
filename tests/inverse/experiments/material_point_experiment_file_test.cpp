// Material-point experiments of a fit file (docs/reference/file-formats.md, "Fit file"): a table of scalars
// (one run and one residual per row), the angle of an experiment over its scene's, a scene
// without a card of its own, and their input errors naming file, key and value.
#include "forward/io/input_error.hpp"
#include "inverse/fit/fit_file.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }
std::string scene_file(const std::string& name) { return src("experiments/aa3003o/scenes/" + name + ".toml"); }

// Card C.2 with hill.N free (its initial value the card's: 2.977).
std::string fit_text(const std::string& experiments) {
  return "[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\n[parameters.\"hill.N\"]\nlower = 1.0\nupper = 8.0\n" + experiments;
}

// Lankford coefficients of card C.2 (docs/reference/file-formats.md): r0 = H/G, r45 = (2N - F - G) / (2 (F + G)), r90 = H/F.
constexpr double kF = 1.224, kG = 1.193, kH = 0.807, kN = 2.977;
const double kLankford[3] = {kH / kG, (2 * kN - kF - kG) / (2 * (kF + kG)), kH / kF};

const std::string kRValues = "# MEASURED, thesis App. C.1\nangle [deg],r_value [-]\n0,0.68\n45,0.73\n90,0.66\n";

std::string table_experiment(const std::string& data, const std::string& extra = "") {
  return "[[experiment]]\nname = \"r\"\nscene = \"" + scene_file("tensile_00") + "\"\nobservable = \"r_value\"\ndata = \"" + data +
         "\"\nx = \"angle\"\nnoise = 0.02\n" + extra;
}
std::string scalar_experiment(const std::string& name, const std::string& scene_file, double value, const std::string& extra = "") {
  return "[[experiment]]\nname = \"" + name + "\"\nscene = \"" + scene_file + "\"\nobservable = \"r_value\"\nvalue = " + io::format_number(value) +
         "\nnoise = 0.02\n" + extra;
}

inverse::FitProblem read(const std::string& name, const std::string& text) {
  return inverse::read_fit_file(test::write_temp_file(name, text).string());
}

// The residuals of every experiment of a fit at its initial point, one after the other.
std::vector<double> residuals_at_start(const inverse::FitProblem& fp) {
  const auto p = fp.parameters->point(fp.parameters->initial_internal().data());
  std::vector<double> all;
  for (const auto& e : fp.experiments) {
    std::vector<double> r(static_cast<std::size_t>(e->num_residuals()));
    EXPECT_TRUE(e->residuals(p, r.data())) << e->name();
    all.insert(all.end(), r.begin(), r.end());
  }
  return all;
}

// The fit file's error: its file, key and whole message.
struct Failure {
  std::string file, key, what;
};
Failure failure_of(const std::string& text) {
  const std::string path = test::write_temp_file("bad_fit.toml", text).string();
  try {
    inverse::read_fit_file(path);
  } catch (const io::InputError& e) {
    return {e.file(), e.key(), e.what()};
  }
  ADD_FAILURE() << "no error for\n" << text;
  return {};
}

}  // namespace

// A table of r-values at 0, 45 and 90 deg on one tensile scene: three runs, three residuals,
// each (r_simulated - r_measured) / noise, with r_simulated Hill's closed form at each row's angle.
TEST(MaterialPointExperimentFile, TableOfScalarsRunsTheSceneAtEachRowsAngle) {
  const fs::path data = test::write_temp_file("rvalues.csv", kRValues);
  const auto fp = read("fit.toml", fit_text(table_experiment(data.string())));
  ASSERT_EQ(fp.experiments.size(), 1u);
  const auto& e = *fp.experiments.front();
  EXPECT_EQ(e.kind(), "scalar_table");
  ASSERT_EQ(e.num_residuals(), 3);
  EXPECT_EQ(e.scale(), 0.02);
  EXPECT_TRUE(e.noise_given());
  const auto p = fp.parameters->point(fp.parameters->initial_internal().data());
  const auto c = e.compare(p);
  EXPECT_EQ(c.x_name, "angle");
  EXPECT_EQ(c.x_unit, "deg");
  EXPECT_EQ(c.y_name, "r_value");
  EXPECT_EQ(c.x, (std::vector<double>{0.0, 45.0, 90.0}));
  EXPECT_EQ(c.measured, (std::vector<double>{0.68, 0.73, 0.66}));
  ASSERT_EQ(c.simulated.size(), 3u);
  const auto r = residuals_at_start(fp);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(c.simulated[i], kLankford[i], 1e-6) << i;
    EXPECT_NEAR(r[i], (c.simulated[i] - c.measured[i]) / 0.02, 1e-12) << i;
  }
  // With Jets: d r45 / d N = 1 / (F + G), so d residual / d N = 1 / ((F + G) 0.02); r0 and r90
  // do not depend on N.
  auto m = p.material.cast<inverse::Jet>();
  m.N.v[0] = 1.0;
  std::vector<inverse::Jet> rj(3);
  ASSERT_TRUE(e.residuals(m, rj.data()));
  EXPECT_NEAR(rj[1].v[0], 1.0 / ((kF + kG) * 0.02), 1e-6);
  EXPECT_NEAR(rj[0].v[0], 0.0, 1e-9);
  EXPECT_NEAR(rj[2].v[0], 0.0, 1e-9);
  // The Jet pass ends with one more Newton step than the double one: equal to round-off.
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(rj[i].a, r[i], 1e-10) << i;
}

// The table is the three scalar experiments on tensile_00/45/90 in one: the same residuals.
TEST(MaterialPointExperimentFile, TableOfScalarsEqualsOneScalarExperimentPerRow) {
  const fs::path data = test::write_temp_file("rvalues.csv", kRValues);
  const auto table = residuals_at_start(read("table.toml", fit_text(table_experiment(data.string()))));
  const auto scalars = residuals_at_start(read("scalars.toml", fit_text(scalar_experiment("r0", scene_file("tensile_00"), 0.68) +
                                                                         scalar_experiment("r45", scene_file("tensile_45"), 0.73) +
                                                                         scalar_experiment("r90", scene_file("tensile_90"), 0.66))));
  EXPECT_EQ(table, scalars);
}

// Without noise a table is conditioned as a curve: by the range of its values (0.73 - 0.66).
TEST(MaterialPointExperimentFile, TableOfScalarsWithoutNoiseIsScaledByTheRange) {
  const fs::path data = test::write_temp_file("rvalues.csv", kRValues);
  std::string text = fit_text(table_experiment(data.string()));
  text.erase(text.find("noise = 0.02\n"), 13);
  const auto fp = read("fit.toml", text);
  EXPECT_NEAR(fp.experiments.front()->scale(), 0.07, 1e-15);
  EXPECT_FALSE(fp.experiments.front()->noise_given());
}

TEST(MaterialPointExperimentFile, TableOfScalarsErrorsNameFileKeyAndValue) {
  struct Case {
    std::string csv, extra, file_end, key, what;
  };
  const std::vector<Case> cases{
      {"angle [deg],r_valu\n0,0.68\n", "", "unknown_column.csv", "column", "column = r_value: no such column (columns: angle, r_valu)"},
      {"angle [deg],r_value\n0,0.68\n200,0.7\n", "", "angle_outside.csv", "column angle",
       "column angle = 200: scene.angle must lie in [-180, 180] deg (row 2)"},
      {"angle [deg],r_value\n0,0.68\n45,0.7x\n", "", "not_a_number.csv", "line 3, column r_value", "line 3, column r_value = 0.7x: not a finite number"},
      {"angle [rad],r_value\n0,0.68\n", "", "radians.csv", "column angle", "column angle = rad: a unit other than the scene input's (scene.angle is in deg)"},
  };
  for (const auto& c : cases) {
    const fs::path data = test::write_temp_file(c.file_end, c.csv);
    const Failure f = failure_of(fit_text(table_experiment(data.string(), c.extra)));
    EXPECT_EQ(f.file, data.string()) << c.file_end;
    EXPECT_EQ(f.key, c.key) << c.file_end;
    EXPECT_EQ(f.what, data.string() + ": " + c.what) << c.file_end;
  }
  const fs::path data = test::write_temp_file("rvalues.csv", kRValues);
  // Errors of the experiment itself: x that is no scene input of the kind, keys of other forms.
  std::string text = fit_text(table_experiment(data.string()));
  text.replace(text.find("x = \"angle\""), 11, "x = \"stress_ratio\"");
  Failure f = failure_of(text);
  EXPECT_EQ(f.key, "experiment[0].x");
  EXPECT_NE(f.what.find("experiment[0].x = \"stress_ratio\": not an input of scene kind tensile a row can set (known: angle, r_value_strain)"),
            std::string::npos)
      << f.what;
  f = failure_of(fit_text(table_experiment(data.string(), "angle = 45\n")));
  EXPECT_NE(f.what.find("experiment[0].angle = 45: the data's column angle sets each row's angle"), std::string::npos) << f.what;
  f = failure_of(fit_text(table_experiment(data.string(), "value = 0.7\n")));
  EXPECT_EQ(f.key, "experiment[0].value");
  f = failure_of(fit_text(table_experiment(data.string(), "y = \"r\"\n")));
  EXPECT_EQ(f.key, "experiment[0].y");
  std::string shear = fit_text(table_experiment(data.string()));
  shear.replace(shear.find("tensile_00"), 10, "shear_00");
  f = failure_of(shear);
  EXPECT_NE(f.what.find("experiment[0].observable = \"r_value\": r_value and yield_stress need a tensile scene"), std::string::npos) << f.what;
}

// A table over another scene input than the angle: r at two strains of a tensile test.
TEST(MaterialPointExperimentFile, TableOfScalarsOverTheRValueStrain) {
  const fs::path data = test::write_temp_file("r_strain.csv", "r_value_strain,r_value\n0.05,0.68\n0.2,0.68\n");
  std::string text = fit_text(table_experiment(data.string()));
  text.replace(text.find("x = \"angle\""), 11, "x = \"r_value_strain\"");
  const auto fp = read("fit.toml", text);
  const auto p = fp.parameters->point(fp.parameters->initial_internal().data());
  const auto c = fp.experiments.front()->compare(p);
  EXPECT_EQ(c.x, (std::vector<double>{0.05, 0.2}));
  ASSERT_EQ(c.simulated.size(), 2u);
  // Isotropic hardening: the plastic flow direction, and so r, does not change with strain.
  EXPECT_NEAR(c.simulated[0], kLankford[0], 1e-6);
  EXPECT_NEAR(c.simulated[1], kLankford[0], 1e-6);
}

// angle = 45 runs tensile_00.toml at 45 deg: the same numbers as tensile_45.toml, for a scalar
// and for a curve.
TEST(MaterialPointExperimentFile, AngleOverridesTheScenesAngle) {
  const auto over = residuals_at_start(read("over.toml", fit_text(scalar_experiment("r45", scene_file("tensile_00"), 0.73, "angle = 45\n"))));
  const auto own = residuals_at_start(read("own.toml", fit_text(scalar_experiment("r45", scene_file("tensile_45"), 0.73))));
  ASSERT_EQ(over.size(), 1u);
  EXPECT_EQ(over, own);
  EXPECT_NEAR(over[0], (kLankford[1] - 0.73) / 0.02, 1e-4);
  const std::string data = src("experiments/aa3003o/data/tensile_90_c2_synthetic.csv");
  auto curve = [&](const std::string& scene_name, const std::string& extra) {
    return fit_text("[[experiment]]\nname = \"t90\"\nscene = \"" + scene_file(scene_name) + "\"\ndata = \"" + data + "\"\nnoise = 0.5\n" + extra);
  };
  const auto curve_over = residuals_at_start(read("curve_over.toml", curve("tensile_00", "angle = 90.0\n")));
  EXPECT_EQ(curve_over.size(), 50u);
  EXPECT_EQ(curve_over, residuals_at_start(read("curve_own.toml", curve("tensile_90", ""))));
}

TEST(MaterialPointExperimentFile, AngleErrorsNameFileKeyAndValue) {
  Failure f = failure_of(fit_text(scalar_experiment("r", scene_file("tensile_00"), 0.7, "angle = [0, 45, 90]\n")));
  EXPECT_EQ(f.key, "experiment[0].angle");
  EXPECT_NE(f.what.find("experiment[0].angle = [0, 45, 90]: one angle per experiment; for several, a table of scalars"), std::string::npos) << f.what;
  f = failure_of(fit_text(scalar_experiment("r", scene_file("tensile_00"), 0.7, "angle = 190\n")));
  EXPECT_NE(f.what.find("bad_fit.toml: experiment[0].angle = 190: must lie in [-180, 180] deg"), std::string::npos) << f.what;
  // Only material-point experiments take an angle.
  f = failure_of(fit_text("[[experiment]]\nscene = \"" + scene_file("indent") + "\"\nobservable = \"peak_fz\"\nvalue = 100.0\nangle = 45\n"));
  EXPECT_EQ(f.key, "experiment[0].angle");
  EXPECT_NE(f.what.find("unknown key"), std::string::npos) << f.what;
}

// A scene without [scene] material, outside the bundled tree (no default card there): a fit
// runs it with the fit's card, as the bundled scene that names a card.
TEST(MaterialPointExperimentFile, SceneWithoutACardRunsWithTheFitsCard) {
  const fs::path own = test::write_temp_file("tensile_no_card.toml", "[scene]\nkind = \"tensile\"\nangle = 45.0\nstrain_path = [0.30]\nincrements = 200\n");
  const auto without = residuals_at_start(read("without.toml", fit_text(scalar_experiment("r45", own.string(), 0.73))));
  const auto with = residuals_at_start(read("with.toml", fit_text(scalar_experiment("r45", scene_file("tensile_45"), 0.73))));
  EXPECT_EQ(without, with);
  const auto fp = read("without.toml", fit_text(scalar_experiment("r45", own.string(), 0.73)));
  EXPECT_NE(std::find(fp.input_files.begin(), fp.input_files.end(), own.string()), fp.input_files.end());
  // A card the scene names must still exist.
  const fs::path wrong = test::write_temp_file("tensile_wrong_card.toml", "[scene]\nkind = \"tensile\"\nmaterial = \"nope.toml\"\n");
  const Failure f = failure_of(fit_text(scalar_experiment("r", wrong.string(), 0.73)));
  EXPECT_EQ(f.file, wrong.string());
  EXPECT_EQ(f.key, "scene.material");
}
