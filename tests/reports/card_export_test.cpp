// Card exports (reports/card_export.hpp): every deck read back and compared with the card, the
// Hill notation checked against Abaqus's own definition of the potential, tables, options,
// names and malformed decks. card_export_equivalence_test.cpp runs the law each deck encodes.
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "reports/card_export.hpp"
#include "tests/support/card_export_readers.hpp"

#include "forward/material/hill48.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

using namespace spifit;
using material::MaterialCard;

namespace {

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// Expected values, written from the card independently of the exporter.
struct Expected {
  double h;           // sqrt((G+H)/2)
  double C, gamma;    // Abaqus nonlinear kinematic (RD-normalised)
  double size(const MaterialCard& c, double ebar) const {
    const auto& k = c.params.hardening.c;
    const double p = ebar / h;
    const std::string law = material::hardening_law(c.params.hardening.law).name;
    if (law == "voce") return (k[0] + k[1] * (1.0 - std::exp(-k[2] * p))) / h;
    if (law == "swift_voce")
      return (k[6] * k[0] * std::pow(k[1] + p, k[2]) + (1.0 - k[6]) * (k[3] + k[4] * (1.0 - std::exp(-k[5] * p)))) / h;
    return k[0] * std::pow(k[1] + p, k[2]) / h;  // Swift
  }
  double back(double ebar) const { return gamma == 0.0 ? C * ebar : C / gamma * (1.0 - std::exp(-gamma * ebar)); }
};

Expected expected(const MaterialCard& c) {
  const auto& p = c.params;
  Expected e{std::sqrt((p.G + p.H) / 2.0), 0.0, 0.0};
  if (material::is_kinematic<material::Ziegler>(p.kinematic)) {
    e.C = p.kinematic[material::Ziegler::CA] / (e.h * e.h);
    e.gamma = p.kinematic[material::Ziegler::GA] / e.h;
  } else if (material::is_kinematic<material::ArmstrongFrederick>(p.kinematic)) {
    const double k = ((p.G + p.H) * (p.G + p.H) + p.G * p.G + p.H * p.H) / (2.0 * (p.G + p.H));
    e.C = p.kinematic[material::ArmstrongFrederick::CX] * p.kinematic[material::ArmstrongFrederick::Xsat] * k / (e.h * e.h);
    e.gamma = p.kinematic[material::ArmstrongFrederick::CX] / e.h;
  }
  return e;
}

// Thesis eq. 3.5 (factor 1/2, L on xz, M on yz); s = xx, yy, zz, xy, xz, yz.
double thesis_sigma_eq(const MaterialCard& c, const std::array<double, 6>& s) {
  const auto& p = c.params;
  const double q = p.H * std::pow(s[0] - s[1], 2) + p.G * std::pow(s[0] - s[2], 2) + p.F * std::pow(s[1] - s[2], 2) +
                   2 * p.N * s[3] * s[3] + 2 * p.L * s[4] * s[4] + 2 * p.M * s[5] * s[5];
  return std::sqrt(0.5 * q);
}

// Abaqus's Hill potential from *POTENTIAL ratios (Abaqus Analysis User's Guide, "Anisotropic
// yield/creep": no factor 1/2, L on 23 = yz, M on 13 = zx).
double abaqus_hill(const material::AbaqusPotential& r, const std::array<double, 6>& s) {
  const double a = 1 / (r.R11 * r.R11), b = 1 / (r.R22 * r.R22), c = 1 / (r.R33 * r.R33);
  const double F = 0.5 * (b + c - a), G = 0.5 * (c + a - b), H = 0.5 * (a + b - c);
  const double N = 1.5 / (r.R12 * r.R12), M = 1.5 / (r.R13 * r.R13), L = 1.5 / (r.R23 * r.R23);
  return std::sqrt(F * std::pow(s[1] - s[2], 2) + G * std::pow(s[2] - s[0], 2) + H * std::pow(s[0] - s[1], 2) +
                   2 * L * s[5] * s[5] + 2 * M * s[4] * s[4] + 2 * N * s[3] * s[3]);
}

bool is_scaled_von_mises(const MaterialCard& c) {
  const auto& p = c.params;
  return p.F == p.G && p.G == p.H && std::abs(p.N - 3 * p.F) < 1e-12 && std::abs(p.L - 3 * p.F) < 1e-12 &&
         std::abs(p.M - 3 * p.F) < 1e-12;
}

void check_table(const MaterialCard& card, const std::vector<std::array<double, 2>>& rows, bool monotonic,
                 double tol, const char* what) {
  const Expected ex = expected(card);
  ASSERT_EQ(rows.size(), 151u) << what;
  EXPECT_EQ(rows.front()[1], 0.0) << what;
  EXPECT_NEAR(rows.back()[1], 2.0, 1e-15) << what;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double e = rows[i][1];
    if (i > 0) {
      EXPECT_GT(e, rows[i - 1][1]) << what;
    }
    const double want = ex.size(card, e) + (monotonic ? ex.back(e) : 0.0);
    EXPECT_LT(rel(rows[i][0], want), tol) << what << " row " << i << " ebar " << e;
  }
}

// Every numeric field of every data line of a ccx deck fits CalculiX's 20-character read.
void check_calculix_widths(const std::string& deck) {
  std::istringstream is(deck);
  std::string line;
  while (std::getline(is, line)) {
    if (line.empty() || line[0] == '*') continue;
    std::istringstream fs(line);
    std::string f;
    while (std::getline(fs, f, ',')) {
      const auto b = f.find_first_not_of(' ');
      EXPECT_LE(b == std::string::npos ? 0 : f.size() - b, 20u) << line;
    }
  }
}

}  // namespace

class CardExport : public ::testing::TestWithParam<std::string> {
 protected:
  MaterialCard card() const {
    for (const auto& c : test::all_test_cards()) {
      if (c.name == GetParam()) return c;
    }
    throw std::runtime_error("no test card " + GetParam());
  }
};

TEST_P(CardExport, AbaqusRoundTrip) {
  const auto c = card();
  std::vector<std::string> notes;
  const std::string deck = reports::export_abaqus(c, &notes);
  ASSERT_FALSE(notes.empty());
  const auto m = test::read_inp_material(deck);
  EXPECT_EQ(m.name, reports::deck_material_name(c));
  EXPECT_EQ(m.E, c.params.E);
  EXPECT_EQ(m.nu, c.params.nu);
  ASSERT_TRUE(m.density.has_value());
  EXPECT_EQ(*m.density, c.density);
  const Expected ex = expected(c);
  if (!c.params.plastic) {
    EXPECT_TRUE(m.plastic.empty() && m.plastic_parameters.empty() && !m.potential);
    return;
  }
  if (!c.params.kinematic.active()) {
    EXPECT_EQ(m.hardening, "ISOTROPIC");
    check_table(c, m.plastic, false, 1e-14, "*PLASTIC");
  } else {
    EXPECT_EQ(m.hardening, "COMBINED");
    EXPECT_EQ(m.data_type, "PARAMETERS");
    ASSERT_EQ(m.plastic_parameters.size(), 3u);
    EXPECT_LT(rel(m.plastic_parameters[0], ex.size(c, 0.0)), 1e-14);
    EXPECT_LT(rel(m.plastic_parameters[1], ex.C), 1e-14);
    EXPECT_LT(rel(m.plastic_parameters[2], ex.gamma), 1e-14);
    check_table(c, m.cyclic_hardening, false, 1e-14, "*CYCLIC HARDENING");
    if (material::is_kinematic<material::ArmstrongFrederick>(c.params.kinematic) && c.hill().is_von_mises()) {
      // The classic von Mises mapping: gamma = CX, C = 1.5 CX Xsat.
      EXPECT_LT(rel(m.plastic_parameters[1], 1.5 * c.params.kinematic[material::ArmstrongFrederick::CX] * c.params.kinematic[material::ArmstrongFrederick::Xsat]), 1e-14);
      EXPECT_LT(rel(m.plastic_parameters[2], c.params.kinematic[material::ArmstrongFrederick::CX]), 1e-14);
    }
    if (material::is_kinematic<material::Ziegler>(c.params.kinematic) && c.hill().is_von_mises()) {
      EXPECT_EQ(m.plastic_parameters[1], c.params.kinematic[material::Ziegler::CA]);
      EXPECT_EQ(m.plastic_parameters[2], c.params.kinematic[material::Ziegler::GA]);
    }
  }
  if (is_scaled_von_mises(c)) {
    EXPECT_FALSE(m.potential.has_value());
    return;
  }
  ASSERT_TRUE(m.potential.has_value());
  // The ratios are the existing hill48 conversion scaled by h (R11 = 1) ...
  const auto r0 = material::abaqus_potential_from_hill(c.hill());
  const auto& r = *m.potential;
  EXPECT_EQ(r.R11, 1.0);
  EXPECT_LT(rel(r.R22, r0.R22 * ex.h), 1e-14);
  EXPECT_LT(rel(r.R33, r0.R33 * ex.h), 1e-14);
  EXPECT_LT(rel(r.R12, r0.R12 * ex.h), 1e-14);
  EXPECT_LT(rel(r.R13, r0.R13 * ex.h), 1e-14);
  EXPECT_LT(rel(r.R23, r0.R23 * ex.h), 1e-14);
  // ... and convert back to the card's Hill coefficients times 1/h^2.
  const auto back = material::hill_from_abaqus_potential(r);
  const double s = ex.h * ex.h;
  EXPECT_LT(rel(back.F * s, c.params.F), 1e-12);
  EXPECT_LT(rel(back.G * s, c.params.G), 1e-12);
  EXPECT_LT(rel(back.H * s, c.params.H), 1e-12);
  EXPECT_LT(rel(back.N * s, c.params.N), 1e-12);
  EXPECT_LT(rel(back.L * s, c.params.L), 1e-12);
  EXPECT_LT(rel(back.M * s, c.params.M), 1e-12);
}

// The Abaqus yield condition f(sigma) = sigma_0(ebar) and spifit's sigma_eq(sigma) = sigma_F(p)
// are the same surface for random stress states at every table point (ebar = h p).
TEST_P(CardExport, AbaqusYieldSurfaceEqualsCard) {
  const auto c = card();
  if (!c.params.plastic) GTEST_SKIP() << "elastic-only card";
  const auto m = test::read_inp_material(reports::export_abaqus(c, nullptr));
  const material::AbaqusPotential r = m.potential.value_or(material::AbaqusPotential{});
  const auto& table = !c.params.kinematic.active() ? m.plastic : m.cyclic_hardening;
  const double h = expected(c).h;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-200.0, 200.0);
  for (int k = 0; k < 50; ++k) {
    const std::array<double, 6> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    for (std::size_t i = 0; i < table.size(); i += 17) {
      const double p = table[i][1] / h;
      const double card_ratio = thesis_sigma_eq(c, s) / material::hardening_stress(c.params, p);
      const double deck_ratio = abaqus_hill(r, s) / table[i][0];
      EXPECT_LT(rel(deck_ratio, card_ratio), 1e-12);
    }
  }
}

TEST_P(CardExport, LsDynaRoundTrip) {
  const auto c = card();
  std::vector<std::string> notes;
  const std::string deck = reports::export_lsdyna(c, &notes);
  const auto m = test::read_lsdyna_material(deck);
  EXPECT_EQ(m.title, reports::deck_material_name(c));
  EXPECT_EQ(m.mid, 1);
  EXPECT_EQ(m.ro, c.density);
  EXPECT_EQ(m.e, c.params.E);
  EXPECT_EQ(m.pr, c.params.nu);
  if (!c.params.plastic) {
    EXPECT_EQ(m.keyword, "MAT_ELASTIC");
    return;
  }
  EXPECT_EQ(m.keyword, "MAT_HILL_3R");
  EXPECT_EQ(m.hr, 3.0);
  EXPECT_EQ(m.lcid, 1);
  const auto& p = c.params;
  EXPECT_LT(rel(m.r00, p.H / p.G), 1e-13);
  EXPECT_LT(rel(m.r45, (2 * p.N - p.F - p.G) / (2 * (p.F + p.G))), 1e-13);
  EXPECT_LT(rel(m.r90, p.H / p.F), 1e-13);
  // The r-values and the RD curve fix the in-plane Hill coefficients (thesis eq. C.3 scaled to G + H).
  const auto h = material::hill_from_lankford({m.r00, m.r45, m.r90});
  const double s = (p.G + p.H) / 2.0;
  EXPECT_LT(rel(h.F * s, p.F), 1e-12);
  EXPECT_LT(rel(h.G * s, p.G), 1e-12);
  EXPECT_LT(rel(h.H * s, p.H), 1e-12);
  EXPECT_LT(rel(h.N * s, p.N), 1e-12);
  EXPECT_EQ(m.aopt, 2.0);
  EXPECT_EQ(m.a, (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(m.d, (std::array<double, 3>{0, 1, 0}));
  std::vector<std::array<double, 2>> rows;
  for (const auto& pt : m.curve) rows.push_back({pt[1], pt[0]});
  check_table(c, rows, true, 1e-13, "*DEFINE_CURVE");
  // Every data line of the long format holds 20-character fields.
  std::istringstream is(deck);
  std::string line;
  while (std::getline(is, line)) {
    if (line.empty() || line[0] == '$' || line[0] == '*' || line.find_first_of("0123456789") == std::string::npos) continue;
    if (line.find_first_not_of(" 0123456789.eE+-") != std::string::npos) continue;  // titles
    EXPECT_EQ(line.size() % 20, 0u) << line;
  }
}

TEST_P(CardExport, CalculixRoundTrip) {
  const auto c = card();
  std::vector<std::string> notes;
  const std::string deck = reports::export_calculix(c, &notes);
  check_calculix_widths(deck);
  const auto m = test::read_inp_material(deck);
  EXPECT_EQ(m.E, c.params.E);
  EXPECT_EQ(m.nu, c.params.nu);
  EXPECT_EQ(m.density.value_or(0.0), c.density);
  EXPECT_FALSE(m.potential.has_value());
  if (!c.params.plastic) {
    EXPECT_TRUE(m.plastic.empty());
    return;
  }
  // Kinematic hardening goes in as its isotropic equivalent in monotonic RD tension by default.
  EXPECT_EQ(m.hardening, "ISOTROPIC");
  EXPECT_TRUE(m.cyclic_hardening.empty());
  check_table(c, m.plastic, true, 1e-13, "*PLASTIC");
  if (!c.params.kinematic.active()) return;
  // Optionally with ccx's own combined hardening.
  reports::ExportOptions o;
  o.calculix_combined_hardening = true;
  const std::string combined = reports::export_calculix(c, nullptr, o);
  check_calculix_widths(combined);
  const auto mc = test::read_inp_material(combined);
  EXPECT_EQ(mc.hardening, "COMBINED");
  check_table(c, mc.cyclic_hardening, false, 1e-13, "*CYCLIC HARDENING");
  // Kinematic curve: sigma_0(0) + X_RD(ebar).
  const Expected ex = expected(c);
  ASSERT_EQ(mc.plastic.size(), 151u);
  for (const auto& r : mc.plastic) EXPECT_LT(rel(r[0], ex.size(c, 0.0) + ex.back(r[1])), 1e-13);
}

TEST_P(CardExport, HeaderNamesCardUnitsAndEveryNote) {
  const auto c = card();
  for (auto f : {reports::ExportFormat::abaqus, reports::ExportFormat::lsdyna, reports::ExportFormat::calculix}) {
    std::vector<std::string> notes;
    const std::string deck = reports::export_card(c, f, &notes);
    const std::string cm = f == reports::ExportFormat::lsdyna ? "$ " : "** ";
    EXPECT_EQ(deck.rfind(cm + "spifit ", 0), 0u) << reports::to_string(f);
    EXPECT_NE(deck.find("\"" + c.name + "\""), std::string::npos);
    EXPECT_NE(deck.find("units: mm, N, s, t"), std::string::npos);
    ASSERT_FALSE(notes.empty());
    // Each note heads the deck (first words, before any line wrap).
    for (std::size_t i = 0; i < notes.size(); ++i) {
      const std::string start = std::to_string(i + 1) + ". " + notes[i].substr(0, 30);
      EXPECT_NE(deck.find(start), std::string::npos) << reports::to_string(f) << ": " << notes[i];
    }
    // No line is longer than the codes accept (Abaqus/CalculiX 256; LS-DYNA long format 160).
    std::istringstream is(deck);
    std::string line;
    while (std::getline(is, line)) EXPECT_LE(line.size(), 160u) << line;
  }
}

INSTANTIATE_TEST_SUITE_P(Cards, CardExport,
                         ::testing::Values("aa3003o_c2", "aa3003o_c3c4", "aa3003o_c5_af_brick", "aa3003o_c6_ziegler_brick",
                                           "aa3003o_c7_af_shell", "aa3003o_c7n_af_shell", "aa3003o_c8_ziegler_shell",
                                           "aa3003o_c5_af_brick_vm", "aa3003o_c7_af_shell_vm", "perfect_plastic",
                                           "elastic_only", "voce_test", "swift_voce_af_test"));

// Notes say what is approximate, and only then.
TEST(CardExportNotes, ApproximationsAreNamed) {
  auto joined = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
  };
  std::vector<std::string> n;
  reports::export_abaqus(test::card("aa3003o_c7_af_shell"), &n);
  std::string s = joined(n);
  EXPECT_NE(s.find("APPROXIMATION"), std::string::npos);
  EXPECT_NE(s.find("Abaqus/Explicit only"), std::string::npos);
  EXPECT_NE(s.find("Measured with spifit"), std::string::npos);
  EXPECT_NE(s.find("simple shear"), std::string::npos);
  EXPECT_NE(s.find("G + H = 1.9997"), std::string::npos);

  n.clear();
  reports::export_abaqus(test::card("aa3003o_c8_ziegler_shell"), &n);
  s = joined(n);
  EXPECT_EQ(s.find("APPROXIMATION"), std::string::npos);
  EXPECT_NE(s.find("exact"), std::string::npos);
  EXPECT_EQ(s.find("Explicit only"), std::string::npos);  // von Mises: Standard is fine

  n.clear();
  reports::export_abaqus(test::card("aa3003o_c3c4"), &n);
  s = joined(n);
  EXPECT_EQ(s.find("APPROXIMATION"), std::string::npos);
  EXPECT_NE(s.find("*ORIENTATION"), std::string::npos);

  n.clear();
  reports::export_calculix(test::card("aa3003o_c3c4"), &n);
  s = joined(n);
  EXPECT_NE(s.find("APPROXIMATION: CalculiX's *PLASTIC is von Mises"), std::string::npos);
  EXPECT_NE(s.find("r0/r45/r90 = 0.676/1.180/0.659"), std::string::npos);

  n.clear();
  reports::export_calculix(test::von_mises_copy(test::card("aa3003o_c3c4")), &n);
  EXPECT_EQ(joined(n).find("APPROXIMATION"), std::string::npos);

  n.clear();
  reports::export_calculix(test::card("aa3003o_c8_ziegler_shell"), &n);
  EXPECT_NE(joined(n).find("APPROXIMATION: kinematic hardening is written as its isotropic equivalent"), std::string::npos);
  n.clear();
  reports::ExportOptions combined;
  combined.calculix_combined_hardening = true;
  reports::export_calculix(test::card("aa3003o_c8_ziegler_shell"), &n, combined);
  EXPECT_NE(joined(n).find("APPROXIMATION: CalculiX's combined hardening"), std::string::npos);

  n.clear();
  reports::export_lsdyna(test::card("aa3003o_c8_ziegler_shell"), &n);
  s = joined(n);
  EXPECT_NE(s.find("APPROXIMATION: *MAT_122 has no kinematic hardening"), std::string::npos);
  EXPECT_NE(s.find("105.4 MPa"), std::string::npos);  // 2 CA/GA = 2 * 3000/56.9

  n.clear();
  reports::export_lsdyna(test::card("aa3003o_c3c4"), &n);
  s = joined(n);
  EXPECT_EQ(s.find("APPROXIMATION"), std::string::npos);
  EXPECT_NE(s.find("HR = 2"), std::string::npos);
}

TEST(CardExportTables, InterpolationErrorIsSmall) {
  for (const auto& c : test::all_test_cards()) {
    if (!c.params.plastic) continue;
    const auto law = reports::exported_law(c);
    EXPECT_LT(law.interpolation_error, 5e-4) << c.name;
    std::cout << "[ measured ] " << c.name << ": table interpolation error " << law.interpolation_error << "\n";
  }
  // eps0 far below the default first grid point: the grid starts at 0.1 h eps0.
  auto c = test::card("aa3003o_c3c4");
  c.params.hardening[material::SwiftHardening::eps0] = 1e-7;
  const auto law = reports::exported_law(c);
  EXPECT_LT(law.strain[1], 1.01e-8);
  EXPECT_LT(law.interpolation_error, 1e-3);
}

TEST(CardExportOptions, Validation) {
  reports::ExportOptions o;
  std::string err;
  EXPECT_TRUE(o.IsValid(&err));
  o.table_points = 250;
  EXPECT_FALSE(o.IsValid(&err));
  EXPECT_NE(err.find("200"), std::string::npos);
  EXPECT_THROW(reports::export_abaqus(test::card("aa3003o_c3c4"), nullptr, o), std::invalid_argument);
  o = {};
  o.table_points = 20;
  o.max_plastic_strain = 1.0;
  const auto m = test::read_inp_material(reports::export_abaqus(test::card("aa3003o_c3c4"), nullptr, o));
  ASSERT_EQ(m.plastic.size(), 21u);
  EXPECT_EQ(m.plastic.back()[1], 1.0);
}

TEST(CardExportFormat, NamesAndNumbers) {
  reports::ExportFormat f{};
  EXPECT_TRUE(reports::export_format_from_string("ls-dyna", &f));
  EXPECT_EQ(f, reports::ExportFormat::lsdyna);
  EXPECT_TRUE(reports::export_format_from_string("ccx", &f));
  EXPECT_EQ(f, reports::ExportFormat::calculix);
  EXPECT_FALSE(reports::export_format_from_string("nastran", &f));
  EXPECT_EQ(reports::default_extension(reports::ExportFormat::lsdyna), ".k");
  EXPECT_EQ(reports::format_real(0.36), "0.36");
  EXPECT_EQ(reports::format_real(72600.0), "72600");
  EXPECT_EQ(reports::format_real(2.7e-9), "2.7e-09");
  const double v = 1.0 / 3.0 * 1e-5;
  EXPECT_EQ(std::stod(reports::format_real(v)), v);
  const std::string s20 = reports::format_real(-v, 20);
  EXPECT_LE(s20.size(), 20u);
  EXPECT_LT(rel(std::stod(s20), -v), 1e-13);
  MaterialCard c = test::card("aa3003o_c3c4");
  c.name = "3003 O/shell";
  EXPECT_EQ(reports::deck_material_name(c), "M_3003_O_shell");
}

TEST(CardExportReaders, RejectMalformedDecks) {
  EXPECT_THROW(test::read_inp_material("*ELASTIC\n1, 2\n"), std::runtime_error);
  EXPECT_THROW(test::read_inp_material("*MATERIAL, NAME=A\n*ELASTIC\n72600, abc\n"), std::runtime_error);
  EXPECT_THROW(test::read_inp_material("*MATERIAL, NAME=A\n*DENSITY\n1e-9\n"), std::runtime_error);
  EXPECT_THROW(test::read_lsdyna_material("*KEYWORD\n*END\n"), std::runtime_error);
  // Abaqus syntax variants: blanks in parameter names, lower case, D exponents.
  const auto m = test::read_inp_material(
      "*Material, name=Al\n*Elastic\n7.26D+04, 0.36,\n*Plastic, hardening=combined, data type=parameters\n"
      "42.9, 3000, 56.9\n*Cyclic Hardening\n42.9, 0\n100, 1\n*Step\n");
  EXPECT_EQ(m.name, "Al");
  EXPECT_EQ(m.E, 72600.0);
  EXPECT_EQ(m.hardening, "COMBINED");
  EXPECT_EQ(m.data_type, "PARAMETERS");
  EXPECT_EQ(m.cyclic_hardening.size(), 2u);
}

// A Yld2000-2d card goes to LS-DYNA as *MAT_BARLAT_YLD2000: read back, the alphas times h and
// the exponent are the card's, the RD-normalised alphas give sigma_eq = 1 in RD tension, the
// curve is sigma_F(ebar / h) / h; Abaqus and CalculiX refuse it, naming LS-DYNA.
TEST(CardExportYld2000, LsDynaMat133RoundTrip) {
  using Y = material::Yld2000_2d;
  MaterialCard card = test::card("aa3003o_c3c4");
  card.params.yield = material::make_yield_function<Y>({1.01, 0.909, 1.0, 1.0, 1.015, 1.0, 1.09, 1.41, 8.0});
  std::vector<std::string> notes;
  const std::string deck = reports::export_lsdyna(card, &notes);
  const auto m = test::read_lsdyna_material(deck);
  EXPECT_EQ(m.keyword, "MAT_BARLAT_YLD2000");
  EXPECT_EQ(m.fit, 0.0);
  EXPECT_EQ(m.exponent, 8.0);
  ASSERT_EQ(m.lcid, 1);
  const double h = material::uniaxial_yield_factor(card.params, 0.0);
  auto back = card.params;
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(m.alpha[static_cast<std::size_t>(i)] * h, card.params.yield[i], 1e-13) << i;
    back.yield[i] = m.alpha[static_cast<std::size_t>(i)];
  }
  EXPECT_NEAR(material::uniaxial_yield_factor(back, 0.0), 1.0, 1e-13);
  // The exported law's r-values are the card's (normalising does not move the flow direction).
  for (double deg : {0.0, 45.0, 90.0})
    EXPECT_NEAR(material::uniaxial_r_value(back, test::deg(deg)), material::uniaxial_r_value(card.params, test::deg(deg)), 1e-12);
  ASSERT_FALSE(m.curve.empty());
  for (const auto& [e, s] : m.curve) EXPECT_NEAR(s, material::hardening_stress(card.params, e / h) / h, 1e-9 * s) << e;
  EXPECT_EQ(m.aopt, 2.0);
  for (const char* n : {"MAT_133", "alpha is divided by h"}) {
    bool found = false;
    for (const auto& line : notes) found = found || line.find(n) != std::string::npos;
    EXPECT_TRUE(found) << n;
  }
  for (auto f : {reports::export_abaqus, reports::export_calculix}) {
    try {
      f(card, nullptr, {});
      ADD_FAILURE() << "exported";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("MAT_133"), std::string::npos) << e.what();
    }
  }
  // With kinematic hardening: refused, naming the law.
  card.params.kinematic = material::make_kinematic<material::ArmstrongFrederick>({10.0, 20.0});
  EXPECT_THROW(reports::export_lsdyna(card, nullptr), std::invalid_argument);
}
