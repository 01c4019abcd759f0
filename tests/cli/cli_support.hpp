#pragma once
// Running the spifit executable from the CLI tests: exit code, stdout and stderr.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

// A resumed run ends as the uninterrupted one: these files of DIR are byte-identical to REF's,
// and these keys of summary.json are equal.
inline void expect_same_run(const std::filesystem::path& ref, const std::filesystem::path& out, const std::vector<std::string>& files,
                            const std::vector<std::string>& keys) {
  const auto slurp = [](const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return std::filesystem::exists(f) ? ss.str() : std::string("(missing)");
  };
  for (const auto& f : files) EXPECT_EQ(slurp(out / f), slurp(ref / f)) << f << " differs";
  const auto a = nlohmann::json::parse(std::ifstream(ref / "summary.json"));
  const auto b = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  for (const auto& k : keys) EXPECT_EQ(b[k], a[k]) << k;
}

}  // namespace spifit::test
