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

// A bundled scene of experiments/aa3003o/scenes/ written to a temporary file `name` with its
// card's relative path made absolute and the first `from` replaced by `to` (a failure if absent).
inline std::filesystem::path bundled_scene_with(const std::string& scene, const std::string& name, const std::string& from, const std::string& to) {
  const std::string root = std::string(SPIFIT_SOURCE_DIR) + "/";
  std::string text = slurp(root + "experiments/aa3003o/scenes/" + scene);
  const std::string rel = "../../../materials/";
  if (const auto card = text.find(rel); card != std::string::npos) text.replace(card, rel.size(), root + "materials/");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return write_temp_file(name, text);
}

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

// Runs `spifit ARGS...` in a child process (stdout and stderr to /dev/null) and kills it with
// SIGKILL once `ready()` holds (checked every 10 ms) and `delay` has passed. Returns whether the
// kill hit the running process (false: it finished first, or ready() never held within 300 s).
template <typename Ready>
bool spifit_and_kill(const std::vector<std::string>& args, Ready ready, std::chrono::milliseconds delay) {
  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    std::vector<char*> argv{const_cast<char*>(SPIFIT_EXE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SPIFIT_EXE, argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  int status = 0;
  bool is_ready = false;
  while (!(is_ready = ready()) && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (is_ready) std::this_thread::sleep_for(delay);
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

// `spifit -q run SCENE --out OUT`, killed `delay` after the file `marker` (e.g. its first
// checkpoint) appears.
inline bool run_and_kill(const std::filesystem::path& scene, const std::filesystem::path& out, const std::filesystem::path& marker,
                         std::chrono::milliseconds delay) {
  return spifit_and_kill({"-q", "run", scene.string(), "--out", out.string()}, [&] { return std::filesystem::exists(marker); }, delay);
}

}  // namespace spifit::test
