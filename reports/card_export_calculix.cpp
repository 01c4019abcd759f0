// The CalculiX deck (*MATERIAL block): docs/reference/outputs.md "CalculiX".
#include "reports/card_export.hpp"
#include "reports/card_export_text.hpp"

#include "forward/material/yield/yield_functions.hpp"

#include <numbers>
#include <sstream>
#include <stdexcept>

namespace spifit::reports {

using material::MaterialCard;
using namespace deck;

namespace {

std::vector<std::string> calculix_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const bool combined = law.kinematic >= 0 && o.calculix_combined_hardening;
  auto n = common_notes(card, law, o, combined ? "*CYCLIC HARDENING" : "*PLASTIC",
                        "CalculiX keeps the last value (perfectly plastic)");
  if (!card.params.plastic) return n;
  const material::Hill48 hill = card.hill();
  if (!hill.is_von_mises() && !proportional_to_von_mises(hill)) {
    const double h0 = material::uniaxial_stress_factor(hill, 0.0);
    const double h45 = material::uniaxial_stress_factor(hill, std::numbers::pi / 4);
    const double h90 = material::uniaxial_stress_factor(hill, std::numbers::pi / 2);
    n.push_back("APPROXIMATION: CalculiX's *PLASTIC is von Mises (its built-in ANISO_PLAS model has a von Mises yield "
                "too): the Hill anisotropy is dropped and the deck reproduces RD tension only. The card predicts r0/r45/"
                "r90 = " + fixed(law.lankford.r0, 3) + "/" + fixed(law.lankford.r45, 3) + "/" +
                fixed(law.lankford.r90, 3) + " and yield-stress ratios sigma45/sigma0 = " + fixed(h0 / h45, 4) +
                ", sigma90/sigma0 = " + fixed(h0 / h90, 4) + ", tau_xy/sigma0 = " +
                fixed(h0 / material::shear_stress_factor(hill), 4) + "; the deck gives r = 1, 1, 1 and 1/sqrt(3) = 0.5774 "
                "in shear.");
  }
  if (law.kinematic < 0) return n;
  const std::string fit = law.kinematic_exact ? "" : " (itself the nearest Ziegler-form fit of Hill + Armstrong-Frederick)";
  if (!combined) {
    const double xmax = law.gamma > 0 ? law.C / law.gamma : rd_back_stress(law.C, law.gamma, o.max_plastic_strain);
    n.push_back("APPROXIMATION: kinematic hardening is written as its isotropic equivalent in monotonic RD tension: "
                "*PLASTIC = isotropic size + RD back-stress (C/gamma)(1 - exp(-gamma ebar)), C = " + num(law.C) +
                " MPa, gamma = " + num(law.gamma) + fit + ". Monotonic tension is reproduced; there is no Bauschinger "
                "effect: after a reversal the reverse yield stress is too high by 2 X_RD (up to " + fixed(2.0 * xmax, 1) +
                " MPa), a difference that decays over a reverse strain of a few 1/gamma. CalculiX's own combined "
                "hardening was measured worse (docs/results/validation.md).");
  } else {
    n.push_back("APPROXIMATION: CalculiX's combined hardening (*PLASTIC, HARDENING=COMBINED = kinematic curve sigma_0(0) "
                "+ (C/gamma)(1 - exp(-gamma ebar)), C = " + num(law.C) + " MPa, gamma = " + num(law.gamma) + fit +
                "; *CYCLIC HARDENING = isotropic size) moves the back-stress with the slope of the kinematic curve at the "
                "accumulated plastic strain, C exp(-gamma ebar), instead of C + gamma |X| after a reversal, and its "
                "finite-strain formulation stores the back-stress in the reference configuration (it keeps growing with "
                "the stretch). Measured for card C.8, one C3D8 element: monotonic tension to 0.2 off by up to 7.8 %; "
                "after reversing by 0.1 the stress is -14 MPa instead of -120 MPa (docs/results/validation.md).");
  }
  return n;
}

}  // namespace

std::string export_calculix(const MaterialCard& card, std::vector<std::string>* notes_out, const ExportOptions& o) {
  if (card.params.yield.active())
    throw std::invalid_argument("card " + card.name + ": CalculiX has no built-in " + material::yield_function_title(card.params.yield.law) +
                                " (it needs a user material subroutine); export it to LS-DYNA (*MAT_BARLAT_YLD2000, MAT_133)");
  const ExportedLaw law = exported_law(card, o);
  const auto notes = calculix_notes(card, law, o);
  append(notes_out, notes);
  // CalculiX reads at most 20 characters per number.
  auto n20 = [](double v) { return format_real(v, 20); };
  std::ostringstream os;
  write_header(os, "** ", "CalculiX ccx (*MATERIAL block)", card, notes, 96);
  os << "*MATERIAL, NAME=" << deck_material_name(card) << "\n";
  os << "*ELASTIC\n" << n20(card.params.E) << ", " << n20(card.params.nu) << "\n";
  os << "*DENSITY\n" << n20(card.density) << "\n";
  if (law.plastic) {
    if (law.kinematic < 0 || !o.calculix_combined_hardening) {
      os << "** von Mises stress [MPa], equivalent plastic strain"
         << (law.kinematic < 0 ? "" : " (isotropic equivalent of the kinematic hardening)")
         << "\n*PLASTIC\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) {
        os << n20(law.monotonic[i]) << ", " << n20(law.strain[i]) << "\n";
      }
    } else {
      os << "** kinematic curve: von Mises stress [MPa], equivalent plastic strain\n*PLASTIC, HARDENING=COMBINED\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) {
        os << n20(law.size.front() + rd_back_stress(law.C, law.gamma, law.strain[i])) << ", " << n20(law.strain[i]) << "\n";
      }
      os << "** isotropic size: von Mises stress [MPa], equivalent plastic strain\n*CYCLIC HARDENING\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) os << n20(law.size[i]) << ", " << n20(law.strain[i]) << "\n";
    }
  }
  return os.str();
}

}  // namespace spifit::reports
