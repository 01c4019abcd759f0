// Checkpoints and resume of the cone scene (docs/cone-scene.md, "Checkpoints and resume"): a
// two-contour cone stopped after its first contour, or killed in the middle of the second,
// and resumed from DIR/checkpoint/state.bin, writes force.csv, contours.csv, sections/,
// sections.csv, stages.csv, history.csv and VTU files identical byte for byte to those of the
// uninterrupted run, with the same summary numbers. A checkpoint of another scene, or a
// missing, truncated or corrupted one, is refused with an InputError naming the checkpoint
// file, before any output is touched.
#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"
#include "forward/scenes/common/run_checkpoint.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "tests/support/csv_rows.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("spifit_ckpt_" + std::to_string(::getpid()) + "_" + name); }

// Two contours of the tiny cone of cone_scene_test (45 deg, top radius 20 mm, 90 deg pie).
std::string tiny_scene(int contours, const std::string& extra = "") {
  return "[scene]\nkind = \"cone\"\nmaterial = \"" + std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml\"\n" +
         "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = " + std::to_string(contours) + "\ntop_radius = 20.0\npie_angle = 90.0\n" +
         "[sheet]\nthickness = 1.0\nelements_per_45deg = 8\nthickness_points = 3\n[solver]\ntravel_per_increment = 0.5\n" + extra;
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path f = temp(name);
  std::ofstream(f) << text;
  return f;
}

std::string slurp(const fs::path& f) { return spifit::io::read_text_file(f.string()); }

int data_rows(const fs::path& csv) {
  std::ifstream in(csv);
  int n = -1;  // the header
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') ++n;
  return n;
}

ConeResult run(const ConeScene& scene, const fs::path& dir, RunControl o = {}) {
  if (!o.resume) fs::remove_all(dir);
  const auto out = o.resume ? io::OutputDirectory::existing(dir.string()) : io::OutputDirectory::prepare(dir.string(), false);
  return run_cone_scene(scene, RunFiles(out), o);
}

// Everything but wall times and the checkpoint bookkeeping must be identical.
void expect_same_outputs(const fs::path& ref, const ConeResult& ref_report, const fs::path& dir, const ConeResult& report) {
  for (const char* f : {"force.csv", "energies.csv", "contours.csv", "sections.csv", "stages.csv", "history.csv", "vtu/sheet.pvd"}) {
    EXPECT_EQ(fs::exists(dir / f), fs::exists(ref / f)) << f;
    EXPECT_EQ(slurp(dir / f), slurp(ref / f)) << f << " differs";
  }
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(ref / "sections")) names.insert(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(ref / "vtu")) names.insert("../vtu/" + e.path().filename().string());
  std::set<std::string> other;
  for (const auto& e : fs::directory_iterator(dir / "sections")) other.insert(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(dir / "vtu")) other.insert("../vtu/" + e.path().filename().string());
  EXPECT_EQ(other, names);
  for (const auto& n : names) EXPECT_EQ(slurp(dir / "sections" / n), slurp(ref / "sections" / n)) << n << " differs";
  const auto a = ref_report.to_json();
  const auto b = report.to_json();
  for (const char* k : {"status", "increments", "newton_iterations", "cutbacks", "factorisations", "factorisations_by_solver",
                        "travel_reached", "contours_completed", "peak_force", "peak_polar_force", "final_force", "final_polar_force",
                        "max_penetration", "max_surface_penetration", "model", "path", "warnings", "observables", "stabilised"})
    EXPECT_EQ(b[k], a[k]) << k;
  EXPECT_EQ(b["contour_wall_seconds"].size(), a["contour_wall_seconds"].size());
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
  const fs::path file = write("two.toml", tiny_scene(2, "[output]\nhistory_element = { r = 18.0, theta = 45.0 }\n"));
  const ConeScene scene = read_cone_scene(file.string());
  ASSERT_EQ(scene.checkpoint_every, 1);

  const fs::path ref = temp("ref");
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
  const fs::path a = temp("stop_resume"), b = temp("kill_resume");
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
  const fs::path file = write("one.toml", tiny_scene(1));
  const ConeScene scene = read_cone_scene(file.string());
  const fs::path dir = temp("refuse");
  RunControl stop;
  stop.stop_after_marks = 1;
  ASSERT_EQ(run(scene, dir, stop).status, RunStatus::stopped);
  const fs::path state = dir / "checkpoint" / "state.bin";
  const std::string good = slurp(state);
  ASSERT_GT(good.size(), 1000u);

  // Another scene (one key differs; the same mesh, so only the contents tell).
  const fs::path other = write("other.toml", tiny_scene(1, "[contact]\npenalty = 1200.0\n"));
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
  const fs::path f0 = write("every0.toml", tiny_scene(1, "[output]\ncheckpoint_every = 0\n"));
  EXPECT_EQ(read_cone_scene(f0.string()).checkpoint_every, 0);
  const fs::path bad = write("every_bad.toml", tiny_scene(1, "[output]\ncheckpoint_every = -1\n"));
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
