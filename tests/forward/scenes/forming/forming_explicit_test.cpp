// The explicit scheme on a forming scene: the thesis §7.1 indent with mass scaling against the
// implicit run of the same scene (force and energy balance), the same files twice, and the
// start-up refusal of a run that would need too many steps.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "forward/scenes/forming/forming_scene.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

FormingScene indent(double travel) {
  FormingScene s = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml");
  s.path.back().tip.z() = -travel;
  return s;
}

FormingScene explicit_indent(double travel, double mass_scaling) {
  FormingScene s = indent(travel);
  s.explicit_scheme = true;
  s.explicit_options.mass_scaling = mass_scaling;
  return s;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ExplicitIndent, MatchesTheImplicitForceAndClosesItsEnergyBalance) {
  const FormingResult implicit = run_forming_scene(indent(2.0));
  ASSERT_TRUE(implicit.ok()) << implicit.message;
  const FormingResult r = run_forming_scene(explicit_indent(2.0, 1e6));
  ASSERT_TRUE(r.ok()) << r.message;
  // Measured: 289.28 N against 289.40 N (-0.04 %).
  EXPECT_NEAR(r.force.peak().z() / implicit.force.peak().z(), 1.0, 5e-3);
  const model::ModelEnergies& en = r.final_energies;
  EXPECT_GT(en.external_work, 100.0);
  EXPECT_LT(std::abs(en.balance_error()), 0.01 * en.external_work) << "balance error " << en.balance_error() << " N mm";
  EXPECT_LT(en.kinetic, 0.01 * en.internal());  // quasi-static
  const nlohmann::json j = r.to_json();
  EXPECT_EQ(j.at("solver").at("scheme"), "explicit");
  EXPECT_GT(j.at("explicit").at("steps").get<long>(), 1000);
  EXPECT_DOUBLE_EQ(j.at("explicit").at("mass_scaling").get<double>(), 1e6);
}

TEST(ExplicitIndent, SameInputsWriteTheSameFiles) {
  const FormingScene s = explicit_indent(0.5, 1e6);
  std::string first;
  for (const char* tag : {"a", "b"}) {
    const fs::path d = fs::temp_directory_path() / ("spifit_explicit_" + std::string(tag) + "_" + std::to_string(::getpid()));
    const auto out = io::OutputDirectory::prepare(d.string(), true);
    const FormingResult r = run_forming_scene(s, RunFiles(out));
    ASSERT_TRUE(r.ok()) << r.message;
    const std::string files = read_bytes(d / "force.csv") + read_bytes(d / "energies.csv");
    EXPECT_GT(files.size(), 500u);
    if (first.empty()) first = files;
    else EXPECT_EQ(files, first);
    fs::remove_all(d);
  }
}

TEST(ExplicitIndent, ARunNeedingTooManyStepsStopsAtStartUpNamingTheElementAndTheScaling) {
  FormingScene s = explicit_indent(2.0, 1.0);
  s.explicit_options.max_steps = 1e5;
  try {
    (void)run_forming_scene(s);
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), "solver.mass_scaling");
    EXPECT_NE(what.find("indent.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("element "), std::string::npos) << what;
    EXPECT_NE(what.find("mass_scaling = "), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace spifit::scene
