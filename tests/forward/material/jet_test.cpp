// With T = ceres::Jet the material-point curve carries exact parameter derivatives
// (needed by the Ceres fits): compare them with central differences of double runs.
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"

#include <ceres/jet.h>
#include <gtest/gtest.h>

using namespace spifit;
using Jet = ceres::Jet<double, 4>;

namespace {

material::MaterialParams<Jet> seeded(const material::MaterialParams<double>& p) {
  auto j = p.cast<Jet>();
  j.hardening[material::SwiftHardening::K].v[0] = 1.0;     // d/dK
  j.hardening[material::SwiftHardening::n].v[1] = 1.0;     // d/dn
  j.N.v[2] = 1.0;     // d/dN (Hill shear coefficient)
  j.L = j.N;
  j.M = j.N;
  if (material::is_kinematic<material::ArmstrongFrederick>(p.kinematic)) j.kinematic[material::ArmstrongFrederick::CX].v[3] = 1.0;
  if (material::is_kinematic<material::Ziegler>(p.kinematic)) j.kinematic[material::Ziegler::CA].v[3] = 1.0;
  return j;
}

material::MaterialParams<double> perturbed(material::MaterialParams<double> p, int k, double h) {
  switch (k) {
    case 0: p.hardening[material::SwiftHardening::K] += h; break;
    case 1: p.hardening[material::SwiftHardening::n] += h; break;
    case 2: p.N += h; p.L = p.N; p.M = p.N; break;
    case 3:
      if (material::is_kinematic<material::ArmstrongFrederick>(p.kinematic)) p.kinematic[material::ArmstrongFrederick::CX] += h;
      else p.kinematic[material::Ziegler::CA] += h;
      break;
  }
  return p;
}

double step_for(const material::MaterialParams<double>& p, int k) {
  switch (k) {
    case 0: return 1e-4 * p.hardening[material::SwiftHardening::K];
    case 1: return 1e-5;
    case 2: return 1e-5;
    default: return 1e-4 * (material::is_kinematic<material::Ziegler>(p.kinematic) ? p.kinematic[material::Ziegler::CA] : std::max(p.kinematic[material::ArmstrongFrederick::CX], 1.0));
  }
}

}  // namespace

class JetDerivatives : public ::testing::TestWithParam<std::string> {};

TEST_P(JetDerivatives, TensileCurveMatchesCentralDifferences) {
  const auto card = test::card(GetParam());
  auto setup = test::tensile(45.0, {0.2, 0.1}, 60);
  setup.driver.kinematic_substep = 0.0;  // fixed steps: the discrete curve is smooth in the parameters
  const auto rj = scene::run_material_point(seeded(card.params), setup);
  ASSERT_TRUE(rj.ok) << rj.message;
  const int nk = !card.params.kinematic.active() ? 3 : 4;
  for (int k = 0; k < nk; ++k) {
    SCOPED_TRACE(k);
    const double h = step_for(card.params, k);
    const auto rp = scene::run_material_point(perturbed(card.params, k, h), setup);
    const auto rm = scene::run_material_point(perturbed(card.params, k, -h), setup);
    ASSERT_TRUE(rp.ok && rm.ok);
    for (std::size_t i : {std::size_t(20), std::size_t(40), rj.curve.size() - 1}) {
      const double fd = (rp.curve[i].stress - rm.curve[i].stress) / (2 * h);
      const double ad = rj.curve[i].stress.v[k];
      EXPECT_NEAR(ad, fd, 1e-5 * std::max(1.0, std::abs(fd))) << "point " << i;
    }
    const double fd_r = (*rp.r_value - *rm.r_value) / (2 * h);
    EXPECT_NEAR(rj.r_value->v[k], fd_r, 1e-5 * std::max(1.0, std::abs(fd_r)));
    const double fd_y = (*rp.offset_yield_stress - *rm.offset_yield_stress) / (2 * h);
    EXPECT_NEAR(rj.offset_yield_stress->v[k], fd_y, 2e-7 * std::max(1.0, std::abs(fd_y)));  // Cauchy incl. dJ/dx
  }
}

// The DDM's single Jet evaluation (ReturnMappingOptions::single_jet_evaluation) against the
// Newton step and second evaluation: the same derivatives of the whole state, to round-off.
TEST_P(JetDerivatives, SingleEvaluationGivesTheSameDerivatives) {
  const auto card = test::card(GetParam());
  const material::ReturnMapping<double, 3> law(card.params);
  material::MaterialState<double, 3> s0, s1;
  ASSERT_TRUE(law.integrate(s0, Eigen::Vector3d(0.004, -0.001, 0.002), s1, nullptr).ok());  // plastic: a back-stress to start from
  material::ReturnMappingOptions single;
  single.single_jet_evaluation = true;
  const material::ReturnMapping<Jet, 3> two(seeded(card.params)), one(seeded(card.params), single);
  material::MaterialState<Jet, 3> j0, a, b;
  for (int i = 0; i < 3; ++i) {
    j0.stress(i) = Jet(s1.stress(i));
    j0.plastic_strain(i) = Jet(s1.plastic_strain(i));
    j0.back_stress(i) = Jet(s1.back_stress(i));
  }
  j0.back_stress_zz = Jet(s1.back_stress_zz);
  j0.eqps = Jet(s1.eqps);
  const Eigen::Matrix<Jet, 3, 1> d_eps(Jet(-0.002), Jet(0.003), Jet(0.001));
  const auto ra = two.integrate(j0, d_eps, a, nullptr), rb = one.integrate(j0, d_eps, b, nullptr);
  ASSERT_TRUE(ra.ok() && rb.ok() && ra.plastic);
  auto close = [](const Jet& x, const Jet& y) {
    const double scale = std::max(1.0, x.v.cwiseAbs().maxCoeff());
    EXPECT_LT((x.v - y.v).cwiseAbs().maxCoeff(), 1e-10 * scale) << x.v.transpose() << " | " << y.v.transpose();
  };
  for (int i = 0; i < 3; ++i) {
    close(a.stress(i), b.stress(i));
    close(a.back_stress(i), b.back_stress(i));
    close(a.plastic_strain(i), b.plastic_strain(i));
  }
  close(a.eqps, b.eqps);
  close(a.back_stress_zz, b.back_stress_zz);
  EXPECT_GT(a.eqps.v.cwiseAbs().maxCoeff(), 1e-6);  // the derivatives are not zero
}

INSTANTIATE_TEST_SUITE_P(Cards, JetDerivatives,
                         ::testing::Values("aa3003o_c3c4", "aa3003o_c7_af_shell", "aa3003o_c8_ziegler_shell"));
