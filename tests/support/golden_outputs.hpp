#pragma once
// Golden outputs of the bundled scenes (tests/golden/scene_outputs.json): every file a scene run
// writes (checkpoints and summary.json aside) by its size and FNV-1a 64-bit fingerprint, which
// a change of one bit changes, and the summary's values. The numbers must stay the same through
// a restructuring; a change of results must be explained and the goldens renewed with
//   SPIFIT_UPDATE_GOLDEN=1 ctest --test-dir build -R GoldenOutputs
// which runs both the short scenes (scene_tests) and the long ones (long_tests, label long; each
// rewrites the entries of its own scenes), under the tests' environment: run directly, the
// binaries take other OpenBLAS kernels and write other last bits (tests/CMakeLists.txt,
// OPENBLAS_CORETYPE).
#include "forward/io/output_directory.hpp"
#include "forward/io/text_file.hpp"
#include "forward/scenes/scene_registry.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace spifit::test {

inline std::string fingerprint(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, "%016llx:%zu", static_cast<unsigned long long>(h), bytes.size());
  return buf;
}

// Timing and provenance: they differ from run to run or machine to machine.
inline const std::set<std::string>& golden_ignored_keys() {
  static const std::set<std::string> k{"wall_seconds", "profile_seconds", "contour_wall_seconds", "checkpoints", "scene_file",
                                       "material_file", "spifit_version", "gcode", "resumed_at_mark"};
  return k;
}

inline nlohmann::json strip_ignored(const nlohmann::json& j) {
  if (!j.is_object()) return j;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [k, v] : j.items())
    if (!golden_ignored_keys().count(k)) out[k] = strip_ignored(v);
  return out;
}

// Numbers equal to 1e-12 relative, everything else equal; keys of the golden must be present.
inline void expect_json_close(const nlohmann::json& golden, const nlohmann::json& actual, const std::string& path) {
  if (golden.is_object()) {
    ASSERT_TRUE(actual.is_object()) << path;
    for (const auto& [k, v] : golden.items()) {
      ASSERT_TRUE(actual.contains(k)) << path << "." << k << " missing";
      expect_json_close(v, actual[k], path + "." + k);
    }
  } else if (golden.is_array()) {
    ASSERT_TRUE(actual.is_array() && actual.size() == golden.size()) << path << ": " << actual.dump();
    for (std::size_t i = 0; i < golden.size(); ++i) expect_json_close(golden[i], actual[i], path + "[" + std::to_string(i) + "]");
  } else if (golden.is_number() && actual.is_number()) {
    const double g = golden.get<double>(), a = actual.get<double>();
    EXPECT_TRUE(a == g || std::abs(a - g) <= 1e-12 * std::max(std::abs(a), std::abs(g))) << path << ": " << a << " vs golden " << g;
  } else {
    EXPECT_EQ(actual, golden) << path;
  }
}

inline std::filesystem::path golden_file() { return std::filesystem::path(SPIFIT_SOURCE_DIR) / "tests" / "golden" / "scene_outputs.json"; }

// Runs each scene (paths relative to the source tree) and compares with, or with
// SPIFIT_UPDATE_GOLDEN=1 renews, its golden entry.
inline void check_golden_outputs(const std::vector<std::string>& scenes) {
  namespace fs = std::filesystem;
  nlohmann::json golden = fs::exists(golden_file()) ? nlohmann::json::parse(std::ifstream(golden_file())) : nlohmann::json::object();
  const bool update = std::getenv("SPIFIT_UPDATE_GOLDEN") != nullptr;
  const fs::path out = fs::temp_directory_path() / ("spifit_golden_" + std::to_string(::getpid()));
  for (const auto& rel : scenes) {
    SCOPED_TRACE(rel);
    const auto scene = scene::read_scene(std::string(SPIFIT_SOURCE_DIR) + "/" + rel);
    fs::remove_all(out);
    const auto dir = io::OutputDirectory::prepare(out.string(), false);
    const auto result = scene->run(scene::RunFiles(dir), {});
    ASSERT_TRUE(result->ok()) << result->message;
    nlohmann::json entry;
    entry["summary"] = strip_ignored(result->to_json());
    for (const auto& e : fs::recursive_directory_iterator(out)) {
      const std::string name = fs::relative(e.path(), out).string();
      if (!e.is_regular_file() || name == "summary.json" || name == io::OutputDirectory::kManifest || name == io::DirectoryLock::kFile ||
          name.rfind("checkpoint", 0) == 0)
        continue;
      entry["files"][name] = fingerprint(io::read_text_file(e.path().string()));
    }
    if (update) {
      golden[rel] = entry;
      continue;
    }
    ASSERT_TRUE(golden.contains(rel)) << "no golden entry (renew with SPIFIT_UPDATE_GOLDEN=1)";
    EXPECT_EQ(entry["files"], golden[rel]["files"]) << "files or their contents differ";
    expect_json_close(golden[rel]["summary"], entry["summary"], "summary");
  }
  fs::remove_all(out);
  if (update) {
    fs::create_directories(golden_file().parent_path());
    std::ofstream(golden_file()) << golden.dump(1) << "\n";
  }
}

}  // namespace spifit::test
