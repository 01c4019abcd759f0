// Yld2000-2d (Barlat et al. 2003) and the return mapping for a non-quadratic yield function:
// von Mises to round-off at a = 2, the function against one written here from principal values,
// gradient and Hessian against finite differences (also where principal values coincide), closed
// forms of the isotropic Hershey-Hosford case, the return mapping and its tangent, material-point
// r-values against the flow direction, Jets, and cards refused with file, key and value.
#include "forward/io/input_error.hpp"
#include "forward/material/material_card.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/return_mapping.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"
#include "tests/support/temp_files.hpp"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

using namespace spifit;
using material::MaterialParams;
using material::Yld2000_2d;
using V3 = Eigen::Vector3d;

namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// An anisotropic set in the range published for aluminium sheets (AA2090-T3 of Barlat et al.
// 2003 has alphas from 0.5 to 1.4).
const std::array<double, 9> kAniso{0.89, 1.12, 0.97, 1.03, 1.01, 0.93, 1.05, 1.21, 8.0};

std::array<double, 9> isotropic(double a) { return {1, 1, 1, 1, 1, 1, 1, 1, a}; }

material::YieldValue<double> yld(const std::array<double, 9>& c, const V3& s, bool hess = true) {
  material::YieldValue<double> v;
  Yld2000_2d::evaluate(c.data(), s, v, hess);
  return v;
}

// Written here from the definition with principal values (Barlat et al. 2003, eqs. 17-19).
double yld_reference(const std::array<double, 9>& c, const V3& s) {
  const double a1 = c[0], a2 = c[1], a3 = c[2], a4 = c[3], a5 = c[4], a6 = c[5], a7 = c[6], a8 = c[7], a = c[8];
  const double x1 = (2 * a1 * s(0) - a1 * s(1)) / 3, y1 = (-a2 * s(0) + 2 * a2 * s(1)) / 3, z1 = a7 * s(2);
  const double x2 = ((-2 * a3 + 2 * a4 + 8 * a5 - 2 * a6) * s(0) + (a3 - 4 * a4 - 4 * a5 + 4 * a6) * s(1)) / 9;
  const double y2 = ((4 * a3 - 4 * a4 - 4 * a5 + a6) * s(0) + (-2 * a3 + 8 * a4 + 2 * a5 - 2 * a6) * s(1)) / 9;
  const double z2 = a8 * s(2);
  auto principal = [](double x, double y, double z, double& p1, double& p2) {
    const double r = std::sqrt((x - y) * (x - y) / 4 + z * z);
    p1 = (x + y) / 2 + r;
    p2 = (x + y) / 2 - r;
  };
  double p1, p2, q1, q2;
  principal(x1, y1, z1, p1, p2);
  principal(x2, y2, z2, q1, q2);
  const double phi = std::pow(std::abs(p1 - p2), a) + std::pow(std::abs(2 * q2 + q1), a) + std::pow(std::abs(2 * q1 + q2), a);
  return std::pow(phi / 2, 1 / a);
}

MaterialParams<double> yld_params(const std::array<double, 9>& c) {
  MaterialParams<double> m = test::card("aa3003o_c3c4").params;
  m.yield.law = material::yield_function_index<Yld2000_2d>();
  for (int i = 0; i < 9; ++i) m.yield[i] = c[static_cast<std::size_t>(i)];
  return m;
}

std::vector<V3> stresses() {
  std::vector<V3> out{{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, -1, 0}, {0, 0, 1}, {2, 1, 0}, {1, 1, 1e-5}, {-1, -1, 0}, {1, 1 + 1e-4, 0},
                      {1, 1 + 1e-2, 0}, {0.3, -0.7, 0.4}};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20; ++i) out.push_back(V3(u(rng), u(rng), u(rng)) * 150.0);
  return out;
}

}  // namespace

TEST(Yld2000, RegisteredWithNamedInputs) {
  const auto* f = material::find_yield_function("yld2000");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->coefficients.size(), 9u);
  for (const char* k : {"yld2000.alpha1", "yld2000.alpha8", "yld2000.a"}) EXPECT_NE(material::find_material_input(k), nullptr) << k;
}

// a = 2 and every alpha 1: von Mises (sigma_eq^2 = sxx^2 - sxx syy + syy^2 + 3 sxy^2) to round-off,
// value, gradient and Hessian.
TEST(Yld2000, VonMisesAtExponentTwo) {
  MaterialParams<double> vm;  // Hill defaults: von Mises
  const Eigen::Matrix3d P = material::StressSpace<double, 3>::hill(vm);
  for (const V3& s : stresses()) {
    SCOPED_TRACE(s.transpose());
    const auto v = yld(isotropic(2.0), s);
    const double seq = std::sqrt(0.5 * s.dot(P * s));
    EXPECT_NEAR(v.value, seq, 1e-14 * seq);
    const V3 n = P * s / (2 * seq);
    EXPECT_LT((v.gradient - n).norm(), 1e-13 * n.norm());
    const Eigen::Matrix3d H = P / (2 * seq) - n * n.transpose() / seq;
    EXPECT_LT((v.hessian - H).norm(), 1e-12 * (P / seq).norm());
  }
}

TEST(Yld2000, MatchesPrincipalValueDefinition) {
  for (const auto& c : {kAniso, isotropic(8.0), isotropic(6.0), std::array<double, 9>{1.1, 0.9, 1.2, 0.8, 1.0, 1.1, 0.95, 1.05, 3.0}}) {
    for (const V3& s : stresses()) {
      const double ref = yld_reference(c, s);
      EXPECT_NEAR(yld(c, s).value, ref, 2e-14 * ref) << s.transpose() << " a = " << c[8];
    }
  }
}

// Central differences of sigma_eq and of its gradient; the stresses include equibiaxial ones, where
// X' and X'' have equal principal values (the series branch), and ones just beside them.
TEST(Yld2000, GradientAndHessianMatchFiniteDifferences) {
  for (const auto& c : {kAniso, isotropic(8.0), std::array<double, 9>{1.1, 0.9, 1.2, 0.8, 1.0, 1.1, 0.95, 1.05, 3.0}}) {
    for (const V3& s : stresses()) {
      SCOPED_TRACE(testing::Message() << s.transpose() << " a = " << c[8]);
      const auto v = yld(c, s);
      const double h = 1e-6 * s.norm();
      for (int j = 0; j < 3; ++j) {
        V3 sp = s, sm = s;
        sp(j) += h;
        sm(j) -= h;
        EXPECT_NEAR(v.gradient(j), (yld(c, sp).value - yld(c, sm).value) / (2 * h), 1e-7 * v.gradient.norm());
        const V3 dg = (yld(c, sp).gradient - yld(c, sm).gradient) / (2 * h);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(v.hessian(i, j), dg(i), 1e-6 * v.hessian.norm() + 1e-9 / s.norm()) << i << "," << j;
      }
      // Degree-one homogeneity: n . s = sigma_eq, H s = 0.
      EXPECT_NEAR(v.gradient.dot(s), v.value, 1e-13 * v.value);
      EXPECT_LT((v.hessian * s).norm(), 1e-12 * v.hessian.norm() * s.norm() + 1e-15);
    }
  }
}

// The isotropic Hershey-Hosford case: uniaxial and equibiaxial yield equal, r = 1, pure shear
// (sxx = -syy) at sigma_eq = ((2^a + 2)/2)^(1/a), in-plane shear the same.
TEST(Yld2000, IsotropicHosfordClosedForms) {
  for (double a : {2.0, 6.0, 8.0}) {
    const auto m = yld_params(isotropic(a));
    EXPECT_NEAR(material::uniaxial_yield_factor(m, 0.0), 1.0, 1e-14);
    EXPECT_NEAR(material::uniaxial_yield_factor(m, test::deg(30.0)), 1.0, 1e-14);
    EXPECT_NEAR(material::equibiaxial_yield_factor(m), 1.0, 1e-14);
    EXPECT_NEAR(material::uniaxial_r_value(m, test::deg(45.0)), 1.0, 1e-12);
    EXPECT_NEAR(material::equibiaxial_r_value(m), 1.0, 1e-12);
    const double shear = std::pow((std::pow(2.0, a) + 2.0) / 2.0, 1.0 / a);
    EXPECT_NEAR(material::plane_stress_equivalent(m, V3(1.0, -1.0, 0.0)), shear, 1e-13 * shear) << a;
    EXPECT_NEAR(material::shear_yield_factor(m), shear, 1e-13 * shear) << a;
  }
}

// The return mapping at a = 2 (every alpha 1) reproduces the von Mises one of the Hill path, with
// and without Armstrong-Frederick, over large increments.
TEST(Yld2000, ReturnMappingAtExponentTwoIsVonMises) {
  for (bool af : {false, true}) {
    MaterialParams<double> vm = test::card(af ? "aa3003o_c7_af_shell" : "aa3003o_c3c4").params;
    vm.F = vm.G = vm.H = 1.0;
    vm.L = vm.M = vm.N = 3.0;
    MaterialParams<double> y = vm;
    y.yield = material::make_yield_function<Yld2000_2d>({1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0});
    const material::ReturnMapping<double, 3> a(vm), b(y);
    material::MaterialState<double, 3> sa, sb, na, nb;
    for (const V3& de : {V3(0.02, -0.01, 0.005), V3(0.1, 0.03, -0.02), V3(-0.15, -0.02, 0.04), V3(0.0, 0.0, 0.2)}) {
      Eigen::Matrix3d ta, tb;
      ASSERT_TRUE(a.integrate(sa, de, na, &ta).ok());
      ASSERT_TRUE(b.integrate(sb, de, nb, &tb).ok());
      EXPECT_LT((na.stress - nb.stress).norm(), 1e-10 * na.stress.norm()) << af;
      EXPECT_LT((na.back_stress - nb.back_stress).norm(), 1e-9 * (1.0 + na.back_stress.norm())) << af;
      EXPECT_NEAR(na.eqps, nb.eqps, 1e-12);
      EXPECT_LT((ta - tb).norm(), 1e-8 * ta.norm()) << af;
      sa = na;
      sb = nb;
    }
  }
}

// The consistent tangent of the non-quadratic return mapping against central differences, a = 8,
// anisotropic, isotropic and Armstrong-Frederick hardening, increments up to 10 %.
TEST(Yld2000, TangentMatchesFiniteDifferences) {
  for (bool af : {false, true}) {
    MaterialParams<double> m = test::card(af ? "aa3003o_c7_af_shell" : "aa3003o_c3c4").params;
    m.yield = material::make_yield_function<Yld2000_2d>({kAniso[0], kAniso[1], kAniso[2], kAniso[3], kAniso[4], kAniso[5], kAniso[6], kAniso[7], kAniso[8]});
    const material::ReturnMapping<double, 3> law(m);
    material::MaterialState<double, 3> s0, s1;
    ASSERT_TRUE(law.integrate(s0, V3(0.01, -0.004, 0.003), s1, nullptr).ok());
    s0 = s1;
    for (const V3& de : {V3(0.002, 0.001, 0.0), V3(0.1, -0.05, 0.03), V3(-0.03, 0.02, 0.08)}) {
      Eigen::Matrix3d t;
      ASSERT_TRUE(law.integrate(s0, de, s1, &t).ok());
      const double h = 1e-7;
      for (int j = 0; j < 3; ++j) {
        V3 dp = de, dm = de;
        dp(j) += h;
        dm(j) -= h;
        material::MaterialState<double, 3> sp, sm;
        ASSERT_TRUE(law.integrate(s0, dp, sp, nullptr).ok());
        ASSERT_TRUE(law.integrate(s0, dm, sm, nullptr).ok());
        const V3 fd = (sp.stress - sm.stress) / (2 * h);
        EXPECT_LT((t.col(j) - fd).norm(), 1e-6 * t.norm()) << af << " column " << j << " de " << de.transpose();
      }
      // On the surface at the end.
      EXPECT_NEAR(law.yield_function(s1), 0.0, 1e-9 * law.flow_stress(s1));
    }
  }
}

// Material-point tension at several angles: the r-value from the driver's flow direction equals
// the one of the function's gradient, the yield onset sigma_F(0) / sigma_eq(unit stress).
TEST(Yld2000, TensionRValuesAndYieldAtAngles) {
  const auto m = yld_params(kAniso);
  const double s0 = material::hardening_stress(m, 0.0);
  for (double angle : {0.0, 30.0, 45.0, 90.0}) {
    SCOPED_TRACE(angle);
    const auto r = scene::run_material_point(m, test::tensile(angle, {0.2}, 100));
    ASSERT_TRUE(r.ok) << r.message;
    ASSERT_TRUE(r.r_value.has_value());
    EXPECT_LT(rel(*r.r_value, material::uniaxial_r_value(m, test::deg(angle))), 1e-6);
    ASSERT_FALSE(r.yield_events.empty());
    EXPECT_LT(rel(r.yield_events.front().stress_kirchhoff, s0 / material::uniaxial_yield_factor(m, test::deg(angle))), 1e-6);
  }
}

// Jets carry d stress / d alpha through the non-quadratic return mapping: against central
// differences.
TEST(Yld2000, JetDerivativeOfAnAlpha) {
  using Jet = ceres::Jet<double, 1>;
  const auto base = yld_params(kAniso);
  const V3 de(0.08, -0.03, 0.02);
  for (int k : {Yld2000_2d::alpha1, Yld2000_2d::alpha5, Yld2000_2d::alpha8}) {
    auto stress = [&](double v) {
      auto m = base;
      m.yield[k] = v;
      const material::ReturnMapping<double, 3> law(m);
      material::MaterialState<double, 3> s0, s1;
      EXPECT_TRUE(law.integrate(s0, de, s1, nullptr).ok());
      return s1.stress;
    };
    MaterialParams<Jet> mj = base.cast<Jet>();
    mj.yield[k].v[0] = 1.0;
    const material::ReturnMapping<Jet, 3> law(mj);
    material::MaterialState<Jet, 3> s0, s1;
    Eigen::Matrix<Jet, 3, 1> dj;
    for (int i = 0; i < 3; ++i) dj(i) = Jet(de(i));
    ASSERT_TRUE(law.integrate(s0, dj, s1, nullptr).ok());
    const double v = base.yield[k], h = 1e-5;
    const V3 fd = (stress(v + h) - stress(v - h)) / (2.0 * h);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(s1.stress(i).v[0], fd(i), 1e-6 * fd.norm()) << k << " " << i;
  }
}

TEST(Yld2000, CardRoundTripsAndShows) {
  auto card = test::card("aa3003o_c3c4");
  card.params = yld_params(kAniso);
  const std::string text = material::material_card_to_toml(card);
  EXPECT_NE(text.find("[yld2000]"), std::string::npos) << text;
  EXPECT_EQ(text.find("[hill]"), std::string::npos) << text;
  const auto back = material::load_material_card(test::write_temp_file("yld_round_trip.toml", text).string());
  EXPECT_EQ(back.params.yield.law, card.params.yield.law);
  EXPECT_EQ(back.params.yield.c, card.params.yield.c);
  const std::string shown = material::describe_material_card(back);
  EXPECT_NE(shown.find("Yld2000-2d"), std::string::npos) << shown;
  EXPECT_NE(shown.find("equibiaxial"), std::string::npos) << shown;
  // Hill's names are not parameters of this card.
  const auto* n = material::find_material_input("hill.N");
  EXPECT_FALSE(material::holds_input(back.params, *n));
  EXPECT_NE(material::why_not_held(back.params, *n).find("its yield function is yld2000"), std::string::npos);
}

TEST(Yld2000, BadCardsAreRefusedNamingFileKeyValue) {
  auto card = test::card("aa3003o_c3c4");
  const std::string base = material::material_card_to_toml(card);
  const std::string no_hill = base.substr(0, base.find("[hill]")) + base.substr(base.find("[swift]"));
  auto error_of = [](const std::string& text) {
    try {
      material::load_material_card(test::write_temp_file("y.toml", text).string());
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string alphas = "alpha1 = 1.0\nalpha2 = 1.0\nalpha3 = 1.0\nalpha4 = 1.0\nalpha5 = 1.0\nalpha6 = 1.0\n";
  // a < 2 (a < 1 would not be convex).
  std::string e = error_of(no_hill + "\n[yld2000]\n" + alphas + "alpha7 = 1.0\nalpha8 = 1.0\na = 0.5\n");
  EXPECT_NE(e.find("y.toml"), std::string::npos) << e;
  EXPECT_NE(e.find("yld2000.a"), std::string::npos) << e;
  EXPECT_NE(e.find("0.5"), std::string::npos) << e;
  // No shear resistance: an open surface.
  e = error_of(no_hill + "\n[yld2000]\n" + alphas + "alpha7 = 0.0\nalpha8 = 0.0\na = 8.0\n");
  EXPECT_NE(e.find("yld2000.alpha8"), std::string::npos) << e;
  EXPECT_NE(e.find("open"), std::string::npos) << e;
  // Hill and Yld2000 together.
  e = error_of(base + "\n[yld2000]\n" + alphas + "alpha7 = 1.0\nalpha8 = 1.0\na = 8.0\n");
  EXPECT_NE(e.find("one yield function"), std::string::npos) << e;
  // The 3D return mapping refuses a plane-stress function.
  EXPECT_THROW((material::ReturnMapping<double, 6>(yld_params(kAniso))), std::invalid_argument);
}
