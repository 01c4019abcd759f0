// Run status of FE runs (docs/reference/file-formats.md, "Run status"): the running summary.json names the
// process (pid, host), when it started and a heartbeat with the progress, rewritten as
// increments complete; an interrupt (RunControl::interrupt, as the SIGINT/SIGTERM handler of
// `spifit run` sets it) ends the run at the end of the increment with a checkpoint and status
// "interrupted", and the resumed run ends with the outputs of an uninterrupted one.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/run_heartbeat.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <csignal>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

using test::temp_path;

nlohmann::json summary(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "summary.json")); }

FormingResult run(const FormingScene& s, const fs::path& dir, RunControl c = {}) {
  if (!c.resume) fs::remove_all(dir);
  const auto out = c.resume ? io::OutputDirectory::existing(dir.string()) : io::OutputDirectory::prepare(dir.string(), false);
  return run_forming_scene(s, RunFiles(out), c);
}

TEST(RunHeartbeat, WritesTheProcessTheTimesAndTheProgressAtMostEveryInterval) {
  const fs::path dir = test::fresh_temp_path("out");
  const auto out = io::OutputDirectory::prepare(dir.string(), false);
  RunHeartbeat hb(RunFiles(out), {{"kind", "line"}, {"scene", "s"}}, 3600.0);
  hb.write();
  auto j = summary(dir);
  EXPECT_EQ(j["status"], "running");
  EXPECT_EQ(j["kind"], "line");
  EXPECT_EQ(j["pid"].get<long long>(), static_cast<long long>(::getpid()));
  EXPECT_EQ(j["host"], host_name());
  EXPECT_FALSE(j["host"].get<std::string>().empty());
  EXPECT_EQ(j["heartbeat_interval"].get<double>(), 3600.0);
  std::time_t started = 0, beat = 0;
  ASSERT_TRUE(parse_utc_iso(j["started"].get<std::string>(), &started)) << j["started"];
  ASSERT_TRUE(parse_utc_iso(j["heartbeat"].get<std::string>(), &beat)) << j["heartbeat"];
  EXPECT_LE(std::abs(std::difftime(std::time(nullptr), beat)), 5.0);
  EXPECT_EQ(utc_iso(beat), j["heartbeat"].get<std::string>());
  // Not due within the interval: the file is not rewritten.
  hb.beat({{"increments", 7}});
  EXPECT_FALSE(summary(dir).contains("progress"));
  // finish() after stop() writes nothing: the caller's final summary stays.
  out.write_file("summary.json", nlohmann::json{{"status", "ok"}}.dump());
  hb.stop();
  EXPECT_FALSE(hb.finish({{"status", "interrupted"}}));
  EXPECT_EQ(summary(dir)["status"], "ok");
  fs::remove_all(dir);

  EXPECT_FALSE(parse_utc_iso("yesterday", &beat));
  EXPECT_TRUE(parse_utc_iso("1970-01-01T00:01:40Z", &beat));
  EXPECT_EQ(beat, 100);
}

TEST(RunStatus, TheRunningSummaryOfAnFeRunNamesTheProcessAndBeatsWithItsIncrements) {
  const FormingScene s = read_forming_scene(test::write_tiny_line(temp_path("line.toml")).string());
  const fs::path dir = temp_path("run");
  RunControl c;
  c.heartbeat_seconds = 0.0;  // every increment
  c.stop_after_increments = 6;
  std::vector<nlohmann::json> seen;
  c.progress = [&](const ProgressEvent& e) {
    if (e.kind == ProgressEvent::Kind::increment) seen.push_back(summary(dir));
  };
  const FormingResult r = run(s, dir, c);
  ASSERT_EQ(r.status, RunStatus::stopped) << r.message;
  ASSERT_EQ(seen.size(), 6u);
  for (const auto& j : seen) {
    EXPECT_EQ(j["status"], "running");
    EXPECT_EQ(j["kind"], "line");
    EXPECT_EQ(j["pid"].get<long long>(), static_cast<long long>(::getpid()));
    EXPECT_EQ(j["host"], host_name());
    std::time_t t = 0;
    EXPECT_TRUE(parse_utc_iso(j["started"].get<std::string>(), &t));
    EXPECT_TRUE(parse_utc_iso(j["heartbeat"].get<std::string>(), &t));
  }
  // The summary seen at increment k holds the progress of increment k - 1 (the sink is called first).
  EXPECT_FALSE(seen[0].contains("progress"));
  EXPECT_EQ(seen[5]["progress"]["increments"], 5);
  EXPECT_GT(seen[5]["progress"]["travel_reached"].get<double>(), 0.0);
  EXPECT_EQ(seen[5]["progress"]["travel"].get<double>(), r.path_length);
  fs::remove_all(dir);
}

TEST(RunStatus, AnInterruptedFeRunCheckpointsAndResumesToTheUninterruptedResult) {
  FormingScene s = read_forming_scene(test::write_tiny_line(temp_path("line.toml")).string());
  s.checkpoint_every = 0;  // no checkpoints by schedule: the interrupt writes the only one
  const fs::path ref = temp_path("ref"), dir = temp_path("interrupted");
  const FormingResult a = run(s, ref);
  ASSERT_TRUE(a.ok()) << a.message;

  // The "signal" comes during increment 8 (its progress line): the run ends after it.
  std::atomic<int> interrupt{0};
  RunControl c;
  c.interrupt = &interrupt;
  int increments = 0;
  c.progress = [&](const ProgressEvent& e) {
    if (e.kind == ProgressEvent::Kind::increment && ++increments == 8) interrupt = SIGINT;
  };
  const FormingResult b = run(s, dir, c);
  ASSERT_EQ(b.status, RunStatus::interrupted) << b.message;
  EXPECT_EQ(b.run.counters.increments, 8);
  EXPECT_EQ(b.run.checkpoints.written, 1);
  EXPECT_NE(b.message.find("interrupted by SIGINT"), std::string::npos) << b.message;
  EXPECT_EQ(summary(dir)["status"], "interrupted");
  ASSERT_TRUE(fs::exists(dir / "checkpoint" / "state.bin"));

  RunControl resume;
  resume.resume = true;
  const FormingResult r = run(s, dir, resume);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(summary(dir)["status"], "ok");
  test::expect_same_outputs(ref, dir, {"force.csv", "energies.csv", "vtu/sheet.pvd"}, {"vtu", "sections"});
  EXPECT_EQ(r.run.counters.increments, a.run.counters.increments);
  EXPECT_EQ(r.force.peak(), a.force.peak());
  fs::remove_all(ref);
  fs::remove_all(dir);
}

TEST(RunStatus, AnInterruptAtTheEndOfThePathLetsTheRunEndOk) {
  const FormingScene s = read_forming_scene(test::write_tiny_line(temp_path("line.toml")).string());
  std::atomic<int> interrupt{0};
  RunControl c;
  c.interrupt = &interrupt;
  // Set from the last increment's progress line: nothing is left to resume, the run ends ok.
  c.progress = [&](const ProgressEvent& e) {
    if (e.kind == ProgressEvent::Kind::increment && e.fraction >= 1.0 - 1e-9) interrupt = SIGTERM;
  };
  const fs::path dir = temp_path("run");
  const FormingResult r = run(s, dir, c);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(interrupt.load(), SIGTERM);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace spifit::scene
