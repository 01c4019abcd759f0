#pragma once
// Material-card exports to other FE codes: Abaqus (*MATERIAL block), LS-DYNA (*MAT_HILL_3R +
// *DEFINE_CURVE) and CalculiX (*MATERIAL block). What each deck contains, the notation
// conversions and every approximation are in docs/reference/outputs.md.
//
// Every exporter writes the card in one "RD-normalised" form, exact for any Hill card:
//   h = sqrt((G + H)/2)              (sigma_eq of a unit uniaxial stress along RD)
//   sigma_0(ebar) = sigma_F(ebar/h)/h (yield-surface size = RD uniaxial yield stress)
//   ebar = h p                        (equivalent plastic strain work-conjugate to sigma_eq/h)
// so the reference stress of the tables is the RD tensile yield stress and R11 = 1 even when
// G + H != 2 (cards C.5 and C.7 print G + H = 1.9997). For G + H = 2, h = 1 and this is the
// card itself.
#include "forward/material/hill48.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/material_card.hpp"

#include <string>
#include <vector>

namespace spifit::reports {

enum class ExportFormat { abaqus, lsdyna, calculix };

std::string to_string(ExportFormat f);
// Accepts "abaqus", "lsdyna" (alias "ls-dyna"), "calculix" (alias "ccx"); false otherwise.
bool export_format_from_string(const std::string& s, ExportFormat* f);
// Usual file extension of a deck: ".inp" (Abaqus, CalculiX), ".k" (LS-DYNA).
std::string default_extension(ExportFormat f);

struct ExportOptions {
  // Hardening tables: 0, then table_points values on a geometric grid from first_plastic_strain
  // to max_plastic_strain (RD-equivalent plastic strain ebar). The first value is lowered to
  // 0.1 h eps0 when that is smaller, so that the Swift offset eps0 is resolved.
  double max_plastic_strain = 2.0;
  double first_plastic_strain = 1e-5;
  int table_points = 150;  // CalculiX keeps at most 200 points per curve
  int lsdyna_material_id = 1;
  int lsdyna_curve_id = 1;
  // CalculiX: write kinematic hardening with ccx's own combined model (*PLASTIC,
  // HARDENING=COMBINED + *CYCLIC HARDENING) instead of the isotropic equivalent in monotonic RD
  // tension (default). Measured worse (docs/reference/outputs.md): ccx's back-stress modulus is the table
  // slope at the accumulated strain and its back-stress is convected with the stretch.
  bool calculix_combined_hardening = false;
  // Measure (with spifit's own integrator) how far the exported law is from the card when the
  // export is approximate (Hill + Armstrong-Frederick in Abaqus) and print it in the notes.
  bool measure_approximations = true;

  bool IsValid(std::string* error) const;
};

// The law every deck encodes, in RD-normalised form (see the header comment).
struct ExportedLaw {
  double h = 1.0;                    // sqrt((G + H)/2)
  material::AbaqusPotential ratios;  // Abaqus *POTENTIAL ratios of the normalised Hill: R11 = 1
  material::Lankford lankford;       // r0, r45, r90 (LS-DYNA *MAT_122)
  bool plastic = true;
  std::vector<double> strain;     // ebar grid, strain[0] = 0
  std::vector<double> size;       // isotropic yield-surface size sigma_F(ebar/h)/h
  std::vector<double> monotonic;  // RD monotonic tension: size + X_RD(ebar)
  int kinematic = -1;  // the card's kinematic law (kinematic_laws.hpp); -1: none
  // Nonlinear kinematic hardening in Abaqus's (Ziegler) form, in ebar units:
  //   d alpha = C (sigma - alpha)/sigma_0 d ebar - gamma alpha d ebar,
  // giving X_RD(ebar) = (C/gamma)(1 - exp(-gamma ebar)) in monotonic RD tension.
  double C = 0.0, gamma = 0.0;
  bool kinematic_exact = true;  // false for Hill + Armstrong-Frederick (nearest (C, gamma))
  double interpolation_error = 0.0;  // max relative error of linear interpolation in the table
};

ExportedLaw exported_law(const material::MaterialCard& card, const ExportOptions& options = {});

// The law written to the Abaqus deck, as a spifit card: Hill/h^2, Swift K h^-(1+n), h eps0, n,
// and Ziegler CA = C, GA = gamma. Identical to the card (same curves at any angle and along any
// path) except for Hill + Armstrong-Frederick, where it is the nearest Ziegler-form law.
material::MaterialCard exported_equivalent_card(const material::MaterialCard& card);

// Back-stress contribution to the RD monotonic tension stress, (C/gamma)(1 - exp(-gamma ebar))
// (C ebar for gamma = 0).
double rd_back_stress(double C, double gamma, double ebar);

// Each exporter returns the deck text; `notes` (may be null) receives one line per
// approximation or convention, the same lines that head the deck as comments.
std::string export_abaqus(const material::MaterialCard& card, std::vector<std::string>* notes,
                          const ExportOptions& options = {});
std::string export_lsdyna(const material::MaterialCard& card, std::vector<std::string>* notes,
                          const ExportOptions& options = {});
std::string export_calculix(const material::MaterialCard& card, std::vector<std::string>* notes,
                            const ExportOptions& options = {});
std::string export_card(const material::MaterialCard& card, ExportFormat format, std::vector<std::string>* notes,
                        const ExportOptions& options = {});

// Material name as written in the decks: letters, digits and '_' (others replaced by '_'),
// starting with a letter, at most 80 characters (Abaqus and CalculiX limits).
std::string deck_material_name(const material::MaterialCard& card);

// Shortest text that reads back to exactly v; when max_width > 0 and that is longer, the
// most significant digits that fit (CalculiX reads at most 20 characters per number).
std::string format_real(double v, int max_width = 0);

}  // namespace spifit::reports
