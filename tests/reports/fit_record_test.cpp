// FitRecord, the fit.json schema shared by `spifit fit` (writer) and the reports (reader): a
// bundled fit's fit.json reads back and writes out byte for byte, optional and null values
// survive, and a broken fit.json names the file and the key path.
#include "tests/support/temp_files.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "inverse/fit/run_fit.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_output.hpp"
#include "inverse/fit/fit_record.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace spifit;
using inverse::FitRecord;

namespace {

using spifit::test::slurp;

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::string file_text(const FitRecord& r) { return inverse::to_json(r).dump(2) + "\n"; }

// fit_n_conflict: per-experiment fits and conflicts, curves and scalars, a fixed expression, and
// the reasons it is not usable.
class FitRecordTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("spifit_fit_record_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    const auto problem = inverse::read_fit_file(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/fit_n_conflict.toml");
    const auto result = inverse::run_fit(problem, {"", 2});
    ASSERT_FALSE(result.usable) << result.termination;
    inverse::write_fit_outputs(problem, result, io::OutputDirectory::prepare(dir_.string(), false));
    text_ = slurp(dir_ / "fit.json");
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static fs::path dir_;
  static std::string text_;
};
fs::path FitRecordTest::dir_;
std::string FitRecordTest::text_;

TEST_F(FitRecordTest, BundledFitJsonRoundTripsByteForByte) {
  const std::string file = (dir_ / "fit.json").string();
  const FitRecord r = inverse::fit_record_from_json(json::parse(text_), file);
  EXPECT_EQ(file_text(r), text_);
  EXPECT_EQ(file_text(inverse::read_fit_record(file)), text_);

  EXPECT_EQ(r.name, "fit_n_conflict");
  ASSERT_TRUE(r.usable.has_value());
  EXPECT_FALSE(*r.usable);
  ASSERT_EQ(r.not_usable.size(), 1u);
  EXPECT_EQ(r.not_usable[0].rfind("experiment r45: ", 0), 0u) << r.not_usable[0];
  ASSERT_FALSE(r.parameters.empty());
  ASSERT_EQ(r.parameters.size(), r.correlation.names.size());
  for (std::size_t k = 0; k < r.parameters.size(); ++k) EXPECT_EQ(r.parameters[k].name, r.correlation.names[k]) << "fit order";
  EXPECT_FALSE(r.per_experiment.empty());
  EXPECT_FALSE(r.conflicts.empty());
  ASSERT_FALSE(r.experiments.empty());
  for (const auto& e : r.experiments) {
    EXPECT_TRUE(e.noise_given.has_value()) << e.name;
    EXPECT_EQ(e.data_file, "experiments/" + e.name + ".csv");
  }
  EXPECT_EQ(r.multistart.starts, 1) << "no multistart block in a single-start fit";
  EXPECT_EQ(json::parse(text_).count("multistart"), 0u);
}

TEST(FitRecord, MultiStartOptionalAndNullValuesRoundTrip) {
  FitRecord r;
  r.name = "hand made";
  r.algorithm = "bobyqa";
  r.seed = 7u;
  r.iterations = 3;
  r.cost_history = {2.0, FitRecord::kNaN, 0.5};
  FitRecord::Parameter p;
  p.name = "swift.K";
  p.value = 170.0;
  p.initial = 150.0;
  p.lower = 50.0;
  p.upper = 400.0;
  p.has_uncertainty = true;
  p.std_error = FitRecord::kNaN;  // not identifiable: null in fit.json
  p.identifiable = false;
  r.parameters = {p};
  r.correlation.names = {"swift.K"};
  r.correlation.matrix = {{1.0}};
  r.fixed = {{"hill.H", FitRecord::kNaN, "2 - hill.G"}, {"swift.n", 0.25, ""}};
  r.multistart.starts = 3;
  r.multistart.best_start = 1;
  r.multistart.starts_at_best_cost = 2;
  r.multistart.spread_at_best_cost = {{"swift.K", 169.5, 170.0}};
  r.multistart.solutions = {{true, 1.5, {160.0}, {170.0}}, {false, FitRecord::kNaN, {300.0}, {}}};
  FitRecord::Experiment e;
  e.name = "tensile_00";
  e.kind = "curve";
  e.points = 40;
  r.experiments = {e};

  const std::string text = file_text(r);
  const json j = json::parse(text);
  EXPECT_TRUE(j["parameters"]["swift.K"]["std_error"].is_null());
  EXPECT_TRUE(j["cost_history"][1].is_null());
  EXPECT_EQ(j["fixed"]["hill.H"], "2 - hill.G");
  EXPECT_EQ(j["seed"], 7u);
  EXPECT_EQ(j.count("usable"), 0u) << "absent optionals are not written";
  EXPECT_EQ(j["experiments"][0].count("noise_given"), 0u);

  const FitRecord back = inverse::fit_record_from_json(j, "hand.json");
  EXPECT_EQ(file_text(back), text);
  EXPECT_FALSE(back.usable.has_value());
  EXPECT_FALSE(back.forward_runs.has_value());
  EXPECT_TRUE(std::isnan(back.cost_history[1]));
  ASSERT_EQ(back.multistart.solutions.size(), 2u);
  EXPECT_TRUE(std::isnan(back.multistart.solutions[1].cost));
  EXPECT_FALSE(back.parameters[0].identifiable);
  ASSERT_EQ(back.fixed.size(), 2u);
  EXPECT_EQ(back.fixed[0].expression, "2 - hill.G");
  EXPECT_EQ(back.fixed[1].value, 0.25);
}

// The forward runs (per experiment, per scene file) and the information shares: written when
// known, read back, absent from an older fit.json.
TEST(FitRecord, RunsAndInformationSharesRoundTripAndAreOptional) {
  FitRecord r;
  r.name = "fe";
  for (const char* n : {"swift.K", "contact.friction"}) {
    FitRecord::Parameter p;
    p.name = n;
    r.parameters.push_back(p);
    r.correlation.names.push_back(n);
  }
  FitRecord::Experiment fe, old;
  fe.name = "press";
  fe.kind = "force_curve";
  fe.evaluations = 33;
  fe.scene_runs = 10;
  fe.run_seconds = 14.5;
  fe.information_share = {0.25, FitRecord::kNaN};
  old.name = "tensile_00";
  old.kind = "curve";
  r.experiments = {fe, old};
  r.scene_runs = 10;
  r.runs_by_scene = {{"line.toml", 12, 1, 2, 20.0, 1.75}};

  const std::string text = file_text(r);
  const json j = json::parse(text);
  const auto& e = j["experiments"][0];
  EXPECT_EQ(e["evaluations"], 33);
  EXPECT_EQ(e["scene_runs"], 10);
  EXPECT_EQ(e["run_seconds"], 14.5);
  EXPECT_EQ(e["information_share"]["swift.K"], 0.25);
  EXPECT_TRUE(e["information_share"]["contact.friction"].is_null());
  for (const char* k : {"evaluations", "scene_runs", "run_seconds", "information_share"}) EXPECT_EQ(j["experiments"][1].count(k), 0u) << k;
  EXPECT_EQ(j["runs_by_scene"], json::parse(R"([{"scene": "line.toml", "runs": 12, "failures": 1, "retried": 2, "seconds": 20.0, "median_seconds": 1.75}])"));

  const FitRecord back = inverse::fit_record_from_json(j, "fe.json");
  EXPECT_EQ(file_text(back), text);
  ASSERT_EQ(back.experiments[0].information_share.size(), 2u);
  EXPECT_EQ(back.experiments[0].information_share[0], 0.25);
  EXPECT_TRUE(std::isnan(back.experiments[0].information_share[1]));
  EXPECT_EQ(*back.experiments[0].evaluations, 33);
  EXPECT_FALSE(back.experiments[1].evaluations.has_value());
  EXPECT_FALSE(back.experiments[1].scene_runs.has_value());
  EXPECT_TRUE(back.experiments[1].information_share.empty());
  ASSERT_EQ(back.runs_by_scene.size(), 1u);
  EXPECT_EQ(back.runs_by_scene[0].retried, 2);
  EXPECT_EQ(back.runs_by_scene[0].median_seconds, 1.75);

  // Without FE scenes there are no scene runs to list.
  r.scene_runs.reset();
  EXPECT_EQ(inverse::to_json(r).count("runs_by_scene"), 0u);
}

void expect_error(const json& j, const std::string& key, const std::string& message) {
  try {
    inverse::fit_record_from_json(j, "DIR/fit.json");
    ADD_FAILURE() << "no error for " << key;
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), "DIR/fit.json");
    EXPECT_EQ(e.key(), key);
    EXPECT_NE(e.message().find(message), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("DIR/fit.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST_F(FitRecordTest, BrokenFitJsonNamesTheFileAndTheKey) {
  const json good = json::parse(text_);
  json j = good;
  j["experiments"][1]["rms"] = "large";
  expect_error(j, "experiments[1].rms", "expected a number");
  j = good;
  const std::string first = good["parameters"].begin().key();
  j["parameters"][first]["upper"] = json::array();
  expect_error(j, "parameters." + first + ".upper", "expected a number");
  j = good;
  j["per_experiment"][0]["parameters"][first]["ci95"] = {1.0, "x"};
  expect_error(j, "per_experiment[0].parameters." + first + ".ci95", "expected an array of numbers");
  j = good;
  j["iterations"] = 2.5;
  expect_error(j, "iterations", "whole number");
  j = good;
  j["experiments"][0]["evaluations"] = 2.5;
  expect_error(j, "experiments[0].evaluations", "whole number");
  j = good;
  j["experiments"][0]["information_share"] = 0.5;
  expect_error(j, "experiments[0].information_share", "expected an object");
  j = good;
  j["runs_by_scene"] = "line.toml";
  expect_error(j, "runs_by_scene", "expected an array");
  j = good;
  j["runs_by_scene"] = json::array({{{"scene", "line.toml"}, {"runs", "many"}}});
  expect_error(j, "runs_by_scene[0].runs", "expected a number");
  j = good;
  j.erase("experiments");
  expect_error(j, "experiments", "not a fit.json");
  j = good;
  j["experiments"][0].erase("name");
  expect_error(j, "experiments[0].name", "missing experiment name");

  // Through the file: the path is the file named.
  const fs::path broken = dir_ / "broken.json";
  j = good;
  j["uncertainty"]["sse"] = "?";
  write(broken, j.dump(2));
  try {
    inverse::read_fit_record(broken);
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), broken.string());
    EXPECT_EQ(e.key(), "uncertainty.sse");
  }
  write(broken, "{\"parameters\": ");
  try {
    inverse::read_fit_record(broken);
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), broken.string());
    EXPECT_NE(e.message().find("not valid JSON"), std::string::npos);
  }
  EXPECT_THROW(inverse::read_fit_record(dir_ / "missing.json"), io::InputError);
}

}  // namespace
