#include "forward/io/toml_reader.hpp"

#include "forward/io/text_file.hpp"

#include <toml.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace spifit::io {

struct TomlTable::Impl {
  std::shared_ptr<const toml::value> root;
  const toml::value* table = nullptr;
  std::string file;
  std::string prefix;  // "" or "section."
};

namespace {
std::string scalar_text(const toml::value& v) {
  if (v.is_floating()) return format_number(v.as_floating());
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
  if (v.is_string()) return "\"" + v.as_string().str + "\"";
  if (v.is_array()) {
    std::string out = "[";
    for (const auto& e : v.as_array()) {
      if (out.size() > 1) out += ", ";
      out += scalar_text(e);
      if (out.size() > 60) return out + ", ...]";
    }
    return out + "]";
  }
  if (v.is_table()) return "{table}";
  return "?";
}
// toml11 reports syntax errors as a multi-line excerpt:
//   [error] toml::parse_key: an invalid key appeared.
//    --> file.toml
//     1 | [scene
//       | ^--- is not a valid key
// Condensed to "line 1: an invalid key appeared (is not a valid key): [scene".
std::string condense_syntax_error(const std::string& what) {
  std::istringstream in(what);
  std::string line, headline, number, excerpt, hint;
  while (std::getline(in, line)) {
    if (headline.empty() && line.rfind("[error]", 0) == 0) {
      headline = line.substr(7);
      const auto colon = headline.find(": ");
      if (headline.find("toml::") != std::string::npos && colon != std::string::npos) headline = headline.substr(colon + 2);
      continue;
    }
    const auto bar = line.find(" | ");
    if (bar == std::string::npos) continue;
    const std::string left = one_line(line.substr(0, bar)), right = line.substr(bar + 3);
    if (number.empty() && !left.empty() && std::all_of(left.begin(), left.end(), ::isdigit)) {
      number = left;
      excerpt = one_line(right, 60);
    } else if (hint.empty() && left.empty() && right.find('^') != std::string::npos) {
      hint = one_line(right.substr(right.find_first_not_of("^-~ ")), 80);
    }
  }
  if (headline.empty() || number.empty()) return one_line(what, 200);
  std::string out = "line " + number + ": " + one_line(headline, 120);
  if (!out.empty() && out.back() == '.') out.pop_back();
  if (!hint.empty()) out += " (" + hint + ")";
  if (!excerpt.empty()) out += ": " + excerpt;
  return out;
}

const char* type_name(const toml::value& v) {
  if (v.is_floating() || v.is_integer()) return "a number";
  if (v.is_boolean()) return "a boolean";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  if (v.is_table()) return "a table";
  return "a date or time";
}
}  // namespace

TomlTable::TomlTable(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

TomlTable TomlTable::parse_file(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "", "", "file not found");
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "", "not a regular file");
  // TOML is UTF-8 text. Checked here, before toml11 sees the bytes: a clearer message than the
  // parser's, and toml11 3.7.1 (Debian 12) reads a byte past its buffer when a literal string
  // holds invalid UTF-8 (the library's issue #199; found by tests/fuzz/fuzz_card).
  const std::string text = read_text_file(path);
  if (const std::size_t bad = first_non_text(text); bad != std::string::npos) {
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n');
    char byte[8];
    std::snprintf(byte, sizeof byte, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[bad])));
    throw InputError(path, "", "", "not a text file: line " + std::to_string(line) + " holds byte " + byte +
                                       ", which is no UTF-8 text (a TOML file is UTF-8 text)");
  }
  auto impl = std::make_shared<Impl>();
  try {
    std::istringstream in(text);
    impl->root = std::make_shared<const toml::value>(toml::parse(in, path));
  } catch (const toml::syntax_error& e) {
    // toml11 prints a multi-line excerpt; keep its first lines as one line.
    throw InputError(path, "", "", "malformed TOML, " + condense_syntax_error(e.what()));
  } catch (const std::exception& e) {
    throw InputError(path, "", "", std::string("cannot read TOML: ") + one_line(e.what(), 240));
  }
  impl->table = impl->root.get();
  impl->file = path;
  return TomlTable(impl);
}

const std::string& TomlTable::file() const { return impl_->file; }
std::string TomlTable::key_path(const std::string& key) const { return impl_->prefix + key; }
bool TomlTable::has(const std::string& key) const { return impl_->table->contains(key); }

std::vector<std::string> TomlTable::keys() const {
  std::vector<std::string> out;
  for (const auto& kv : impl_->table->as_table()) out.push_back(kv.first);
  std::sort(out.begin(), out.end());
  return out;
}

void TomlTable::fail(const std::string& key, const std::string& message) const {
  throw InputError(impl_->file, key_path(key), has(key) ? value_text(key) : "", message);
}

std::string TomlTable::value_text(const std::string& key) const {
  return has(key) ? scalar_text(impl_->table->at(key)) : "";
}

double TomlTable::number(const std::string& key) const {
  if (!has(key)) fail(key, "required key is missing");
  const toml::value& v = impl_->table->at(key);
  double x = 0.0;
  if (v.is_floating()) x = v.as_floating();
  else if (v.is_integer()) x = static_cast<double>(v.as_integer());
  else fail(key, std::string("expected a number, got ") + type_name(v));
  if (!std::isfinite(x)) fail(key, "must be finite");
  return x;
}
double TomlTable::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}
int TomlTable::integer(const std::string& key, int fallback) const {
  if (!has(key)) return fallback;
  const toml::value& v = impl_->table->at(key);
  constexpr double kLimit = 1e9;  // what an int holds, with room: no count spifit takes comes near it
  // A whole number written as a float (200.0, 1e3) is taken as the integer it is.
  double x = 0.0;
  if (v.is_integer()) x = static_cast<double>(v.as_integer());
  else if (v.is_floating() && std::isfinite(v.as_floating()) && v.as_floating() == std::floor(v.as_floating())) x = v.as_floating();
  else fail(key, std::string("expected a whole number, got ") + (v.is_floating() ? value_text(key) : std::string(type_name(v))));
  if (std::abs(x) > kLimit) fail(key, "too large for a count: at most 1000000000 (and far less is meant: see the key's valid range)");
  return static_cast<int>(x);
}
std::string TomlTable::string(const std::string& key) const {
  if (!has(key)) fail(key, "required key is missing");
  const toml::value& v = impl_->table->at(key);
  if (!v.is_string()) fail(key, std::string("expected a string, got ") + type_name(v));
  return v.as_string().str;
}
std::string TomlTable::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}
bool TomlTable::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const toml::value& v = impl_->table->at(key);
  if (!v.is_boolean()) fail(key, std::string("expected true or false, got ") + type_name(v));
  return v.as_boolean();
}
std::vector<double> TomlTable::number_list(const std::string& key) const {
  if (!has(key)) fail(key, "required key is missing");
  const toml::value& v = impl_->table->at(key);
  if (!v.is_array()) fail(key, std::string("expected an array of numbers, got ") + type_name(v));
  std::vector<double> out;
  for (const auto& e : v.as_array()) {
    if (e.is_floating()) out.push_back(e.as_floating());
    else if (e.is_integer()) out.push_back(static_cast<double>(e.as_integer()));
    else fail(key, std::string("array entries must be numbers, found ") + type_name(e));
    if (!std::isfinite(out.back())) fail(key, "array entries must be finite");
  }
  return out;
}
std::vector<std::string> TomlTable::string_list(const std::string& key) const {
  if (!has(key)) fail(key, "required key is missing");
  const toml::value& v = impl_->table->at(key);
  if (!v.is_array()) fail(key, std::string("expected an array of strings, got ") + type_name(v));
  std::vector<std::string> out;
  for (const auto& e : v.as_array()) {
    if (!e.is_string()) fail(key, std::string("array entries must be strings, found ") + type_name(e));
    out.push_back(e.as_string().str);
  }
  return out;
}

std::optional<TomlTable> TomlTable::table(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  const toml::value& v = impl_->table->at(key);
  if (!v.is_table()) fail(key, std::string("expected a table [") + key_path(key) + "], got " + type_name(v));
  auto impl = std::make_shared<Impl>(*impl_);
  impl->table = &v;
  impl->prefix = impl_->prefix + key + ".";
  return TomlTable(impl);
}

std::vector<TomlTable> TomlTable::table_array(const std::string& key) const {
  std::vector<TomlTable> out;
  if (!has(key)) return out;
  const toml::value& v = impl_->table->at(key);
  if (!v.is_array()) fail(key, std::string("expected an array of tables [[") + key_path(key) + "]], got " + type_name(v));
  const auto& arr = v.as_array();
  for (std::size_t i = 0; i < arr.size(); ++i) {
    if (!arr[i].is_table()) fail(key, "entries must be tables ([[" + key_path(key) + "]])");
    auto impl = std::make_shared<Impl>(*impl_);
    impl->table = &arr[i];
    impl->prefix = impl_->prefix + key + "[" + std::to_string(i) + "].";
    out.push_back(TomlTable(impl));
  }
  return out;
}

void TomlTable::allow_only(const std::vector<std::string>& allowed) const {
  for (const auto& k : keys()) {
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      std::ostringstream os;
      os << "unknown key (allowed:";
      for (const auto& a : allowed) os << ' ' << a;
      os << ')';
      fail(k, os.str());
    }
  }
}

}  // namespace spifit::io
