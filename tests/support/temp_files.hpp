#pragma once
// Temporary files of the tests and whole files as strings.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace spifit::test {

// A path in the temporary directory that no other test process uses and no other test of this
// process: spifit_<pid>_<Suite>.<Test>_<name> (ctest runs each test in a process of its own).
inline std::filesystem::path temp_path(const std::string& name) {
  std::string test;
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
    test = std::string(info->test_suite_name()) + "." + info->name() + "_";
  return std::filesystem::temp_directory_path() / ("spifit_" + std::to_string(::getpid()) + "_" + test + name);
}

// temp_path(name) with anything there removed: an output directory to start afresh.
inline std::filesystem::path fresh_temp_path(const std::string& name) {
  const auto p = temp_path(name);
  std::filesystem::remove_all(p);
  return p;
}

// Writes `text` to temp_path(name).
inline std::filesystem::path write_temp_file(const std::string& name, const std::string& text) {
  const auto p = temp_path(name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// The bytes of a file; "(missing)" when there is none (so that two missing files compare equal
// only where a caller allows it: expect_same_outputs requires the reference's files).
inline std::string slurp(const std::filesystem::path& f) {
  if (!std::filesystem::is_regular_file(f)) return "(missing)";
  std::ifstream in(f, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace spifit::test
