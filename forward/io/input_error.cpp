#include "forward/io/input_error.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace spifit::io {

namespace {
// The value of an error message is cut to this many bytes so that what is wrong still follows;
// the whole line to kMaxChars (room for a few long paths: a resume names the checkpoint and two
// scene files).
constexpr std::size_t kMaxValueChars = 80, kMaxChars = 600;

std::string compose(const std::string& file, const std::string& key, const std::string& value,
                    const std::string& message) {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (!key.empty()) {
    s += ": " + key;
    if (!value.empty()) s += " = " + one_line(value, kMaxValueChars);  // a whole line of a binary file, say
  }
  s += ": " + message;
  return one_line(s, kMaxChars);
}
}  // namespace

InputError::InputError(std::string file, std::string key, std::string value, std::string message)
    : std::runtime_error(compose(file, key, value, message)), file_(std::move(file)),
      key_(std::move(key)), value_(std::move(value)), message_(std::move(message)) {}

std::size_t printable_length(const std::string& text, std::size_t i) {
  const auto b = static_cast<unsigned char>(text[i]);
  if (b < 0x80) return (b < 0x20 || b == 0x7f) ? 0 : 1;
  const std::size_t n = b >= 0xC2 && b <= 0xDF ? 2 : b >= 0xE0 && b <= 0xEF ? 3 : b >= 0xF0 && b <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 0;
  const auto b1 = static_cast<unsigned char>(text[i + 1]);
  if (b == 0xC2 && b1 < 0xA0) return 0;  // U+0080..U+009F: C1 controls (U+009B is a terminal's CSI)
  // RFC 3629: no overlong forms (E0 80..9F, F0 80..8F), no surrogates (ED A0..BF), nothing past
  // U+10FFFF (F4 90..BF).
  if ((b == 0xE0 && b1 < 0xA0) || (b == 0xED && b1 > 0x9F) || (b == 0xF0 && b1 < 0x90) || (b == 0xF4 && b1 > 0x8F)) return 0;
  return n;
}

std::size_t first_non_text(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const std::size_t n = (c == '\t' || c == '\n' || c == '\r') ? 1 : printable_length(text, i);
    if (n == 0) return i;
    i += n;
  }
  return std::string::npos;
}

std::string one_line(const std::string& text, std::size_t max_chars) {
  const std::size_t room = max_chars > 3 ? max_chars - 3 : 0;  // for "..."
  std::string out;
  std::size_t keep = 0;  // the longest prefix of whole characters and escapes within room
  bool space = false;
  const auto add = [&](const std::string& unit) {
    if (space) out += ' ';
    space = false;
    out += unit;
    if (out.size() <= room) keep = out.size();
  };
  for (std::size_t i = 0; i < text.size() && out.size() <= max_chars; ++i) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      space = !out.empty();
      continue;
    }
    const std::size_t n = printable_length(text, i);
    if (n > 0) {
      add(text.substr(i, n));
      i += n - 1;
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
      add(hex);
    }
  }
  if (out.size() > max_chars) out = out.substr(0, keep) + "...";
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
