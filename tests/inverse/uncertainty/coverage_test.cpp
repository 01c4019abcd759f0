// Do the 95 % intervals mean what they say? 100 fits of the classic problem (tensile 0/45/90
// + shear, card C.2, Hill + Swift free) to data with seeded Gaussian noise: each interval
// must contain the truth between 88 and 99 times (binomial(100, 0.95): 95 +- 2.2 sigma).
#include "inverse/fit/ceres_fit.hpp"
#include "inverse/experiments/synthetic.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

scene::MaterialPointScene quick(const std::string& name, double angle, bool shear) {
  scene::MaterialPointScene sc;
  sc.name = name;
  sc.card = material::load_material_card(src("materials/aa3003o_c2.toml"));
  sc.setup.kind = shear ? scene::MaterialPointKind::shear : scene::MaterialPointKind::tensile;
  sc.setup.angle_deg = angle;
  sc.setup.strain_path = {shear ? 0.4 : 0.3};
  sc.setup.increments = 60;
  return sc;
}

}  // namespace

TEST(Coverage, NinetyFivePercentIntervals) {
  const auto truth = material::load_material_card(src("materials/aa3003o_c2.toml"));
  const std::vector<std::string> names{"hill.F", "hill.G", "hill.N", "swift.K", "swift.eps0", "swift.n"};
  std::vector<inverse::ParameterSpec> specs;
  for (const auto& n : names) {
    const double v = inverse::parameter_value(truth, n);
    specs.push_back({n, v, n == "swift.eps0" ? v / 100 : 0.2 * v, 5.0 * v, false, n == "swift.eps0"});
  }
  const std::vector<scene::MaterialPointScene> scenes{quick("t00", 0, false), quick("t45", 45, false), quick("t90", 90, false),
                                                      quick("s00", 0, true)};
  // Noise-free curves once; each realisation adds fresh noise.
  std::vector<scene::MaterialPointResult<double>> clean;
  for (const auto& sc : scenes) clean.push_back(scene::run_material_point(truth.params, sc.setup));
  const double noise = 0.5;
  const int fits = 100;
  std::vector<int> covered(names.size(), 0);
  inverse::GaussianNoise rng(20261121);
  for (int f = 0; f < fits; ++f) {
    inverse::FitProblem fp;
    fp.name = "coverage";
    fp.parameters = std::make_unique<inverse::ParameterSet>(truth, specs, true);
    for (std::size_t e = 0; e < scenes.size(); ++e) {
      inverse::CurveExperimentSpec c;
      c.name = scenes[e].name;
      c.scene = scenes[e];
      c.x = "strain";
      c.y = "stress";
      c.noise = noise;
      for (std::size_t i = 2; i < clean[e].curve.size(); i += 2) {
        c.xs.push_back(clean[e].curve[i].control_strain);
        c.ys.push_back(clean[e].curve[i].stress + noise * rng.next());
      }
      fp.experiments.push_back(inverse::make_curve_experiment(std::move(c)));
    }
    const auto r = inverse::fit_with_ceres(fp);
    ASSERT_TRUE(r.usable) << r.termination;
    for (std::size_t k = 0; k < names.size(); ++k) {
      const double t = inverse::parameter_value(truth, names[k]);
      if (r.uncertainty.ci95_lower[k] <= t && t <= r.uncertainty.ci95_upper[k]) ++covered[k];
    }
  }
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::cout << "coverage " << names[k] << ": " << covered[k] << " / " << fits << "\n";
    RecordProperty("coverage_" + names[k], covered[k]);
    EXPECT_GE(covered[k], 88) << names[k];
    EXPECT_LE(covered[k], 99) << names[k];
  }
}
