#include "tests/support/card_export_readers.hpp"

#include "forward/io/input_error.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace spifit::test {

namespace {

using io::trim;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

[[noreturn]] void fail(int line, const std::string& what) {
  throw std::runtime_error("line " + std::to_string(line) + ": " + what);
}

double to_double(const std::string& text, int line) {
  const std::string t = trim(text);
  if (t.empty()) return 0.0;
  // Fortran-style exponents (1.0D+03) are accepted by Abaqus and CalculiX.
  std::string c = t;
  std::replace(c.begin(), c.end(), 'D', 'E');
  std::replace(c.begin(), c.end(), 'd', 'e');
  char* end = nullptr;
  const double v = std::strtod(c.c_str(), &end);
  if (end == c.c_str() || *end != '\0') fail(line, "not a number: '" + t + "'");
  return v;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream is(text);
  std::string l;
  while (std::getline(is, l)) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    out.push_back(l);
  }
  return out;
}

}  // namespace

std::vector<InpKeyword> parse_inp_keywords(const std::string& deck) {
  std::vector<InpKeyword> out;
  const auto lines = lines_of(deck);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int ln = static_cast<int>(i) + 1;
    const std::string l = trim(lines[i]);
    if (l.empty() || l.rfind("**", 0) == 0) continue;
    if (l[0] == '*') {
      InpKeyword k;
      k.line = ln;
      const auto parts = split(l.substr(1), ',');
      // Keyword name: upper case with single blanks.
      std::istringstream words(upper(parts[0]));
      std::string w;
      while (words >> w) k.name += (k.name.empty() ? "" : " ") + w;
      for (std::size_t p = 1; p < parts.size(); ++p) {
        const std::string t = trim(parts[p]);
        if (t.empty()) continue;
        const auto eq = t.find('=');
        std::string key = upper(eq == std::string::npos ? t : t.substr(0, eq));
        key.erase(std::remove_if(key.begin(), key.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
                  key.end());
        k.parameters[key] = eq == std::string::npos ? "" : trim(t.substr(eq + 1));
      }
      out.push_back(std::move(k));
      continue;
    }
    if (out.empty()) fail(ln, "data line before any keyword");
    std::vector<double> row;
    auto fields = split(l, ',');
    if (!fields.empty() && trim(fields.back()).empty()) fields.pop_back();  // trailing comma
    for (const auto& f : fields) row.push_back(to_double(f, ln));
    out.back().rows.push_back(std::move(row));
  }
  return out;
}

InpMaterial read_inp_material(const std::string& deck) {
  const auto kws = parse_inp_keywords(deck);
  auto it = std::find_if(kws.begin(), kws.end(), [](const InpKeyword& k) { return k.name == "MATERIAL"; });
  if (it == kws.end()) throw std::runtime_error("no *MATERIAL keyword");
  InpMaterial m;
  if (auto n = it->parameters.find("NAME"); n != it->parameters.end()) m.name = n->second;
  static const std::vector<std::string> material_options = {"ELASTIC", "DENSITY", "PLASTIC", "CYCLIC HARDENING",
                                                            "POTENTIAL", "EXPANSION", "CONDUCTIVITY", "SPECIFIC HEAT",
                                                            "DEPVAR", "USER MATERIAL", "CREEP", "RATE DEPENDENT"};
  bool have_elastic = false;
  auto need = [](const InpKeyword& k, std::size_t row, std::size_t cols) -> const std::vector<double>& {
    if (k.rows.size() <= row || k.rows[row].size() < cols) {
      fail(k.line, "*" + k.name + " needs " + std::to_string(cols) + " values on data line " + std::to_string(row + 1));
    }
    return k.rows[row];
  };
  auto pairs = [](const InpKeyword& k) {
    std::vector<std::array<double, 2>> out;
    for (const auto& r : k.rows) {
      if (r.size() < 2) fail(k.line, "*" + k.name + ": data lines need (stress, plastic strain)");
      out.push_back({r[0], r[1]});
    }
    return out;
  };
  for (auto k = std::next(it); k != kws.end(); ++k) {
    if (std::find(material_options.begin(), material_options.end(), k->name) == material_options.end()) break;
    if (k->name == "ELASTIC") {
      if (auto t = k->parameters.find("TYPE"); t != k->parameters.end() && upper(t->second) != "ISO" &&
                                                 upper(t->second) != "ISOTROPIC") {
        fail(k->line, "only *ELASTIC, TYPE=ISO is read");
      }
      const auto& r = need(*k, 0, 2);
      m.E = r[0];
      m.nu = r[1];
      have_elastic = true;
    } else if (k->name == "DENSITY") {
      m.density = need(*k, 0, 1)[0];
    } else if (k->name == "PLASTIC") {
      if (auto h = k->parameters.find("HARDENING"); h != k->parameters.end()) m.hardening = upper(h->second);
      if (auto d = k->parameters.find("DATATYPE"); d != k->parameters.end()) m.data_type = upper(d->second);
      if (m.data_type == "PARAMETERS") {
        m.plastic_parameters = need(*k, 0, 1);
      } else {
        m.plastic = pairs(*k);
      }
    } else if (k->name == "CYCLIC HARDENING") {
      if (k->parameters.count("PARAMETERS")) fail(k->line, "*CYCLIC HARDENING, PARAMETERS is not read");
      m.cyclic_hardening = pairs(*k);
    } else if (k->name == "POTENTIAL") {
      // Six ratios, possibly over several data lines.
      std::vector<double> v;
      for (const auto& r : k->rows) v.insert(v.end(), r.begin(), r.end());
      if (v.size() < 6) fail(k->line, "*POTENTIAL needs six ratios R11, R22, R33, R12, R13, R23");
      m.potential = material::AbaqusPotential{v[0], v[1], v[2], v[3], v[4], v[5]};
    }
  }
  if (!have_elastic) fail(it->line, "material " + m.name + " has no *ELASTIC");
  return m;
}

namespace {

// Splits an LS-DYNA data card into fields: comma-separated if it has a comma, otherwise fixed
// width.
std::vector<std::string> dyna_fields(const std::string& line, std::size_t width) {
  if (line.find(',') != std::string::npos) {
    auto f = split(line, ',');
    for (auto& s : f) s = trim(s);
    return f;
  }
  std::vector<std::string> f;
  for (std::size_t p = 0; p < line.size(); p += width) f.push_back(trim(line.substr(p, width)));
  return f;
}

struct DynaKeyword {
  std::string name;  // upper case, without '*', options kept ("MAT_HILL_3R_TITLE")
  std::vector<std::pair<int, std::string>> cards;  // (line, text), comments removed
};

// The keywords of a deck with their data cards; long_format: *KEYWORD LONG=Y.
std::vector<DynaKeyword> dyna_keywords(const std::string& deck, bool* long_format) {
  const auto lines = lines_of(deck);
  std::vector<DynaKeyword> kws;
  *long_format = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.empty() || l[0] == '$') continue;
    if (l[0] == '*') {
      std::string name = upper(trim(l.substr(1)));
      if (name.rfind("KEYWORD", 0) == 0) {
        std::string opts = name.substr(7);
        opts.erase(std::remove(opts.begin(), opts.end(), ' '), opts.end());
        *long_format = opts.find("LONG=Y") != std::string::npos;
      }
      const bool plus = !name.empty() && name.back() == '+';
      if (plus) name.pop_back();
      kws.push_back({name, {}});
      continue;
    }
    if (!kws.empty()) kws.back().cards.emplace_back(static_cast<int>(i) + 1, l);
  }
  return kws;
}

double field_value(const std::vector<std::string>& f, std::size_t i, int line) { return i < f.size() ? to_double(f[i], line) : 0.0; }

// The cards of *MAT_HILL_3R / *MAT_ELASTIC (fields of width w).
void read_dyna_material_cards(const DynaKeyword& mat, bool title, std::size_t w, LsDynaMaterial& m) {
  const auto& get = field_value;
  std::size_t c = 0;
  auto card = [&](std::size_t n) -> const std::pair<int, std::string>& {
    if (mat.cards.size() <= n) throw std::runtime_error("*" + mat.name + ": card " + std::to_string(n + 1) + " missing");
    return mat.cards[n];
  };
  if (title) m.title = trim(card(c++).second);
  {
    const auto& [ln, text] = card(c++);
    const auto f = dyna_fields(text, w);
    m.mid = static_cast<int>(get(f, 0, ln));
    m.ro = get(f, 1, ln);
    m.e = get(f, 2, ln);
    m.pr = get(f, 3, ln);
    m.hr = get(f, 4, ln);
    m.p1 = get(f, 5, ln);
    m.p2 = get(f, 6, ln);
  }
  if (m.keyword == "MAT_ELASTIC") return;
  if (m.keyword == "MAT_BARLAT_YLD2000") {  // FIT, BETA, ITER; K, E0, N, C, P, HARD, A; the alphas
    m.fit = m.hr;
    m.beta = m.p1;
    m.iter = m.p2;
    m.hr = m.p1 = m.p2 = 0.0;
    {
      const auto& [ln, text] = card(c++);
      const auto f = dyna_fields(text, w);
      m.hard = get(f, 5, ln);
      m.exponent = get(f, 6, ln);
      m.lcid = m.hard < 0 ? static_cast<int>(-m.hard) : 0;
    }
    const auto& [ln, text] = card(c++);
    const auto f = dyna_fields(text, w);
    for (std::size_t i = 0; i < 8; ++i) m.alpha[i] = get(f, i, ln);
  } else {
    const auto& [ln, text] = card(c++);
    const auto f = dyna_fields(text, w);
    m.r00 = get(f, 0, ln);
    m.r45 = get(f, 1, ln);
    m.r90 = get(f, 2, ln);
    m.lcid = static_cast<int>(get(f, 3, ln));
    m.e0 = get(f, 4, ln);
  }
  if (c < mat.cards.size()) {
    const auto& [ln, text] = card(c++);
    m.aopt = get(dyna_fields(text, w), 0, ln);
  }
  if (c < mat.cards.size()) {
    const auto& [ln, text] = card(c++);
    const auto f = dyna_fields(text, w);
    m.a = {get(f, 3, ln), get(f, 4, ln), get(f, 5, ln)};
  }
  if (c < mat.cards.size()) {
    const auto& [ln, text] = card(c++);
    const auto f = dyna_fields(text, w);
    m.v = {get(f, 0, ln), get(f, 1, ln), get(f, 2, ln)};
    m.d = {get(f, 3, ln), get(f, 4, ln), get(f, 5, ln)};
    if (m.keyword != "MAT_BARLAT_YLD2000") m.beta = get(f, 6, ln);
  }
}

// The points of *DEFINE_CURVE m.lcid, scaled and offset; false when there is no such curve.
bool read_dyna_curve(const std::vector<DynaKeyword>& kws, std::size_t w, LsDynaMaterial& m) {
  const auto& get = field_value;
  for (const auto& k : kws) {
    if (k.name.rfind("DEFINE_CURVE", 0) != 0) continue;
    const bool ctitle = k.name.find("_TITLE") != std::string::npos;
    std::size_t cc = ctitle ? 1 : 0;
    if (k.cards.size() <= cc) continue;
    const auto& [ln, text] = k.cards[cc];
    const auto f = dyna_fields(text, w);
    if (static_cast<int>(get(f, 0, ln)) != m.lcid) continue;
    double sfa = get(f, 2, ln), sfo = get(f, 3, ln);
    if (sfa == 0.0) sfa = 1.0;
    if (sfo == 0.0) sfo = 1.0;
    const double offa = get(f, 4, ln), offo = get(f, 5, ln);
    for (std::size_t p = cc + 1; p < k.cards.size(); ++p) {
      const auto& [pl, pt] = k.cards[p];
      const auto pf = dyna_fields(pt, 20);  // point cards are 2 x 20 characters in both formats
      m.curve.push_back({sfa * (get(pf, 0, pl) + offa), sfo * (get(pf, 1, pl) + offo)});
    }
    return true;
  }
  return false;
}

}  // namespace

LsDynaMaterial read_lsdyna_material(const std::string& deck) {
  bool long_format = false;
  const auto kws = dyna_keywords(deck, &long_format);
  const std::size_t w = long_format ? 20 : 10;
  LsDynaMaterial m;
  const DynaKeyword* mat = nullptr;
  for (const auto& k : kws) {
    if (k.name.rfind("MAT_HILL_3R", 0) == 0 || k.name.rfind("MAT_122", 0) == 0 || k.name.rfind("MAT_ELASTIC", 0) == 0 ||
        k.name.rfind("MAT_BARLAT_YLD2000", 0) == 0 || k.name.rfind("MAT_133", 0) == 0 ||
        k.name.rfind("MAT_001", 0) == 0) {
      mat = &k;
      break;
    }
  }
  if (!mat) throw std::runtime_error("no *MAT_HILL_3R or *MAT_ELASTIC keyword");
  const bool title = mat->name.size() > 6 && mat->name.substr(mat->name.size() - 6) == "_TITLE";
  m.keyword = title ? mat->name.substr(0, mat->name.size() - 6) : mat->name;
  if (m.keyword == "MAT_122") m.keyword = "MAT_HILL_3R";
  if (m.keyword == "MAT_001") m.keyword = "MAT_ELASTIC";
  if (m.keyword == "MAT_133") m.keyword = "MAT_BARLAT_YLD2000";
  read_dyna_material_cards(*mat, title, w, m);
  if (m.keyword == "MAT_ELASTIC" || m.lcid == 0) return m;
  if (read_dyna_curve(kws, w, m)) return m;
  throw std::runtime_error("*DEFINE_CURVE " + std::to_string(m.lcid) + " (LCID of *" + mat->name + ") not found");
}

}  // namespace spifit::test
