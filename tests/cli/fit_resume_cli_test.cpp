// A fit on an FE scene killed (SIGKILL) after some of its forward runs and resumed with --resume
// reads the finished evaluations back (DIR/runs/evaluations.jsonl) and ends with the result of
// an uninterrupted fit, bit for bit; a resume with changed inputs or nothing to resume is an
// input error.
#include "tests/cli/cli_support.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using spifit::test::run_spifit;
using spifit::test::temp_path;

std::size_t lines(const fs::path& f) {
  std::ifstream in(f);
  std::size_t n = 0;
  for (std::string l; std::getline(in, l);) ++n;
  return n;
}

nlohmann::json fit_json(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "fit.json")); }

TEST(FitResumeCli, AKilledFeFitResumesToTheUninterruptedResult) {
  const fs::path scene = spifit::test::write_tiny_line(temp_path("line.toml"));
  const fs::path data = temp_path("fx.csv"), fit = temp_path("fit.toml");
  auto r = run_spifit("-q synth " + scene.string() + " --set contact.friction=0.1 --x travel --y fx --every 4 --out " + data.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ofstream(fit) << "[fit]\ncard = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                     << "[parameters.\"contact.friction\"]\ninitial = 0.14\nlower = 0.0\nupper = 0.5\n"
                     << "[[experiment]]\nscene = \"" << scene.string() << "\"\ndata = \"" << data.string() << "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n";
  const fs::path ref = temp_path("ref"), out = temp_path("killed");
  fs::remove_all(ref);
  fs::remove_all(out);
  r = run_spifit("-q fit " + fit.string() + " --out " + ref.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t all = lines(ref / "runs" / "evaluations.jsonl");

  // Killed after 4 evaluations of about 15 (line 1 is the signature).
  const fs::path evaluations = out / "runs" / "evaluations.jsonl";
  const bool killed = spifit::test::spifit_and_kill({"-q", "fit", fit.string(), "--out", out.string()}, [&] { return lines(evaluations) >= 5; },
                                                    std::chrono::milliseconds(0));
  ASSERT_TRUE(killed) << "the fit ended before the kill";
  const std::size_t kept = lines(evaluations);
  std::printf("killed after %zu of %zu evaluations\n", kept - 1, all - 1);
  EXPECT_LT(kept, all);

  // A resume after the data changed is refused, naming the evaluations file.
  const std::string original = spifit::test::slurp(data);
  std::ofstream(data, std::ios::app) << "\n";
  r = run_spifit("fit " + fit.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("evaluations.jsonl"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("changed"), std::string::npos) << r.err;
  std::ofstream(data, std::ios::trunc) << original;

  r = run_spifit("fit " + fit.string() + " --out " + out.string() + " --resume");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("resuming: "), std::string::npos) << r.out;
  const auto a = fit_json(ref), b = fit_json(out);
  for (const char* k : {"parameters", "cost_initial", "cost_final", "cost_history", "iterations", "usable"}) EXPECT_EQ(b[k], a[k]) << k;
  // The resumed fit ran only what the killed one had not finished.
  EXPECT_LT(b["scene_runs"].get<long>(), a["scene_runs"].get<long>());

  // A resume of the finished fit, or of nothing, is refused.
  r = run_spifit("fit " + fit.string() + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("the run in this directory is complete"), std::string::npos) << r.err;
  const fs::path fresh = temp_path("fresh");
  fs::remove_all(fresh);
  r = run_spifit("fit " + fit.string() + " --out " + fresh.string() + " --resume");
  EXPECT_EQ(r.code, 2) << r.err;
  for (const auto& p : {ref, out, fresh}) fs::remove_all(p);
  for (const auto& p : {scene, data, fit}) fs::remove(p);
}

}  // namespace
