#pragma once
// A material card: the constitutive parameters of one material, read from a TOML file
// (schema in docs/reference/file-formats.md) and validated.
#include "forward/material/hill48.hpp"
#include "forward/material/material_params.hpp"

#include <optional>
#include <string>
#include <vector>

namespace spifit::io { class TomlTable; }

namespace spifit::material {

// Where a fitted card comes from (its [fitted] table; docs/reference/file-formats.md): the fit
// file, the card the fit started from, the measurement files, the spifit version and the date
// (UTC, YYYY-MM-DD), and whether the fit was usable.
struct FitProvenance {
  std::string fit_file, start_card, spifit_version, date;
  std::vector<std::string> data;
  bool usable = true;
};

struct MaterialCard {
  std::string name;         // short identifier, e.g. "aa3003o_c3c4"
  std::string description;  // one line
  std::string source;       // provenance (thesis tables)
  std::string file;         // where it was read from ("" if built in code)
  double density = 2.7e-9;  // t/mm^3
  MaterialParams<double> params;
  std::optional<FitProvenance> fitted;  // a card written by a fit ([fitted])

  Hill48 hill() const;
  void set_hill(const Hill48& h);
};

// Reads and validates a card; throws io::InputError naming file, key and value.
MaterialCard load_material_card(const std::string& path);
MaterialCard read_material_card(const io::TomlTable& root);

// Validates the parameters (convex Hill, E > 0, -1 < nu < 0.5, K > 0, eps0 > 0, 0 <= n < 1,
// kinematic constants >= 0); throws io::InputError with the card's file and the key.
void validate_material_card(const MaterialCard& card);

// What is legal but odd, one sentence each: a card written by a fit that was not usable; predicted
// r-values outside 0.1 to 10 (measured sheets lie between about 0.2 and 6), an initial yield
// stress outside 1 to 5000 MPa.
std::vector<std::string> material_card_warnings(const MaterialCard& card);

// The card as TOML in the schema read by load_material_card (round-trips exactly).
std::string material_card_to_toml(const MaterialCard& card);

// Readable summary: parameters, initial yield stress, predicted r-values (closed form).
std::string describe_material_card(const MaterialCard& card);

}  // namespace spifit::material
