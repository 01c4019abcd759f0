// Sweeps: grid order, closed-form sensitivity, failing points, thread independence.
#include "forward/io/input_error.hpp"
#include "forward/material/hill48.hpp"
#include "forward/material/material_card.hpp"
#include "inverse/sweeps/sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

using namespace spifit;

namespace {
std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }
}  // namespace

TEST(Sweep, BundledHillNSweep) {
  const auto spec = inverse::read_sweep_file(src("experiments/aa3003o/sweep_hill_n.toml"));
  const auto r = inverse::run_sweep(spec, {2, nullptr, {}});
  ASSERT_EQ(r.points.size(), 27u);  // 9 x 3, last input fastest
  EXPECT_EQ(r.points[0].inputs, (std::vector<double>{2.5, 0.18}));
  EXPECT_EQ(r.points[1].inputs, (std::vector<double>{2.5, 0.21}));
  for (const auto& p : r.points) {
    ASSERT_TRUE(p.ok) << p.message;
    // r45 = (2N - F - G) / (2 (F + G)) whatever the hardening (closed form).
    EXPECT_NEAR(p.metrics[0], (2 * p.inputs[0] - 1.224 - 1.193) / (2 * (1.224 + 1.193)), 1e-9);
  }
  // d ln r45 / d ln N = N / ((F + G) r45) at N = 4.06.
  const double r45 = (2 * 4.06 - 2.417) / (2 * 2.417);
  bool found = false;
  for (const auto& s : r.sensitivities) {
    if (s.input == "hill.N" && s.metric == "r_value") {
      EXPECT_NEAR(s.value, 4.06 / (2.417 * r45), 2e-4);
      found = true;
    }
    if (s.input == "swift.n" && s.metric == "r_value") {
      EXPECT_NEAR(s.value, 0.0, 1e-9);  // r does not depend on hardening
    }
  }
  EXPECT_TRUE(found);
  // Same results with one thread.
  const auto r1 = inverse::run_sweep(spec, {1, nullptr, {}});
  for (std::size_t i = 0; i < r.points.size(); ++i) EXPECT_EQ(r.points[i].metrics, r1.points[i].metrics);
}

// A grid point with an invalid card (negative N) is an input error naming the file, the key and
// the value, before anything runs; so is an unknown metric.
TEST(Sweep, InvalidGridValueIsAnInputError) {
  const auto dir = std::filesystem::temp_directory_path() / ("spifit_sweep_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto f = dir / "s.toml";
  std::ofstream(f) << "[sweep]\nscene = \"" << src("experiments/aa3003o/scenes/tensile_45.toml")
                   << "\"\nmetrics = [\"r_value\"]\nsensitivities = false\n[inputs.\"hill.N\"]\nvalues = [-1.0, 3.0]\n";
  try {
    inverse::read_sweep_file(f.string());
    ADD_FAILURE() << "hill.N = -1 accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), f.string());
    EXPECT_EQ(e.key(), "inputs.hill.N.values");
    EXPECT_EQ(e.value(), "-1");
  }
  std::ofstream(f) << "[sweep]\nscene = \"" << src("experiments/aa3003o/scenes/tensile_45.toml") << "\"\nmetrics = [\"r_valu\"]\n[inputs.\"hill.N\"]\nvalues = [3.0]\n";
  EXPECT_THROW(inverse::read_sweep_file(f.string()), io::InputError);
  std::filesystem::remove_all(dir);
}

// A material-point scene's own named input: the r-value of card C.3 + C.4 over the loading
// angle follows Hill's closed form r(alpha) (thesis eq. C.2 at 0, 45 and 90 deg).
TEST(Sweep, TensileAngleIsANamedInput) {
  const auto dir = std::filesystem::temp_directory_path() / ("spifit_sweep_angle_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto f = dir / "s.toml";
  std::ofstream(f) << "[sweep]\nscene = \"" << src("experiments/aa3003o/scenes/tensile_00.toml")
                   << "\"\nmetrics = [\"r_value\"]\nsensitivities = false\n[inputs.\"scene.angle\"]\nvalues = [0.0, 30.0, 45.0, 90.0]\n";
  const auto spec = inverse::read_sweep_file(f.string());
  const auto r = inverse::run_sweep(spec, {2, nullptr, {}});
  const auto card = material::load_material_card(src("materials/aa3003o_c3c4.toml"));
  ASSERT_EQ(r.points.size(), 4u);
  for (const auto& p : r.points) {
    ASSERT_TRUE(p.ok) << p.message;
    const double closed = material::r_value_at_angle(card.hill(), p.inputs[0] * std::numbers::pi / 180.0);
    EXPECT_NEAR(p.metrics[0] / closed, 1.0, 1e-6) << "angle " << p.inputs[0];
  }
  // The reader's range: an angle beyond 180 deg is refused before anything runs.
  std::ofstream(f) << "[sweep]\nscene = \"" << src("experiments/aa3003o/scenes/tensile_00.toml")
                   << "\"\nmetrics = [\"r_value\"]\n[inputs.\"scene.angle\"]\nvalues = [200.0]\n";
  try {
    inverse::read_sweep_file(f.string());
    ADD_FAILURE() << "angle 200 accepted";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("must lie in [-180, 180] deg"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// A material-point sweep reports the scene's own metric in sensitivities.csv even when no input
// can be stepped (the loading angle's base is 0 deg: no logarithm): base_metric is r0 of the card
// (thesis eq. C.2), the sensitivity NaN.
TEST(Sweep, BaseMetricIsReportedWhenNoInputCanBeStepped) {
  const auto dir = std::filesystem::temp_directory_path() / ("spifit_sweep_base_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto f = dir / "s.toml";
  std::ofstream(f) << "[sweep]\nscene = \"" << src("experiments/aa3003o/scenes/tensile_00.toml")
                   << "\"\nmetrics = [\"r_value\"]\nsensitivities = true\n[inputs.\"scene.angle\"]\nvalues = [0.0]\n";
  const auto r = inverse::run_sweep(inverse::read_sweep_file(f.string()), {1, nullptr, {}});
  const auto card = material::load_material_card(src("materials/aa3003o_c3c4.toml"));
  ASSERT_EQ(r.sensitivities.size(), 1u);
  EXPECT_EQ(r.sensitivities[0].base_input, 0.0);
  EXPECT_NEAR(r.sensitivities[0].base_metric / material::r_value_at_angle(card.hill(), 0.0), 1.0, 1e-6);
  EXPECT_TRUE(std::isnan(r.sensitivities[0].value));
  std::filesystem::remove_all(dir);
}
