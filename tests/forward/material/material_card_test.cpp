// Loading and validating material cards: every bundled card loads with the thesis values;
// bad cards fail with an InputError naming file, key and value.
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/io/input_error.hpp"
#include "forward/material/material_card.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "tests/support/cards.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

using namespace spifit;

TEST(MaterialCard, BundledCardsCarryTheThesisValues) {
  const auto c = test::card("aa3003o_c3c4");
  EXPECT_EQ(c.params.E, 72600.0);
  EXPECT_EQ(c.params.nu, 0.36);
  EXPECT_EQ(c.params.F, 1.224);
  EXPECT_EQ(c.params.N, 4.06);
  EXPECT_EQ(c.params.L, 4.06);
  EXPECT_EQ(c.params.hardening[material::SwiftHardening::K], 180.0);
  EXPECT_NEAR(material::hardening_stress(c.params, 0.0), 42.97, 5e-3);  // Table C.4
  const auto c7 = test::card("aa3003o_c7_af_shell");
  EXPECT_TRUE(material::is_kinematic<material::ArmstrongFrederick>(c7.params.kinematic));
  EXPECT_EQ(c7.params.kinematic[material::ArmstrongFrederick::CX], 51.4);
  EXPECT_EQ(c7.params.kinematic[material::ArmstrongFrederick::Xsat], 46.0);
  EXPECT_EQ(c7.params.H, 0.8067);
  EXPECT_EQ(test::card("aa3003o_c7n_af_shell").params.H, 0.807);
  const auto c8 = test::card("aa3003o_c8_ziegler_shell");
  EXPECT_TRUE(c8.hill().is_von_mises());
  EXPECT_TRUE(material::is_kinematic<material::Ziegler>(c8.params.kinematic));
  EXPECT_EQ(c8.params.kinematic[material::Ziegler::CA], 3000.0);
  EXPECT_EQ(c8.params.kinematic[material::Ziegler::GA], 56.9);
  for (const auto& n : test::thesis_card_names()) EXPECT_NO_THROW(test::card(n)) << n;
}

namespace {

struct TempCard {
  std::string path;
  explicit TempCard(const std::string& text) {
    path = (std::filesystem::temp_directory_path() / ("spifit_card_" + std::to_string(::getpid()) + "_" +
                                                      std::to_string(counter()++) + ".toml")).string();
    std::ofstream(path) << text;
  }
  ~TempCard() { std::filesystem::remove(path); }
  static int& counter() { static int c = 0; return c; }
};

const char* kValid = R"(
[elastic]
E = 72600.0
nu = 0.36
[hill]
F = 1.224
G = 1.193
H = 0.807
N = 4.06
[swift]
K = 180.0
eps0 = 0.00109
n = 0.21
)";

// Replaces `from` by `to` in the valid card and expects an error naming key and value.
void expect_error(const std::string& from, const std::string& to, const std::string& key, const std::string& value) {
  std::string text = kValid;
  const auto pos = text.find(from);
  ASSERT_NE(pos, std::string::npos) << from;
  text.replace(pos, from.size(), to);
  TempCard card(text);
  try {
    material::load_material_card(card.path);
    FAIL() << "no error for " << to;
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), card.path);
    EXPECT_EQ(e.key(), key);
    EXPECT_EQ(e.value(), value);
    const std::string w = e.what();
    EXPECT_EQ(w.find('\n'), std::string::npos);
    EXPECT_NE(w.find(card.path), std::string::npos);
    EXPECT_NE(w.find(key), std::string::npos);
  }
}

}  // namespace

TEST(MaterialCard, ValidCardLoads) {
  TempCard card(kValid);
  const auto c = material::load_material_card(card.path);
  EXPECT_EQ(c.params.G, 1.193);
  EXPECT_TRUE(c.params.plastic);
}

TEST(MaterialCard, Errors) {
  expect_error("K = 180.0", "K = -5.0", "swift.K", "-5");
  expect_error("K = 180.0", "K = \"hard\"", "swift.K", "\"hard\"");
  expect_error("eps0 = 0.00109", "eps0 = 0.0", "swift.eps0", "0");
  expect_error("n = 0.21", "n = 1.2", "swift.n", "1.2");
  expect_error("E = 72600.0", "E = 0.0", "elastic.E", "0");
  expect_error("nu = 0.36", "nu = 0.5", "elastic.nu", "0.5");
  expect_error("nu = 0.36", "nu = 0.36\nnuu = 0.3", "elastic.nuu", "0.3");
  expect_error("N = 4.06", "N = -4.06", "hill.N", "-4.06");
  expect_error("F = 1.224\nG = 1.193", "F = -1.5\nG = -1.5", "hill.F", "-1.5");
  expect_error("H = 0.807", "H = -0.7", "hill.F/G/H", "1.224/1.193/-0.7");
  expect_error("[swift]", "[armstrong_frederick]\nCX = -1.0\nXsat = 3.0\n[swift]", "armstrong_frederick.CX", "-1");
  expect_error("E = 72600.0\n", "", "elastic.E", "");
  // A misspelt key is named as unknown, not as the missing one it was meant to be.
  expect_error("K = 180.0", "k = 180.0", "swift.k", "180");
  expect_error("n = 0.21", "n = 1.0", "swift.n", "1");  // the range [0, 1) of the named inputs
  expect_error("N = 4.06", "N = 4.06\nL = 0.0", "hill.L", "0");
  expect_error("[swift]", "[ziegler]\nCA = 10.0\nGA = -2.0\n[swift]", "ziegler.GA", "-2");
}

// The card accepts exactly what the named inputs allow: each parameter's error message is the
// one its InputInfo gives (one table for cards, fits, sweeps and the documentation).
TEST(MaterialCard, RangeMessagesComeFromTheNamedInputs) {
  TempCard card(std::string(kValid) + "[armstrong_frederick]\nCX = 1.0\nXsat = 2.0\n");
  const auto valid = material::load_material_card(card.path);
  for (const auto& in : material::material_inputs()) {
    if (in.info.range.lo == -std::numeric_limits<double>::infinity()) continue;  // Hill F, G, H: convexity
    auto c = valid;
    if (!material::holds_input(c.params, in)) {  // another law than the card's: 0.5 is in every coefficient's range
      if (in.field.kind == material::MaterialField::yield) {  // the registered function's defaults
        c.params.yield = material::YieldFunction<double>{in.field.law, {}};
        const auto& d = material::yield_function(in.field.law).defaults;
        for (std::size_t i = 0; i < d.size(); ++i) c.params.yield[static_cast<int>(i)] = d[i];
      } else if (in.field.kind == material::MaterialField::hardening) {
        c.params.hardening = material::Hardening<double>{in.field.law, {}};
        c.params.hardening.c.fill(0.5);
      } else {
        c.params.kinematic = material::Kinematic<double>{in.field.law, {}};
        c.params.kinematic.c.fill(0.5);
      }
    }
    material::set_material_input(c.params, in, in.info.range.lo - 1.0);
    try {
      material::validate_material_card(c);
      ADD_FAILURE() << in.info.name << " accepted " << in.info.range.lo - 1.0;
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.key(), in.card_key);
      EXPECT_NE(std::string(e.what()).find(in.info.check(in.info.range.lo - 1.0)), std::string::npos) << e.what();
    }
  }
}

TEST(MaterialCard, ElasticOnlyCardIsAllowed) {
  std::string text = kValid;
  text = text.substr(0, text.find("[swift]"));
  TempCard card(text);
  EXPECT_FALSE(material::load_material_card(card.path).params.plastic);
}

TEST(MaterialCard, MalformedTomlAndMissingFile) {
  TempCard card("[elastic\nE = 1");
  try {
    material::load_material_card(card.path);
    FAIL();
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), card.path);
    EXPECT_NE(std::string(e.what()).find("malformed TOML"), std::string::npos);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  EXPECT_THROW(material::load_material_card("/nonexistent/card.toml"), io::InputError);
}

TEST(MaterialCard, DescribeListsPredictedRValues) {
  const std::string d = material::describe_material_card(test::card("aa3003o_c3c4"));
  EXPECT_NE(d.find("42.967"), std::string::npos);  // initial yield stress
  EXPECT_NE(d.find("1.1798"), std::string::npos);  // r45 predicted by N = 4.06
  EXPECT_NE(d.find("72600"), std::string::npos);
}
