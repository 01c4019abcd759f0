// The Abaqus deck (*MATERIAL block; Standard and Explicit): docs/reference/outputs.md "Abaqus".
#include "reports/card_export.hpp"
#include "reports/card_export_text.hpp"

#include "forward/material/yield/yield_functions.hpp"

#include "forward/scenes/material_point/material_point_run.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spifit::reports {

using material::MaterialCard;
using namespace deck;

namespace {

// Largest stress differences between the card and the exported law (spifit's integrator for
// both): tension to 0.2 and back to 0.1 at 0, 45 and 90 degrees, and simple shear along RD to
// gamma = 0.2 and back to -0.1.
struct Deviation {
  double tension = 0.0, tension_peak = 0.0, tension_angle = 0.0;
  double shear = 0.0, shear_peak = 0.0;
  bool ok = true;
};

Deviation measure_deviation(const MaterialCard& card, const MaterialCard& exported) {
  Deviation d;
  auto run = [&](scene::MaterialPointKind kind, double angle, std::vector<double> path, double* worst, double* peak,
                 double* worst_angle) {
    scene::MaterialPointSetup s;
    s.kind = kind;
    s.angle_deg = angle;
    s.strain_path = std::move(path);
    s.increments = 150;
    s.want_r_value = false;
    s.want_offset_yield = false;
    const auto a = scene::run_material_point(card.params, s);
    const auto b = scene::run_material_point(exported.params, s);
    if (!a.ok || !b.ok || a.curve.size() != b.curve.size()) {
      d.ok = false;
      return;
    }
    for (std::size_t i = 0; i < a.curve.size(); ++i) {
      *peak = std::max(*peak, std::abs(a.curve[i].stress));
      const double e = std::abs(a.curve[i].stress - b.curve[i].stress);
      if (e > *worst) {
        *worst = e;
        if (worst_angle) *worst_angle = angle;
      }
    }
  };
  for (double angle : {0.0, 45.0, 90.0}) {
    run(scene::MaterialPointKind::tensile, angle, {0.2, 0.1}, &d.tension, &d.tension_peak, &d.tension_angle);
  }
  run(scene::MaterialPointKind::bauschinger, 0.0, {0.2, -0.1}, &d.shear, &d.shear_peak, nullptr);
  return d;
}

std::string kinematic_note(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const auto& p = card.params;
  std::string s;
  if (law.kinematic == material::kinematic_law_index<material::Ziegler>()) {
    s = "Ziegler kinematic hardening (eq. 3.9) is Abaqus's nonlinear kinematic law: C = CA/h^2 = " + num(law.C) +
        " MPa, gamma = GA/h = " + num(law.gamma) + " (CA = " + num(p.kinematic[material::Ziegler::CA]) + ", GA = " + num(p.kinematic[material::Ziegler::GA]) + ", h = " + num(law.h) +
        "): exact.";
  } else if (law.kinematic_exact) {
    s = "Armstrong-Frederick kinematic hardening (eq. 3.8, tensor components) with von Mises: gamma = CX/h = " +
        num(law.gamma) + ", C = 1.5 CX Xsat/h = " + num(law.C) + " MPa (CX = " + num(p.kinematic[material::ArmstrongFrederick::CX]) + ", Xsat = " + num(p.kinematic[material::ArmstrongFrederick::Xsat]) +
        "): exact for von Mises.";
  } else {
    s = "APPROXIMATION: Armstrong-Frederick (eq. 3.8) with Hill moves the back-stress along the Hill normal; no Abaqus "
        "(C, gamma) reproduces it. Exported the nearest Ziegler-form pair, matching the initial rate and the saturation "
        "of the RD tensile back-stress: gamma = CX/h = " + num(law.gamma) + ", C = CX Xsat k/h^2 = " + num(law.C) +
        " MPa, k = ((G+H)^2 + G^2 + H^2)/(2(G+H)) = " +
        num(((p.G + p.H) * (p.G + p.H) + p.G * p.G + p.H * p.H) / (2 * (p.G + p.H))) + " (1.5 for von Mises).";
    if (o.measure_approximations) {
      const Deviation d = measure_deviation(card, exported_equivalent_card(card));
      if (d.ok) {
        s += " Measured with spifit, card vs exported law: tension to 0.2 and back to 0.1 at 0/45/90 deg, largest "
             "stress difference " + fixed(d.tension, 1) + " MPa (" + fixed(100.0 * d.tension / d.tension_peak, 1) +
             " % of " + fixed(d.tension_peak, 1) + " MPa, at " + fixed(d.tension_angle, 0) +
             " deg); simple shear along RD to 0.2 and back to -0.1, " + fixed(d.shear, 1) + " MPa (" +
             fixed(100.0 * d.shear / d.shear_peak, 1) + " % of " + fixed(d.shear_peak, 1) +
             " MPa). Where this matters, use a user material (VUMAT) with spifit's law.";
      }
    }
  }
  return s;
}

std::vector<std::string> abaqus_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  auto n = common_notes(card, law, o, law.kinematic < 0 ? "*PLASTIC" : "*CYCLIC HARDENING",
                        "Abaqus keeps the last yield stress (perfectly plastic)");
  if (!card.params.plastic) return n;
  if (!all_ratios_one(law.ratios)) {
    n.push_back("Hill 1948: spifit stores the thesis notation (eq. 3.5, factor 1/2, von Mises F = G = H = 1, N = L = M "
                "= 3, L on xz, M on yz); *POTENTIAL takes stress ratios R11 = 1, R22 = sqrt((G+H)/(F+H)), R33 = "
                "sqrt((G+H)/(F+G)), R12 = sqrt(1.5 (G+H)/N), R13 = sqrt(1.5 (G+H)/L) (thesis L = xz), R23 = sqrt(1.5 "
                "(G+H)/M) (thesis M = yz); for G + H = 2 these are sqrt(2/(F+H)), sqrt(2/(F+G)), sqrt(3/N), ...");
    n.push_back("the ratios refer to the local material axes: give the section an *ORIENTATION with 1 = RD, 2 = TD, "
                "3 = ND.");
  } else {
    n.push_back("von Mises card: no *POTENTIAL (all stress ratios are 1).");
  }
  if (law.kinematic >= 0) {
    n.push_back(kinematic_note(card, law, o));
    n.push_back("combined hardening: *PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS gives sigma_0(0), C, gamma; "
                "*CYCLIC HARDENING gives the isotropic size sigma_0(ebar) (Swift).");
    if (!all_ratios_one(law.ratios)) {
      n.push_back("Abaqus/Standard allows nonlinear isotropic/kinematic hardening with the Mises yield surface only: "
                  "Hill (*POTENTIAL) + this kinematic hardening runs in Abaqus/Explicit only.");
    }
  }
  return n;
}

}  // namespace

std::string export_abaqus(const MaterialCard& card, std::vector<std::string>* notes_out, const ExportOptions& o) {
  if (card.params.yield.active())
    throw std::invalid_argument("card " + card.name + ": Abaqus has no built-in " + material::yield_function_title(card.params.yield.law) +
                                " (it needs a user material subroutine); export it to LS-DYNA (*MAT_BARLAT_YLD2000, MAT_133)");
  const ExportedLaw law = exported_law(card, o);
  const auto notes = abaqus_notes(card, law, o);
  append(notes_out, notes);
  std::ostringstream os;
  write_header(os, "** ", "Abaqus (*MATERIAL block; Standard and Explicit)", card, notes, 96);
  os << "*MATERIAL, NAME=" << deck_material_name(card) << "\n";
  os << "*DENSITY\n" << num(card.density) << "\n";
  os << "*ELASTIC\n" << num(card.params.E) << ", " << num(card.params.nu) << "\n";
  if (law.plastic) {
    if (law.kinematic < 0) {
      os << "** yield stress [MPa], equivalent plastic strain\n*PLASTIC\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) os << num(law.size[i]) << ", " << num(law.strain[i]) << "\n";
    } else {
      os << "** yield stress at zero plastic strain [MPa], C1 [MPa], gamma1\n";
      os << "*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n";
      os << num(law.size.front()) << ", " << num(law.C) << ", " << num(law.gamma) << "\n";
      os << "** size of the elastic range [MPa], equivalent plastic strain\n*CYCLIC HARDENING\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) os << num(law.size[i]) << ", " << num(law.strain[i]) << "\n";
    }
    if (!all_ratios_one(law.ratios)) {
      const auto& r = law.ratios;
      os << "** R11, R22, R33, R12, R13, R23 (1 = RD, 2 = TD, 3 = ND)\n*POTENTIAL\n";
      os << num(r.R11) << ", " << num(r.R22) << ", " << num(r.R33) << ", " << num(r.R12) << ", " << num(r.R13) << ", "
         << num(r.R23) << "\n";
    }
  }
  return os.str();
}

}  // namespace spifit::reports
