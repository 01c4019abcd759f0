// The LS-DYNA deck (*MAT_HILL_3R or *MAT_BARLAT_YLD2000 + *DEFINE_CURVE, long format): docs/reference/outputs.md "LS-DYNA".
#include "reports/card_export.hpp"
#include "reports/card_export_text.hpp"

#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"

#include <cmath>
#include <sstream>

namespace spifit::reports {

using material::MaterialCard;
using namespace deck;

namespace {

constexpr int kW = 20;  // LS-DYNA long-format field width

std::string field(double v) {
  std::string s = format_real(v, kW - 1);  // keep one blank between fields
  return std::string(static_cast<std::size_t>(kW) - s.size(), ' ') + s;
}
std::string field(int v) {
  std::string s = std::to_string(v);
  return std::string(static_cast<std::size_t>(kW) - s.size(), ' ') + s;
}
std::string blank() { return std::string(kW, ' '); }
std::string labels(std::initializer_list<const char*> names) {
  std::string s = "$#";
  bool first = true;
  for (const char* n : names) {
    std::string f(n);
    const std::size_t w = first ? kW - 2 : kW;
    if (f.size() >= w) f = f.substr(0, w - 1);
    s += std::string(w - f.size(), ' ') + f;
    first = false;
  }
  return s + "\n";
}

std::vector<std::string> lsdyna_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const auto& p = card.params;
  auto n = common_notes(card, law, o, "*DEFINE_CURVE, effective plastic strain vs yield stress",
                        "LS-DYNA extrapolates the last segment of the curve");
  n.push_back("keyword file in long format (*KEYWORD LONG=Y, 20-character fields) so that every number keeps 14 "
              "significant digits; include it as a separate file.");
  if (!p.plastic) {
    n.push_back("*MAT_ELASTIC (MAT_001).");
    return n;
  }
  if (p.yield.active()) {
    n.push_back("*MAT_BARLAT_YLD2000 (MAT_133) with FIT = 0 (the alphas given), the exponent A = " + num(p.yield[material::Yld2000_2d::a]) +
                ", HARD = -LCID (the yield stress curve), BETA = 0 (isotropic hardening) and ITER = 0 (plane-stress return); r-values of the card from its flow direction: r00 = " + num(law.lankford.r0) +
                ", r45 = " + num(law.lankford.r45) + ", r90 = " + num(law.lankford.r90) + ".");
    n.push_back("material axes: AOPT = 2 with a = global x = RD and d = global y = TD (spifit's convention); change A/D "
                "(or AOPT) to match the mesh.");
    return n;
  }
  n.push_back("*MAT_HILL_3R (MAT_122): Hill 1948 for shell elements (plane stress), given by r-values r00 = H/G, r45 = "
              "(2N - F - G)/(2(F + G)), r90 = H/F (thesis eq. C.2) and the RD hardening curve: exact for the in-plane "
              "Hill coefficients; the card's out-of-plane L, M are not used.");
  n.push_back("material axes: AOPT = 2 with a = global x = RD and d = global y = TD (spifit's convention); change A/D "
              "(or AOPT) to match the mesh.");
  if (law.kinematic < 0 && p.hardening.law == material::hardening_law_index<material::SwiftHardening>()) {
    using S = material::SwiftHardening;
    const double K = p.hardening[S::K], eps0 = p.hardening[S::eps0], hn = p.hardening[S::n];
    n.push_back("analytic alternative: HR = 2 (sigma = P1 (E0 + ebar)^P2) with P1 = K h^-(1+n) = " +
                num(K * std::pow(law.h, -(1.0 + hn))) + ", P2 = n = " + num(hn) + ", E0 = h eps0 = " +
                num(law.h * eps0) + " gives the same curve; the deck uses HR = 3 (load curve).");
  } else if (law.kinematic >= 0) {
    const double xmax = law.gamma > 0 ? law.C / law.gamma : rd_back_stress(law.C, law.gamma, o.max_plastic_strain);
    n.push_back("APPROXIMATION: *MAT_122 has no kinematic hardening. The curve is the card's monotonic RD tension "
                "(isotropic size + RD back-stress (C/gamma)(1 - exp(-gamma ebar)), C = " + num(law.C) +
                " MPa, gamma = " + num(law.gamma) + "), i.e. isotropic hardening equivalent in monotonic RD tension" +
                (law.kinematic_exact ? "" : " (itself the nearest Ziegler-form fit of Hill + Armstrong-Frederick)") +
                "; there is no Bauschinger effect: after a reversal the reverse yield stress is too high by 2 X_RD "
                "(up to " + fixed(2.0 * xmax, 1) + " MPa), a difference that decays over a reverse strain of a few "
                "1/gamma.");
  }
  return n;
}

}  // namespace

namespace {
void write_mat_122(std::ostringstream& os, const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o);
void write_mat_133(std::ostringstream& os, const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o);
}  // namespace

std::string export_lsdyna(const MaterialCard& card, std::vector<std::string>* notes_out, const ExportOptions& o) {
  const ExportedLaw law = exported_law(card, o);
  const auto notes = lsdyna_notes(card, law, o);
  append(notes_out, notes);
  const auto& p = card.params;
  std::ostringstream os;
  write_header(os, "$ ", "LS-DYNA (keyword, units mm-t-s-N-MPa)", card, notes, 76);
  os << "*KEYWORD LONG=Y\n";
  if (!law.plastic) {
    os << "*MAT_ELASTIC_TITLE\n" << deck_material_name(card) << "\n";
    os << labels({"MID", "RO", "E", "PR"});
    os << field(o.lsdyna_material_id) << field(card.density) << field(p.E) << field(p.nu) << "\n";
    os << "*END\n";
    return os.str();
  }
  if (p.yield.active()) {
    write_mat_133(os, card, law, o);
  } else {
    write_mat_122(os, card, law, o);
  }
  os << "*DEFINE_CURVE_TITLE\n" << deck_material_name(card) << " RD yield stress vs effective plastic strain\n";
  os << labels({"LCID", "SIDR", "SFA", "SFO", "OFFA", "OFFO", "DATTYP"});
  os << field(o.lsdyna_curve_id) << field(0) << field(1.0) << field(1.0) << field(0.0) << field(0.0) << field(0) << "\n";
  os << labels({"A1 (ebar)", "O1 (MPa)"});
  for (std::size_t i = 0; i < law.strain.size(); ++i) os << field(law.strain[i]) << field(law.monotonic[i]) << "\n";
  os << "*END\n";
  return os.str();
}

namespace {

// *MAT_HILL_3R: Hill 1948 by its r-values.
void write_mat_122(std::ostringstream& os, const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const auto& p = card.params;
  os << "*MAT_HILL_3R_TITLE\n" << deck_material_name(card) << "\n";
  os << labels({"MID", "RO", "E", "PR", "HR", "P1", "P2"});
  os << field(o.lsdyna_material_id) << field(card.density) << field(p.E) << field(p.nu) << field(3.0) << field(0.0)
     << field(0.0) << "\n";
  os << labels({"R00", "R45", "R90", "LCID", "E0"});
  os << field(law.lankford.r0) << field(law.lankford.r45) << field(law.lankford.r90) << field(o.lsdyna_curve_id)
     << field(0.0) << "\n";
  os << labels({"AOPT"});
  os << field(2.0) << "\n";
  os << labels({"", "", "", "A1", "A2", "A3"});
  os << blank() << blank() << blank() << field(1.0) << field(0.0) << field(0.0) << "\n";
  os << labels({"V1", "V2", "V3", "D1", "D2", "D3", "BETA"});
  os << field(0.0) << field(0.0) << field(0.0) << field(0.0) << field(1.0) << field(0.0) << field(0.0) << "\n";
}

// *MAT_BARLAT_YLD2000 with its alphas divided by h (RD-normalised, card_export_text.cpp).
void write_mat_133(std::ostringstream& os, const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  using Y = material::Yld2000_2d;
  const auto& p = card.params;
  os << "*MAT_BARLAT_YLD2000_TITLE\n" << deck_material_name(card) << "\n";
  os << labels({"MID", "RO", "E", "PR", "FIT", "BETA", "ITER"});
  os << field(o.lsdyna_material_id) << field(card.density) << field(p.E) << field(p.nu) << field(0.0) << field(0.0) << field(0.0) << "\n";
  os << labels({"K", "E0", "N", "C", "P", "HARD", "A"});
  os << blank() << blank() << blank() << field(0.0) << field(0.0) << field(-static_cast<double>(o.lsdyna_curve_id)) << field(p.yield[Y::a]) << "\n";
  os << labels({"ALPHA1", "ALPHA2", "ALPHA3", "ALPHA4", "ALPHA5", "ALPHA6", "ALPHA7", "ALPHA8"});
  for (int i = Y::alpha1; i <= Y::alpha8; ++i) os << field(p.yield[i] / law.h);
  os << "\n";
  os << labels({"AOPT"});
  os << field(2.0) << "\n";
  os << labels({"", "", "", "A1", "A2", "A3"});
  os << blank() << blank() << blank() << field(1.0) << field(0.0) << field(0.0) << "\n";
  os << labels({"V1", "V2", "V3", "D1", "D2", "D3"});
  os << field(0.0) << field(0.0) << field(0.0) << field(0.0) << field(1.0) << field(0.0) << "\n";
}

}  // namespace

}  // namespace spifit::reports
