#pragma once
// A resumed (or otherwise repeated) run ends as the reference run: the same files, byte for byte,
// and the same summary values.
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace spifit::test {

// Each of `files` (paths relative to the run directories) exists in REF and is byte-identical in
// OUT; each of `dirs` holds the same file names in both, each file byte-identical.
inline void expect_same_outputs(const std::filesystem::path& ref, const std::filesystem::path& out, const std::vector<std::string>& files,
                                const std::vector<std::string>& dirs = {}) {
  namespace fs = std::filesystem;
  for (const auto& f : files) {
    EXPECT_TRUE(fs::is_regular_file(ref / f)) << f << " missing in the reference run";
    EXPECT_EQ(slurp(out / f), slurp(ref / f)) << f << " differs";
  }
  for (const auto& d : dirs) {
    const auto names = [&](const fs::path& dir) {
      std::set<std::string> n;
      if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir)) n.insert(e.path().filename().string());
      return n;
    };
    const std::set<std::string> in_ref = names(ref / d);
    EXPECT_FALSE(in_ref.empty()) << d << "/ empty or missing in the reference run";
    EXPECT_EQ(names(out / d), in_ref) << "the files in " << d << "/ differ";
    for (const auto& n : in_ref) EXPECT_EQ(slurp(out / d / n), slurp(ref / d / n)) << d << "/" << n << " differs";
  }
}

// These keys of two summaries (summary.json or a result's to_json()) are equal.
inline void expect_same_keys(const nlohmann::json& ref, const nlohmann::json& out, const std::vector<std::string>& keys) {
  for (const auto& k : keys) {
    EXPECT_TRUE(ref.contains(k)) << k << " missing in the reference summary";
    EXPECT_EQ(out.value(k, nlohmann::json()), ref.value(k, nlohmann::json())) << k;
  }
}

inline nlohmann::json read_summary(const std::filesystem::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "summary.json")); }

// Both of the above with the runs' summary.json.
inline void expect_same_run(const std::filesystem::path& ref, const std::filesystem::path& out, const std::vector<std::string>& files,
                            const std::vector<std::string>& keys) {
  expect_same_outputs(ref, out, files);
  expect_same_keys(read_summary(ref), read_summary(out), keys);
}

}  // namespace spifit::test
