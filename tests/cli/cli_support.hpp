#pragma once
// Running the spifit executable from the CLI tests: exit code, stdout and stderr.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

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

}  // namespace spifit::test
