// Checkpoints and resume of the cone scene (docs/design/architecture.md, "Checkpoints and resume"): a
// two-contour cone stopped after its first contour, or killed in the middle of the second,
// and resumed from DIR/checkpoint/state.bin, writes force.csv, contours.csv, sections/,
// sections.csv, stages.csv, history.csv and VTU files identical byte for byte to those of the
// uninterrupted run, with the same summary numbers. A checkpoint of another scene, or a
// missing, truncated or corrupted one, is refused with an InputError naming the checkpoint
// file, before any output is touched.
#include "forward/io/input_error.hpp"
#include "forward/scenes/common/run_checkpoint.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "tests/support/csv_rows.hpp"
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

using test::slurp;
using test::temp_path;

// Two contours of the tiny cone (45 deg, top radius 20 mm, 90 deg pie).
fs::path write_tiny(const std::string& name, int contours, const std::string& extra = "") {
  return test::write_tiny_cone(temp_path(name), extra, {.contours = contours});
}

int data_rows(const fs::path& csv) { return static_cast<int>(test::read_csv_rows(csv).size()); }

ConeResult run(const ConeScene& scene, const fs::path& dir, RunControl o = {}) {
  if (!o.resume) fs::remove_all(dir);
  const auto out = o.resume ? io::OutputDirectory::existing(dir.string()) : io::OutputDirectory::prepare(dir.string(), false);
  return run_cone_scene(scene, RunFiles(out), o);
}

// Everything but wall times and the checkpoint bookkeeping must be identical.
void expect_same_outputs(const fs::path& ref, const ConeResult& ref_report, const fs::path& dir, const ConeResult& report) {
  test::expect_same_outputs(ref, dir, {"force.csv", "energies.csv", "contours.csv", "sections.csv", "stages.csv", "history.csv", "vtu/sheet.pvd"},
                            {"sections", "vtu"});
  const auto a = ref_report.to_json();
  const auto b = report.to_json();
  test::expect_same_keys(a, b, {"status", "increments", "newton_iterations", "cutbacks", "factorisations", "factorisations_by_solver",
                                "travel_reached", "contours_completed", "peak_force", "peak_polar_force", "final_force", "final_polar_force",
                                "max_penetration", "max_surface_penetration", "model", "path", "warnings", "observables", "stabilised"});
  EXPECT_EQ(b["contour_wall_seconds"].size(), a["contour_wall_seconds"].size());
  // The section points a fit compares with (ConeResult::section_profiles) come back with the checkpoint.
  ASSERT_EQ(report.section_profiles.size(), ref_report.section_profiles.size());
  for (std::size_t i = 0; i < report.section_profiles.size(); ++i) {
    const ConeSection &x = ref_report.section_profiles[i], &y = report.section_profiles[i];
    EXPECT_EQ(y.stage, x.stage);
    EXPECT_EQ(y.contour, x.contour);
    ASSERT_EQ(y.points.size(), x.points.size());
    for (std::size_t k = 0; k < x.points.size(); ++k) {
      EXPECT_EQ(y.points[k].r, x.points[k].r) << "section " << i << ", point " << k;
      EXPECT_EQ(y.points[k].z, x.points[k].z) << "section " << i << ", point " << k;
      EXPECT_EQ(y.points[k].thickness, x.points[k].thickness) << "section " << i << ", point " << k;
      EXPECT_EQ(y.points[k].dtheta_deg, x.points[k].dtheta_deg) << "section " << i << ", point " << k;
    }
  }
}

// Increments of the reference run up to the end of its first contour (force.csv rows).
int increments_to_first_contour(const ConeScene& scene, const fs::path& ref) {
  const ConeTrack track(cone_scene_path(scene));
  const double end = track.contours().at(0).end;
  int row = 0;
  for (const auto& r : test::read_csv_rows(ref / "force.csv")) {
    ++row;
    if (r.at(0) * scene.feed >= end - 1e-9) return row;  // time [s] x feed = travel
  }
  return -1;
}

TEST(ConeCheckpoint, ResumedAfterAContourOrAKillTheRunEndsAsAnUninterruptedOne) {
  // With an element history (history.csv: one row per increment, kept in memory).
  const fs::path file = write_tiny("two.toml", 2, "[output]\nhistory_element = { r = 18.0, theta = 45.0 }\n");
  const ConeScene scene = read_cone_scene(file.string());
  ASSERT_EQ(scene.checkpoint_every, 1);

  const fs::path ref = temp_path("ref");
  const ConeResult r0 = run(scene, ref);
  ASSERT_TRUE(r0.ok()) << r0.to_json().dump();
  ASSERT_EQ(r0.to_json()["contours_completed"].get<int>(), 2);
  ASSERT_TRUE(fs::exists(ref / "history.csv"));
  const auto ck = r0.to_json()["checkpoints"];
  EXPECT_EQ(ck["written"].get<int>(), 2);
  EXPECT_TRUE(fs::exists(ref / "checkpoint" / "state.bin"));
  std::printf("tiny cone, 2 contours: %d increments, %d iterations, %.2f s; checkpoint %zu bytes, %d written in %.4f s\n",
              r0.to_json()["increments"].get<int>(), r0.to_json()["newton_iterations"].get<int>(), r0.to_json()["wall_seconds"].get<double>(),
              ck["bytes"].get<std::size_t>(), ck["written"].get<int>(), ck["write_seconds"].get<double>());

  // Stopped right after the checkpoint of contour 1 (a copy of the directory is kept for the
  // kill below), then resumed.
  const fs::path a = temp_path("stop_resume"), b = temp_path("kill_resume");
  RunControl stop;
  stop.stop_after_marks = 1;
  const ConeResult s1 = run(scene, a, stop);
  ASSERT_TRUE((s1.status == RunStatus::stopped)) << s1.to_json().dump();
  const int k1 = increments_to_first_contour(scene, ref);
  ASSERT_GT(k1, 0);
  EXPECT_EQ(data_rows(a / "force.csv"), k1);
  fs::remove_all(b);
  fs::copy(a, b, fs::copy_options::recursive);
  RunControl resume;
  resume.resume = true;
  const ConeResult s2 = run(scene, a, resume);
  ASSERT_TRUE(s2.ok()) << s2.to_json().dump();
  EXPECT_EQ(s2.to_json()["resumed_at_contour"].get<int>(), 1);
  expect_same_outputs(ref, r0, a, s2);

  // Killed 10 increments into contour 2 (not a contour end), in a resumed session: the rows
  // written after the checkpoint are then in force.csv, and the next resume starts again from
  // the end of contour 1.
  RunControl kill = resume;
  kill.stop_after_increments = k1 + 10;
  ASSERT_LT(k1 + 10, r0.to_json()["increments"].get<int>() - 10);
  const ConeResult k = run(scene, b, kill);
  ASSERT_TRUE((k.status == RunStatus::stopped));
  EXPECT_EQ(data_rows(b / "force.csv"), k1 + 10);
  const ConeResult k2 = run(scene, b, resume);
  ASSERT_TRUE(k2.ok()) << k2.to_json().dump();
  EXPECT_EQ(k2.to_json()["resumed_at_contour"].get<int>(), 1);
  expect_same_outputs(ref, r0, b, k2);

  for (const auto& d : {ref, a, b}) fs::remove_all(d);
  fs::remove(file);
}

// A cone with sensitivities (cyclic ties, virtual tools, friction) stopped after its first contour
// and resumed: the force's derivatives, the centre depth's and the contour means' are those of the
// uninterrupted run, to the bit.
TEST(ConeCheckpoint, ResumedWithSensitivitiesTheDerivativesAreThoseOfAnUninterruptedRun) {
  const fs::path file = test::write_tiny_cone(temp_path("sens.toml"), "[contact]\nfriction = 0.1\n[output]\nhistory_element = { r = 10.0, theta = 45.0 }\n",
                                              test::small_tiny_cone(2));
  const ConeScene scene = read_cone_scene(file.string());
  RunControl plain;
  plain.sensitivities = {"swift.K", "contact.friction", "contact.penalty"};
  const fs::path ref = temp_path("sens_ref"), dir = temp_path("sens_resume");
  const ConeResult r0 = run(scene, ref, plain);
  ASSERT_TRUE(r0.ok()) << r0.to_json().dump();
  ASSERT_EQ(r0.centre_depth_sensitivity.size(), 3);
  RunControl stop = plain;
  stop.stop_after_marks = 1;
  ASSERT_TRUE((run(scene, dir, stop).status == RunStatus::stopped));
  RunControl resume = plain;
  resume.resume = true;
  const ConeResult r1 = run(scene, dir, resume);
  ASSERT_TRUE(r1.ok()) << r1.to_json().dump();
  EXPECT_EQ(r1.to_json()["resumed_at_contour"].get<int>(), 1);
  expect_same_outputs(ref, r0, dir, r1);
  test::expect_same_outputs(ref, dir, {"sensitivities.csv"}, {});
  EXPECT_EQ(r1.centre_depth_sensitivity, r0.centre_depth_sensitivity);
  for (const char* y : {"fr", "ftheta", "fz"}) {
    const ResultCurve a = r0.contour_means(y), b = r1.contour_means(y);
    ASSERT_EQ(a.dy.rows(), 2) << y;
    EXPECT_EQ(b.dy, a.dy) << y;
  }
  for (const auto& d : {ref, dir}) fs::remove_all(d);
  fs::remove(file);
}

// An InputError naming the checkpoint file, with this fragment in its message; the outputs in
// DIR are untouched.
void expect_refused(const ConeScene& scene, const fs::path& dir, const std::string& fragment) {
  const std::string before = slurp(dir / "force.csv") + slurp(dir / "summary.json");
  RunControl resume;
  resume.resume = true;
  try {
    run(scene, dir, resume);
    ADD_FAILURE() << "resumed although: " << fragment;
  } catch (const io::InputError& e) {
    std::printf("%s\n", e.what());
    EXPECT_EQ(e.file(), (dir / "checkpoint" / "state.bin").string());
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(dir / "force.csv") + slurp(dir / "summary.json"), before);
}

TEST(ConeCheckpoint, AnotherSceneOrADamagedCheckpointIsRefused) {
  const fs::path file = write_tiny("one.toml", 1);
  const ConeScene scene = read_cone_scene(file.string());
  const fs::path dir = temp_path("refuse");
  RunControl stop;
  stop.stop_after_marks = 1;
  ASSERT_EQ(run(scene, dir, stop).status, RunStatus::stopped);
  const fs::path state = dir / "checkpoint" / "state.bin";
  const std::string good = slurp(state);
  ASSERT_GT(good.size(), 1000u);

  // Another scene (one key differs; the same mesh, so only the contents tell).
  const fs::path other = write_tiny("other.toml", 1, "[contact]\npenalty = 1200.0\n");
  expect_refused(read_cone_scene(other.string()), dir, "written with another scene: the contents of " + other.string());
  // Truncated, corrupted, missing.
  std::ofstream(state, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() / 2);
  expect_refused(scene, dir, "truncated or corrupted");
  std::string flipped = good;
  flipped[flipped.size() / 3] = static_cast<char>(flipped[flipped.size() / 3] ^ 0x01);
  std::ofstream(state, std::ios::binary | std::ios::trunc) << flipped;
  expect_refused(scene, dir, "checksum mismatch");
  std::ofstream(state, std::ios::binary | std::ios::trunc) << "[scene]\nkind = \"cone\"\n";
  expect_refused(scene, dir, "not a spifit state archive");
  fs::remove(state);
  expect_refused(scene, dir, "no checkpoint");
  // The intact checkpoint still resumes.
  std::ofstream(state, std::ios::binary | std::ios::trunc) << good;
  RunControl resume;
  resume.resume = true;
  EXPECT_TRUE(run(scene, dir, resume).ok());
  fs::remove_all(dir);
  fs::remove(file);
  fs::remove(other);
}

TEST(ConeCheckpoint, CheckpointEveryIsReadAndChecked) {
  const fs::path f0 = write_tiny("every0.toml", 1, "[output]\ncheckpoint_every = 0\n");
  EXPECT_EQ(read_cone_scene(f0.string()).checkpoint_every, 0);
  const fs::path bad = write_tiny("every_bad.toml", 1, "[output]\ncheckpoint_every = -1\n");
  try {
    read_cone_scene(bad.string());
    ADD_FAILURE() << "checkpoint_every = -1 accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "output.checkpoint_every") << e.what();
  }
  fs::remove(f0);
  fs::remove(bad);
}

}  // namespace
}  // namespace spifit::scene
