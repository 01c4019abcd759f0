#include "forward/io/input_error.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace spifit::io {

namespace {
std::string compose(const std::string& file, const std::string& key, const std::string& value,
                    const std::string& message) {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (!key.empty()) {
    s += ": " + key;
    if (!value.empty()) s += " = " + value;
  }
  s += ": " + message;
  return one_line(s, 400);
}
}  // namespace

InputError::InputError(std::string file, std::string key, std::string value, std::string message)
    : std::runtime_error(compose(file, key, value, message)), file_(std::move(file)),
      key_(std::move(key)), value_(std::move(value)), message_(std::move(message)) {}

std::string one_line(const std::string& text, std::size_t max_chars) {
  std::string out;
  bool space = false;
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  if (out.size() > max_chars) out = out.substr(0, max_chars - 3) + "...";
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string format_number(double v) {
  // Shortest text that reads back to the same double; plain decimals for everyday magnitudes.
  char buf[64];
  const double a = std::abs(v);
  if (a == 0.0 || (a >= 1e-4 && a < 1e15)) {
    for (int dec = 0; dec <= 20; ++dec) {
      std::snprintf(buf, sizeof buf, "%.*f", dec, v);
      if (std::strtod(buf, nullptr) == v) return buf;
    }
  }
  for (int prec = 1; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace spifit::io
