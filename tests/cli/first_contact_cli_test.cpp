// What a new user met at first contact: a fit that is not usable says so (exit 1, its card named
// NOT_USABLE, the warnings on the terminal); a data file whose header names the wrong unit, an
// absurd sheet, tool, penalty or card is named before anything runs; a live run's directory is
// not replaced; a fitted card says where it comes from; an FE fit says where it is; a finished
// run is not "resumed"; permission errors are input errors.
#include "tests/cli/cli_support.hpp"
#include "tests/support/lock_holder.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using spifit::test::fresh_temp_path;
using spifit::test::run_spifit;
using spifit::test::slurp;
using spifit::test::temp_path;

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

using spifit::test::bundled_scene_with;

TEST(FirstContactCli, AFitThatIsNotUsableSaysSoExitsOneAndNamesItsCardSo) {
  const fs::path out = fresh_temp_path("conflict");
  const auto r = run_spifit("fit " + src("experiments/aa3003o/fit_n_conflict.toml") + " --out " + out.string());
  EXPECT_EQ(r.code, 1) << r.err;
  // The report's warnings follow the table on the terminal, the verdict is on stderr.
  EXPECT_TRUE(has(r.out, "WARNING: The result is NOT USABLE: experiment r45: its residuals are on average 22")) << r.out;
  EXPECT_TRUE(has(r.out, "WARNING: Conflict: experiments r45 and shear_00 disagree on hill.N")) << r.out;
  EXPECT_TRUE(has(r.err, "spifit: fit fit_n_conflict: the result is NOT USABLE")) << r.err;
  EXPECT_FALSE(has(r.err, "InitGoogleLogging")) << r.err;
  EXPECT_FALSE(fs::exists(out / "card.toml"));
  EXPECT_TRUE(has(slurp(out / "card_NOT_USABLE.toml"), "usable = false"));
  for (const auto& [deck, plain] : {std::pair{"card_abaqus_NOT_USABLE.inp", "card_abaqus.inp"}, std::pair{"card_lsdyna_NOT_USABLE.k", "card_lsdyna.k"},
                                     std::pair{"card_calculix_NOT_USABLE.inp", "card_calculix.inp"}}) {
    EXPECT_TRUE(has(slurp(out / "exports" / deck), "NOT USABLE")) << deck;
    EXPECT_FALSE(fs::exists(out / "exports" / plain)) << plain;
  }
  // Such a card still loads, and says what it is.
  const auto show = run_spifit("material show " + (out / "card_NOT_USABLE.toml").string());
  EXPECT_EQ(show.code, 0) << show.err;
  EXPECT_TRUE(has(show.out, "warning        it was written by a fit whose result is NOT USABLE")) << show.out;
  const auto fit = nlohmann::json::parse(slurp(out / "fit.json"));
  EXPECT_EQ(fit["usable"], false);
  ASSERT_EQ(fit["not_usable_because"].size(), 1u);
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "summary.json"))["status"], "failed");
  const std::string report = slurp(out / "report.md");
  EXPECT_TRUE(has(report, "| result usable | **NO (see the warnings): card_NOT_USABLE.toml** |")) << report.substr(0, 3000);
  fs::remove_all(out);
}

// A cost that overflows (r45 said to be known to 1e-300): Ceres gives up and logs it through glog,
// whose "Logging before InitGoogleLogging()" line and log record never reach the user; the fit
// exits 1, not usable, its card named so.
TEST(FirstContactCli, AnOverflowingCostIsNotUsableAndGlogStaysQuiet) {
  const fs::path fit = spifit::test::write_temp_file(
      "overflow.toml", "[fit]\ncard = \"" + src("materials/aa3003o_c3c4.toml") +
                           "\"\n[parameters.\"hill.N\"]\ninitial = 3.5\nlower = 1.0\nupper = 8.0\n[[experiment]]\nname = \"r45\"\nscene = \"" +
                           src("experiments/aa3003o/scenes/tensile_45.toml") + "\"\nobservable = \"r_value\"\nvalue = 0.73\nnoise = 1e-300\n");
  const fs::path out = fresh_temp_path("overflow_out");
  const auto r = run_spifit("fit " + fit.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_FALSE(has(r.err, "InitGoogleLogging")) << r.err;
  EXPECT_FALSE(has(r.err, "trust_region_minimizer")) << r.err;
  EXPECT_TRUE(has(r.out, "the cost at the solution is not finite (inf)")) << r.out;
  EXPECT_FALSE(fs::exists(out / "card.toml"));
  EXPECT_TRUE(fs::exists(out / "card_NOT_USABLE.toml"));
  fs::remove_all(out);
}

TEST(FirstContactCli, AStressHeaderInGpaIsAnInputErrorBeforeAnyOutput) {
  std::string text = slurp(src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv"));
  text.replace(text.find("stress [MPa]"), 12, "stress [GPa]");
  const fs::path data = spifit::test::write_temp_file("gpa.csv", text);
  const fs::path fit = spifit::test::write_temp_file(
      "gpa_fit.toml", "[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") + "\"\n[parameters.\"swift.K\"]\ninitial = 150.0\nlower = 50.0\nupper = 500.0\n" +
                          "[[experiment]]\nname = \"t\"\nscene = \"" + src("experiments/aa3003o/scenes/tensile_00.toml") + "\"\ndata = \"" +
                          data.string() + "\"\nnoise = 0.5\n");
  const fs::path out = fresh_temp_path("gpa_out");
  const auto r = run_spifit("fit " + fit.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, data.string() + ": column stress = [GPa]: measured stress values reach ")) << r.err;
  EXPECT_TRUE(has(r.err, "is the unit in the data file's header right?")) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(FirstContactCli, AFittedCardAndItsDecksSayWhereTheyComeFrom) {
  const fs::path out = fresh_temp_path("provenance");
  const auto r = run_spifit("fit " + src("experiments/aa3003o/fit_classic.toml") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string card = slurp(out / "card.toml");
  EXPECT_TRUE(has(card, "name = \"fit_classic\"")) << card;
  EXPECT_FALSE(has(card, "Table C.2")) << card;  // the start card's identity stays with it
  EXPECT_TRUE(has(card, "[fitted]")) << card;
  EXPECT_TRUE(has(card, "fit_file = \"" + src("experiments/aa3003o/fit_classic.toml") + "\"")) << card;
  EXPECT_TRUE(has(card, "start_card = \"" + src("materials/aa3003o_c2.toml") + "\"")) << card;
  EXPECT_TRUE(has(card, "data/tensile_45_c2_synthetic.csv")) << card;
  EXPECT_TRUE(has(card, "spifit_version = \"" SPIFIT_VERSION "\"")) << card;
  EXPECT_TRUE(has(card, "date = \"20")) << card;
  for (const char* deck : {"card_abaqus.inp", "card_lsdyna.k", "card_calculix.inp"}) {
    const std::string text = slurp(out / "exports" / deck);
    EXPECT_TRUE(has(text, "fitted by spifit " SPIFIT_VERSION " on 20")) << deck;
    EXPECT_FALSE(has(text, "Table C.2")) << deck;
  }
  // The card reads back with its provenance.
  const auto show = run_spifit("material show " + (out / "card.toml").string());
  EXPECT_EQ(show.code, 0) << show.err;
  EXPECT_TRUE(has(show.out, "fitted         by spifit " SPIFIT_VERSION)) << show.out;
  // The report shows the whole card, what it predicts and the decks.
  const std::string report = slurp(out / "report.md");
  EXPECT_TRUE(has(report, "| elastic.E | MPa | 72600 | start card |")) << report;
  EXPECT_TRUE(has(report, "| hill.H | - | 0.809614 | = 2 - hill.G |")) << report;
  EXPECT_TRUE(has(report, "| 45° | 0.73")) << report;
  EXPECT_TRUE(has(report, "exports/card_lsdyna.k")) << report;
  fs::remove_all(out);
}

TEST(FirstContactCli, AbsurdSheetsToolsPenaltiesAndCardsAreNamedBeforeTheRun) {
  struct Case {
    std::string scene, from, to, expect;
  };
  const std::vector<Case> cases{
      {"indent.toml", "thickness = 0.3", "thickness = 1e-9", "sheet.thickness = 1e-09: a sheet thinner than one micrometre"},
      {"indent.toml", "penalty = 1000.0", "penalty = 1e30", "contact.penalty = 1e+30: a million times stiffer than the sheet"},
      {"line_half.toml", "radius = 5.0", "radius = 1000.0", "tool.radius = 1000: the tool (diameter 2000 mm) is larger than the sheet it forms (182 mm"},
  };
  for (const Case& c : cases) {
    const fs::path scene = bundled_scene_with(c.scene, "absurd.toml", c.from, c.to);
    const auto r = run_spifit("run " + scene.string() + " --out " + fresh_temp_path("absurd_out").string());
    EXPECT_EQ(r.code, 2) << c.to;
    EXPECT_TRUE(has(r.err, c.expect)) << r.err;
    EXPECT_FALSE(fs::exists(temp_path("absurd_out")));
  }
  std::string card = slurp(src("materials/aa3003o_c3c4.toml"));
  card.replace(card.find("F = 1.224"), 9, "F = 1e308");
  const fs::path bad_card = spifit::test::write_temp_file("needle.toml", card);
  const auto m = run_spifit("material show " + bad_card.string());
  EXPECT_EQ(m.code, 2);
  EXPECT_TRUE(has(m.err, "hill.F = 1e+308: the Hill coefficients differ by more than a factor of a million")) << m.err;
  // Legal but odd: said before the run, which goes on.
  const fs::path slow = bundled_scene_with("indent.toml", "slow.toml", "feed = 2.0", "feed = 1e-12");
  const auto r = run_spifit("run " + slow.string() + " --out " + fresh_temp_path("slow_out").string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "spifit: warning: " + slow.string() + ": tool.feed = 1e-12 mm/s is beyond any SPIF feed")) << r.err;
  fs::remove_all(temp_path("slow_out"));
}

TEST(FirstContactCli, ALiveRunsDirectoryIsNotReplacedWithForce) {
  const fs::path out = fresh_temp_path("live");
  auto r = run_spifit("-q run " + src("experiments/aa3003o/scenes/tensile_00.toml") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  spifit::test::LockHolder live(out);  // as a run still writing there
  ASSERT_GT(live.pid, 0);
  r = run_spifit("run " + src("experiments/aa3003o/scenes/tensile_00.toml") + " --out " + out.string() + " --force");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "--out = " + out.string() + ": in use: a live spifit process is writing there (pid " + std::to_string(live.pid))) << r.err;
  EXPECT_FALSE(has(r.err, "pass --force")) << r.err;
  EXPECT_TRUE(fs::exists(out / "curve.csv"));
  live.kill();  // killed while it held the lock: the next run takes it over and says so
  r = run_spifit("run " + src("experiments/aa3003o/scenes/tensile_00.toml") + " --out " + out.string() + " --force");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "ended without releasing it (killed?); taking it over")) << r.err;
  fs::remove_all(out);
}

TEST(FirstContactCli, AFinishedRunIsCompleteNotMissingACheckpoint) {
  const fs::path out = fresh_temp_path("done");
  auto r = run_spifit("-q run " + src("experiments/aa3003o/scenes/indent.toml") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_spifit("run " + src("experiments/aa3003o/scenes/indent.toml") + " --out " + out.string() + " --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "the run in this directory is complete (summary.json: status ok): nothing to resume")) << r.err;
  fs::remove_all(out);
}

TEST(FirstContactCli, AnOutputDirectoryWithoutPermissionIsAnInputError) {
  // /sys refuses new entries even to root (EPERM), as a read-only directory refuses a user.
  const auto r = run_spifit("run " + src("experiments/aa3003o/scenes/tensile_00.toml") + " --out /sys/spifit_out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(has(r.err, "--out = /sys/spifit_out: permission denied")) << r.err;
}

TEST(FirstContactCli, AHugeCountSaysItIsTooLarge) {
  const fs::path scene = bundled_scene_with("tensile_00.toml", "huge.toml", "increments = 200", "increments = 1e12");
  const auto r = run_spifit("run " + scene.string() + " --out " + fresh_temp_path("huge_out").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "scene.increments = 1000000000000: too large for a count")) << r.err;
}

TEST(FirstContactCli, AnFeFitSaysWhichIterationItIsInWithoutVerbose) {
  const fs::path scene = spifit::test::write_tiny_line(temp_path("line.toml"));
  const fs::path data = temp_path("fx.csv"), fit = temp_path("fit.toml");
  auto r = run_spifit("-q synth " + scene.string() + " --set contact.friction=0.1 --x travel --y fx --every 4 --out " + data.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ofstream(fit) << "[fit]\ncard = \"" << src("materials/aa3003o_c3c4.toml") << "\"\n"
                     << "[parameters.\"contact.friction\"]\ninitial = 0.14\nlower = 0.0\nupper = 0.5\n"
                     << "[[experiment]]\nscene = \"" << scene.string() << "\"\ndata = \"" << data.string() << "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n";
  const fs::path out = fresh_temp_path("fe_fit");
  r = run_spifit("fit " + fit.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  // One friction parameter with the exact Jacobian: one run per iteration.
  EXPECT_TRUE(has(r.err, "spifit: iteration 0: cost ")) << r.err;
  EXPECT_TRUE(has(r.err, ", 1 FE runs (1 in all), ")) << r.err;
  EXPECT_TRUE(has(r.err, "spifit: iteration 1: cost ")) << r.err;
  // The closing line counts the scene runs the fit made, as fit.json does, beside the
  // evaluations of the experiments (the Jacobian's at the solution among them, from the runs'
  // cache): not the evaluations alone as if each had been a forward run.
  const auto fit_json = nlohmann::json::parse(slurp(out / "fit.json"));
  const long runs = fit_json["scene_runs"].get<long>(), evaluations = fit_json["forward_runs"].get<long>();
  EXPECT_GT(evaluations, runs);
  EXPECT_TRUE(has(r.out, " iterations, " + std::to_string(runs) + " FE scene runs (" + std::to_string(evaluations) + " evaluations of the experiments), "))
      << r.out;
  fs::remove_all(out);
}

}  // namespace
