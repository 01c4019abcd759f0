// The shared FE runs of a fit (SceneRuns): a failed run retried with smaller increments that then
// succeeds, and the stopping tolerances a fit with FE experiments gets by default.
#include "forward/io/input_error.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/runs/scene_runs.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

// A real scene whose runs fail (status failed, after running) while its travel per increment is
// above `limit`: a scene that needs smaller increments than its file gives.
class NeedsSmallIncrements final : public scene::Scene {
 public:
  NeedsSmallIncrements(std::unique_ptr<scene::Scene> inner, double limit) : inner_(std::move(inner)), limit_(limit) {}
  const std::string& kind() const override { return inner_->kind(); }
  const std::string& name() const override { return inner_->name(); }
  const std::string& file() const override { return inner_->file(); }
  std::vector<std::string> input_files() const override { return inner_->input_files(); }
  std::unique_ptr<scene::Scene> clone() const override { return std::make_unique<NeedsSmallIncrements>(inner_->clone(), limit_); }
  std::unique_ptr<scene::SceneResult> run(const scene::RunFiles& files, const scene::RunControl& control) const override {
    auto r = inner_->run(files, control);
    if (inner_->input(kIncrement) > limit_) {
      r->status = scene::RunStatus::failed;
      r->message = "no convergence at the minimum increment (test double)";
    }
    return r;
  }
  const material::MaterialCard* card() const override { return inner_->card(); }
  material::MaterialCard* card() override { return inner_->card(); }

  static constexpr const char* kIncrement = "solver.travel_per_increment";

 protected:
  double own_input(const std::string& n) const override { return inner_->input(n); }
  std::string set_own_input(const std::string& n, double v) override { return inner_->set_input(n, v); }
  bool has_own_input(const std::string& n) const override {
    try {
      (void)inner_->input(n);
      return true;
    } catch (const std::invalid_argument&) {
      return false;
    }
  }

 private:
  std::unique_ptr<scene::Scene> inner_;
  double limit_;
};

// The tiny line runs at 0.5 mm per increment (its default); the double needs 0.3 mm or less, so
// the first run fails, the retry at 0.25 mm succeeds, and the failure is listed as recovered.
TEST(SceneRuns, ARetryWithHalfTheIncrementRecoversAndIsListed) {
  const fs::path file = test::write_tiny_line(test::temp_path("line.toml"));
  const auto tiny = scene::read_scene(file.string());
  const double travel = tiny->input(NeedsSmallIncrements::kIncrement);
  ASSERT_GT(travel, 0.3);
  ASSERT_LE(0.5 * travel, 0.3);
  const NeedsSmallIncrements sc(tiny->clone(), 0.3);
  inverse::SceneRuns runs(sc.card()->params);
  const inverse::ParameterPoint p{sc.card()->params, {{"contact.friction", 0.05}}};
  const auto r = runs.result(sc, p);
  ASSERT_NE(r, nullptr);
  EXPECT_TRUE(r->ok());
  EXPECT_EQ(runs.runs(), 2);
  const auto failures = runs.failures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_TRUE(failures.front().recovered);
  EXPECT_EQ(failures.front().point, "contact.friction=0.05");
  const std::string expected = "retried with solver.travel_per_increment = " + io::format_number(0.5 * travel) +
                               " after: no convergence at the minimum increment (test double)";
  EXPECT_EQ(failures.front().message, expected);
  // The same point again is the kept result: no third run.
  EXPECT_EQ(runs.result(sc, p), r);
  EXPECT_EQ(runs.runs(), 2);
}

std::string fit_text(const fs::path& scene, const fs::path& data, const std::string& fit_extra) {
  return "[fit]\nname = \"tol\"\ncard = \"" + std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml\"\nnormalise_hill = false\n" +
         fit_extra + "[parameters.\"contact.friction\"]\ninitial = 0.1\nlower = 0.0\nupper = 0.3\n[[experiment]]\nname = \"fx\"\nscene = \"" +
         scene.string() + "\"\ndata = \"" + data.string() + "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n";
}

// A fit with FE experiments stops at function, parameter and gradient tolerances of 1e-9, 1e-8
// and 1e-10 (an FE cost is not smooth below about 1e-11 of itself; docs/design/identification.md,
// "Stopping"), or at a relative offset of 1e-3; a tolerance the file states wins.
TEST(FitFile, FeFitsStopAtTheFeTolerancesUnlessTheFileSetsThem) {
  const fs::path scene = test::write_tiny_line(test::temp_path("line.toml"));
  const fs::path data = test::temp_path("fx.csv");
  std::ofstream(data) << "travel [mm],fx [N]\n1.0,-5.0\n2.0,-6.0\n4.0,-7.0\n";
  const fs::path f = test::temp_path("fit.toml");
  std::ofstream(f) << fit_text(scene, data, "");
  const auto fe = inverse::read_fit_file(f.string());
  EXPECT_EQ(fe.settings.function_tolerance, 1e-9);
  EXPECT_EQ(fe.settings.parameter_tolerance, 1e-8);
  EXPECT_EQ(fe.settings.gradient_tolerance, 1e-10);
  EXPECT_EQ(fe.settings.offset_tolerance, 1e-3);
  std::ofstream(f) << fit_text(scene, data, "function_tolerance = 1e-12\noffset_tolerance = 0.0\n");
  const auto stated = inverse::read_fit_file(f.string());
  EXPECT_EQ(stated.settings.function_tolerance, 1e-12);
  EXPECT_EQ(stated.settings.parameter_tolerance, 1e-8);
  EXPECT_EQ(stated.settings.offset_tolerance, 0.0);
  EXPECT_EQ(inverse::FitSettings{}.function_tolerance, 1e-14);  // material-point fits keep theirs
  EXPECT_EQ(inverse::FitSettings{}.offset_tolerance, 0.0);
}

}  // namespace
