// The spifit executable: version/help, lankford, material show, run; exit codes and the
// one-line error contract; the --out/--force rule.
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using Result = spifit::test::CliResult;
Result run(const std::string& args) { return spifit::test::run_spifit(args); }

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

fs::path fresh_dir(const std::string& name) { return spifit::test::fresh_temp_path(name); }

std::string write_temp(const std::string& name, const std::string& text) { return spifit::test::write_temp_file(name, text).string(); }

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace

TEST(Cli, VersionAndHelp) {
  const auto v = run("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.out.find("spifit "), std::string::npos);
  for (const char* sub : {"--help", "lankford --help", "material --help", "material show --help", "run --help"}) {
    const auto h = run(sub);
    EXPECT_EQ(h.code, 0) << sub;
    EXPECT_NE(h.out.find("Usage"), std::string::npos) << sub;
  }
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("frobnicate").code, 2);
}

TEST(Cli, LankfordJson) {
  const auto r = run("lankford --r0 0.68 --r45 0.73 --r90 0.66 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["F"].get<double>(), 1.2266, 1e-4);
  EXPECT_NEAR(j["G"].get<double>(), 1.1905, 1e-4);
  EXPECT_NEAR(j["H"].get<double>(), 0.8095, 1e-4);
  EXPECT_NEAR(j["N"].get<double>(), 2.9729, 1e-4);
  const auto t = nlohmann::json::parse(run("lankford --r0 0.6765 --r45 0.7317 --r90 0.6593 --json").out);
  EXPECT_NEAR(t["F"].get<double>(), 1.224, 5e-4);  // Table C.2
  EXPECT_NEAR(t["N"].get<double>(), 2.977, 5e-4);
  EXPECT_EQ(run("lankford --r0 -1 --r45 0.73 --r90 0.66").code, 2);
  EXPECT_EQ(run("lankford --r0 0.68").code, 2);
}

TEST(Cli, MaterialShow) {
  const auto r = run("material show " + src("materials/aa3003o_c3c4.toml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("42.967"), std::string::npos);
  EXPECT_NE(r.out.find("0.6764"), std::string::npos);  // r0 = H/G
  const auto m = run("material show /nonexistent/card.toml");
  EXPECT_EQ(m.code, 2);
  EXPECT_EQ(count_lines(m.err), 1);
  EXPECT_NE(m.err.find("/nonexistent/card.toml"), std::string::npos);
}

TEST(Cli, RunTensileWritesSummaryAndCurve) {
  const auto out = fresh_dir("tensile");
  const auto r = run("run " + src("experiments/aa3003o/scenes/tensile_45.toml") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream f(out / "summary.json");
  const auto s = nlohmann::json::parse(f);
  EXPECT_EQ(s["kind"], "tensile");
  EXPECT_EQ(s["status"], "ok");
  EXPECT_EQ(s["material"], "aa3003o_c3c4");
  EXPECT_GT(s["wall_seconds"].get<double>(), 0.0);
  EXPECT_NEAR(s["r_value"].get<double>(), 1.1798, 1e-4);
  EXPECT_NEAR(s["initial_yield_stress"].get<double>(), 37.439, 1e-2);
  EXPECT_TRUE(s["yield_stress"].is_number());
  std::ifstream c(out / "curve.csv");
  std::string header;
  std::getline(c, header);
  EXPECT_EQ(header.rfind("increment,segment,strain,cumulative_strain,stress,", 0), 0u) << header;
  int rows = 0;
  for (std::string line; std::getline(c, line);) ++rows;
  EXPECT_EQ(rows, 201);

  // An existing --out is never overwritten without --force ...
  const auto again = run("run " + src("experiments/aa3003o/scenes/tensile_45.toml") + " --out " + out.string());
  EXPECT_EQ(again.code, 2);
  EXPECT_EQ(count_lines(again.err), 1);
  EXPECT_NE(again.err.find("--force"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "curve.csv"));
  // ... and is replaced with it.
  EXPECT_EQ(run("run " + src("experiments/aa3003o/scenes/tensile_00.toml") + " --out " + out.string() + " --force").code, 0);
  std::ifstream f2(out / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(f2)["angle_deg"].get<double>(), 0.0);
  fs::remove_all(out);

  // --force never clears a directory that is not a spifit output, or that holds the inputs.
  const auto foreign = fresh_dir("foreign");
  fs::create_directories(foreign);
  std::ofstream(foreign / "notes.txt") << "keep";
  const auto fr = run("run " + src("experiments/aa3003o/scenes/tensile_00.toml") + " --out " + foreign.string() + " --force");
  EXPECT_EQ(fr.code, 2);
  EXPECT_TRUE(fs::exists(foreign / "notes.txt"));
  fs::remove_all(foreign);
  const auto own = fresh_dir("own");
  fs::create_directories(own);
  fs::copy_file(src("experiments/aa3003o/scenes/tensile_00.toml"), own / "scene.toml");
  std::string text = spifit::test::slurp(own / "scene.toml");
  const auto pos = text.find("../../../materials/");
  text.replace(pos, std::string("../../../materials/").size(), src("materials/"));
  std::ofstream(own / "scene.toml") << text;
  std::ofstream(own / "summary.json") << "{}";
  const auto g = run("run " + (own / "scene.toml").string() + " --out " + own.string() + " --force");
  EXPECT_EQ(g.code, 2) << g.err;
  EXPECT_NE(g.err.find("holds an input"), std::string::npos) << g.err;
  EXPECT_TRUE(fs::exists(own / "scene.toml"));
  fs::remove_all(own);
}

TEST(Cli, BadScenesExitTwoWithOneLine) {
  const std::string mat = src("materials/aa3003o_c3c4.toml");
  struct Case { std::string name, text, must_contain; };
  const std::vector<Case> cases{
      {"malformed.toml", "[scene\nkind = 1", "malformed TOML"},
      {"unknown_key.toml", "[scene]\nkind = \"tensile\"\nmaterial = \"" + mat + "\"\nangel = 45.0\n", "scene.angel"},
      {"wrong_type.toml", "[scene]\nkind = \"tensile\"\nmaterial = \"" + mat + "\"\nincrements = \"many\"\n", "scene.increments = \"many\""},
      {"unknown_kind.toml", "[scene]\nkind = \"tensle\"\nmaterial = \"" + mat + "\"\n", "scene.kind = \"tensle\""},
      {"missing_card.toml", "[scene]\nkind = \"tensile\"\nmaterial = \"nope.toml\"\n", "scene.material = \"nope.toml\""},
      // No card and no default card C.3 + C.4 beside the temporary directory.
      {"no_card.toml", "[scene]\nkind = \"tensile\"\n", "no_card.toml: scene.material: not given, and the default card C.3 + C.4 is not at"},
      {"negative_K.toml", "", "swift.K = -180"},
      {"one_newton.toml", "[scene]\nkind = \"tensile\"\nmaterial = \"" + mat + "\"\n[solver]\nmax_newton_iterations = 1\n", "solver.max_newton_iterations = 1"},
  };
  const std::string bad_card = write_temp("bad_card.toml", "[elastic]\nE = 72600.0\nnu = 0.36\n[swift]\nK = -180.0\neps0 = 0.001\nn = 0.2\n");
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = c.text.empty() ? "[scene]\nkind = \"tensile\"\nmaterial = \"" + bad_card + "\"\n" : c.text;
    const std::string path = write_temp(c.name, text);
    const auto out = fresh_dir("bad");
    const auto r = run("run " + path + " --out " + out.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.must_contain), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << "input errors must not create the output directory";
    fs::remove(path);
  }
  fs::remove(bad_card);
  const auto missing = run("run /nonexistent/scene.toml --out " + fresh_dir("x").string());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/scene.toml"), std::string::npos);
}

// A numerically failing run leaves only a summary marked failed (exit code 1).
TEST(Cli, FailedRunLeavesOnlyAFailedSummary) {
  const std::string mat = src("materials/aa3003o_c3c4.toml");
  const std::string path = write_temp("failing.toml", "[scene]\nkind = \"tensile\"\nmaterial = \"" + mat +
                                                          "\"\nstrain_path = [0.3]\nincrements = 1\n[solver]\nmax_newton_iterations = 2\nmax_cutbacks = 0\n");
  const auto out = fresh_dir("failing");
  const auto r = run("run " + path + " --out " + out.string());
  EXPECT_EQ(r.code, 1);
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "curve.csv"));
  std::ifstream f(out / "summary.json");
  const auto s = nlohmann::json::parse(f);
  EXPECT_EQ(s["status"], "failed");
  EXPECT_NE(s["message"].get<std::string>().find("control strain"), std::string::npos);
  fs::remove_all(out);
  fs::remove(path);
}

// spifit fit: fit.json with the keys of the issue, the fitted card, exports; errors exit 2. The
// N-conflict fit is not usable (r45 is 22 sigma off): exit 1, its card and decks named so.
TEST(Cli, FitWritesFitJsonCardAndExports) {
  const auto out = fresh_dir("fit");
  const auto r = run("fit " + src("experiments/aa3003o/fit_n_conflict.toml") + " --out " + out.string());
  ASSERT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("WARNING: Conflict: experiments r45 and shear_00 disagree on hill.N"), std::string::npos) << r.out;
  std::ifstream f(out / "fit.json");
  const auto j = nlohmann::json::parse(f);
  for (const char* k : {"parameters", "cost_initial", "cost_final", "forward_runs", "wall_seconds", "termination", "algorithm", "correlation"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  const auto& n = j["parameters"]["hill.N"];
  for (const char* k : {"value", "initial", "std_error", "ci95", "lower", "upper"}) EXPECT_TRUE(n.contains(k)) << k;
  EXPECT_LT(n["ci95"][0].get<double>(), n["value"].get<double>());
  EXPECT_TRUE(fs::exists(out / "card_NOT_USABLE.toml"));
  EXPECT_TRUE(fs::exists(out / "exports" / "card_abaqus_NOT_USABLE.inp"));
  EXPECT_TRUE(fs::exists(out / "exports" / "card_calculix_NOT_USABLE.inp"));
  EXPECT_TRUE(fs::exists(out / "exports" / "card_lsdyna_NOT_USABLE.k"));
  EXPECT_TRUE(fs::exists(out / "report.md"));
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_EQ(run("report " + out.string() + " --no-plots").code, 0);
  EXPECT_EQ(run("report " + fresh_dir("nofit").string()).code, 2);
  // A fit.json of an older spifit, without the evaluations and information shares of the
  // experiments, still makes a report.
  for (const char* k : {"evaluations", "information_share"}) EXPECT_TRUE(j["experiments"][0].contains(k)) << k;
  auto older = j;
  for (auto& e : older["experiments"]) {
    e.erase("evaluations");
    e.erase("information_share");
  }
  std::ofstream(out / "fit.json") << older.dump(2);
  const auto old_report = run("report " + out.string() + " --no-plots");
  EXPECT_EQ(old_report.code, 0) << old_report.err;
  EXPECT_NE(spifit::test::slurp(out / "report.md").find("fit.json does not count the forward runs per experiment"), std::string::npos);
  // The fitted card loads and shows.
  EXPECT_EQ(run("material show " + (out / "card_NOT_USABLE.toml").string()).code, 0);
  fs::remove_all(out);

  const std::string bad = write_temp("badfit.toml", "[fit]\ncard = \"" + src("materials/aa3003o_c2.toml") +
                                                        "\"\n[parameters.\"swift.KK\"]\nlower = 1.0\nupper = 2.0\n");
  const auto b = run("fit " + bad + " --out " + fresh_dir("badfit").string());
  EXPECT_EQ(b.code, 2);
  EXPECT_EQ(count_lines(b.err), 1);
  EXPECT_NE(b.err.find("parameters.swift.KK"), std::string::npos) << b.err;
  fs::remove(bad);
}

TEST(Cli, MaterialExport) {
  const auto r = run("material export " + src("materials/aa3003o_c8_ziegler_shell.toml") + " --format abaqus");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("*PLASTIC, HARDENING=COMBINED"), std::string::npos);
  const auto b = run("material export " + src("materials/aa3003o_c8_ziegler_shell.toml") + " --format nastran");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("--format = nastran"), std::string::npos) << b.err;
}

// spifit synth: the file says it is synthetic and how it was made; the same seed gives the
// same numbers, another seed different ones; an existing file is kept without --force.
TEST(Cli, SynthIsLabelledAndReproducible) {
  const fs::path a = spifit::test::temp_path("synth_a.csv");
  const fs::path b = spifit::test::temp_path("synth_b.csv");
  const fs::path c = spifit::test::temp_path("synth_c.csv");
  const std::string scene = src("experiments/aa3003o/scenes/tensile_00.toml");
  ASSERT_EQ(run("synth " + scene + " --noise 0.5 --seed 7 --every 4 --out " + a.string()).code, 0);
  ASSERT_EQ(run("synth " + scene + " --noise 0.5 --seed 7 --every 4 --out " + b.string()).code, 0);
  ASSERT_EQ(run("synth " + scene + " --noise 0.5 --seed 8 --every 4 --out " + c.string()).code, 0);
  const std::string ta = spifit::test::slurp(a), tb = spifit::test::slurp(b), tc = spifit::test::slurp(c);
  EXPECT_EQ(ta.rfind("# SYNTHETIC DATA", 0), 0u);
  EXPECT_NE(ta.find("seed 7"), std::string::npos);
  EXPECT_NE(ta.find("# command: spifit synth"), std::string::npos);
  EXPECT_NE(ta.find("strain [-],stress [MPa]"), std::string::npos);
  auto body = [](const std::string& t) { return t.substr(t.find("strain [-]")); };
  EXPECT_EQ(body(ta), body(tb));
  EXPECT_NE(body(ta), body(tc));
  EXPECT_EQ(run("synth " + scene + " --out " + a.string()).code, 2);
  EXPECT_EQ(spifit::test::slurp(a), ta);
  for (const auto& p : {a, b, c}) fs::remove(p);
}
