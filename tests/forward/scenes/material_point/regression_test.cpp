// Regressions found in review (2026-11-21); each test failed before its fix.
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/material/return_mapping.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace spifit;

// The control strain must land exactly on the increment targets (no drift from summing
// sub-steps), so an r-value strain on an increment boundary is found.
TEST(Regression, RValueOnIncrementBoundary) {
  for (const char* name : {"aa3003o_c5_af_brick", "aa3003o_c6_ziegler_brick", "aa3003o_c8_ziegler_shell"}) {
    for (int inc : {3, 6, 9, 12}) {
      SCOPED_TRACE(std::string(name) + " " + std::to_string(inc));
      const auto r = scene::run_material_point(test::card(name).params, test::tensile(0.0, {0.3}, inc));
      ASSERT_TRUE(r.ok);
      EXPECT_TRUE(r.r_value.has_value());
      EXPECT_EQ(r.curve.back().control_strain, 0.3);
    }
  }
}

// r-value and offset yield are evaluated on the first monotonic stretch, not only segment 0.
TEST(Regression, RValueAfterLeadingSegment) {
  const auto card = test::card("aa3003o_c3c4");
  const auto r = scene::run_material_point(card.params, test::tensile(0.0, {0.001, 0.3}, 200));
  ASSERT_TRUE(r.ok);
  ASSERT_TRUE(r.r_value.has_value());
  ASSERT_TRUE(r.offset_yield_stress.has_value());
  const auto ref = scene::run_material_point(card.params, test::tensile(0.0, {0.3}, 200));
  EXPECT_NEAR(*r.r_value, *ref.r_value, 1e-9);
  EXPECT_NEAR(*r.offset_yield_stress_kirchhoff, *ref.offset_yield_stress_kirchhoff, 1e-9 * *ref.offset_yield_stress_kirchhoff);
}

// Accuracy sub-steps have their own budget: the failure cut-back limit does not change them.
TEST(Regression, AccuracySubstepsIndependentOfCutbackBudget) {
  const auto card = test::card("aa3003o_c5_af_brick");
  auto s = test::tensile(30.0, {0.3}, 1);
  const auto a = scene::run_material_point(card.params, s);
  s.driver.max_cutbacks = 0;
  const auto b = scene::run_material_point(card.params, s);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_EQ(a.substeps, b.substeps);
  EXPECT_EQ(a.curve.back().stress, b.curve.back().stress);
  EXPECT_EQ(*a.r_value, *b.r_value);
}

// Extreme kinematic rates are bounded: at most max_substeps sub-steps per increment, then
// the remaining accuracy bound is waived and reported.
TEST(Regression, SubstepsAreCapped) {
  auto card = test::card("aa3003o_c7_af_shell");
  card.params.kinematic[material::ArmstrongFrederick::CX] = 1e6;
  auto s = test::tensile(0.0, {0.3}, 10);
  const auto r = scene::run_material_point(card.params, s);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_LE(r.substeps, 10 * (s.driver.max_substeps + 1) + 100);
  EXPECT_GT(r.accuracy_limited_substeps, 0);
}

// A loose return-mapping tolerance must not lose the initial yield event.
TEST(Regression, OnsetWithLooseTolerance) {
  const auto card = test::card("aa3003o_c3c4");
  auto s = test::tensile(0.0, {0.3}, 200);
  s.driver.return_mapping.tolerance = 1e-4;
  const auto r = scene::run_material_point(card.params, s);
  ASSERT_TRUE(r.ok);
  ASSERT_FALSE(r.yield_events.empty());
  EXPECT_NEAR(r.yield_events[0].stress_kirchhoff, 42.9667, 1e-2);
}

// Large plastic increments converge in few iterations (residual sigma_F / sigma_eq - 1).
TEST(Regression, LargeStepIterationCount) {
  for (const auto& c : test::all_test_cards()) {
    if (!c.params.plastic) continue;
    SCOPED_TRACE(c.name);
    const material::ReturnMapping<double, 3> law(c.params);
    material::MaterialState<double, 3> s0, s1;
    const auto r = law.integrate(s0, Eigen::Vector3d(1.0, -0.3, 0.4), s1, nullptr);
    ASSERT_TRUE(r.ok());
    EXPECT_LE(r.iterations, 10);
  }
}

// 3D: a huge hydrostatic trial stress must not spoil the deviatoric return.
TEST(Regression, HydrostaticTrialStress3D) {
  const auto c = test::card("aa3003o_c7_af_shell");
  const material::ReturnMapping<double, 6> law(c.params);
  material::MaterialState<double, 6> s0, s1;
  Eigen::Matrix<double, 6, 1> de;
  de << 1.0 + 0.01, 1.0, 1.0, 0.0, 0.0, 0.0;  // ~1e5 MPa hydrostatic + a small deviator
  const auto r = law.integrate(s0, de, s1, nullptr);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_LE(r.iterations, 12);
  // Floor: a 1e5 MPa pressure leaves the deviator known to ~1e5 * 2e-16 = 2e-11 MPa.
  EXPECT_LT(std::abs(law.yield_function(s1)) / law.yield_stress(s1.eqps), 1e-9);
}

// --force replaces a spifit output directory, never an arbitrary one.
TEST(Regression, ForceOnlyReplacesSpifitOutput) {
  const fs::path d = fs::temp_directory_path() / ("spifit_force_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "notes.txt") << "precious";
  EXPECT_THROW(io::OutputDirectory::prepare(d.string(), true), io::InputError);
  EXPECT_TRUE(fs::exists(d / "notes.txt"));
  fs::remove(d / "notes.txt");
  std::ofstream(d / "summary.json") << "{\"spifit_version\": \"0.1.0\"}";
  std::ofstream(d / "curve.csv") << "x\n";
  EXPECT_NO_THROW(io::OutputDirectory::prepare(d.string(), true));
  EXPECT_FALSE(fs::exists(d / "curve.csv"));
  fs::remove_all(d);
}
