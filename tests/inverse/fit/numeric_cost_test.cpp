// Black-box experiments (no Jets) are differentiated by central differences inside the bounds.
#include "forward/material/hardening/hardening_laws.hpp"
#include "inverse/fit/ceres_fit.hpp"
#include "inverse/experiments/synthetic.hpp"

#include <gtest/gtest.h>

#include <mutex>

using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// Hides the Jet path of a real experiment and records the K values it was run at.
class BlackBox final : public inverse::Experiment {
 public:
  explicit BlackBox(std::shared_ptr<inverse::Experiment> inner) : inner_(std::move(inner)) { name_ = inner_->name(); kind_ = inner_->kind(); }
  int num_residuals() const override { return inner_->num_residuals(); }
  bool residuals(const inverse::ParameterPoint& m, double* r) const override {
    {
      std::lock_guard<std::mutex> lock(mu_);
      max_k_ = std::max(max_k_, m.material.hardening[material::SwiftHardening::K]);
      ++calls_;
    }
    return inner_->residuals(m, r);
  }
  bool residuals(const material::MaterialParams<inverse::Jet>&, inverse::Jet*) const override { return false; }
  bool supports_jets() const override { return false; }
  inverse::ExperimentCurve compare(const inverse::ParameterPoint& m) const override { return inner_->compare(m); }
  inverse::ExperimentCurve axes() const override { return inner_->axes(); }
  double max_k() const { return max_k_; }

 private:
  std::shared_ptr<inverse::Experiment> inner_;
  mutable std::mutex mu_;
  mutable double max_k_ = 0.0;
  mutable long calls_ = 0;
};

inverse::FitProblem problem(double k_upper) {
  const auto truth = material::load_material_card(src("materials/aa3003o_c2.toml"));
  inverse::FitProblem fp;
  fp.name = "blackbox";
  fp.parameters = std::make_unique<inverse::ParameterSet>(
      truth, std::vector<inverse::ParameterSpec>{{"swift.K", 150.0, 50.0, k_upper, false, false}, {"swift.n", 0.3, 0.05, 0.6, false, false}}, true);
  auto sc = scene::read_material_point_scene(src("experiments/aa3003o/scenes/tensile_00.toml"));
  sc.card = truth;
  const auto clean = scene::run_material_point(truth.params, sc.setup);
  inverse::CurveExperimentSpec c;
  c.name = "t";
  c.scene = sc;
  c.x = "strain";
  c.y = "stress";
  for (std::size_t i = 4; i < clean.curve.size(); i += 4) {
    c.xs.push_back(clean.curve[i].control_strain);
    c.ys.push_back(clean.curve[i].stress);
  }
  fp.experiments.push_back(inverse::make_curve_experiment(std::move(c)));
  return fp;
}

}  // namespace

TEST(NumericDiff, BlackBoxFitMatchesJetFitInsideBounds) {
  auto jet = problem(180.0);  // the truth K = 180 sits on the upper bound: one-sided there
  const auto rj = inverse::fit_with_ceres(jet);
  auto bb = problem(180.0);
  auto wrapper = std::make_shared<BlackBox>(bb.experiments[0]);
  bb.experiments[0] = wrapper;
  const auto rb = inverse::fit_with_ceres(bb);
  ASSERT_TRUE(rj.usable && rb.usable) << rb.termination;
  EXPECT_NEAR(rb.values[0] / 180.0, 1.0, 1e-6);
  EXPECT_NEAR(rb.values[1] / 0.21, 1.0, 1e-6);
  EXPECT_NEAR(rb.values[0], rj.values[0], 1e-6 * rj.values[0]);
  EXPECT_LE(wrapper->max_k(), 180.0);  // no forward run outside the bounds
  // Standard errors from the finite-difference Jacobian agree with the exact ones.
  EXPECT_NEAR(rb.uncertainty.singular_values[0] / rj.uncertainty.singular_values[0], 1.0, 1e-4);
}
