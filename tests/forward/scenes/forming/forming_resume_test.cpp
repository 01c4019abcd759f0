// Checkpoints and resume of the forming scenes (docs/design/architecture.md, "Checkpoints and resume"): an
// indent_line or line run stopped after a checkpoint -- at a named path point or in the middle
// of a segment -- and resumed writes the force history, energies, sections and VTU steps of the
// uninterrupted run, byte for byte, with the same counts.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

using test::slurp;
using test::temp_path;

FormingResult run(const FormingScene& s, const fs::path& dir, RunControl c = {}) {
  if (!c.resume) fs::remove_all(dir);
  const auto out = c.resume ? io::OutputDirectory::existing(dir.string()) : io::OutputDirectory::prepare(dir.string(), false);
  return run_forming_scene(s, RunFiles(out), c);
}

void expect_same(const fs::path& ref, const FormingResult& a, const fs::path& dir, const FormingResult& b) {
  std::vector<std::string> dirs{"vtu"};
  if (fs::exists(ref / "sections")) dirs.push_back("sections");
  test::expect_same_outputs(ref, dir, {"force.csv", "energies.csv", "vtu/sheet.pvd"}, dirs);
  EXPECT_EQ(b.run.counters.increments, a.run.counters.increments);
  EXPECT_EQ(b.run.counters.iterations, a.run.counters.iterations);
  EXPECT_EQ(b.run.counters.cutbacks, a.run.counters.cutbacks);
  EXPECT_EQ(b.force.peak(), a.force.peak());
  EXPECT_EQ(b.final_energies.external_work, a.final_energies.external_work);
  EXPECT_EQ(b.run.marks_reached, a.run.marks_reached);
}

// Stopped (as a kill would) by `stop`, then resumed from the last checkpoint.
void stop_and_resume(const FormingScene& s, const std::string& name, RunControl stop) {
  const fs::path ref = temp_path(name + "_ref"), dir = temp_path(name);
  const FormingResult a = run(s, ref);
  ASSERT_TRUE(a.ok()) << a.message;
  const FormingResult stopped = run(s, dir, stop);
  ASSERT_EQ(stopped.status, RunStatus::stopped) << stopped.message;
  ASSERT_TRUE(fs::exists(dir / "checkpoint" / "state.bin"));
  RunControl resume;
  resume.resume = true;
  const FormingResult b = run(s, dir, resume);
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_GE(b.run.resumed_at_mark, 0);
  std::printf("%s: %d increments, %d checkpoints in the stopped run (%zu bytes), resumed at mark %d\n", name.c_str(),
              a.run.counters.increments, stopped.run.checkpoints.written, stopped.run.checkpoints.bytes, b.run.resumed_at_mark);
  expect_same(ref, a, dir, b);
  fs::remove_all(ref);
  fs::remove_all(dir);
}

TEST(FormingResume, IndentLineStoppedMidwayResumesBitForBit) {
  FormingScene s = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent_line.toml");
  s.checkpoint_increments = 3;
  RunControl stop;
  stop.stop_after_increments = 7;  // checkpoint after 6
  stop_and_resume(s, "indent_line", stop);
}

// A bundled indent of a solid sheet stopped after 21 increments (checkpoint after 16, deep in the
// plastic range) and resumed.
void stop_and_resume_solid_indent(const std::string& name) {
  FormingScene s = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + name + ".toml");
  s.checkpoint_increments = 8;
  RunControl stop;
  stop.stop_after_increments = 21;
  stop_and_resume(s, name, stop);
}

// The brick family's checkpoint state (centre points, hourglass amplitudes and forces) and the
// tool's contact on the top faces.
TEST(FormingResume, BrickIndentStoppedMidwayResumesBitForBit) { stop_and_resume_solid_indent("indent_brick"); }

// The solid-shell's checkpoint state (its points, the enhanced strains and their predictor).
TEST(FormingResume, SolidShellIndentStoppedMidwayResumesBitForBit) { stop_and_resume_solid_indent("indent_solid_shell"); }

TEST(FormingResume, LineStoppedAtAPathPointOrMidSegmentResumesBitForBit) {
  const fs::path file = test::write_tiny_line(temp_path("line.toml"), "checkpoint_increments = 10\n");
  const FormingScene s = read_forming_scene(file.string());
  RunControl at_c;
  at_c.stop_after_marks = 2;  // B and C reached: the section at C is written before the stop
  stop_and_resume(s, "line_at_c", at_c);
  RunControl mid;
  mid.stop_after_increments = 57;  // between C and D, 7 increments after a checkpoint
  stop_and_resume(s, "line_mid", mid);
  fs::remove(file);
}

// A resumed run with sensitivities against the uninterrupted one: the outputs, the derivatives
// table byte for byte, and the sections' derivatives.
void expect_same_derivatives(const fs::path& ref, const FormingResult& a, const fs::path& dir, const FormingResult& b) {
  expect_same(ref, a, dir, b);
  test::expect_same_outputs(ref, dir, {"sensitivities.csv"}, {});
  ASSERT_EQ(b.sections.size(), a.sections.size());
  for (std::size_t i = 0; i < a.sections.size(); ++i) {
    EXPECT_EQ(b.sections[i].dx, a.sections[i].dx) << a.sections[i].point;
    EXPECT_EQ(b.sections[i].dz, a.sections[i].dz) << a.sections[i].point;
    EXPECT_EQ(b.sections[i].dthickness, a.sections[i].dthickness) << a.sections[i].point;
  }
}

// A run with sensitivities keeps the state's derivatives in its checkpoints: the layers', the
// contact points' stick history, the nodes' and the tool force's, and the sections' so far. Stopped
// after C (its section written) and again between C and D, each resumed run writes the force
// history and its derivatives of the uninterrupted run, byte for byte, and its sections carry the
// same derivatives.
TEST(FormingResume, LineWithSensitivitiesResumesBitForBit) {
  const fs::path file = test::write_tiny_line(temp_path("line_sens.toml"), "checkpoint_increments = 10\n[contact]\nfriction = 0.1\n");
  const FormingScene s = read_forming_scene(file.string());
  RunControl plain;
  plain.sensitivities = {"swift.K", "contact.friction", "contact.penalty"};
  const fs::path ref = temp_path("line_sens_ref");
  const FormingResult a = run(s, ref, plain);
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_EQ(a.sections.size(), 2u);
  ASSERT_EQ(a.sections[1].dz.cols(), 3);
  for (const int stop_marks : {2, 0}) {
    const fs::path dir = temp_path("line_sens");
    RunControl stop = plain;
    if (stop_marks > 0) stop.stop_after_marks = stop_marks;
    else stop.stop_after_increments = 57;
    const FormingResult stopped = run(s, dir, stop);
    ASSERT_EQ(stopped.status, RunStatus::stopped) << stopped.message;
    RunControl resume = plain;
    resume.resume = true;
    const FormingResult b = run(s, dir, resume);
    ASSERT_TRUE(b.ok()) << b.message;
    expect_same_derivatives(ref, a, dir, b);
    fs::remove_all(dir);
  }
  fs::remove_all(ref);
  fs::remove(file);
}

// A solid indent with sensitivities, stopped after 21 increments (checkpoint after 16) and
// resumed, writes the uninterrupted run's derivatives byte for byte.
void expect_solid_indent_derivatives_resume(const std::string& name) {
  FormingScene s = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + name + ".toml");
  s.checkpoint_increments = 8;
  RunControl plain;
  plain.sensitivities = {"swift.K", "elastic.E"};
  const fs::path ref = temp_path(name + "_sens_ref"), dir = temp_path(name + "_sens");
  const FormingResult a = run(s, ref, plain);
  ASSERT_TRUE(a.ok()) << a.message;
  RunControl stop = plain;
  stop.stop_after_increments = 21;
  ASSERT_EQ(run(s, dir, stop).status, RunStatus::stopped);
  RunControl resume = plain;
  resume.resume = true;
  const FormingResult b = run(s, dir, resume);
  ASSERT_TRUE(b.ok()) << b.message;
  expect_same_derivatives(ref, a, dir, b);
  for (const auto& section : a.sections) EXPECT_GT(section.dthickness.cwiseAbs().maxCoeff(), 0.0) << section.point;
  fs::remove_all(ref);
  fs::remove_all(dir);
}

// The bricks' derivatives in the checkpoint: the centres' states and tangents, hourglass
// amplitudes and forces, thickness ratios.
TEST(FormingResume, BrickIndentWithSensitivitiesResumesBitForBit) { expect_solid_indent_derivatives_resume("indent_brick"); }

// The solid-shells': their points' states (without the tangents' derivatives, which nothing
// builds on) and thickness ratios.
TEST(FormingResume, SolidShellIndentWithSensitivitiesResumesBitForBit) { expect_solid_indent_derivatives_resume("indent_solid_shell"); }

// A checkpoint holds the derivatives with respect to the parameters it was written with: a resume
// asking for others, or for none, or a checkpoint without derivatives resumed with them, is
// refused naming both, before any output is touched.
TEST(FormingResume, OtherSensitivitiesAreRefusedBeforeAnyOutputIsTouched) {
  const fs::path file = test::write_tiny_line(temp_path("line_sens_other.toml"), "checkpoint_increments = 10\n");
  const FormingScene s = read_forming_scene(file.string());
  const fs::path dir = temp_path("sens_refused");
  RunControl stop;
  stop.sensitivities = {"swift.K"};
  stop.stop_after_increments = 15;
  ASSERT_EQ(run(s, dir, stop).status, RunStatus::stopped);
  const std::string before = slurp(dir / "force.csv") + slurp(dir / "summary.json") + slurp(dir / "sensitivities.csv");
  struct Case {
    std::vector<std::string> names;
    std::string expect;
  };
  for (const Case& c : {Case{{"swift.n"}, "sensitivities swift.K, not swift.n"}, Case{{}, "with sensitivities swift.K"},
                        Case{{"swift.K", "contact.penalty"}, "sensitivities swift.K, not swift.K,contact.penalty"}}) {
    RunControl resume;
    resume.resume = true;
    resume.sensitivities = c.names;
    try {
      run(s, dir, resume);
      ADD_FAILURE() << "resumed with other sensitivities: " << c.expect;
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.file(), (dir / "checkpoint" / "state.bin").string());
      EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
    }
    EXPECT_EQ(slurp(dir / "force.csv") + slurp(dir / "summary.json") + slurp(dir / "sensitivities.csv"), before);
  }
  // A checkpoint of a plain run, resumed with sensitivities.
  const fs::path plain_dir = temp_path("sens_refused_plain");
  RunControl plain_stop;
  plain_stop.stop_after_increments = 15;
  ASSERT_EQ(run(s, plain_dir, plain_stop).status, RunStatus::stopped);
  RunControl resume;
  resume.resume = true;
  resume.sensitivities = {"swift.K"};
  try {
    run(s, plain_dir, resume);
    ADD_FAILURE() << "a plain checkpoint resumed with sensitivities";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("without sensitivities"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
  fs::remove_all(plain_dir);
  fs::remove(file);
}

TEST(FormingResume, AnotherSceneIsRefusedBeforeAnyOutputIsTouched) {
  const fs::path file = test::write_tiny_line(temp_path("line_a.toml"), "checkpoint_increments = 10\n");
  const fs::path dir = temp_path("refused");
  RunControl stop;
  stop.stop_after_increments = 15;
  ASSERT_EQ(run(read_forming_scene(file.string()), dir, stop).status, RunStatus::stopped);
  const std::string before = slurp(dir / "force.csv") + slurp(dir / "summary.json");
  const fs::path other = test::write_tiny_line(temp_path("line_b.toml"), "checkpoint_increments = 11\n");
  RunControl resume;
  resume.resume = true;
  try {
    run(read_forming_scene(other.string()), dir, resume);
    ADD_FAILURE() << "resumed with another scene";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), (dir / "checkpoint" / "state.bin").string());
    EXPECT_NE(std::string(e.what()).find("written with another scene"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(dir / "force.csv") + slurp(dir / "summary.json"), before);
  fs::remove_all(dir);
  fs::remove(file);
  fs::remove(other);
}

}  // namespace
}  // namespace spifit::scene
