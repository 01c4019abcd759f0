// Determinism of a forming run: the same scene with the same number of threads writes the same
// files, byte for byte; and the parallel parts (element evaluation, the row-split scatter into
// the tangent) make the results independent of the thread count too. indent_line with the
// AF card exercises sliding friction's non-symmetric tangent and kinematic hardening.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "forward/scenes/forming/forming_scene.hpp"

#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// force.csv and energies.csv of a run of `scene` with `threads` OpenMP threads.
std::string run_with_threads(const FormingScene& scene, int threads, const std::string& tag) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  const fs::path d = fs::temp_directory_path() / ("spifit_determinism_" + tag + "_" + std::to_string(::getpid()));
  const auto out = io::OutputDirectory::prepare(d.string(), true);
  const FormingResult r = run_forming_scene(scene, RunFiles(out));
  omp_set_num_threads(saved);
  EXPECT_TRUE(r.ok()) << r.message;
  const std::string files = read_bytes(d / "force.csv") + read_bytes(d / "energies.csv");
  EXPECT_GT(files.size(), 1000u);
  fs::remove_all(d);
  return files;
}

void expect_deterministic(const std::string& file) {
  FormingScene s = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + file);
  s.contact.friction = 0.1;
  const std::string two = run_with_threads(s, 2, "a");
  EXPECT_EQ(run_with_threads(s, 2, "b"), two) << file << ": two runs with 2 threads differ";
  EXPECT_EQ(run_with_threads(s, 1, "c"), two) << file << ": 1 thread differs from 2";
  EXPECT_EQ(run_with_threads(s, 3, "d"), two) << file << ": 3 threads differ from 2";
}

TEST(FormingDeterminism, SameInputsGiveTheSameFilesForAnyThreadCount) {
  expect_deterministic("indent_line.toml");
  expect_deterministic("indent_line_c7_af.toml");
}

}  // namespace
}  // namespace spifit::scene
