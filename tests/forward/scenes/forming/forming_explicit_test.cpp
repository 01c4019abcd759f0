// The explicit scheme on a forming scene: the thesis §7.1 indent with mass scaling against the
// implicit run of the same scene (force and energy balance, also with bulk viscosity), the same files twice, the start-up
// refusal of a run that would need too many steps, and checkpoints: a run stopped after a
// checkpoint and resumed writes the uninterrupted run's files byte for byte.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "forward/scenes/forming/forming_scene.hpp"
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <cstdio>
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

// The bulk viscosity with Abaqus/Explicit's coefficients: the force stays, its work joins the
// energy balance as damping work.
TEST(ExplicitIndent, BulkViscosityKeepsTheForceAndClosesTheEnergyBalanceWithItsWork) {
  const FormingResult implicit = run_forming_scene(indent(2.0));
  ASSERT_TRUE(implicit.ok()) << implicit.message;
  FormingScene s = explicit_indent(2.0, 1e6);
  s.explicit_options.bulk_viscosity_linear = 0.06;
  s.explicit_options.bulk_viscosity_quadratic = 1.2;
  const FormingResult r = run_forming_scene(s);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.force.peak().z() / implicit.force.peak().z(), 1.0, 5e-3);
  const model::ModelEnergies& en = r.final_energies;
  EXPECT_GT(en.damping, 0.0);
  EXPECT_LT(std::abs(en.balance_error()), 0.01 * en.external_work) << "balance error " << en.balance_error() << " N mm";
  const nlohmann::json j = r.to_json();
  EXPECT_DOUBLE_EQ(j.at("explicit").at("bulk_viscosity").at("quadratic").get<double>(), 1.2);
  std::printf("bulk viscosity: peak Fz %.2f N (implicit %.2f N), damping work %.4g of %.4g N mm, balance %.3g, %ld steps\n",
              r.force.peak().z(), implicit.force.peak().z(), en.damping, en.external_work, en.balance_error() / en.external_work,
              j.at("explicit").at("steps").get<long>());
}

// The one-point element (layers at the centre, hourglass stiffness 0.01 of the elastic section's):
// the implicit 2 x 2 force within 1 %, the hourglass energy in the balance.
TEST(ExplicitIndent, OnePointElementKeepsTheForceAndClosesTheEnergyBalance) {
  const FormingResult implicit = run_forming_scene(indent(2.0));
  ASSERT_TRUE(implicit.ok()) << implicit.message;
  FormingScene s = explicit_indent(2.0, 1e6);
  s.hourglass_stiffness = 0.01;
  const FormingResult r = run_forming_scene(s);
  ASSERT_TRUE(r.ok()) << r.message;
  // Measured: 288.95 N against 289.40 N (-0.16 %); 0.003 gives -0.9 %, 0.03 +1.8 %.
  EXPECT_NEAR(r.force.peak().z() / implicit.force.peak().z(), 1.0, 0.01);
  const model::ModelEnergies& en = r.final_energies;
  EXPECT_LT(std::abs(en.balance_error()), 0.01 * en.external_work) << "balance error " << en.balance_error() << " N mm";
  const nlohmann::json j = r.to_json();
  EXPECT_DOUBLE_EQ(j.at("model").at("hourglass_stiffness").get<double>(), 0.01);
  std::printf("one point: peak Fz %.2f N (implicit %.2f N), balance %.3g, %ld steps\n", r.force.peak().z(), implicit.force.peak().z(),
              en.balance_error() / en.external_work, j.at("explicit").at("steps").get<long>());
}

// The Moving Spherical Tool (thesis §5.3): no penetration and Coulomb's law at every contact
// point, the force of the penalty runs, the energy balance closed by the work of its forces.
TEST(ExplicitIndent, MovingSphericalToolLeavesNoPenetrationAndKeepsCoulombsLaw) {
  // The reference: implicit with a penalty stiff enough to leave no penetration to speak of
  // (K_p = 1e5: 2e-4 mm), as the MST leaves none.
  FormingScene implicit_scene = indent(1.0);
  implicit_scene.contact.friction = 0.1;
  implicit_scene.contact.penalty = 1e5;
  const FormingResult implicit = run_forming_scene(implicit_scene);
  ASSERT_TRUE(implicit.ok()) << implicit.message;
  FormingScene s = explicit_indent(1.0, 1e6);
  s.contact.friction = 0.1;
  s.contact.method = contact::ContactOptions::Method::mst;
  const FormingResult r = run_forming_scene(s);
  ASSERT_TRUE(r.ok()) << r.message;
  const nlohmann::json mst = r.to_json().at("explicit").at("mst");
  // Measured: 2.7e-4 mm at a contact point, 4e-6 mm anywhere on the surface (the bundled
  // penalty K_p = 1e3 lets the tool 0.02 mm in).
  EXPECT_LT(mst.at("max_penetration").get<double>(), 1e-3);
  EXPECT_LT(r.force.max_surface_penetration(), 1e-3);
  EXPECT_LE(mst.at("max_friction_over_mu_normal").get<double>(), 1.0 + 1e-12);
  EXPECT_GT(mst.at("solves").get<long>(), 100);
  // Measured: 99.61 N against 97.21 N (+2.5 %).
  EXPECT_NEAR(r.force.peak().z() / implicit.force.peak().z(), 1.0, 0.03);
  const model::ModelEnergies& en = r.final_energies;
  EXPECT_NEAR(en.external_work, mst.at("work_on_sheet").get<double>(), 1e-9 * en.external_work);
  EXPECT_LT(std::abs(en.balance_error()), 0.01 * en.external_work) << "balance error " << en.balance_error() << " N mm";
}

// Below mass scaling 1e6 the Moving Spherical Tool's force used to fall with the step (-22 % at
// 1e4, -47 % at 1e3 over the 2 mm indent): the tool-side surface was offset by the committed
// thickness, which changes with every step's membrane strains unforeseen by the prediction, and
// the next solve closed the gap that opened, feeding an oscillation of the nodes under the tool
// (docs/design/explicit.md, "MST contact"). The first 0.2 mm at 1e4 show it in 7 500 steps.
TEST(ExplicitIndent, MovingSphericalToolKeepsTheForceAndTheEnergyBalanceAtSmallMassScaling) {
  FormingScene implicit_scene = indent(0.2);
  implicit_scene.contact.penalty = 1e5;
  const FormingResult implicit = run_forming_scene(implicit_scene);
  ASSERT_TRUE(implicit.ok()) << implicit.message;
  FormingScene s = explicit_indent(0.2, 1e4);
  s.contact.method = contact::ContactOptions::Method::mst;
  const FormingResult r = run_forming_scene(s);
  ASSERT_TRUE(r.ok()) << r.message;
  // Measured: 16.76 N against 16.96 N (-1.1 %; the offset by the committed thickness: -10.8 %).
  EXPECT_NEAR(r.force.peak().z() / implicit.force.peak().z(), 1.0, 0.03);
  // Measured: 3.6e-5 of the external work and a kinetic energy of 7e-5 of the internal one (the
  // committed thickness: -1.3e-2 and 1.1e-2).
  const model::ModelEnergies& en = r.final_energies;
  EXPECT_LT(std::abs(en.balance_error()), 1e-3 * en.external_work) << "balance error " << en.balance_error() << " N mm";
  EXPECT_LT(en.kinetic, 1e-3 * en.internal());
}

TEST(ExplicitIndent, TheMovingSphericalToolNeedsTheExplicitScheme) {
  const std::string dir = (fs::temp_directory_path() / ("spifit_mst_" + std::to_string(::getpid()))).string();
  fs::create_directories(dir);
  std::string text = read_bytes(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml");
  text.replace(text.find("points = 2"), 10, "points = 2\nmethod = \"mst\"");
  text.replace(text.find("../../../materials"), 18, std::string(SPIFIT_SOURCE_DIR) + "/materials");
  std::ofstream(dir + "/indent_mst.toml") << text;
  try {
    (void)read_forming_scene(dir + "/indent_mst.toml");
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "contact.method");
    EXPECT_NE(std::string(e.what()).find("solver.scheme = \"explicit\""), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// Same inputs, same files: twice with 2 threads, and with 1 thread.
TEST(ExplicitIndent, SameInputsWriteTheSameFiles) {
  FormingScene s = explicit_indent(0.5, 1e6);
  s.contact.friction = 0.1;
  s.contact.method = contact::ContactOptions::Method::mst;
  std::string first;
  const int saved = omp_get_max_threads();
  for (const int threads : {2, 2, 1}) {
    omp_set_num_threads(threads);
    const fs::path d = fs::temp_directory_path() / ("spifit_explicit_" + std::to_string(threads) + "_" + std::to_string(::getpid()));
    const auto out = io::OutputDirectory::prepare(d.string(), true);
    const FormingResult r = run_forming_scene(s, RunFiles(out));
    omp_set_num_threads(saved);
    ASSERT_TRUE(r.ok()) << r.message;
    const std::string files = read_bytes(d / "force.csv") + read_bytes(d / "energies.csv");
    EXPECT_GT(files.size(), 500u);
    if (first.empty()) first = files;
    else EXPECT_EQ(files, first) << threads << " threads";
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

FormingResult run_in(const FormingScene& s, const fs::path& dir, RunControl c = {}) {
  if (!c.resume) fs::remove_all(dir);
  const auto out = c.resume ? io::OutputDirectory::existing(dir.string()) : io::OutputDirectory::prepare(dir.string(), false);
  return run_forming_scene(s, RunFiles(out), c);
}

// The summary values that must not depend on an interruption (wall times and checkpoint counts do).
void expect_same_summary(const FormingResult& ref, const FormingResult& resumed) {
  test::expect_same_keys(ref.to_json(), resumed.to_json(),
                         {"explicit", "peak_force", "final_force", "energies", "increments", "travel_reached", "max_penetration",
                          "max_surface_penetration", "force_ripple", "status"});
}

// Stopped after 5 output intervals (the checkpoint after the 4th), refused with other explicit
// options, then resumed: the files and summary of the uninterrupted run.
void stop_and_resume(FormingScene s, const std::string& name) {
  s.checkpoint_increments = 4;
  const fs::path ref = test::temp_path(name + "_ref"), dir = test::temp_path(name);
  const FormingResult a = run_in(s, ref);
  ASSERT_TRUE(a.ok()) << a.message;
  RunControl stop;
  stop.stop_after_increments = 5;
  ASSERT_EQ(run_in(s, dir, stop).status, RunStatus::stopped);
  ASSERT_TRUE(fs::exists(dir / "checkpoint" / "state.bin"));
  std::printf("%s: checkpoint of %ju bytes\n", name.c_str(), static_cast<std::uintmax_t>(fs::file_size(dir / "checkpoint" / "state.bin")));
  RunControl resume;
  resume.resume = true;
  FormingScene other = s;
  other.explicit_options.mass_scaling *= 2.0;
  try {
    (void)run_in(other, dir, resume);
    ADD_FAILURE() << "resumed with another mass scaling";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), (dir / "checkpoint" / "state.bin").string());
    EXPECT_NE(std::string(e.what()).find("solver.mass_scaling"), std::string::npos) << e.what();
  }
  const FormingResult b = run_in(s, dir, resume);
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_GE(b.run.resumed_at_mark, 0);
  test::expect_same_outputs(ref, dir, {"force.csv", "energies.csv", "vtu/sheet.pvd"}, {"vtu"});
  expect_same_summary(a, b);
  fs::remove_all(ref);
  fs::remove_all(dir);
}

// The penalty contact: the solver's velocities, accelerations and step bound (re-estimated every
// 100 steps, across the checkpoint), the mass of the start and the energies carry over.
TEST(ExplicitIndentResume, PenaltyRunStoppedAfterACheckpointResumesBitForBit) {
  stop_and_resume(explicit_indent(0.5, 1e6), "explicit_penalty");
}

// The damping forces of the last step (mass-proportional and bulk viscosity) carry over: the
// next step's damping work pairs with them.
TEST(ExplicitIndentResume, DampedRunWithBulkViscosityResumesBitForBit) {
  FormingScene s = explicit_indent(0.5, 1e6);
  s.explicit_options.damping = 50.0;
  s.explicit_options.bulk_viscosity_linear = 0.06;
  s.explicit_options.bulk_viscosity_quadratic = 1.2;
  stop_and_resume(s, "explicit_damped");
}

// The one-point element: one section per element in the checkpoint.
TEST(ExplicitIndentResume, OnePointElementRunResumesBitForBit) {
  FormingScene s = explicit_indent(0.5, 1e6);
  s.hourglass_stiffness = 0.01;
  stop_and_resume(s, "explicit_one_point");
}

// The Moving Spherical Tool: its followed thickness, neighbourhoods, last forces and work carry over too.
TEST(ExplicitIndentResume, MovingSphericalToolRunStoppedAfterACheckpointResumesBitForBit) {
  FormingScene s = explicit_indent(0.5, 1e6);
  s.contact.friction = 0.1;
  s.contact.method = contact::ContactOptions::Method::mst;
  stop_and_resume(s, "explicit_mst");
}

}  // namespace
}  // namespace spifit::scene
