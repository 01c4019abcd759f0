// The hardening-law registry and its laws: Voce and Swift-Voce against formulas written here
// independently of the laws' code, slopes against finite differences, Jets against finite
// differences, material-point tension (several angles), equibiaxial tension and shear against
// closed forms, and cards with the new tables.
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/io/input_error.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/hill48.hpp"
#include "forward/material/material_card.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/return_mapping.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"
#include "tests/support/temp_files.hpp"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace spifit;
using material::Hardening;
using material::MaterialParams;

namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Written from the formulas, not from the laws' code.
double voce(double s0, double Q, double b, double p) { return s0 + Q * (1.0 - std::exp(-b * p)); }
double swift(double K, double e0, double n, double p) { return K * std::pow(e0 + p, n); }

MaterialParams<double> with(const Hardening<double>& h) {
  MaterialParams<double> m = test::card("aa3003o_c3c4").params;
  m.hardening = h;
  return m;
}

}  // namespace

TEST(HardeningLaws, RegistryNamesEveryLawOnce) {
  const auto& laws = material::hardening_laws();
  ASSERT_EQ(laws.size(), 3u);
  EXPECT_EQ(laws[0].name, "swift");  // the default of MaterialParams
  EXPECT_EQ(material::find_hardening_law("voce")->id, material::hardening_law_index<material::VoceHardening>());
  EXPECT_EQ(material::find_hardening_law("swift_voce")->coefficients.size(), 7u);
  EXPECT_EQ(material::find_hardening_law("ludwik"), nullptr);
  EXPECT_EQ(material::hardening_table_list(), "[swift], [voce] or [swift_voce]");
  // Every coefficient is a named input "law.key" with the law's unit.
  for (const auto& law : laws)
    for (const auto& c : law.coefficients) {
      const auto* in = material::find_material_input(law.name + "." + c.key);
      ASSERT_NE(in, nullptr) << law.name << "." << c.key;
      EXPECT_EQ(in->info.unit, c.unit);
      EXPECT_EQ(in->card_key, law.name + "." + c.key);
    }
}

TEST(HardeningLaws, StressMatchesTheFormulas) {
  const auto v = with(material::make_hardening<material::VoceHardening>({43.0, 140.0, 8.0}));
  const auto sv = with(material::make_hardening<material::SwiftVoceHardening>({180.0, 0.00109, 0.21, 40.0, 90.0, 12.0, 0.6}));
  for (double p : {0.0, 1e-4, 0.01, 0.1, 0.5, 2.0}) {
    EXPECT_LT(rel(material::hardening_stress(v, p), voce(43.0, 140.0, 8.0, p)), 1e-15) << p;
    EXPECT_LT(rel(material::hardening_stress(sv, p), 0.6 * swift(180.0, 0.00109, 0.21, p) + 0.4 * voce(40.0, 90.0, 12.0, p)), 1e-15) << p;
  }
  // Saturation: Voce tends to sigma0 + Q.
  EXPECT_NEAR(material::hardening_stress(v, 10.0), 183.0, 1e-9);
}

// alpha = 1 is Swift and alpha = 0 is Voce, to round-off.
TEST(HardeningLaws, SwiftVoceEndsAreItsParts) {
  const auto s = with(material::make_hardening<material::SwiftHardening>({180.0, 0.00109, 0.21}));
  const auto v = with(material::make_hardening<material::VoceHardening>({40.0, 90.0, 12.0}));
  const auto a1 = with(material::make_hardening<material::SwiftVoceHardening>({180.0, 0.00109, 0.21, 40.0, 90.0, 12.0, 1.0}));
  const auto a0 = with(material::make_hardening<material::SwiftVoceHardening>({180.0, 0.00109, 0.21, 40.0, 90.0, 12.0, 0.0}));
  for (double p : {0.0, 0.003, 0.2, 1.0}) {
    EXPECT_LT(rel(material::hardening_stress(a1, p), material::hardening_stress(s, p)), 1e-15);
    EXPECT_LT(rel(material::hardening_stress(a0, p), material::hardening_stress(v, p)), 1e-15);
  }
}

// The slope against central differences (h = 1e-6 p, error ~1e-9 relative).
TEST(HardeningLaws, SlopeMatchesFiniteDifferences) {
  for (const auto& h : {material::make_hardening<material::SwiftHardening>({180.0, 0.00109, 0.21}),
                        material::make_hardening<material::VoceHardening>({43.0, 140.0, 8.0}),
                        material::make_hardening<material::SwiftVoceHardening>({180.0, 0.00109, 0.21, 40.0, 90.0, 12.0, 0.6})}) {
    const auto m = with(h);
    for (double p0 : {0.001, 0.05, 0.4}) {
      const double dl = 0.5 * p0, p = p0 + dl, step = 1e-6 * p;
      const double s = material::hardening_stress(m, p);
      const double fd = (material::hardening_stress(m, p + step) - material::hardening_stress(m, p - step)) / (2.0 * step);
      EXPECT_LT(rel(material::hardening_slope(m, p0, dl, s), fd), 1e-7) << material::hardening_law(h.law).name << " p = " << p;
    }
  }
}

// Tension at 0, 30, 45 and 90 deg to RD on a Hill card with Voce hardening: the stress along the
// curve is sigma_F(p) / h(alpha), the r-value Hill's (hardening does not change it).
TEST(HardeningLaws, VoceUniaxialAtAnglesMatchesClosedForm) {
  const auto card = test::voce_test_card();
  const auto hill = card.hill();
  for (double angle : {0.0, 30.0, 45.0, 90.0}) {
    SCOPED_TRACE(angle);
    const double hf = material::uniaxial_stress_factor(hill, test::deg(angle));
    const auto r = scene::run_material_point(card.params, test::tensile(angle, {0.3}, 200));
    ASSERT_TRUE(r.ok) << r.message;
    ASSERT_TRUE(r.r_value.has_value());
    EXPECT_LT(rel(*r.r_value, material::r_value_at_angle(hill, test::deg(angle))), 1e-6);
    ASSERT_FALSE(r.yield_events.empty());
    EXPECT_LT(rel(r.yield_events.front().stress_kirchhoff, 43.0 / hf), 1e-6);
    // Late in the curve: the axial plastic strain is h p, so p = eps_p / h (the Kirchhoff
    // stress along the log strain: eps = tau / E + h p).
    const auto& last = r.curve.back();
    const double tau = last.stress_kirchhoff;
    const double p = (last.control_strain - tau / card.params.E) / hf;
    EXPECT_LT(rel(tau, voce(43.0, 140.0, 8.0, p) / hf), 1e-6);
  }
}

// Equibiaxial tension: sigma_eq = sqrt((F + G)/2) sigma (thesis eq. 3.6 with sxx = syy).
TEST(HardeningLaws, SwiftVoceEquibiaxialYield) {
  const auto card = test::swift_voce_af_test_card();
  auto m = card.params;
  m.kinematic = {};  // isotropic: the whole curve has a closed form
  scene::MaterialPointSetup s;
  s.kind = scene::MaterialPointKind::biaxial;
  s.stress_ratio = 1.0;
  s.strain_path = {0.1};
  const auto r = scene::run_material_point(m, s);
  ASSERT_TRUE(r.ok) << r.message;
  const double f = std::sqrt((m.F + m.G) / 2.0);
  const auto& k = m.hardening;
  ASSERT_FALSE(r.yield_events.empty());
  EXPECT_LT(rel(r.yield_events[0].stress_kirchhoff, (0.6 * swift(k[0], k[1], k[2], 0.0) + 0.4 * voce(40.0, 90.0, 12.0, 0.0)) / f), 1e-9);
  for (const auto& p : r.curve) EXPECT_NEAR(p.stress_material(1), p.stress_material(0), 1e-9 * (1 + std::abs(p.stress)));
}

// Pure shear on a Voce card: tau = sigma_F(p) / sqrt(N), gamma = tau / mu + sqrt(N) p.
TEST(HardeningLaws, VoceShearMatchesClosedForm) {
  const auto card = test::voce_test_card();
  const auto r = scene::run_material_point(card.params, test::shear(0.0, {0.2}, 200));
  ASSERT_TRUE(r.ok) << r.message;
  const double rn = std::sqrt(card.params.N), mu = card.params.E / (2.0 * (1.0 + card.params.nu));
  const auto& last = r.curve.back();
  const double tau = last.stress_kirchhoff;
  const double p = (last.control_strain - tau / mu) / rn;
  EXPECT_LT(rel(tau, voce(43.0, 140.0, 8.0, p) / rn), 1e-6);
}

// Jets carry the derivative of the stress with respect to a Voce coefficient through the
// return mapping: against central differences of the double law.
TEST(HardeningLaws, JetDerivativeOfVoceQ) {
  using Jet = ceres::Jet<double, 1>;
  const auto card = test::voce_test_card();
  const Eigen::Vector3d de(0.08, -0.03, 0.02);
  auto stress = [&](double Q) {
    auto m = card.params;
    m.hardening[material::VoceHardening::Q] = Q;
    const material::ReturnMapping<double, 3> law(m);
    material::MaterialState<double, 3> s0, s1;
    EXPECT_TRUE(law.integrate(s0, de, s1, nullptr).ok());
    return s1.stress;
  };
  MaterialParams<Jet> mj = card.params.cast<Jet>();
  mj.hardening[material::VoceHardening::Q].v[0] = 1.0;
  const material::ReturnMapping<Jet, 3> law(mj);
  material::MaterialState<Jet, 3> s0, s1;
  Eigen::Matrix<Jet, 3, 1> dj;
  for (int i = 0; i < 3; ++i) dj(i) = Jet(de(i));
  ASSERT_TRUE(law.integrate(s0, dj, s1, nullptr).ok());
  const double Q = 140.0, h = 1e-4 * Q;
  const Eigen::Vector3d fd = (stress(Q + h) - stress(Q - h)) / (2.0 * h);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(s1.stress(i).v[0], fd(i), 1e-7 * fd.norm()) << i;
}

TEST(HardeningLaws, CardWithVoceRoundTrips) {
  const auto card = test::voce_test_card();
  const std::string text = material::material_card_to_toml(card);
  EXPECT_NE(text.find("[voce]\nsigma0 = 43\nQ = 140\nb = 8\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("[swift]"), std::string::npos);
  const auto back = material::load_material_card(test::write_temp_file("voce_round_trip.toml", text).string());
  EXPECT_EQ(back.params.hardening.law, card.params.hardening.law);
  EXPECT_EQ(back.params.hardening.c, card.params.hardening.c);
  const std::string shown = material::describe_material_card(back);
  EXPECT_NE(shown.find("Voce sigma_F = sigma0 + Q (1 - exp(-b p)): sigma0 = 43 MPa, Q = 140 MPa, b = 8"), std::string::npos) << shown;
  EXPECT_NE(shown.find("sigma_F(0) = sigma0 = 43 MPa"), std::string::npos) << shown;
}

TEST(HardeningLaws, CardErrorsNameTheKey) {
  const std::string base = material::material_card_to_toml(test::card("aa3003o_c3c4"));
  auto error_of = [](const std::string& text) {
    try {
      material::load_material_card(test::write_temp_file("c.toml", text).string());
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Two hardening laws.
  std::string e = error_of(base + "\n[voce]\nsigma0 = 43.0\nQ = 140.0\nb = 8.0\n");
  EXPECT_NE(e.find("c.toml"), std::string::npos) << e;
  EXPECT_NE(e.find("voce"), std::string::npos) << e;
  EXPECT_NE(e.find("at most one hardening law"), std::string::npos) << e;
  // A coefficient out of range, named with its table.
  const std::string voce_card = base.substr(0, base.find("[swift]")) + "[voce]\nsigma0 = 43.0\nQ = -1.0\nb = 8.0\n";
  e = error_of(voce_card);
  EXPECT_NE(e.find("voce.Q"), std::string::npos) << e;
  EXPECT_NE(e.find("-1"), std::string::npos) << e;
  // A missing coefficient and a misspelt one.
  EXPECT_NE(error_of(base.substr(0, base.find("[swift]")) + "[voce]\nsigma0 = 43.0\nQ = 1.0\n").find("voce.b"), std::string::npos);
  EXPECT_NE(error_of(base.substr(0, base.find("[swift]")) + "[swift_voce]\nK = 1.0\n").find("swift_voce"), std::string::npos);
}

// A parameter of another law than the card's is refused with the card's law and its names.
TEST(HardeningLaws, InputOfAnotherLawIsNamed) {
  const auto card = test::voce_test_card();
  const auto* k = material::find_material_input("swift.K");
  ASSERT_NE(k, nullptr);
  EXPECT_FALSE(material::holds_input(card.params, *k));
  EXPECT_EQ(material::why_not_held(card.params, *k),
            "swift.K is not a parameter of this card: its hardening law is voce (voce.sigma0, voce.Q, voce.b)");
  EXPECT_TRUE(material::why_not_held(card.params, *material::find_material_input("voce.Q")).empty());
  EXPECT_THROW(material::material_field(card.params, k->field), std::logic_error);
}

// The RD-normalised law of the FE decks: sigma'(p) = sigma(p / h) / h for every law.
TEST(HardeningLaws, StrainScalingKeepsTheCurve) {
  for (const auto& h : {material::make_hardening<material::SwiftHardening>({180.0, 0.00109, 0.21}),
                        material::make_hardening<material::VoceHardening>({43.0, 140.0, 8.0}),
                        material::make_hardening<material::SwiftVoceHardening>({180.0, 0.00109, 0.21, 40.0, 90.0, 12.0, 0.6})}) {
    const auto m = with(h);
    auto scaled = m;
    const double f = 1.07;
    material::scale_hardening_strain(scaled.hardening, f);
    for (double p : {0.0, 0.01, 0.3})
      EXPECT_LT(rel(material::hardening_stress(scaled, p), material::hardening_stress(m, p / f) / f), 1e-14) << material::hardening_law(h.law).name;
  }
}
