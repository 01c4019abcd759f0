#pragma once
// Running the spifit executable from the CLI tests: exit code, stdout and stderr; killing a run.
// (expect_same_run, temp_path, slurp: tests/support.)
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <thread>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace spifit::test {

struct CliResult {
  int code = -1;
  std::string out, err;
};

inline CliResult run_spifit(const std::string& args) {
  const std::filesystem::path tmp = std::filesystem::temp_directory_path() / ("spifit_cli_err_" + std::to_string(::getpid()));
  const std::string cmd = std::string(SPIFIT_EXE) + " " + args + " 2>" + tmp.string();
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), p)) r.out += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream f(tmp);
  std::stringstream ss;
  ss << f.rdbuf();
  r.err = ss.str();
  std::filesystem::remove(tmp);
  return r;
}

// Runs `spifit -q run SCENE --out OUT` in a child process and kills it with SIGKILL `delay`
// after the file `marker` (e.g. its first checkpoint) appears. Returns whether the kill hit the
// running process (false: it finished first, or the marker never appeared within 300 s).
inline bool run_and_kill(const std::filesystem::path& scene, const std::filesystem::path& out, const std::filesystem::path& marker,
                         std::chrono::milliseconds delay) {
  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execl(SPIFIT_EXE, SPIFIT_EXE, "-q", "run", scene.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  int status = 0;
  while (!std::filesystem::exists(marker) && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (std::filesystem::exists(marker)) std::this_thread::sleep_for(delay);
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

}  // namespace spifit::test
