#pragma once
// Bundled material cards for the tests, plus von Mises copies of the Hill cards.
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/material_card.hpp"

#include <string>
#include <vector>

namespace spifit::test {

inline std::string card_path(const std::string& name) {
  return std::string(SPIFIT_SOURCE_DIR) + "/materials/" + name + ".toml";
}
inline material::MaterialCard card(const std::string& name) { return material::load_material_card(card_path(name)); }

inline std::vector<std::string> thesis_card_names() {
  return {"aa3003o_c2", "aa3003o_c3c4", "aa3003o_c5_af_brick", "aa3003o_c6_ziegler_brick",
          "aa3003o_c7_af_shell", "aa3003o_c7n_af_shell", "aa3003o_c8_ziegler_shell"};
}

inline material::MaterialCard von_mises_copy(material::MaterialCard c) {
  c.set_hill(material::Hill48::von_mises());
  c.name += "_vm";
  return c;
}

// C.3 + C.4's Hill coefficients with Voce hardening (no kinematic hardening) and with Swift-Voce
// plus C.7's Armstrong-Frederick constants: made up for the law tests, of AA3003-O's size
// (sigma_F from about 43 MPa, saturating near 180 MPa).
inline material::MaterialCard voce_test_card() {
  auto c = card("aa3003o_c3c4");
  c.name = "voce_test";
  c.params.hardening = material::make_hardening<material::VoceHardening>({43.0, 140.0, 8.0});
  return c;
}
inline material::MaterialCard swift_voce_af_test_card() {
  auto c = card("aa3003o_c7_af_shell");
  c.name = "swift_voce_af_test";
  const auto& s = c.params.hardening;
  c.params.hardening = material::make_hardening<material::SwiftVoceHardening>(
      {s[material::SwiftHardening::K], s[material::SwiftHardening::eps0], s[material::SwiftHardening::n], 40.0, 90.0, 12.0, 0.6});
  return c;
}

// Every card the law tests run over: the thesis cards, von Mises copies of C.5 and C.7,
// a perfectly plastic card, an elastic-only card and the Voce and Swift-Voce cards above.
inline std::vector<material::MaterialCard> all_test_cards() {
  std::vector<material::MaterialCard> out;
  for (const auto& n : thesis_card_names()) out.push_back(card(n));
  out.push_back(von_mises_copy(card("aa3003o_c5_af_brick")));
  out.push_back(von_mises_copy(card("aa3003o_c7_af_shell")));
  auto perfect = card("aa3003o_c3c4");
  perfect.name = "perfect_plastic";
  perfect.params.hardening[material::SwiftHardening::n] = 0.0;
  perfect.params.hardening[material::SwiftHardening::K] = 100.0;
  out.push_back(perfect);
  auto elastic = card("aa3003o_c3c4");
  elastic.name = "elastic_only";
  elastic.params.plastic = false;
  out.push_back(elastic);
  out.push_back(voce_test_card());
  out.push_back(swift_voce_af_test_card());
  return out;
}

}  // namespace spifit::test
