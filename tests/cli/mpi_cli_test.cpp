// spifit fit and spifit sweep under mpiexec (3 ranks on however many cores: --oversubscribe)
// give what the serial commands give: the same card.toml, the same fit.json but for wall times,
// the same sweep.csv but for its wall_seconds column, the same files of every point; an MPI fit
// killed after some evaluations resumes (--resume, again under mpiexec) to the same card
// (docs/guide/parallel-runs.md).
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Open MPI refuses root without these; yield: idle ranks leave the cores to the runs.
const char* kEnv = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 ";
const char* kLaunch = " --oversubscribe --bind-to none -np 3 ";

spifit::test::CliResult run_mpi(const std::string& args) {
  const fs::path err = spifit::test::temp_path("mpi_err.txt");
  const std::string cmd = std::string(kEnv) + SPIFIT_MPIEXEC + kLaunch + SPIFIT_EXE + " " + args + " 2>" + err.string();
  spifit::test::CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  while (fgets(buf, sizeof buf, p)) r.out += buf;
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = spifit::test::slurp(err);
  return r;
}

// The tiny line test at mu = 0.1 and K = 170 MPa, its Fx and Fz along the travel (synthetic, no
// noise), and a fit of mu and K to both from mu = 0.14, K = 180 (card C.3 + C.4).
fs::path write_fit(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path scene = spifit::test::write_tiny_line(dir / "line.toml");
  std::ofstream(scene, std::ios::app) << "[contact]\nfriction = 0.1\n";
  for (const char* y : {"fx", "fz"}) {
    const auto r = spifit::test::run_spifit("-q synth " + scene.string() + " --x travel --y " + y + " --every 4 --set swift.K=170 --out " +
                                            (dir / (std::string(y) + ".csv")).string());
    EXPECT_EQ(r.code, 0) << r.err;
  }
  std::ofstream(dir / "fit.toml") << "[fit]\ncard = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                                  << "[parameters.\"contact.friction\"]\ninitial = 0.14\nlower = 0.0\nupper = 0.5\n"
                                  << "[parameters.\"swift.K\"]\nlower = 100.0\nupper = 300.0\n"
                                  << "[[experiment]]\nname = \"drag\"\nscene = \"line.toml\"\ndata = \"fx.csv\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n"
                                  << "[[experiment]]\nname = \"press\"\nscene = \"line.toml\"\ndata = \"fz.csv\"\nx = \"travel\"\ny = \"fz\"\nnoise = 1.0\n";
  return dir / "fit.toml";
}

json without_times(json j);

// fit.json without what depends on the clock, and without which experiment on a shared scene
// asked for a run first (experiments[].scene_runs: in one process too it depends on which
// thread came first; the total scene_runs does not).
json comparable(json j) {
  for (auto& e : j["experiments"]) e.erase("scene_runs");
  return without_times(j);
}
json without_times(json j) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end();) {
      if (it.key().find("seconds") != std::string::npos) it = j.erase(it);
      else *it = without_times(*it), ++it;
    }
  } else if (j.is_array()) {
    for (auto& e : j) e = without_times(e);
  }
  return j;
}

class MpiFit : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = spifit::test::fresh_temp_path("mpi_fit");
    fit_ = write_fit(dir_);
    const auto r = spifit::test::run_spifit("-q fit " + fit_.string() + " --out " + (dir_ / "serial").string());
    ASSERT_EQ(r.code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static fs::path dir_, fit_;
};
fs::path MpiFit::dir_, MpiFit::fit_;

TEST_F(MpiFit, GivesTheSerialCardAndFit) {
  const auto r = run_mpi("fit " + fit_.string() + " --out " + (dir_ / "mpi").string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("MPI: FE evaluations on 2 worker rank(s)"), std::string::npos) << r.out;
  EXPECT_EQ(spifit::test::slurp(dir_ / "mpi" / "card.toml"), spifit::test::slurp(dir_ / "serial" / "card.toml"));
  const json serial = comparable(json::parse(spifit::test::slurp(dir_ / "serial" / "fit.json")));
  const json mpi = comparable(json::parse(spifit::test::slurp(dir_ / "mpi" / "fit.json")));
  EXPECT_EQ(mpi, serial);
  EXPECT_EQ(mpi["scene_runs"], serial["scene_runs"]);  // one run per scene and point, as in one process
}

// Killed with SIGTERM (mpiexec passes it to every rank) once 6 evaluations are kept, then resumed
// under mpiexec: the evaluations are read back and the card is the serial one.
TEST_F(MpiFit, AKilledFitResumesToTheSameCard) {
  const fs::path out = dir_ / "killed";
  const fs::path kept = out / "runs" / "evaluations.jsonl";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string cmd = std::string(kEnv) + "exec " + SPIFIT_MPIEXEC + kLaunch + SPIFIT_EXE + " -q fit " + fit_.string() + " --out " +
                            out.string() + " >/dev/null 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  auto lines = [&] {
    std::ifstream f(kept);
    int n = 0;
    for (std::string l; std::getline(f, l);) ++n;
    return n;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  bool finished = false;
  while (lines() < 7 && std::chrono::steady_clock::now() < deadline) {  // a signature line and 6 evaluations
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      finished = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_FALSE(finished) << "the fit ended before it could be killed";
  ::kill(pid, SIGTERM);
  ::waitpid(pid, &status, 0);
  const int read_back = lines() - 1;
  ASSERT_GE(read_back, 6);
  const auto r = run_mpi("fit " + fit_.string() + " --out " + out.string() + " --resume");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("resuming: "), std::string::npos) << r.out;
  EXPECT_EQ(spifit::test::slurp(out / "card.toml"), spifit::test::slurp(dir_ / "serial" / "card.toml"));
}

// The pid of a `spifit job --fit FIT` process (a worker rank's forward run), or 0.
pid_t job_process_of(const fs::path& fit) {
  const std::string needle = std::string("job") + '\0' + "--fit" + '\0' + fit.string();
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string cmdline = spifit::test::slurp(e.path() / "cmdline");
    if (cmdline.find(needle) != std::string::npos) return static_cast<pid_t>(std::stol(name));
  }
  return 0;
}

// An MPI fit of fit into out (stderr to err), launched with `launch` before mpiexec's own
// options (environment, MCA options); once it has kept a few evaluations, the process victim()
// finds is killed with SIGKILL and the fit is waited for. Whether a victim was killed, and how
// mpiexec ended.
struct KilledFit {
  bool killed = false;
  int status = 0;
};
template <typename Victim>
KilledFit kill_in_mpi_fit(const fs::path& fit, const fs::path& out, const fs::path& err, const std::string& env,
                          const std::string& mca, Victim victim) {
  KilledFit k;
  const pid_t pid = ::fork();
  if (pid < 0) return k;
  if (pid == 0) {
    const std::string cmd = std::string(kEnv) + env + " exec " + SPIFIT_MPIEXEC + mca + kLaunch + SPIFIT_EXE + " -q fit " + fit.string() +
                            " --out " + out.string() + " >/dev/null 2>" + err.string();
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  pid_t target = 0;
  while (!target && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &k.status, WNOHANG) == pid) return k;  // ended before a kill
    if (fs::exists(out / "runs" / "evaluations.jsonl") && spifit::test::slurp(out / "runs" / "evaluations.jsonl").size() > 200)
      target = victim();
    if (!target) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (target) k.killed = ::kill(target, SIGKILL) == 0;
  ::waitpid(pid, &k.status, 0);
  return k;
}

// A forward run's process killed (SIGKILL) while a worker waits for it: the worker runs the job
// once more, says so on stderr, and the fit ends as the serial one (docs/guide/parallel-runs.md).
TEST_F(MpiFit, AKilledRunProcessDoesNotEndTheFit) {
  const fs::path out = dir_ / "run_killed", err = dir_ / "run_killed.err";
  const KilledFit k = kill_in_mpi_fit(fit_, out, err, "", "", [] { return job_process_of(fit_); });
  ASSERT_TRUE(k.killed) << "no run's process was killed";
  ASSERT_TRUE(WIFEXITED(k.status)) << "mpiexec ended by a signal";
  const std::string said = spifit::test::slurp(err);
  EXPECT_EQ(WEXITSTATUS(k.status), 0) << said;
  EXPECT_NE(said.find("the process of a forward run ended (killed by signal 9): running it once more"), std::string::npos) << said;
  EXPECT_EQ(spifit::test::slurp(out / "card.toml"), spifit::test::slurp(dir_ / "serial" / "card.toml"));
}

// The pid of the rank `rank` of an MPI `spifit ... fit FIT` (not of its runs' processes), or 0.
pid_t rank_process_of(const fs::path& fit, int rank) {
  const std::string needle = std::string("fit") + '\0' + fit.string(), env = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank) + '\0';
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    if (spifit::test::slurp(e.path() / "cmdline").find(needle) == std::string::npos) continue;
    if (spifit::test::slurp(e.path() / "environ").find(env) != std::string::npos) return static_cast<pid_t>(std::stol(name));
  }
  return 0;
}

// A worker rank killed (SIGKILL) mid-fit under `mpirun --mca orte_enable_recovery 1`: rank 0
// counts it dead once it has been silent for SPIFIT_MPI_DEAD_AFTER (6 s here), runs its job on
// the other worker, and the fit ends as the serial one with exit 0 (docs/guide/parallel-runs.md).
TEST_F(MpiFit, ADeadRankDoesNotEndTheFit) {
  const fs::path out = dir_ / "rank_killed", err = dir_ / "rank_killed.err";
  const KilledFit k = kill_in_mpi_fit(fit_, out, err, "SPIFIT_MPI_DEAD_AFTER=6", " --mca orte_enable_recovery 1",
                                      [] { return rank_process_of(fit_, 2); });
  ASSERT_TRUE(k.killed) << "rank 2 was not killed";
  ASSERT_TRUE(WIFEXITED(k.status)) << "mpiexec ended by a signal";
  const std::string said = spifit::test::slurp(err);
  EXPECT_EQ(WEXITSTATUS(k.status), 0) << said;
  EXPECT_NE(said.find("spifit: rank 2 has not answered for 6 s: counted as dead"), std::string::npos) << said;
  EXPECT_EQ(spifit::test::slurp(out / "card.toml"), spifit::test::slurp(dir_ / "serial" / "card.toml"));
}

// An FE sweep over the contact penalty with its sensitivities: the points run on the two worker
// ranks side by side and come back in grid order.
TEST(MpiSweep, GivesTheSerialPointsInGridOrder) {
  const fs::path dir = spifit::test::fresh_temp_path("mpi_sweep");
  fs::create_directories(dir);
  const fs::path scene = spifit::test::write_tiny_line(dir / "line.toml");
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"line.toml\"\nmetrics = [\"peak_fz\", \"newton_iterations\", \"max_penetration\"]\n"
                                    << "sensitivities = true\n[inputs.\"contact.penalty\"]\nvalues = [300.0, 1000.0, 3000.0]\n";
  const auto serial = spifit::test::run_spifit("-q sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "serial").string());
  ASSERT_EQ(serial.code, 0) << serial.err;
  const auto mpi = run_mpi("-q sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "mpi").string());
  ASSERT_EQ(mpi.code, 0) << mpi.out << mpi.err;
  // sweep.csv: every column but wall_seconds (the next to last).
  auto strip = [](const std::string& csv) {
    std::string out;
    std::istringstream in(csv);
    for (std::string line; std::getline(in, line);) {
      const auto last = line.rfind(','), before = line.rfind(',', last - 1);
      out += line.substr(0, before) + line.substr(last) + "\n";
    }
    return out;
  };
  EXPECT_EQ(strip(spifit::test::slurp(dir / "mpi" / "sweep.csv")), strip(spifit::test::slurp(dir / "serial" / "sweep.csv")));
  EXPECT_EQ(spifit::test::slurp(dir / "mpi" / "sensitivities.csv"), spifit::test::slurp(dir / "serial" / "sensitivities.csv"));
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir / "serial")) {
    const auto rel = e.path().lexically_relative(dir / "serial").string();
    if (rel.rfind("points/", 0) != 0 && rel.rfind("sensitivities/", 0) != 0) continue;
    if (e.path().filename() != "force.csv" && e.path().filename() != "energies.csv" && e.path().extension() != ".csv") continue;
    EXPECT_EQ(spifit::test::slurp(dir / "mpi" / rel), spifit::test::slurp(e.path())) << rel;
    ++files;
  }
  EXPECT_GE(files, 12);
  // The workers' points are in the sweep directory's manifest (--force removes them).
  const std::string manifest = spifit::test::slurp(dir / "mpi" / ".spifit-manifest");
  EXPECT_NE(manifest.find("points/"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("sensitivities/"), std::string::npos) << manifest;
  fs::remove_all(dir);
}

// Other commands run in one process: under mpiexec they exit 2 and say so (rank 0 only).
TEST(MpiOther, RunIsRefusedUnderMpiexec) {
  const auto r = run_mpi("inputs");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("spifit inputs runs in one process: under mpirun only fit and sweep spread their runs over the ranks"), std::string::npos)
      << r.err;
}

}  // namespace
