// spifit fit and spifit sweep under mpiexec (3 ranks on however many cores: --oversubscribe)
// give what the serial commands give: the same card.toml, the same fit.json but for wall times,
// the same sweep.csv but for its wall_seconds column, the same files of every point
// (docs/guide/parallel-runs.md). An MPI fit killed, a run's process or a rank killed:
// mpi_failure_cli_test.cpp (label long).
#include "tests/cli/mpi_support.hpp"

#include <fstream>
#include <sstream>

namespace {

using namespace spifit::test::mpi;

TEST_F(MpiFit, GivesTheSerialCardAndFit) {
  const auto r = run_mpi("fit " + fit_.string() + " --out " + (dir_ / "mpi").string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("MPI: FE evaluations on 2 worker rank(s)"), std::string::npos) << r.out;
  EXPECT_EQ(spifit::test::slurp(dir_ / "mpi" / "card.toml"), spifit::test::slurp(dir_ / "serial" / "card.toml"));
  const json serial = comparable(json::parse(spifit::test::slurp(dir_ / "serial" / "fit.json")));
  const json mpi = comparable(json::parse(spifit::test::slurp(dir_ / "mpi" / "fit.json")));
  EXPECT_EQ(mpi, serial);
  EXPECT_EQ(mpi["scene_runs"], serial["scene_runs"]);  // one run per scene and point, as in one process
}

// A fit with the exact Jacobian (frictionless: the runs carry sensitivities; a worker answers
// the residuals and their derivatives together) under MPI, with --jacobian exact on the command
// line handed to the workers: the serial card and fit.json, from one run per point.
TEST(MpiExactFit, GivesTheSerialCardAndFit) {
  const fs::path dir = spifit::test::fresh_temp_path("mpi_exact_fit");
  fs::create_directories(dir);
  const fs::path scene = spifit::test::write_tiny_line(dir / "line.toml");
  const auto synth = spifit::test::run_spifit("-q synth " + scene.string() + " --x travel --y fz --every 4 --set swift.K=170 --out " +
                                              (dir / "fz.csv").string());
  ASSERT_EQ(synth.code, 0) << synth.err;
  std::ofstream(dir / "fit.toml") << "[fit]\ncard = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                                  << "[parameters.\"swift.K\"]\ninitial = 200.0\nlower = 100.0\nupper = 300.0\n"
                                  << "[parameters.\"swift.n\"]\nlower = 0.05\nupper = 0.5\n"
                                  << "[[experiment]]\nname = \"press\"\nscene = \"line.toml\"\ndata = \"fz.csv\"\nx = \"travel\"\ny = \"fz\"\nnoise = 1.0\n";
  const std::string fit = (dir / "fit.toml").string();
  const auto serial = spifit::test::run_spifit("-q fit " + fit + " --jacobian exact --out " + (dir / "serial").string());
  ASSERT_EQ(serial.code, 0) << serial.err;
  const auto r = run_mpi("fit " + fit + " --jacobian exact --out " + (dir / "mpi").string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_EQ(spifit::test::slurp(dir / "mpi" / "card.toml"), spifit::test::slurp(dir / "serial" / "card.toml"));
  const json s = comparable(json::parse(spifit::test::slurp(dir / "serial" / "fit.json")));
  const json m = comparable(json::parse(spifit::test::slurp(dir / "mpi" / "fit.json")));
  EXPECT_EQ(m, s);
  EXPECT_EQ(s["experiments"][0]["jacobian"], "exact");
  EXPECT_LE(s["scene_runs"].get<long>(), s["iterations"].get<long>() + 2);  // one run per point
  fs::remove_all(dir);
}

// An FE sweep over the contact penalty with its sensitivities: the points run on the two worker
// ranks side by side and come back in grid order.
TEST(MpiSweep, GivesTheSerialPointsInGridOrder) {
  const fs::path dir = spifit::test::fresh_temp_path("mpi_sweep");
  fs::create_directories(dir);
  const fs::path scene = spifit::test::write_tiny_line(dir / "line.toml");
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"line.toml\"\nmetrics = [\"peak_fz\", \"newton_iterations\", \"max_penetration\"]\n"
                                    << "sensitivities = true\n[inputs.\"contact.penalty\"]\nvalues = [300.0, 1000.0, 3000.0]\n";
  const auto serial = spifit::test::run_spifit("-q sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "serial").string());
  ASSERT_EQ(serial.code, 0) << serial.err;
  const auto mpi = run_mpi("-q sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "mpi").string());
  ASSERT_EQ(mpi.code, 0) << mpi.out << mpi.err;
  // sweep.csv: every column but wall_seconds (the next to last).
  auto strip = [](const std::string& csv) {
    std::string out;
    std::istringstream in(csv);
    for (std::string line; std::getline(in, line);) {
      const auto last = line.rfind(','), before = line.rfind(',', last - 1);
      out += line.substr(0, before) + line.substr(last) + "\n";
    }
    return out;
  };
  EXPECT_EQ(strip(spifit::test::slurp(dir / "mpi" / "sweep.csv")), strip(spifit::test::slurp(dir / "serial" / "sweep.csv")));
  EXPECT_EQ(spifit::test::slurp(dir / "mpi" / "sensitivities.csv"), spifit::test::slurp(dir / "serial" / "sensitivities.csv"));
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir / "serial")) {
    const auto rel = e.path().lexically_relative(dir / "serial").string();
    if (rel.rfind("points/", 0) != 0 && rel.rfind("sensitivities/", 0) != 0) continue;
    if (e.path().filename() != "force.csv" && e.path().filename() != "energies.csv" && e.path().extension() != ".csv") continue;
    EXPECT_EQ(spifit::test::slurp(dir / "mpi" / rel), spifit::test::slurp(e.path())) << rel;
    ++files;
  }
  EXPECT_GE(files, 12);
  // The workers' points are in the sweep directory's manifest (--force removes them).
  const std::string manifest = spifit::test::slurp(dir / "mpi" / ".spifit-manifest");
  EXPECT_NE(manifest.find("points/"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("sensitivities/"), std::string::npos) << manifest;
  fs::remove_all(dir);
}

// Other commands run in one process: under mpiexec they exit 2 and say so (rank 0 only).
TEST(MpiOther, RunIsRefusedUnderMpiexec) {
  const auto r = run_mpi("inputs");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("spifit inputs runs in one process: under mpirun only fit and sweep spread their runs over the ranks"), std::string::npos)
      << r.err;
}

}  // namespace
