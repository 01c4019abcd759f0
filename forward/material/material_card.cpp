#include "forward/material/material_card.hpp"

#include "forward/io/toml_reader.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <sstream>

namespace spifit::material {

using io::format_number;
using io::InputError;

Hill48 MaterialCard::hill() const {
  return {params.F, params.G, params.H, params.L, params.M, params.N};
}

void MaterialCard::set_hill(const Hill48& h) {
  params.F = h.F; params.G = h.G; params.H = h.H;
  params.L = h.L; params.M = h.M; params.N = h.N;
}

namespace {

std::string card_table(const MaterialInput& in) { return in.card_key.substr(0, in.card_key.find('.')); }
std::string card_key(const MaterialInput& in) { return in.card_key.substr(in.card_key.find('.') + 1); }

// Reads the parameters of one card table, named by material_inputs(); [hill] may also give L and
// M, which default to N (the shell's transverse shear uses them, the fits tie them to N).
void read_law_table(const io::TomlTable& t, const std::string& table, MaterialParams<double>& p) {
  std::vector<const MaterialInput*> inputs;
  std::vector<std::string> keys;
  for (const auto& in : material_inputs()) {
    if (card_table(in) != table) continue;
    inputs.push_back(&in);
    keys.push_back(card_key(in));
  }
  if (table == "hill") keys.insert(keys.end(), {"L", "M"});
  t.allow_only(keys);  // an unknown key (a misspelt one) before a missing one
  for (const MaterialInput* in : inputs) set_material_input(p, *in, t.number(card_key(*in)));
  if (table == "hill") {
    p.L = t.number("L", p.N);
    p.M = t.number("M", p.N);
  }
}

}  // namespace

namespace {
constexpr double kHillSpread = 1e6;  // largest over smallest of F + G, G + H, H + F, N, L, M
}  // namespace

MaterialCard read_material_card(const io::TomlTable& root) {
  std::vector<std::string> tables{"card", "elastic", "hill", "density", "fitted"};
  for (const auto& law : yield_functions()) tables.push_back(law.name);
  for (const auto& law : hardening_laws()) tables.push_back(law.name);
  for (const auto& law : kinematic_laws()) tables.push_back(law.name);
  root.allow_only(tables);
  MaterialCard card;
  card.file = root.file();
  auto& p = card.params;

  if (auto t = root.table("card")) {
    t->allow_only({"name", "description", "source", "units"});
    card.name = t->string("name", "");
    card.description = t->string("description", "");
    card.source = t->string("source", "");
    const std::string units = t->string("units", "mm-N-MPa");
    if (units != "mm-N-MPa") t->fail("units", "only mm-N-MPa (mm, N, MPa, s, t) is supported");
  }
  if (card.name.empty()) {
    std::string stem = card.file;
    const auto slash = stem.find_last_of('/');
    if (slash != std::string::npos) stem = stem.substr(slash + 1);
    const auto dot = stem.rfind(".toml");
    card.name = dot == std::string::npos ? stem : stem.substr(0, dot);
  }
  card.density = root.number("density", card.density);
  if (auto f = root.table("fitted")) {
    f->allow_only({"fit_file", "start_card", "data", "spifit_version", "date", "usable"});
    FitProvenance fitted;
    fitted.fit_file = f->string("fit_file", "");
    fitted.start_card = f->string("start_card", "");
    if (f->has("data")) fitted.data = f->string_list("data");
    fitted.spifit_version = f->string("spifit_version", "");
    fitted.date = f->string("date", "");
    fitted.usable = f->boolean("usable", true);
    card.fitted = fitted;
  }

  auto elastic = root.table("elastic");
  if (!elastic) root.fail("elastic", "required table [elastic] (E, nu) is missing");
  read_law_table(*elastic, "elastic", p);
  if (auto h = root.table("hill")) read_law_table(*h, "hill", p);
  // no [hill]: von Mises (F = G = H = 1, N = L = M = 3), unless a registered function replaces it
  for (const auto& law : yield_functions()) {
    const auto t = root.table(law.name);
    if (!t) continue;
    if (root.table("hill")) root.fail(law.name, "a card has one yield function: [hill] or [" + law.name + "], not both");
    if (p.yield.active()) root.fail(law.name, "a card has one yield function; it also has [" + yield_function(p.yield.law).name + "]");
    p.yield = YieldFunction<double>{law.id, {}};
    read_law_table(*t, law.name, p);
  }
  // At most one hardening table; none: an elastic-only card.
  p.plastic = false;
  for (const auto& law : hardening_laws()) {
    const auto t = root.table(law.name);
    if (!t) continue;
    if (p.plastic) root.fail(law.name, "a card has at most one hardening law (" + hardening_table_list() + "); it also has [" + hardening_law(p.hardening.law).name + "]");
    p.plastic = true;
    p.hardening = Hardening<double>{law.id, {}};
    read_law_table(*t, law.name, p);
  }

  // At most one kinematic table, on a card with a hardening table.
  for (const auto& law : kinematic_laws()) {
    const auto t = root.table(law.name);
    if (!t) continue;
    if (p.kinematic.active()) root.fail(law.name, "a card has at most one kinematic law (" + kinematic_table_list() + ")");
    if (!p.plastic) root.fail(law.name, "kinematic hardening needs a hardening table (" + hardening_table_list() + ")");
    p.kinematic = Kinematic<double>{law.id, {}};
    read_law_table(*t, law.name, p);
  }
  validate_material_card(card);
  return card;
}

MaterialCard load_material_card(const std::string& path) {
  return read_material_card(io::TomlTable::parse_file(path));
}

void validate_material_card(const MaterialCard& card) {
  const auto& p = card.params;
  auto bad = [&](const std::string& key, double v, const std::string& msg) {
    throw InputError(card.file, key, format_number(v), msg);
  };
  for (const auto& in : material_inputs()) {  // each parameter of a law the card uses, alone
    if (!input_in_use(p, in)) continue;
    const double v = material_field(p, in.field);
    if (const std::string msg = in.info.check(v); !msg.empty()) bad(in.card_key, v, msg);
  }
  if (p.yield.active()) {  // a registered function: its own convexity check; F..N are unused
    const YieldFunctionInfo& law = yield_function(p.yield.law);
    int coefficient = 0;
    if (const std::string msg = law.violation(p.yield.c.data(), coefficient); !msg.empty())
      bad(law.name + "." + law.coefficients[static_cast<std::size_t>(coefficient)].key, p.yield[coefficient], "not a closed convex yield surface: " + msg);
    if (!(card.density > 0)) bad("density", card.density, "must be > 0 t/mm^3");
    return;
  }
  // Hill convexity (thesis eq. 3.5: a positive definite quadratic form); name the coefficient
  // involved in the violated condition.
  if (!(p.L > 0)) bad("hill.L", p.L, "must be > 0");
  if (!(p.M > 0)) bad("hill.M", p.M, "must be > 0");
  if (!(p.F + p.G > 0)) bad("hill.F", p.F, "F + G = " + format_number(p.F + p.G) + " must be > 0 (convex Hill)");
  if (!(p.G + p.H > 0)) bad("hill.G", p.G, "G + H = " + format_number(p.G + p.H) + " must be > 0 (convex Hill)");
  if (!(p.H + p.F > 0)) bad("hill.H", p.H, "H + F = " + format_number(p.H + p.F) + " must be > 0 (convex Hill)");
  if (const std::string msg = hill_convexity_violation(card.hill()); !msg.empty()) {
    throw InputError(card.file, "hill.F/G/H", format_number(p.F) + "/" + format_number(p.G) + "/" + format_number(p.H),
                     "not a convex yield surface: " + msg);
  }
  // Beyond any real sheet: measured r-values lie between about 0.2 and 6, so F + G, G + H, H + F
  // and N stay within a factor of about 50 of each other; a million is no anisotropy but a typo
  // (or a unit), and its yield surface a needle the return mapping cannot resolve.
  const double sums[] = {p.F + p.G, p.G + p.H, p.H + p.F, p.N, p.L, p.M};
  const double largest = *std::max_element(std::begin(sums), std::end(sums)), smallest = *std::min_element(std::begin(sums), std::end(sums));
  if (!(largest <= kHillSpread * smallest)) {
    const char* key = largest == sums[0] || largest == sums[2] ? "hill.F" : largest == sums[1] ? "hill.G" : largest == sums[3] ? "hill.N" : largest == sums[4] ? "hill.L" : "hill.M";
    const double value = largest == sums[0] || largest == sums[2] ? p.F : largest == sums[1] ? p.G : largest == sums[3] ? p.N : largest == sums[4] ? p.L : p.M;
    bad(key, value, "the Hill coefficients differ by more than a factor of a million (F + G, G + H, H + F, N, L, M from " + format_number(smallest) +
                        " to " + format_number(largest) + "): beyond any real sheet, whose r-values lie between about 0.2 and 6");
  }
  if (!(card.density > 0)) bad("density", card.density, "must be > 0 t/mm^3");
}

std::vector<std::string> material_card_warnings(const MaterialCard& card) {
  std::vector<std::string> out;
  if (card.fitted && !card.fitted->usable)
    out.push_back("it was written by a fit whose result is NOT USABLE (" + card.fitted->fit_file + "; its fit.json says why)");
  const Hill48 h = card.hill();
  const double deg[] = {0.0, 45.0, 90.0};
  for (double d : deg) {
    const double a = d * std::numbers::pi / 180.0;
    const double r = card.params.yield.active() ? uniaxial_r_value(card.params, a) : r_value_at_angle(h, a);
    if (!(r >= 0.1 && r <= 10.0)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "its r-value at %.0f deg to RD is %.4g, beyond any measured sheet (about 0.2 to 6)", d, r);
      out.push_back(buf);
    }
  }
  if (card.params.plastic) {
    const double s0 = hardening_stress(card.params, 0.0);
    if (!(s0 >= 1.0 && s0 <= 5000.0))
      out.push_back("its initial yield stress " + hardening_law(card.params.hardening.law).initial_formula + " = " + format_number(s0) + " MPa is beyond any sheet metal (about 20 to 2000 MPa): is the unit right (MPa)?");
  }
  return out;
}

std::string material_card_to_toml(const MaterialCard& card) {
  const auto& p = card.params;
  std::ostringstream os;
  auto esc = [](std::string s) {
    std::string o;
    for (char ch : s) {
      if (ch == '"' || ch == '\\') o += '\\';
      o += ch;
    }
    return o;
  };
  os << "# Units: mm, N, MPa, s, t.\n";
  os << "density = " << format_number(card.density) << "\n\n";
  os << "[card]\nname = \"" << esc(card.name) << "\"\n";
  if (!card.description.empty()) os << "description = \"" << esc(card.description) << "\"\n";
  if (!card.source.empty()) os << "source = \"" << esc(card.source) << "\"\n";
  os << "units = \"mm-N-MPa\"\n\n";
  if (card.fitted) {
    const FitProvenance& f = *card.fitted;
    os << "[fitted]  # this card was written by a fit\n";
    if (!f.usable) os << "usable = false   # the fit's result is NOT USABLE (its fit.json says why)\n";
    os << "fit_file = \"" << esc(f.fit_file) << "\"\nstart_card = \"" << esc(f.start_card) << "\"\ndata = [";
    for (std::size_t i = 0; i < f.data.size(); ++i) os << (i ? ", " : "") << "\"" << esc(f.data[i]) << "\"";
    os << "]\nspifit_version = \"" << esc(f.spifit_version) << "\"\ndate = \"" << esc(f.date) << "\"\n\n";
  }
  os << "[elastic]\nE = " << format_number(p.E) << "\nnu = " << format_number(p.nu) << "\n\n";
  if (p.yield.active()) {
    const YieldFunctionInfo& law = yield_function(p.yield.law);
    os << "[" << law.name << "]  # " << law.title << "\n";
    for (std::size_t i = 0; i < law.coefficients.size(); ++i)
      os << law.coefficients[i].key << " = " << format_number(p.yield[static_cast<int>(i)]) << "\n";
  } else {
    os << "[hill]  # thesis notation, eq. 3.5 (factor 1/2)\nF = " << format_number(p.F) << "\nG = " << format_number(p.G)
       << "\nH = " << format_number(p.H) << "\nN = " << format_number(p.N) << "\nL = " << format_number(p.L)
       << "\nM = " << format_number(p.M) << "\n";
  }
  if (p.plastic) {
    const HardeningLawInfo& law = hardening_law(p.hardening.law);
    os << "\n[" << law.name << "]\n";
    for (std::size_t i = 0; i < law.coefficients.size(); ++i)
      os << law.coefficients[i].key << " = " << format_number(p.hardening[static_cast<int>(i)]) << "\n";
  }
  if (p.kinematic.active()) {
    const KinematicLawInfo& law = kinematic_law(p.kinematic.law);
    os << "\n[" << law.name << "]\n";
    for (std::size_t i = 0; i < law.coefficients.size(); ++i)
      os << law.coefficients[i].key << " = " << format_number(p.kinematic[static_cast<int>(i)]) << "\n";
  }
  return os.str();
}

namespace {

// `material show`'s hardening, kinematic and initial-yield lines of a plastic card; returns
// sigma_F(0).
double describe_hardening(std::ostringstream& os, const MaterialParams<double>& p) {
  const double s0 = hardening_stress(p, 0.0);
  const HardeningLawInfo& law = hardening_law(p.hardening.law);
  os << "hardening      " << law.title << " " << law.formula << ":";
  for (std::size_t i = 0; i < law.coefficients.size(); ++i) {
    const HardeningCoefficient& c = law.coefficients[i];
    os << (i == 0 ? " " : ", ") << c.key << " = " << format_number(p.hardening[static_cast<int>(i)]) << (*c.unit ? " " : "") << c.unit;
  }
  os << (is_perfectly_plastic(p) ? " (perfectly plastic)" : "") << "\n";
  if (p.kinematic.active()) {
    const KinematicLawInfo& k = kinematic_law(p.kinematic.law);
    os << "kinematic      " << k.title;
    for (std::size_t i = 0; i < k.coefficients.size(); ++i) {
      const LawCoefficient& c = k.coefficients[i];
      os << (i == 0 ? " " : ", ") << c.key << " = " << format_number(p.kinematic[static_cast<int>(i)]) << (*c.unit ? " " : "") << c.unit;
    }
    os << k.saturation(p.kinematic.c.data()) << "\n";
  } else {
    os << "kinematic      none (isotropic hardening)\n";
  }
  os << "initial yield  sigma_F(0) = " << law.initial_formula << " = " << format_number(s0) << " MPa\n";
  return s0;
}

// `material show` of a card with a registered yield function (Yld2000-2d): its coefficients,
// hardening, and the uniaxial, equibiaxial and shear properties from its gradient.
std::string describe_registered_yield(const MaterialCard& card, std::string head) {
  const auto& p = card.params;
  const YieldFunctionInfo& y = yield_function(p.yield.law);
  std::ostringstream os;
  os << head << "yield          " << y.title << " " << y.formula << ":";
  for (std::size_t i = 0; i < y.coefficients.size(); ++i) os << (i == 0 ? " " : ", ") << y.coefficients[i].key << " = " << format_number(p.yield[static_cast<int>(i)]);
  os << "\n";
  if (!p.plastic) {
    os << "hardening      none (elastic-only card)\n";
    return os.str();
  }
  const double s0 = describe_hardening(os, p);
  char line[200];
  os << "uniaxial       angle   r-value   initial yield [MPa]\n";
  double r[3];
  int i = 0;
  for (double deg : {0.0, 45.0, 90.0}) {
    const double a = deg * std::numbers::pi / 180.0;
    r[i++] = uniaxial_r_value(p, a);
    std::snprintf(line, sizeof line, "               %5.0f   %7.4f   %8.3f\n", deg, r[i - 1], s0 / uniaxial_yield_factor(p, a));
    os << line;
  }
  std::snprintf(line, sizeof line, "               r_bar = (r0 + 2 r45 + r90)/4 = %.4f, delta_r = (r0 - 2 r45 + r90)/2 = %.4f\n",
                (r[0] + 2 * r[1] + r[2]) / 4, (r[0] - 2 * r[1] + r[2]) / 2);
  os << line;
  std::snprintf(line, sizeof line, "equibiaxial    initial yield %.3f MPa, r_b = %.4f\n", s0 / equibiaxial_yield_factor(p), equibiaxial_r_value(p));
  os << line;
  std::snprintf(line, sizeof line, "shear          initial yield tau = %.3f MPa\n", s0 / shear_yield_factor(p));
  os << line;
  for (const auto& w : material_card_warnings(card)) os << "warning        " << w << "\n";
  return os.str();
}

}  // namespace

std::string describe_material_card(const MaterialCard& card) {
  const auto& p = card.params;
  const Hill48 h = card.hill();
  std::ostringstream os;
  os << "material card  " << card.name << "\n";
  if (!card.description.empty()) os << "description    " << card.description << "\n";
  if (!card.source.empty()) os << "source         " << card.source << "\n";
  if (!card.file.empty()) os << "file           " << card.file << "\n";
  if (card.fitted) {
    const FitProvenance& f = *card.fitted;
    os << "fitted         by spifit " << f.spifit_version << " on " << f.date << " from " << f.fit_file << " (start card " << f.start_card
       << ")" << (f.usable ? "" : ": the fit was NOT USABLE") << "\n";
    for (const auto& d : f.data) os << "  data         " << d << "\n";
  }
  os << "elastic        E = " << format_number(p.E) << " MPa, nu = " << format_number(p.nu) << "\n";
  if (p.yield.active()) return describe_registered_yield(card, os.str());
  os << "yield          Hill 1948 (thesis notation, eq. 3.5)" << (h.is_von_mises() ? " = von Mises" : "") << ": F = "
     << format_number(h.F) << ", G = " << format_number(h.G) << ", H = " << format_number(h.H)
     << ", N = " << format_number(h.N) << ", L = " << format_number(h.L) << ", M = " << format_number(h.M) << "\n";
  if (std::abs(h.G + h.H - 2.0) > 1e-9) os << "               note: G + H = " << format_number(h.G + h.H) << " (not normalised to 2)\n";
  if (!p.plastic) {
    os << "hardening      none (elastic-only card)\n";
    return os.str();
  }
  const double s0 = describe_hardening(os, p);
  char line[160];
  os << "uniaxial       angle   r-value   initial yield [MPa]\n";
  for (double deg : {0.0, 45.0, 90.0}) {
    const double a = deg * std::numbers::pi / 180.0;
    std::snprintf(line, sizeof line, "               %5.0f   %7.4f   %8.3f\n", deg, r_value_at_angle(h, a),
                  s0 / uniaxial_stress_factor(h, a));
    os << line;
  }
  const Lankford r = lankford_from_hill(h);
  std::snprintf(line, sizeof line, "               r_bar = (r0 + 2 r45 + r90)/4 = %.4f, delta_r = (r0 - 2 r45 + r90)/2 = %.4f\n",
                (r.r0 + 2 * r.r45 + r.r90) / 4, (r.r0 - 2 * r.r45 + r.r90) / 2);
  os << line;
  std::snprintf(line, sizeof line, "shear          initial yield tau = sigma_F(0)/sqrt(N) = %.3f MPa\n", s0 / shear_stress_factor(h));
  os << line;
  const AbaqusPotential a = abaqus_potential_from_hill(h);
  std::snprintf(line, sizeof line, "Abaqus         *POTENTIAL R11..R23 = %.4f, %.4f, %.4f, %.4f, %.4f, %.4f\n", a.R11,
                a.R22, a.R33, a.R12, a.R13, a.R23);
  os << line;
  for (const auto& w : material_card_warnings(card)) os << "warning        " << w << "\n";
  return os.str();
}

}  // namespace spifit::material
