// G-code reader: the SPIF line test (thesis §4.1.1) in absolute and incremental form, units,
// comments and ignored words, arcs (I/J, R, direction, chord error, helix, full circle) and
// the errors a user can make, each with file, line and word.
#include "forward/toolpath/gcode.hpp"

#include "forward/io/input_error.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

using namespace spifit::toolpath;
using spifit::io::InputError;

namespace {

constexpr double kPi = std::numbers::pi;

void expect_point(const Eigen::Vector3d& p, double x, double y, double z, double tol = 1e-12) {
  EXPECT_NEAR(p.x(), x, tol);
  EXPECT_NEAR(p.y(), y, tol);
  EXPECT_NEAR(p.z(), z, tol);
}

// Runs parse_gcode on text that must fail; returns the error.
InputError parse_error(const std::string& text, const GcodeOptions& o = {}) {
  try {
    parse_gcode(text, "prog.nc", o);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", "", "", "");
}

// Line test (thesis §4.1.1, Fig. 4.1): tool starts above the sheet at (0, 0, 50), rapid to (-50, 0,
// 10), plunge to z = -5, one pass along x, step down to z = -10, pass back.
GcodeOptions above_sheet() {
  GcodeOptions o;
  o.start = Eigen::Vector3d(0, 0, 50);
  return o;
}

void expect_line_test(const ToolPath& p) {
  const auto& w = p.waypoints();
  ASSERT_EQ(w.size(), 6u);
  expect_point(w[0].position, 0, 0, 50);
  expect_point(w[1].position, -50, 0, 10);
  expect_point(w[2].position, -50, 0, -5);
  expect_point(w[3].position, 50, 0, -5);
  expect_point(w[4].position, 50, 0, -10);
  expect_point(w[5].position, -50, 0, -10);
  EXPECT_EQ(w[1].feed, 0.0);  // rapid
  for (std::size_t i = 2; i < w.size(); ++i) EXPECT_NEAR(w[i].feed, 10.0, 1e-12);  // F600 mm/min
  // Rapid sqrt(50^2 + 40^2) = sqrt(4100) at 100 mm/s, then 15 + 100 + 5 + 100 = 220 mm at 10 mm/s.
  const double rapid = std::sqrt(4100.0);
  EXPECT_NEAR(p.length(), 220.0 + rapid, 1e-9);
  EXPECT_NEAR(p.duration(), 22.0 + rapid / 100.0, 1e-9);
}

// Largest sagitta of the chords of an arc about centre c (XY), and the largest deviation of
// a point's radius from r.
struct ArcCheck {
  double max_sagitta = 0.0, max_radius_error = 0.0;
};
ArcCheck check_arc(const std::vector<Waypoint>& w, std::size_t first, const Eigen::Vector2d& c,
                   double r) {
  ArcCheck a;
  for (std::size_t i = first; i < w.size(); ++i) {
    const Eigen::Vector2d p = w[i].position.head<2>();
    a.max_radius_error = std::max(a.max_radius_error, std::abs((p - c).norm() - r));
    if (i > first) {
      const Eigen::Vector2d mid = 0.5 * (p + w[i - 1].position.head<2>());
      a.max_sagitta = std::max(a.max_sagitta, r - (mid - c).norm());
    }
  }
  return a;
}

}  // namespace

TEST(Gcode, LineTestAbsolute) {
  const ToolPath p = parse_gcode(
      "%\n"
      "(SPIF line test, thesis 4.1.1)\n"
      "G21 G90 G17 G94\n"
      "G00 X-50 Y0 Z10\n"
      "G01 Z-5 F600\n"
      "G01 X50\n"
      "G01 Z-10\n"
      "G01 X-50\n"
      "M30\n"
      "%\n",
      "line.nc", above_sheet());
  expect_line_test(p);
  EXPECT_EQ(p.waypoints()[0].source_line, 0);
  EXPECT_EQ(p.waypoints()[1].source_line, 4);
  EXPECT_EQ(p.waypoints()[5].source_line, 8);
}

TEST(Gcode, LineTestIncrementalWithModalRepeats) {
  // Motion mode and F persist: the last three lines are coordinates only.
  const ToolPath p = parse_gcode(
      "G91\n"
      "G00 X-50 Y0 Z-40\n"
      "G01 Z-15 F600\n"
      "X100\n"
      "Z-5\n"
      "X-100\n",
      "line_inc.nc", above_sheet());
  expect_line_test(p);
}

TEST(Gcode, CommentsLineNumbersAndIgnoredWords) {
  const ToolPath p = parse_gcode(
      "; header comment\n"
      "\n"
      "N10 T1 M06 (tool change is ignored)\n"
      "N20 S1200 M03\n"
      "N30 g1 x10 (inline) f1200 ; lower case, trailing comment\n"
      "N40 Y 5\r\n"  // blank between letter and number, CRLF
      "M05\n"
      "M30\n",
      "c.nc");
  const auto& w = p.waypoints();
  ASSERT_EQ(w.size(), 3u);
  expect_point(w[1].position, 10, 0, 0);
  expect_point(w[2].position, 10, 5, 0);
  EXPECT_NEAR(w[2].feed, 20.0, 1e-12);
  EXPECT_EQ(w[1].source_line, 5);
  EXPECT_EQ(w[2].source_line, 6);
}

TEST(Gcode, InchUnitsScaleLengthsAndFeeds) {
  const ToolPath p = parse_gcode("G20 G90\nG01 X1 Y2 Z-0.5 F60\nG21\nG01 X0 F600\n", "inch.nc");
  const auto& w = p.waypoints();
  ASSERT_EQ(w.size(), 3u);
  expect_point(w[1].position, 25.4, 50.8, -12.7);
  EXPECT_NEAR(w[1].feed, 25.4, 1e-12);  // 60 in/min = 25.4 mm/s
  expect_point(w[2].position, 0, 50.8, -12.7);
  EXPECT_NEAR(w[2].feed, 10.0, 1e-12);
  // Incremental inches, arcs too: quarter circle of radius 1 in.
  const ToolPath a = parse_gcode("G20 G91 G01 F60\nG02 X1 Y-1 J-1\n", "inch_arc.nc");
  expect_point(a.waypoints().back().position, 25.4, -25.4, 0, 1e-12);
  EXPECT_LT(check_arc(a.waypoints(), 0, {0, -25.4}, 25.4).max_radius_error, 1e-9);
}

TEST(Gcode, QuarterCircleClockwiseIJ) {
  // From (0, 0) clockwise about (0, -10) to (10, -10): angle 90 deg -> 0 deg.
  GcodeOptions o;
  const ToolPath p = parse_gcode("G01 F600\nG02 X10 Y-10 I0 J-10\n", "arc.nc", o);
  const auto& w = p.waypoints();
  ASSERT_GT(w.size(), 3u);
  const ArcCheck a = check_arc(w, 0, {0, -10}, 10.0);
  EXPECT_LT(a.max_radius_error, 1e-9);
  EXPECT_LE(a.max_sagitta, o.arc_tolerance + 1e-12);
  EXPECT_GT(a.max_sagitta, 0.5 * o.arc_tolerance);  // not needlessly fine
  EXPECT_EQ(w.back().position, Eigen::Vector3d(10, -10, 0));  // end point exact
  for (std::size_t i = 1; i < w.size(); ++i) {
    EXPECT_GE(w[i].position.x(), -1e-12);  // the short clockwise way: x >= 0, y <= 0
    EXPECT_LE(w[i].position.y(), 1e-12);
    EXPECT_EQ(w[i].source_line, 2);
    EXPECT_NEAR(w[i].feed, 10.0, 1e-12);
    EXPECT_EQ(w[i].position.z(), 0.0);
  }
  // Polyline length below the arc length 5 pi by at most the chord-approximation error.
  EXPECT_LT(p.length(), 5.0 * kPi);
  EXPECT_GT(p.length(), 5.0 * kPi * (1.0 - o.arc_tolerance / 10.0));
}

TEST(Gcode, ArcByRadiusGivesTheSamePoints) {
  const ToolPath ij = parse_gcode("G01 F600\nG02 X10 Y-10 I0 J-10\n", "ij.nc");
  const ToolPath r = parse_gcode("G01 F600\nG02 X10 Y-10 R10\n", "r.nc");
  ASSERT_EQ(ij.waypoints().size(), r.waypoints().size());
  for (std::size_t i = 0; i < ij.waypoints().size(); ++i)
    EXPECT_LT((ij.waypoints()[i].position - r.waypoints()[i].position).norm(), 1e-9) << i;
  // R < 0: the longer arc (270 deg clockwise about (10, 0)).
  const ToolPath longer = parse_gcode("G01 F600\nG02 X10 Y-10 R-10\n", "rl.nc");
  EXPECT_LT(check_arc(longer.waypoints(), 0, {10, 0}, 10.0).max_radius_error, 1e-9);
  EXPECT_NEAR(longer.length(), 15.0 * kPi, 15.0 * kPi * 0.005 / 10.0);
}

TEST(Gcode, CounterClockwiseArcGoesTheOtherWay) {
  // Same end and centre as the G02 quarter, counter-clockwise: 90 -> 180 -> 270 -> 360 deg.
  const ToolPath p = parse_gcode("G01 F600\nG03 X10 Y-10 I0 J-10\n", "ccw.nc");
  const auto& w = p.waypoints();
  EXPECT_LT(check_arc(w, 0, {0, -10}, 10.0).max_radius_error, 1e-9);
  EXPECT_NEAR(p.length(), 15.0 * kPi, 15.0 * kPi * 0.005 / 10.0);
  // Second point is left of the start (counter-clockwise from the top of the circle).
  EXPECT_LT(w[1].position.x(), 0.0);
  double min_x = 0.0, min_y = 0.0;
  for (const auto& q : w) {
    min_x = std::min(min_x, q.position.x());
    min_y = std::min(min_y, q.position.y());
  }
  EXPECT_NEAR(min_x, -10.0, 0.005);
  EXPECT_NEAR(min_y, -20.0, 0.005);
  EXPECT_EQ(w.back().position, Eigen::Vector3d(10, -10, 0));
  // A counter-clockwise quarter: (0, 0) about (0, -10) to (-10, -10).
  const ToolPath q = parse_gcode("G01 F600\nG03 X-10 Y-10 R10\n", "ccwq.nc");
  EXPECT_LT(check_arc(q.waypoints(), 0, {0, -10}, 10.0).max_radius_error, 1e-9);
  EXPECT_NEAR(q.length(), 5.0 * kPi, 5.0 * kPi * 0.005 / 10.0);
  for (const auto& x : q.waypoints()) EXPECT_LE(x.position.x(), 1e-12);
}

TEST(Gcode, HelixFullCircle) {
  // To (10, 0, 0), then one clockwise turn about the origin descending to z = -1.
  GcodeOptions o;
  const double r = 10.0;
  const ToolPath p = parse_gcode("G01 X10 Y0 Z0 F600\nG02 X10 Y0 Z-1 I-10 J0\n", "helix.nc", o);
  const auto& w = p.waypoints();
  const ArcCheck a = check_arc(w, 1, {0, 0}, r);
  EXPECT_LT(a.max_radius_error, 1e-9);
  EXPECT_LE(a.max_sagitta, o.arc_tolerance + 1e-12);
  EXPECT_EQ(w.back().position, Eigen::Vector3d(10, 0, -1));
  // Z falls linearly with the swept (clockwise) angle.
  for (std::size_t i = 2; i + 1 < w.size(); ++i) {
    double swept = -std::atan2(w[i].position.y(), w[i].position.x());
    if (swept < 0.0) swept += 2.0 * kPi;
    EXPECT_NEAR(w[i].position.z(), -swept / (2.0 * kPi), 1e-9) << i;
  }
  // A chord of angle phi is shorter than its arc by the factor sin(phi/2)/(phi/2) >= 1 - phi^2/24
  // and the sagitta r (1 - cos(phi/2)) ~ r phi^2/8 <= tol, so the relative error is <= tol/(3 r).
  const double exact = std::sqrt(std::pow(2.0 * kPi * r, 2) + 1.0);
  const double helix = p.length() - 10.0;
  EXPECT_LT(helix, exact);
  EXPECT_GT(helix, exact * (1.0 - 1.01 * o.arc_tolerance / (3.0 * r)));
  // A plain full circle (no Z) with I only.
  const ToolPath c = parse_gcode("G01 X10 F600\nG03 I-10\n", "circle.nc");
  EXPECT_NEAR(c.length() - 10.0, 2.0 * kPi * r, 2.0 * kPi * r * o.arc_tolerance / (3.0 * r));
}

TEST(Gcode, CoarseToleranceStillKeepsQuarterTurns) {
  GcodeOptions o;
  o.arc_tolerance = 100.0;
  const ToolPath p = parse_gcode("G01 X10 F600\nG02 I-10\n", "coarse.nc", o);
  EXPECT_EQ(p.waypoints().size(), 2u + 4u);  // start, (10,0), four quarter chords
}

TEST(Gcode, ReadGcodeFromFile) {
  namespace fs = std::filesystem;
  const fs::path f = fs::temp_directory_path() / ("spifit_gcode_" + std::to_string(::getpid()) + ".nc");
  {
    std::ofstream out(f);
    out << "G00 X-50 Y0 Z10\nG01 Z-5 F600\nG01 X50\nG01 Z-10\nG01 X-50\n";
  }
  expect_line_test(read_gcode(f.string(), above_sheet()));
  fs::remove(f);
  try {
    read_gcode(f.string());
    FAIL() << "no error for a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), f.string());
    EXPECT_EQ(e.message(), "cannot read file");
  }
}

TEST(Gcode, UnsupportedCodeNamesLineAndWord) {
  const InputError e = parse_error("G21\nG90\nG41 X1 F600\n");
  EXPECT_EQ(e.key(), "line 3");
  EXPECT_EQ(e.value(), "G41");
  const std::string what = e.what();
  EXPECT_NE(what.find("line 3"), std::string::npos) << what;
  EXPECT_NE(what.find("G41"), std::string::npos) << what;
  EXPECT_EQ(what.rfind("prog.nc: ", 0), 0u) << what;  // FILE: KEY = VALUE: message
}

TEST(Gcode, OtherUnsupportedWords) {
  for (const char* word : {"G43", "G28", "G18", "G19", "G04", "G17.1", "K1", "H1", "P2", "M98", "E5"}) {
    const InputError e = parse_error(std::string("G01 F600\n") + word + "\n");
    EXPECT_EQ(e.key(), "line 2") << word;
    EXPECT_EQ(e.value(), word) << e.what();
  }
}

TEST(Gcode, ArcEndOffTheCircle) {
  const InputError e = parse_error("G01 F600\nG02 X10 Y-9 I0 J-10\n");
  EXPECT_EQ(e.key(), "line 2");
  EXPECT_NE(e.message().find("not on the circle"), std::string::npos) << e.what();
  // Within 1e-3 mm x max(1, r) it is accepted and the programmed end is hit exactly.
  const ToolPath p = parse_gcode("G01 F600\nG02 X10 Y-10.005 I0 J-10\n", "ok.nc");
  EXPECT_EQ(p.waypoints().back().position, Eigen::Vector3d(10, -10.005, 0));
  // R shorter than half the chord.
  EXPECT_NE(parse_error("G01 F600\nG02 X30 Y0 R10\n").message().find("not on the circle"),
            std::string::npos);
  // Radius zero.
  EXPECT_NE(parse_error("G01 F600\nG02 X0 Y0 I0 J0\n").message().find("radius is zero"),
            std::string::npos);
  EXPECT_NE(parse_error("G01 F600\nG02 X1 Y0 R0\n").message().find("radius is zero"),
            std::string::npos);
  // No centre, both centre forms, I/J outside an arc.
  EXPECT_EQ(parse_error("G01 F600\nG02 X10 Y-10\n").key(), "line 2");
  EXPECT_EQ(parse_error("G01 F600\nG02 X10 Y-10 R10 J-10\n").value(), "R10");
  EXPECT_EQ(parse_error("G01 X1 I2 F600\n").value(), "I2");
}

TEST(Gcode, FeedNotSet) {
  const InputError e = parse_error("G00 X0 Y0 Z5\nG01 Z-5\n");
  EXPECT_EQ(e.key(), "line 2");
  EXPECT_NE(e.message().find("feed rate not set"), std::string::npos) << e.what();
  EXPECT_EQ(parse_error("G02 X10 Y-10 J-10\n").key(), "line 1");
  EXPECT_EQ(parse_error("G01 X1 F0\n").value(), "F0");
  EXPECT_EQ(parse_error("G01 X1 F-5\n").value(), "F-5");
}

TEST(Gcode, MalformedInput) {
  const InputError e = parse_error("G01 F600\nG01 X1.2.3\n");
  EXPECT_EQ(e.key(), "line 2");
  EXPECT_EQ(e.value(), "X1.2.3");
  EXPECT_NE(e.message().find("malformed number"), std::string::npos);
  EXPECT_EQ(parse_error("G01 X F600\n").value(), "X");
  EXPECT_EQ(parse_error("G01 X1-2 F600\n").value(), "X1-2");
  EXPECT_EQ(parse_error("G01 F600\nG00 G01 X1\n").value(), "G01");  // two motion codes
  EXPECT_EQ(parse_error("G20 G21\n").value(), "G21");
  EXPECT_EQ(parse_error("G01 X1 X2 F600\n").value(), "X2");
  EXPECT_EQ(parse_error("G01 F600 (open comment\n").key(), "line 1");
  EXPECT_EQ(parse_error("G01 F600 /X1\n").value(), "/X1");
  EXPECT_EQ(parse_error("X1\n").key(), "line 1");  // no motion mode yet
  const InputError none = parse_error("G21 G90\n(no moves)\n");
  EXPECT_NE(none.message().find("no moves"), std::string::npos);
}

// X1e12 was reported as an unsupported word 'E' (the number ended at the 'e'); a number too
// long for a double as merely malformed.
TEST(Gcode, ExponentsAndHugeNumbersNameTheWord) {
  const InputError e = parse_error("G01 F600\nG01 X1e12 Y0\n");
  EXPECT_EQ(e.key(), "line 2");
  EXPECT_EQ(e.value(), "X1e12");
  EXPECT_EQ(std::string(e.what()).rfind("prog.nc: line 2 = X1e12: malformed number: G-code numbers have no exponent", 0), 0u) << e.what();
  EXPECT_EQ(parse_error("G01 F600\nG01 Z-2.5E-3\n").value(), "Z-2.5E-3");
  EXPECT_EQ(parse_error("G01 F600\nG01 X1e+5\n").value(), "X1e+5");
  const InputError huge = parse_error("G01 F600\nG01 X1" + std::string(400, '0') + "\n");
  EXPECT_EQ(huge.key(), "line 2");
  EXPECT_EQ(huge.message(), "number out of range");
  // A separate E word is still an unsupported word.
  EXPECT_EQ(parse_error("G01 F600\nG01 X1 E5\n").value(), "E5");
}

TEST(Gcode, RejectsMeaninglessOptions) {
  GcodeOptions o;
  o.arc_tolerance = 0.0;
  EXPECT_THROW(parse_gcode("G00 X1\n", "o.nc", o), std::invalid_argument);
  o = GcodeOptions{};
  o.rapid_feed = 0.0;
  EXPECT_THROW(parse_gcode("G00 X1\n", "o.nc", o), std::invalid_argument);
}
