#include "forward/toolpath/gcode.hpp"

#include "forward/io/text_file.hpp"

#include "forward/io/input_error.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace spifit::toolpath {

namespace {

using io::InputError;

constexpr double kInch = 25.4;              // mm per inch (G20)
constexpr double kPi = std::numbers::pi;
constexpr std::size_t kMaxArcSegments = 1000000;  // guards against absurd arc_tolerance values

// One line being parsed: everything an error message needs.
struct Line {
  const std::string& file;
  int number;        // 1-based
  std::string code;  // the line without comments, trimmed

  [[noreturn]] void fail(const std::string& value, const std::string& message) const {
    throw InputError(file, "line " + std::to_string(number), value, message);
  }
  [[noreturn]] void fail_line(const std::string& message) const { fail(io::one_line(code), message); }
};

struct Word {
  char letter;       // upper case
  double value;      // as written (units not applied)
  std::string text;  // as written, for error messages
};

// Removes (comments) and '; comments'. Comments do not nest and do not span lines.
std::string strip_comments(const std::string& raw, const std::string& file, int number) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == ';') break;
    if (raw[i] == '(') {
      const auto close = raw.find(')', i);
      if (close == std::string::npos)
        throw InputError(file, "line " + std::to_string(number), io::one_line(raw.substr(i), 40),
                         "comment '(' is not closed on this line");
      out += ' ';  // a comment separates words
      i = close;
      continue;
    }
    out += raw[i];
  }
  return io::trim(out);
}

// A G-code number: optional sign, digits with at most one '.', at least one digit (no
// exponent: 'E' would be a word letter). None with *why set when it is not one.
std::optional<double> parse_number(const std::string& s, std::string* why) {
  *why = "malformed number";
  const std::size_t sign = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  int digits = 0, dots = 0;
  for (std::size_t k = sign; k < s.size(); ++k) {
    if (std::isdigit(static_cast<unsigned char>(s[k]))) ++digits;
    else if (s[k] == '.') ++dots;
    else return std::nullopt;
  }
  if (digits == 0 || dots > 1) return std::nullopt;
  const std::size_t i = s[0] == '+' ? 1 : 0;  // from_chars takes '-' but not '+'
  double v = 0.0;
  const auto r = std::from_chars(s.data() + i, s.data() + s.size(), v);
  if (r.ec == std::errc::result_out_of_range || (r.ec == std::errc() && !std::isfinite(v))) *why = "number out of range";
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Splits the comment-free code into words (a letter and a number; blanks are allowed between
// words and between a letter and its number).
std::vector<Word> split_words(const Line& line) {
  static const std::string kKnown = "GMNFXYZIJRST";
  std::vector<Word> words;
  const std::string& c = line.code;
  std::size_t i = 0;
  const auto blank = [&](std::size_t k) { return c[k] == ' ' || c[k] == '\t' || c[k] == '\r'; };
  while (i < c.size()) {
    if (blank(i)) {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(c[i]))) {
      std::size_t e = i;
      while (e < c.size() && !blank(e)) ++e;
      line.fail(c.substr(i, e - i), "expected a word (a letter followed by a number)");
    }
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c[i])));
    ++i;
    while (i < c.size() && blank(i)) ++i;
    std::string number;
    while (i < c.size() && (std::isdigit(static_cast<unsigned char>(c[i])) || c[i] == '.' ||
                            c[i] == '+' || c[i] == '-'))
      number += c[i++];
    const std::string text = std::string(1, letter) + number;
    // An exponent (X1e12) would otherwise end the number and start an unsupported word 'E'.
    const auto digit = [&](std::size_t k) { return k < c.size() && std::isdigit(static_cast<unsigned char>(c[k])); };
    if (!number.empty() && i < c.size() && (c[i] == 'e' || c[i] == 'E')) {
      std::size_t e = i + 1;
      if (e < c.size() && (c[e] == '+' || c[e] == '-')) ++e;
      if (digit(e)) {
        while (digit(e)) ++e;
        line.fail(text + c.substr(i, e - i), "malformed number: G-code numbers have no exponent (write the digits, e.g. X1500 for 1.5e3)");
      }
    }
    if (kKnown.find(letter) == std::string::npos)
      line.fail(text, std::string("unsupported word '") + letter + "'");
    std::string why;
    const auto v = parse_number(number, &why);
    if (!v) line.fail(text, why);
    words.push_back(Word{letter, *v, text});
  }
  return words;
}

// The integer code of a G or M word, or -1 when it is not an integer (G17.1 and the like).
int integer_code(const Word& w) {
  if (w.value < 0.0 || w.value > 999.0 || w.value != std::floor(w.value)) return -1;
  return static_cast<int>(w.value);
}

// Modal groups of the supported G codes (one code per group per line, as on real controllers).
enum Group { kMotion, kPlane, kUnits, kDistance, kFeedMode, kNumGroups };

int group_of(int g) {
  switch (g) {
    case 0: case 1: case 2: case 3: return kMotion;
    case 17: return kPlane;
    case 20: case 21: return kUnits;
    case 90: case 91: return kDistance;
    case 94: return kFeedMode;
    default: return -1;
  }
}

// The words of one line after the syntax checks.
struct Block {
  std::array<const Word*, kNumGroups> g{};  // G word per modal group, or null
  const Word *x = nullptr, *y = nullptr, *z = nullptr, *i = nullptr, *j = nullptr,
             *r = nullptr, *f = nullptr;
};

Block classify(const Line& line, const std::vector<Word>& words) {
  Block b;
  for (const Word& w : words) {
    const Word** slot = nullptr;
    switch (w.letter) {
      case 'G': {
        const int code = integer_code(w);
        const int group = code < 0 ? -1 : group_of(code);
        if (group < 0) line.fail(w.text, "unsupported G code");
        auto& s = b.g[static_cast<std::size_t>(group)];
        if (s) line.fail(w.text, "conflicts with " + s->text + " on the same line");
        s = &w;
        continue;
      }
      case 'M': {
        const int code = integer_code(w);
        if (!((code >= 0 && code <= 9) || code == 30)) line.fail(w.text, "unsupported M code");
        continue;
      }
      case 'N': case 'S': case 'T': continue;  // line numbers, spindle speed, tool: ignored
      case 'X': slot = &b.x; break;
      case 'Y': slot = &b.y; break;
      case 'Z': slot = &b.z; break;
      case 'I': slot = &b.i; break;
      case 'J': slot = &b.j; break;
      case 'R': slot = &b.r; break;
      case 'F': slot = &b.f; break;
      default: line.fail(w.text, "unsupported word");
    }
    if (*slot) line.fail(w.text, std::string("'") + w.letter + "' given twice on one line");
    *slot = &w;
  }
  return b;
}

struct ArcInput {
  Eigen::Vector3d start, end;
  bool clockwise;
  const Word *i, *j, *r;
  double scale;  // mm per program unit
  double feed;   // mm/s
  double tolerance;
};

// Appends the points of a G02/G03 arc (helix when Z changes) after its start point. The
// centre comes from I/J (incremental from the start) or from R (R > 0 the shorter arc). The
// radius is interpolated linearly from start to end so that the programmed end point is hit
// exactly even when it is off the circle by the accepted 1e-3 mm x max(1, radius).
void append_arc(const Line& line, const ArcInput& a, std::vector<Waypoint>& out) {
  const Eigen::Vector2d s = a.start.head<2>(), e = a.end.head<2>();
  Eigen::Vector2d c;
  bool full_circle = false;
  if (a.r) {
    if (a.i || a.j) line.fail(a.r->text, "give either R or I/J for an arc, not both");
    const double radius = a.r->value * a.scale;
    if (radius == 0.0) line.fail(a.r->text, "arc radius is zero");
    const double rabs = std::abs(radius);
    const Eigen::Vector2d chord = e - s;
    const double d = chord.norm();
    if (d <= 1e-9 * std::max(1.0, rabs))
      line.fail(a.r->text, "an R arc needs an end point different from its start (use I/J for "
                           "a full circle)");
    if (0.5 * d - rabs > 1e-3 * std::max(1.0, rabs))
      line.fail(a.r->text, "arc end point is not on the circle: the chord (" +
                               io::format_number(d) + " mm) is longer than the diameter");
    // Centre on the chord's perpendicular bisector: left of start->end for a short
    // counter-clockwise arc, right for a short clockwise one, mirrored for R < 0 (long arc).
    const double h = std::sqrt(std::max(0.0, rabs * rabs - 0.25 * d * d));
    const Eigen::Vector2d left(-chord.y() / d, chord.x() / d);
    const double side = (a.clockwise ? -1.0 : 1.0) * (radius > 0.0 ? 1.0 : -1.0);
    c = 0.5 * (s + e) + side * h * left;
  } else {
    if (!a.i && !a.j) line.fail_line("an arc needs I/J (centre) or R (radius)");
    c = s + a.scale * Eigen::Vector2d(a.i ? a.i->value : 0.0, a.j ? a.j->value : 0.0);
    full_circle = (e - s).norm() <= 1e-9 * std::max(1.0, (s - c).norm());
  }
  const double r0 = (s - c).norm(), r1 = (e - c).norm();
  if (r0 <= 1e-12) line.fail_line("arc radius is zero");
  if (std::abs(r1 - r0) > 1e-3 * std::max(1.0, r0))
    line.fail_line("arc end point is not on the circle (radius " + io::format_number(r0) +
                   " mm at the start, " + io::format_number(r1) + " mm at the end)");

  // Swept angle in (0, 2 pi], positive in the direction of travel.
  const double a0 = std::atan2(s.y() - c.y(), s.x() - c.x());
  const double a1 = std::atan2(e.y() - c.y(), e.x() - c.x());
  double sweep = 2.0 * kPi;
  if (!full_circle) {
    sweep = a.clockwise ? a0 - a1 : a1 - a0;
    while (sweep <= 0.0) sweep += 2.0 * kPi;
    while (sweep > 2.0 * kPi) sweep -= 2.0 * kPi;
  }
  // Chord error (sagitta) of a chord spanning angle phi on radius r: r (1 - cos(phi / 2)).
  // Largest phi with sagitta <= tolerance, capped at a quarter turn so that the polyline keeps
  // the arc's shape when the tolerance is coarse.
  const double rmax = std::max(r0, r1);
  double phi_max = kPi / 2.0;
  if (a.tolerance < rmax) phi_max = std::min(phi_max, 2.0 * std::acos(1.0 - a.tolerance / rmax));
  const double segments = std::ceil(sweep / phi_max);
  if (!(segments <= static_cast<double>(kMaxArcSegments)))
    line.fail_line("arc needs more than " + std::to_string(kMaxArcSegments) +
                   " segments for arc_tolerance " + io::format_number(a.tolerance) + " mm");
  const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(segments));
  const double dir = a.clockwise ? -1.0 : 1.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double u = static_cast<double>(k) / static_cast<double>(n);
    const double angle = a0 + dir * sweep * u;
    const double radius = r0 + (r1 - r0) * u;
    const Eigen::Vector3d p(c.x() + radius * std::cos(angle), c.y() + radius * std::sin(angle),
                            a.start.z() + (a.end.z() - a.start.z()) * u);
    out.push_back(Waypoint{p, a.feed, line.number});
  }
  out.push_back(Waypoint{a.end, a.feed, line.number});
}

// Controller state that persists from line to line.
struct Modal {
  int motion = -1;        // 0..3, -1 before the first motion code
  double scale = 1.0;     // mm per program unit (G21: 1, G20: 25.4)
  bool incremental = false;
  double feed = -1.0;     // mm/s, < 0 before the first F
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

void check_options(const GcodeOptions& o) {
  if (!o.start.allFinite()) throw std::invalid_argument("G-code start position must be finite");
  if (!std::isfinite(o.rapid_feed) || o.rapid_feed <= 0.0)
    throw std::invalid_argument("G-code rapid_feed must be > 0");
  if (!std::isfinite(o.arc_tolerance) || o.arc_tolerance <= 0.0)
    throw std::invalid_argument("G-code arc_tolerance must be > 0");
}

}  // namespace

ToolPath parse_gcode(const std::string& text, const std::string& file_name_for_errors,
                     const GcodeOptions& o) {
  check_options(o);
  const std::string& file = file_name_for_errors;
  Modal m;
  m.position = o.start;
  std::vector<Waypoint> points{Waypoint{o.start, 0.0, 0}};

  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const Line line{file, number, strip_comments(raw, file, number)};
    if (line.code.empty() || line.code[0] == '%') continue;
    const std::vector<Word> words = split_words(line);
    const Block b = classify(line, words);

    // Mode words act before the move on the same line.
    if (const Word* g = b.g[kUnits]) m.scale = integer_code(*g) == 20 ? kInch : 1.0;
    if (const Word* g = b.g[kDistance]) m.incremental = integer_code(*g) == 91;
    if (b.f) {
      if (!(b.f->value > 0.0)) line.fail(b.f->text, "feed rate must be > 0");
      m.feed = b.f->value * m.scale / 60.0;  // units/min -> mm/s
    }
    if (const Word* g = b.g[kMotion]) m.motion = integer_code(*g);

    const bool arc = m.motion == 2 || m.motion == 3;
    const Word* arc_word = b.i ? b.i : b.j ? b.j : b.r;
    if (arc_word && !arc) line.fail(arc_word->text, "I, J and R are only allowed with G02/G03");
    const bool move = b.x || b.y || b.z || (arc && arc_word);
    if (!move) continue;
    if (m.motion < 0) line.fail_line("coordinates without a motion mode (G00, G01, G02 or G03)");
    if (m.motion != 0 && m.feed < 0.0) line.fail_line("feed rate not set (no F word before this move)");

    Eigen::Vector3d target = m.position;
    const std::array<const Word*, 3> axes{b.x, b.y, b.z};
    for (int k = 0; k < 3; ++k) {
      const Word* w = axes[static_cast<std::size_t>(k)];
      if (!w) continue;  // a missing axis keeps its value
      target[k] = (m.incremental ? m.position[k] : 0.0) + w->value * m.scale;
    }
    if (!target.allFinite()) line.fail_line("coordinate out of range");
    if (arc) {
      append_arc(line, ArcInput{m.position, target, m.motion == 2, b.i, b.j, b.r, m.scale, m.feed,
                                o.arc_tolerance},
                 points);
    } else {
      points.push_back(Waypoint{target, m.motion == 0 ? 0.0 : m.feed, number});
    }
    m.position = target;
  }
  if (points.size() < 2) throw InputError(file, "", "", "the G-code program has no moves");
  return ToolPath(std::move(points), o.rapid_feed);
}

ToolPath read_gcode(const std::string& file, const GcodeOptions& o) { return parse_gcode(io::read_text_file(file), file, o); }

}  // namespace spifit::toolpath
