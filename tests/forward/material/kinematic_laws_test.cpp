// The kinematic-law registry: names and inputs from the laws' headers, cards read and written
// through it, parameters of a law the card does not have refused with the card's law, and the
// return mapping's kinematic part against the closed form of each law (von Mises, uniaxial, one
// step: the exponential integration is exact along proportional paths).
#include "forward/io/input_error.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/material_card.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/return_mapping.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/closed_form.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

using namespace spifit;

TEST(KinematicLaws, RegistryNamesEveryLawOnce) {
  const auto& laws = material::kinematic_laws();
  ASSERT_EQ(laws.size(), 2u);
  EXPECT_EQ(material::find_kinematic_law("af"), material::find_kinematic_law("armstrong_frederick"));
  EXPECT_EQ(material::find_kinematic_law("ziegler")->id, material::kinematic_law_index<material::Ziegler>());
  EXPECT_EQ(material::find_kinematic_law("chaboche"), nullptr);
  EXPECT_EQ(material::kinematic_table_list(), "[armstrong_frederick] or [ziegler]");
  EXPECT_EQ(material::kinematic_law_name(-1), "none");
  for (const auto& law : laws)
    for (const auto& c : law.coefficients) {
      const auto* in = material::find_material_input(law.input_prefix + "." + c.key);
      ASSERT_NE(in, nullptr) << law.name << "." << c.key;
      EXPECT_EQ(in->card_key, law.name + "." + c.key);
      EXPECT_EQ(in->info.unit, c.unit);
    }
}

TEST(KinematicLaws, CardsGoThroughTheRegistry) {
  const auto c7 = test::card("aa3003o_c7_af_shell");
  ASSERT_TRUE(material::is_kinematic<material::ArmstrongFrederick>(c7.params.kinematic));
  const std::string text = material::material_card_to_toml(c7);
  EXPECT_NE(text.find("[armstrong_frederick]\nCX = 51.4\nXsat = 46\n"), std::string::npos) << text;
  const auto back = material::load_material_card(test::write_temp_file("c7.toml", text).string());
  EXPECT_EQ(back.params.kinematic.law, c7.params.kinematic.law);
  EXPECT_EQ(back.params.kinematic.c, c7.params.kinematic.c);
  // Two kinematic tables: the second is named.
  try {
    material::load_material_card(test::write_temp_file("two.toml", text + "\n[ziegler]\nCA = 1.0\nGA = 1.0\n").string());
    ADD_FAILURE() << "two kinematic laws accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "ziegler");
    EXPECT_NE(std::string(e.what()).find("at most one kinematic law ([armstrong_frederick] or [ziegler])"), std::string::npos) << e.what();
  }
}

TEST(KinematicLaws, InputOfAnotherLawIsNamed) {
  const auto c7 = test::card("aa3003o_c7_af_shell");
  const auto* ca = material::find_material_input("ziegler.CA");
  ASSERT_NE(ca, nullptr);
  EXPECT_EQ(material::why_not_held(c7.params, *ca),
            "ziegler.CA is not a parameter of this card: its kinematic law is armstrong_frederick (af.CX, af.Xsat)");
  const auto c34 = test::card("aa3003o_c3c4");
  EXPECT_EQ(material::why_not_held(c34.params, *material::find_material_input("af.CX")),
            "af.CX is not a parameter of this card: it has no kinematic hardening ([armstrong_frederick] or [ziegler])");
  EXPECT_THROW(material::material_field(c34.params, ca->field), std::logic_error);
}

// One increment to 15 % plastic strain, von Mises, uniaxial: stress = sigma_F(p) + X_RD(p) of
// each law's closed form, and the plane-stress X_zz as the law updates it.
TEST(KinematicLaws, OneStepUniaxialMatchesEachLawsClosedForm) {
  for (const char* name : {"aa3003o_c7_af_shell", "aa3003o_c8_ziegler_shell"}) {
    SCOPED_TRACE(name);
    const auto card = test::von_mises_copy(test::card(name));
    const test::UniaxialClosedForm cf{card.params, 1.0};
    const double p = 0.15, s = cf.stress_at_p(p);
    const double e_axial = s / card.params.E + p, e_lat = -card.params.nu * s / card.params.E - 0.5 * p;
    const material::ReturnMapping<double, 6> law(card.params);
    material::MaterialState<double, 6> s0, s1;
    Eigen::Matrix<double, 6, 1> de;
    de << e_axial, e_lat, e_lat, 0, 0, 0;
    ASSERT_TRUE(law.integrate(s0, de, s1, nullptr).ok());
    EXPECT_NEAR(s1.stress(0), s, 1e-9 * s);
    EXPECT_NEAR(s1.back_stress(0) - s1.back_stress(1), cf.offset(p), 1e-9 * s);  // X_xx - X_yy: the uniaxial offset
  }
}
