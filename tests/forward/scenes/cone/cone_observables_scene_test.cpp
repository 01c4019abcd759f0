// The shape, stage and element observables in a run: one contour of a small 45 deg
// cone on a coarse 90 deg pie with [output] history_element; the files exist, have the
// documented columns and agree with each other.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

using test::temp_path;

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

Csv read_csv(const fs::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  Csv c;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (c.header.empty()) {
      c.header = cells;
      continue;
    }
    std::vector<double> row;
    for (const auto& cell : cells) row.push_back(std::stod(cell));
    EXPECT_EQ(row.size(), c.header.size()) << file;
    c.rows.push_back(row);
  }
  return c;
}

TEST(ConeObservables, SectionsStagesAndElementHistoryOfOneContour) {
  const fs::path file = test::write_tiny_cone(temp_path("tiny.toml"), "[output]\nhistory_element = { r = 18.0, theta = 45.0 }\n");
  const ConeScene scene = read_cone_scene(file.string());
  ASSERT_TRUE(scene.history_element.has_value());
  EXPECT_DOUBLE_EQ(scene.history_element->r, 18.0);
  const fs::path dir = temp_path("out");
  fs::remove_all(dir);
  const auto out = io::OutputDirectory::prepare(dir.string(), true);
  const ConeResult r = run_cone_scene(scene, RunFiles(out));
  ASSERT_TRUE(r.ok()) << r.to_json().dump();
  const auto obs = r.to_json()["observables"];
  std::printf("observables: %s\n", obs.dump().c_str());
  const int increments = r.to_json()["increments"].get<int>();

  // history.csv: one row per increment; E_rr = (lambda_r^2 - 1)/2; the middle layer (zeta = 0) is
  // the membrane; the element at r = 18 mm is thinned by the contour (tool centre at r = 16 mm).
  ASSERT_TRUE(obs.contains("history_element"));
  const double cr = obs["history_element"]["centroid_r"].get<double>();
  EXPECT_NEAR(cr, 18.0, 1.5);
  const Csv h = read_csv(dir / "history.csv");
  ASSERT_EQ(static_cast<int>(h.rows.size()), increments);
  EXPECT_EQ(h.header.size(), 12u + 3u * 9u);
  const int lr = h.column("lambda_r"), err = h.column("E_rr"), l2 = h.column("L2_E_rr"), l2z = h.column("L2_zeta");
  const int th = h.column("thickness [mm]"), eq1 = h.column("L1_eqps"), eq3 = h.column("L3_eqps");
  for (const auto& row : h.rows) {
    EXPECT_NEAR(row[static_cast<std::size_t>(err)], 0.5 * (row[static_cast<std::size_t>(lr)] * row[static_cast<std::size_t>(lr)] - 1.0), 1e-12);
    EXPECT_EQ(row[static_cast<std::size_t>(l2z)], 0.0);
    EXPECT_NEAR(row[static_cast<std::size_t>(l2)], row[static_cast<std::size_t>(err)], 1e-15);
  }
  const auto& last = h.rows.back();
  std::printf("history element end: thickness %.4f mm, E_rr %.4f, E_tt %.4f, gamma %.4f, eqps bottom/top %.4f/%.4f\n",
              last[static_cast<std::size_t>(th)], last[static_cast<std::size_t>(err)], last[static_cast<std::size_t>(h.column("E_tt"))],
              last[static_cast<std::size_t>(h.column("gamma_rt"))], last[static_cast<std::size_t>(eq1)], last[static_cast<std::size_t>(eq3)]);
  EXPECT_LT(last[static_cast<std::size_t>(th)], 0.99);
  EXPECT_GT(last[static_cast<std::size_t>(eq1)] + last[static_cast<std::size_t>(eq3)], 0.0);
  EXPECT_DOUBLE_EQ(last[0], r.to_json()["travel_reached"].get<double>());

  // Section after contour 1: top and bottom h apart along the director, the axis node and the
  // clamped rim do not turn; depth = t0/2 - z_top.
  const Csv s = read_csv(dir / "sections" / "section_s1_c001.csv");
  ASSERT_EQ(s.header.size(), 13u);
  const int rt = s.column("r_top [mm]"), zt = s.column("z_top [mm]"), rb = s.column("r_bottom [mm]"), zb = s.column("z_bottom [mm]");
  const int thk = s.column("thickness [mm]"), ut = s.column("u_theta [mm]"), dep = s.column("depth [mm]");
  for (const auto& row : s.rows) {
    const double gap = std::hypot(row[static_cast<std::size_t>(rt)] - row[static_cast<std::size_t>(rb)],
                                  row[static_cast<std::size_t>(zt)] - row[static_cast<std::size_t>(zb)]);
    EXPECT_NEAR(gap, row[static_cast<std::size_t>(thk)], 0.02 * row[static_cast<std::size_t>(thk)]);
  }
  EXPECT_NEAR(s.rows.front()[static_cast<std::size_t>(ut)], 0.0, 1e-12);
  EXPECT_NEAR(s.rows.back()[static_cast<std::size_t>(ut)], 0.0, 1e-12);
  for (const auto& row : s.rows) EXPECT_NEAR(row[static_cast<std::size_t>(dep)], 0.5 - row[static_cast<std::size_t>(zt)], 1e-12);
  EXPECT_EQ(s.rows.back()[static_cast<std::size_t>(s.column("z [mm]"))], 0.0);  // the clamped rim
  // The rim's top surface: h/2 along the (tilted) director, a little below its initial height.
  EXPECT_GT(s.rows.back()[static_cast<std::size_t>(dep)], 0.0);
  EXPECT_LT(s.rows.back()[static_cast<std::size_t>(dep)], 0.1);
  const Csv e = read_csv(dir / "sections" / "elongation_s1_c001.csv");
  EXPECT_EQ(e.rows.size() + 1, s.rows.size());

  // sections.csv and stages.csv: one contour, one stage ending with the path.
  const Csv sum = read_csv(dir / "sections.csv");
  ASSERT_EQ(sum.rows.size(), 1u);
  EXPECT_NEAR(sum.rows[0][static_cast<std::size_t>(sum.column("sine_law_thickness [mm]"))], std::cos(M_PI / 4.0), 1e-12);
  double max_ratio = 0.0;
  for (const auto& row : e.rows) max_ratio = std::max(max_ratio, row[4]);
  EXPECT_DOUBLE_EQ(sum.rows[0][static_cast<std::size_t>(sum.column("max_elongation"))], max_ratio);
  const Csv st = read_csv(dir / "stages.csv");
  ASSERT_EQ(st.rows.size(), 1u);
  EXPECT_EQ(st.rows[0][0], 1.0);
  EXPECT_EQ(st.rows[0][1], 45.0);
  EXPECT_DOUBLE_EQ(st.rows[0][2], r.to_json()["travel_reached"].get<double>());
  EXPECT_DOUBLE_EQ(st.rows[0][4], -st.rows[0][3]);
  EXPECT_EQ(obs["stages"].size(), 1u);
  fs::remove_all(dir);
  fs::remove(file);
}

TEST(ConeObservables, HistoryElementErrorsNameFileKeyAndValue) {
  const fs::path file = temp_path("bad.toml");
  std::ofstream(file) << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                      << "[cone]\npreset = \"cone70\"\n[sheet]\nelements_per_45deg = 8\n"
                         "[output]\nhistory_element = { r = 75.55, theta = 50.0 }\n";
  try {
    read_cone_scene(file.string());
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& err) {
    EXPECT_EQ(err.key(), "output.history_element.theta") << err.what();
    EXPECT_EQ(err.value(), "50");
    EXPECT_NE(std::string(err.what()).find("pie_angle = 45"), std::string::npos) << err.what();
  }
  std::ofstream(file) << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                      << "[cone]\npreset = \"cone70\"\n[sheet]\nelements_per_45deg = 8\n"
                         "[output]\nhistory_element = { r = 75.55, angle = 22.5 }\n";
  try {
    read_cone_scene(file.string());
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& err) {
    EXPECT_EQ(err.key(), "output.history_element.angle") << err.what();
  }
  fs::remove(file);
}

// The observable steady_ftheta_over_fz (cone_kind.cpp) over contours [2, 3] of a three-contour
// small tiny cone, at mu = 0.1: the mean of the contours' central-third Ftheta over the mean of
// their Fz, both taken from the run's contour log (contours.csv, numbers to 17 digits), to 1e-12.
// Contour 1 (the tool's first pass, another state of the sheet) lies outside the range.
TEST(ConeObservables, SteadyFthetaOverFzIsTheRatioOfTheContourLogsMeans) {
  const fs::path file = test::write_tiny_cone(temp_path("cone.toml"), "[contact]\nfriction = 0.1\n", test::small_tiny_cone(3));
  const auto scene = read_scene(file.string());
  const fs::path dir = temp_path("out");
  fs::remove_all(dir);
  const auto out = io::OutputDirectory::prepare(dir.string(), true);
  const auto result = scene->run(RunFiles(out), RunControl());
  ASSERT_TRUE(result->ok()) << result->message;
  const Observable* o = find_scene_kind("cone")->find_observable("steady_ftheta_over_fz");
  ASSERT_NE(o, nullptr);
  ObservableOptions range;
  range.contours = std::make_pair(2, 3);
  const double value = o->value(*result, range);

  const Csv log = read_csv(dir / "contours.csv");
  ASSERT_EQ(log.rows.size(), 3u);
  const auto col = [&](const char* name) { return static_cast<std::size_t>(log.column(name)); };
  double ftheta = 0.0, fz = 0.0;
  for (std::size_t k = 1; k < 3; ++k) {  // contours 2 and 3
    EXPECT_EQ(log.rows[k][col("contour")], static_cast<double>(k + 1));
    EXPECT_GT(log.rows[k][col("samples")], 0.0);
    ftheta += log.rows[k][col("Ftheta [N]")];
    fz += log.rows[k][col("Fz [N]")];
  }
  const double expected = (ftheta / 2.0) / (fz / 2.0);
  std::printf("steady Ftheta / Fz over contours 2-3: %.15g (contour log: %.15g)\n", value, expected);
  EXPECT_LT(expected, 0.0);  // friction drags the tool back
  EXPECT_NEAR(value, expected, 1e-12 * std::abs(expected));
  // Contour 1 alone: its own ratio, another number.
  range.contours = std::make_pair(1, 1);
  const double first = log.rows[0][col("Ftheta [N]")] / log.rows[0][col("Fz [N]")];
  EXPECT_NEAR(o->value(*result, range), first, 1e-12 * std::abs(first));
  EXPECT_GT(std::abs(first - expected), 1e-6);
  fs::remove_all(dir);
  fs::remove(file);
}

}  // namespace
}  // namespace spifit::scene
