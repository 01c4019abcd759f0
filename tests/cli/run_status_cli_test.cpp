// Run status from the command line (docs/reference/file-formats.md, "Run status"): a running summary names
// its process and beats; `spifit status DIR` tells a live run from a dead one (exit 0 / 1) and
// from a directory that is no spifit output (exit 2); SIGINT and SIGTERM end an FE run at the
// end of an increment with a checkpoint, status "interrupted" and exit code 130 / 143, and
// `--resume` then finishes it; a fit ends at once, its evaluations kept for --resume.
#include "forward/scenes/common/run_heartbeat.hpp"
#include "tests/cli/cli_support.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using spifit::test::fresh_temp_path;
using spifit::test::run_spifit;
using spifit::test::slurp;
using spifit::test::temp_path;

std::string host() {
  char buf[256] = {};
  ::gethostname(buf, sizeof buf - 1);
  return buf;
}

std::string iso(std::time_t t) { return spifit::scene::utc_iso(t); }

// DIR/summary.json, null while there is none (or it cannot be read).
nlohmann::json summary(const fs::path& dir) {
  const std::string text = slurp(dir / "summary.json");
  return nlohmann::json::parse(text, nullptr, false).is_object() ? nlohmann::json::parse(text) : nlohmann::json();
}

// `spifit ARGS...` in a child process, stdout to /dev/null and stderr to `err`, with SIGINT and
// SIGTERM at their defaults.
pid_t start_spifit(const std::vector<std::string>& args, const fs::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    // As from a terminal: a test run in the background (its SIGINT ignored) passes that on.
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    const int null = ::open("/dev/null", O_WRONLY);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(null, 1);
    ::dup2(e, 2);
    std::vector<char*> argv{const_cast<char*>(SPIFIT_EXE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SPIFIT_EXE, argv.data());
    ::_exit(127);
  }
  return pid;
}

// Waits (every 10 ms, at most `limit`) until ready() holds or the child has ended; false then.
template <typename Ready>
bool wait_until(pid_t pid, Ready ready, std::chrono::seconds limit = std::chrono::seconds(120)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (ready()) return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// The child's exit code; -N when signal N ended it.
int exit_code(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? -WTERMSIG(status) : -1000;
}

bool has_pid(const fs::path& dir) {
  const auto j = summary(dir);
  return j.is_object() && j.value("status", "") == "running" && j.contains("pid");
}

// A summary of a run of the line scene S in dir with this status and process fields.
void write_summary(const fs::path& dir, nlohmann::json fields) {
  fs::create_directories(dir);
  nlohmann::json j{{"kind", "line"}, {"scene", "line_half"}, {"scene_file", "S.toml"}, {"started", iso(std::time(nullptr) - 3600)},
                   {"heartbeat_interval", 10.0}};
  j.update(fields);
  std::ofstream(dir / "summary.json") << j.dump(2);
}

TEST(RunStatusCli, StatusTellsALiveRunFromADeadOneAndFromNoOutput) {
  const fs::path dir = fresh_temp_path("out");
  const std::time_t now = std::time(nullptr);
  // A pid that was alive and is gone: a child that has exited and was reaped.
  const pid_t gone = ::fork();
  if (gone == 0) ::_exit(0);
  ASSERT_GT(gone, 0);
  ::waitpid(gone, nullptr, 0);
  write_summary(dir, {{"status", "running"}, {"pid", gone}, {"host", host()}, {"heartbeat", iso(now - 600)}});
  fs::create_directories(dir / "checkpoint");
  std::ofstream(dir / "checkpoint" / "state.bin") << "x";
  auto r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("kind: line\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scene: line_half (S.toml)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("status: running, dead: the process " + std::to_string(gone) + " is gone: the run was killed; resume with spifit run S.toml --out " +
                       dir.string() + " --resume\n"),
            std::string::npos)
      << r.out;

  // A live process (this test) with a fresh heartbeat: alive; the same with an old one: not responding.
  write_summary(dir, {{"status", "running"}, {"pid", ::getpid()}, {"host", host()}, {"heartbeat", iso(now)},
                      {"progress", {{"increments", 12}, {"travel_reached", 3.5}, {"travel", 37.0}, {"marks_reached", 2}, {"marks", 5}}}});
  r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("status: running, alive: pid " + std::to_string(::getpid()) + " on this host"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("progress: 12 increments, tool travel 3.50 of 37.00 mm, 2 of 5 marks\n"), std::string::npos) << r.out;
  write_summary(dir, {{"status", "running"}, {"pid", ::getpid()}, {"host", host()}, {"heartbeat", iso(now - 600)}});
  r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("status: running, not responding: the process " + std::to_string(::getpid()) + " exists, last heartbeat"), std::string::npos)
      << r.out;
  // Another host: the heartbeat alone decides.
  write_summary(dir, {{"status", "running"}, {"pid", 1}, {"host", "elsewhere.invalid"}, {"heartbeat", iso(now)}});
  EXPECT_EQ(run_spifit("status " + dir.string()).code, 0);
  write_summary(dir, {{"status", "running"}, {"pid", 1}, {"host", "elsewhere.invalid"}, {"heartbeat", iso(now - 600)}});
  EXPECT_EQ(run_spifit("status " + dir.string()).code, 1);
  // A running summary without a pid (an older spifit's): not known to be alive.
  write_summary(dir, {{"status", "running"}});
  r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("status: running, unknown: the summary has no pid"), std::string::npos) << r.out;

  // Ended runs: ok 0, failed and interrupted 1.
  write_summary(dir, {{"status", "ok"}, {"increments", 80}, {"travel_reached", 37.0}});
  r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("status: ok\nprogress: 80 increments, tool travel 37.00 mm\n"), std::string::npos) << r.out;
  write_summary(dir, {{"status", "failed"}, {"message", "at tool travel 3 mm: no convergence"}});
  r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("status: failed: at tool travel 3 mm: no convergence\n"), std::string::npos) << r.out;

  // Not a spifit output directory: 2.
  fs::remove(dir / "summary.json");
  r = run_spifit("status " + dir.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not a spifit output directory (no summary.json)"), std::string::npos) << r.err;
  std::ofstream(dir / "summary.json") << "[1, 2]";
  EXPECT_EQ(run_spifit("status " + dir.string()).code, 2);
  EXPECT_EQ(run_spifit("status " + (dir / "nowhere").string()).code, 2);
  fs::remove_all(dir);
}

TEST(RunStatusCli, AKilledRunIsReportedDeadWithHowToResume) {
  const fs::path scene = spifit::test::write_tiny_line(temp_path("line.toml"));
  const fs::path out = fresh_temp_path("killed");
  pid_t pid = 0;
  // Killed once its first checkpoint (at path point B) is there.
  const bool killed = spifit::test::spifit_and_kill(
      {"-q", "run", scene.string(), "--out", out.string()},
      [&] {
        if (!fs::exists(out / "checkpoint" / "state.bin")) return false;
        const auto j = summary(out);
        pid = j.is_object() ? j.value("pid", 0) : 0;
        return pid != 0;
      },
      std::chrono::milliseconds(0));
  ASSERT_TRUE(killed) << "the run ended before the kill";
  auto r = run_spifit("status " + out.string());
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("status: running, dead: the process " + std::to_string(pid) + " is gone: the run was killed; resume with spifit run " +
                       scene.string() + " --out " + out.string() + " --resume\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("kind: line\n"), std::string::npos) << r.out;
  fs::remove_all(out);
  fs::remove(scene);
}

// The tiny line with 0.1 mm increments: some 400 increments, a few seconds.
fs::path slow_tiny_line(const std::string& name) {
  return spifit::test::write_tiny_line(temp_path(name), "[solver]\ntravel_per_increment = 0.1\n");
}

TEST(RunStatusCli, SigintEndsAnFeRunWithACheckpointAndResumeFinishesIt) {
  const fs::path scene = slow_tiny_line("line.toml");
  const fs::path out = fresh_temp_path("out"), err = temp_path("err.txt");
  const pid_t pid = start_spifit({"run", scene.string(), "--out", out.string()}, err);
  ASSERT_TRUE(wait_until(pid, [&] { return has_pid(out); })) << slurp(err);
  const auto running = summary(out);
  EXPECT_EQ(running["pid"].get<long long>(), static_cast<long long>(pid));
  EXPECT_EQ(running["host"], host());
  EXPECT_TRUE(running.contains("started"));
  EXPECT_TRUE(running.contains("heartbeat"));
  auto r = run_spifit("status " + out.string());
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("status: running, alive: pid " + std::to_string(pid)), std::string::npos) << r.out;

  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGINT);
  const int code = exit_code(pid);
  ASSERT_EQ(code, 130) << slurp(err);
  const auto j = summary(out);
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_NE(j["message"].get<std::string>().find("interrupted by SIGINT at tool travel"), std::string::npos) << j["message"];
  EXPECT_GT(j["increments"].get<int>(), 0);
  EXPECT_TRUE(fs::exists(out / "checkpoint" / "state.bin"));
  EXPECT_NE(slurp(err).find("; resume with: spifit run " + scene.string() + " --out " + out.string() + " --resume\n"), std::string::npos)
      << slurp(err);
  r = run_spifit("status " + out.string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("status: interrupted: interrupted by SIGINT"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("resume with spifit run " + scene.string() + " --out " + out.string() + " --resume\n"), std::string::npos) << r.out;

  r = run_spifit("-q run " + scene.string() + " --out " + out.string() + " --resume");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(summary(out)["status"], "ok");
  EXPECT_GE(summary(out)["resumed_at_mark"].get<int>(), 0);
  EXPECT_EQ(run_spifit("status " + out.string()).code, 0);
  fs::remove_all(out);
  fs::remove(scene);
  fs::remove(err);
}

// The line scene of the experiments, ended by SIGTERM shortly after its start.
TEST(RunStatusCli, SigtermEndsTheHalfLineRunAsInterruptedWithACheckpoint) {
  const std::string scene = std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/line_half.toml";
  const fs::path out = fresh_temp_path("out"), err = temp_path("err.txt");
  const pid_t pid = start_spifit({"-q", "run", scene, "--out", out.string()}, err);
  ASSERT_TRUE(wait_until(pid, [&] { return has_pid(out); })) << slurp(err);
  ::kill(pid, SIGTERM);
  ASSERT_EQ(exit_code(pid), 143) << slurp(err);
  const auto j = summary(out);
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_NE(j["message"].get<std::string>().find("interrupted by SIGTERM"), std::string::npos) << j["message"];
  EXPECT_TRUE(fs::exists(out / "checkpoint" / "state.bin"));
  const auto r = run_spifit("status " + out.string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("resume with spifit run " + scene + " --out " + out.string() + " --resume\n"), std::string::npos) << r.out;
  fs::remove_all(out);
  fs::remove(err);
}

TEST(RunStatusCli, SigtermEndsAFitAsInterruptedWithItsEvaluationsKept) {
  const fs::path scene = spifit::test::write_tiny_line(temp_path("line.toml"));
  const fs::path data = temp_path("fx.csv"), fit = temp_path("fit.toml"), err = temp_path("err.txt");
  auto r = run_spifit("-q synth " + scene.string() + " --set contact.friction=0.1 --x travel --y fx --every 4 --out " + data.string());
  ASSERT_EQ(r.code, 0) << r.err;
  // Central differences: iteration 0 takes three runs, and the signal comes after its first.
  std::ofstream(fit) << "[fit]\ncard = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\njacobian = \"central\"\n"
                     << "[parameters.\"contact.friction\"]\ninitial = 0.14\nlower = 0.0\nupper = 0.5\n"
                     << "[[experiment]]\nscene = \"" << scene.string() << "\"\ndata = \"" << data.string() << "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n";
  const fs::path out = fresh_temp_path("fit_out");
  const pid_t pid = start_spifit({"-q", "fit", fit.string(), "--out", out.string()}, err);
  ASSERT_TRUE(wait_until(pid, [&] { return has_pid(out); })) << slurp(err);
  const auto running = summary(out);
  EXPECT_EQ(running["kind"], "fit");
  EXPECT_EQ(running["pid"].get<long long>(), static_cast<long long>(pid));
  EXPECT_TRUE(running.contains("heartbeat"));
  // After the first evaluation is kept.
  ASSERT_TRUE(wait_until(pid, [&] { return slurp(out / "runs" / "evaluations.jsonl").find("\"residuals\"") != std::string::npos; }))
      << slurp(err);
  ::kill(pid, SIGTERM);
  ASSERT_EQ(exit_code(pid), 143) << slurp(err);
  const auto j = summary(out);
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_EQ(j["kind"], "fit");
  EXPECT_NE(j["message"].get<std::string>().find("resume with spifit fit " + fit.string() + " --out " + out.string() + " --resume"),
            std::string::npos)
      << j["message"];
  // The terminal is told how to go on too, and the directory's lock is gone with the fit (the
  // resume takes no "killed" holder over).
  EXPECT_NE(slurp(err).find("spifit: interrupted by SIGTERM; the FE evaluations that finished are kept in runs/evaluations.jsonl: resume with "
                            "spifit fit " + fit.string() + " --out " + out.string() + " --resume"),
            std::string::npos)
      << slurp(err);
  EXPECT_FALSE(fs::exists(out / ".spifit-lock"));
  r = run_spifit("status " + out.string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("kind: fit\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("status: interrupted: interrupted by SIGTERM"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("progress: iteration 0"), std::string::npos) << r.out;  // where the fit was
  fs::remove_all(out);
  for (const auto& f : {scene, data, fit, err}) fs::remove(f);
}

}  // namespace
