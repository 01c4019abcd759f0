#pragma once
// A one-element CalculiX check of an exported material block: one C3D8 unit cube, symmetry
// planes x = 0, y = 0, z = 0, prescribed displacement of the face x = L (NLGEOM), printing
// U, S, E and PEEQ at every increment to the .dat file. Used by tests/reports to compare ccx with
// spifit's tensile scene (docs/results/validation.md, "CalculiX check").
//
// Measures in the .dat file (ccx 2.20, NLGEOM): S is the Cauchy (true) stress, E the
// Green-Lagrange strain; log strain = ln(1 + u/L) = 0.5 ln(1 + 2 E11).
#include <string>
#include <vector>

namespace spifit::reports {

struct CalculixTensionOptions {
  // Log-strain targets of the face x = L, one *STEP each (e.g. {0.2} or {0.2, 0.1} for a
  // reversal); each step has `increments` equal increments (DIRECT).
  std::vector<double> log_strain_path{0.2};
  int increments = 100;
  double length = 1.0;  // mm
};

// Full input file: mesh, boundary conditions, `material_block` (a *MATERIAL block such as
// export_calculix writes, named `material_name`) and the steps.
std::string calculix_tension_deck(const std::string& material_block, const std::string& material_name,
                                  const CalculixTensionOptions& options = {});

struct CalculixTensionPoint {
  double time = 0.0;          // total time: step k runs from k-1 to k
  double u = 0.0;             // displacement of the face x = L [mm]
  double log_strain = 0.0;    // ln(1 + u/L)
  double stress = 0.0;        // Cauchy sxx [MPa], mean over the integration points
  double lagrange_strain = 0.0;  // Green-Lagrange exx, mean over the integration points
  double peeq = 0.0;          // equivalent plastic strain
};

// Parses the .dat file written for calculix_tension_deck; throws std::runtime_error when a
// block is missing or malformed.
std::vector<CalculixTensionPoint> read_calculix_tension_dat(const std::string& dat, double length = 1.0);

// Path of the ccx executable: $SPIFIT_CCX if set, else "ccx" when found on PATH, else "".
std::string find_calculix();

}  // namespace spifit::reports
