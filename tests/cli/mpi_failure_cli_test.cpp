// MPI fits that lose a process (label long: about 45 s each): a fit killed after some
// evaluations resumes (--resume, again under mpiexec) to the serial card; a forward run's process
// or a worker rank killed mid-fit does not end it (docs/guide/parallel-runs.md). The default suite
// keeps the MPI fit and sweep against the serial ones (mpi_cli_test.cpp) and the serial kill and
// resume (fit_resume_cli_test.cpp).
#include "tests/cli/mpi_support.hpp"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>

namespace {

using namespace spifit::test::mpi;

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

}  // namespace
