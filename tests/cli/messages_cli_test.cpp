// Messages a user test found misleading: each names what is wrong (file, key, value) and exits
// with 2, the code of a usage or input error (docs/reference/cli.md).
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using spifit::test::run_spifit;

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// The §7.1 indent scene with `from` replaced by `to` (the card by its absolute path).
fs::path indent_with(const std::string& name, const std::string& from, const std::string& to) {
  return spifit::test::bundled_scene_with("indent.toml", name, from, to);
}

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// No byte a terminal must not get raw: control characters and bytes of no UTF-8 character.
bool printable(const std::string& s) {
  for (unsigned char c : s)
    if ((c < 0x20 && c != '\n') || c == 0x7f || c >= 0x80) return false;
  return true;
}

TEST(MessagesCli, AKindTypoIsAnUnknownKindNotAnUnknownTable) {
  const fs::path scene = indent_with("indnet.toml", "kind = \"indent\"", "kind = \"indnet\"");
  for (const std::string cmd : {"run", "synth"}) {
    const auto r = run_spifit(cmd + " " + scene.string() + " --out " + spifit::test::temp_path("indnet_out").string());
    EXPECT_EQ(r.code, 2) << cmd;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(scene.string() + ": scene.kind = \"indnet\": unknown scene kind (known: tensile,"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("indent, indent_line, line, cone)"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("contact"), std::string::npos) << r.err;
  }
  fs::remove(scene);
}

// A kind of another family (tensile in a forming file): the reader of that kind refused [contact]
// as an unknown key, as if the table were the typo.
TEST(MessagesCli, AKindOfAnotherFamilyNamesTheKindsOfTheTable) {
  const fs::path scene = indent_with("tensile_contact.toml", "kind = \"indent\"", "kind = \"tensile\"");
  for (const std::string cmd : {"run", "synth"}) {
    const auto r = run_spifit(cmd + " " + scene.string() + " --out " + spifit::test::temp_path("tc_out").string());
    EXPECT_EQ(r.code, 2) << cmd;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(": [contact] is not a table of scene kind tensile (its tables: scene, solver); it is one of the kinds indent, "
                         "indent_line, line, cone: is scene.kind = \"tensile\" right?"),
              std::string::npos)
        << r.err;
  }
  fs::remove(scene);
}

// synth on an FE scene it cannot write a curve of says why (no tool), not only the kind.
TEST(MessagesCli, SynthSaysWhatTheSceneLacks) {
  const auto r = run_spifit("synth " + src("experiments/benchmarks/scordelis_lo.toml") + " --out " + spifit::test::temp_path("sl.csv").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scordelis_lo.toml: scene.kind = shell_benchmark: a scene of this kind has no tool: synth writes"), std::string::npos) << r.err;
}

TEST(MessagesCli, AnUnknownSubcommandIsNamed) {
  auto r = run_spifit("foo");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "spifit: unknown subcommand foo (subcommands: lankford, material, run, check-sensitivities, fit, sweep, report, status, scan, inputs, synth) (see --help)\n");
  r = run_spifit("-q --threads 2 foo --out x");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown subcommand foo"), std::string::npos) << r.err;
  r = run_spifit("material foo");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown material subcommand foo (subcommands: show, export)"), std::string::npos) << r.err;
  r = run_spifit("");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("A subcommand is required"), std::string::npos) << r.err;
}

TEST(MessagesCli, ThreadsIsAWholeNumberUpTo512) {
  for (const std::string bad : {"-1", "abc", "1000", "513", "1.5", "99999999999999999999"}) {
    const auto r = run_spifit("--threads " + bad + " inputs");
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--threads: must be a whole number from 0 (OpenMP's default) to 512, got '" + bad + "'"), std::string::npos) << r.err;
    EXPECT_LT(r.err.size(), 160u) << r.err;
  }
  for (const std::string good : {"0", "1", "512"}) EXPECT_EQ(run_spifit("-q --threads " + good + " inputs").code, 0) << good;
}

// t/l > 3 was found by the shell model once the run had started: exit 1, no file, no key.
TEST(MessagesCli, ASheetTooThickForItsElementsNamesTheKeys) {
  const fs::path scene = indent_with("thick.toml", "thickness = 0.3", "thickness = 3.5");
  const fs::path out = spifit::test::temp_path("thick_out");
  fs::remove_all(out);
  const auto r = run_spifit("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(scene.string() + ": sheet.thickness = 3.5: over the shortest element edge, 1 mm (sheet.length = 10 / sheet.elements = 10), "
                                        "t/l = 3.5 exceeds the shell's limit 3"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out)) << "input errors come before the output directory";
  fs::remove(scene);
}

// A binary file given as a cloud: its bytes quoted, the message short.
TEST(MessagesCli, ABinaryCloudIsQuotedAndCut) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  for (int i = 0; i < 3000; ++i) bytes += static_cast<char>((i * 37 + 11) % 256);
  const fs::path cloud = spifit::test::write_temp_file("cloud.png", bytes);
  const fs::path out = spifit::test::temp_path("png_out");
  fs::remove_all(out);
  const auto r = run_spifit("scan " + cloud.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_TRUE(printable(r.err)) << r.err;
  EXPECT_LT(r.err.size(), 400u) << r.err;
  EXPECT_NE(r.err.find(cloud.string() + ": line 1 = \\x89PNG: not text (byte \\x89 at position 1)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(cloud);
}

// --algorithm with an NLopt algorithm over a fit whose offset_tolerance stops Ceres only: a note
// says the stop is left out, rather than nothing.
TEST(MessagesCli, AnNloptAlgorithmOverAnOffsetStopSaysItIsLeftOut) {
  std::string text = spifit::test::slurp(src("experiments/aa3003o/fit_classic.toml"));
  const auto replace_all = [&](const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  };
  replace_all("\"../../materials/", "\"" + src("materials/"));
  replace_all("\"scenes/", "\"" + src("experiments/aa3003o/scenes/"));
  replace_all("\"data/", "\"" + src("experiments/aa3003o/data/"));
  replace_all("algorithm = \"levenberg_marquardt\"", "algorithm = \"levenberg_marquardt\"\noffset_tolerance = 1e-3\nmax_iterations = 2");
  const fs::path fit = spifit::test::write_temp_file("offset_stop_fit.toml", text);
  const auto r = run_spifit("fit " + fit.string() + " --algorithm bobyqa --out " + spifit::test::fresh_temp_path("offset_stop_out").string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("note: bobyqa stops on its own tolerances; offset_tolerance = 0.001 stops Ceres's algorithms only and is left out"),
            std::string::npos)
      << r.err;
  const auto ceres = run_spifit("fit " + fit.string() + " --out " + spifit::test::fresh_temp_path("offset_stop_ceres").string());
  EXPECT_EQ(ceres.code, 0) << ceres.err;
  EXPECT_EQ(ceres.err.find("note:"), std::string::npos) << ceres.err;
  fs::remove(fit);
}

}  // namespace
