#pragma once
// What the MPI tests share (mpi_cli_test.cpp, mpi_failure_cli_test.cpp): spifit under mpiexec (3
// ranks on however many cores: --oversubscribe), a small FE fit to run there, and fit.json
// without what depends on the clock.
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace spifit::test::mpi {

namespace fs = std::filesystem;
using nlohmann::json;


// Open MPI refuses root without these; yield: idle ranks leave the cores to the runs.
inline const char* kEnv = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 ";
inline const char* kLaunch = " --oversubscribe --bind-to none -np 3 ";

inline spifit::test::CliResult run_mpi(const std::string& args) {
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
inline fs::path write_fit(const fs::path& dir) {
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

inline json without_times(json j);

// fit.json without what depends on the clock, and without which experiment on a shared scene
// asked for a run first (experiments[].scene_runs: in one process too it depends on which
// thread came first; the total scene_runs does not).
inline json comparable(json j) {
  for (auto& e : j["experiments"]) e.erase("scene_runs");
  return without_times(j);
}
inline json without_times(json j) {
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
  inline static fs::path dir_, fit_;
};


}  // namespace spifit::test::mpi
