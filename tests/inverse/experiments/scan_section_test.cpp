// Laser-scan processing (thesis §8.2.1, footnotes 4, 5): synthetic point clouds of
// known surfaces with seeded Gaussian noise. The bin means must recover the surface, the 90 %
// band must hold about 90 % of the points of a second, independent cloud, the shifts must move
// the section by T/2 vertically or along the normal; malformed files name file, line and value.
#include "forward/io/input_error.hpp"
#include "inverse/experiments/scan_section.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

namespace fs = std::filesystem;

namespace spifit::inverse {
namespace {

constexpr double kPi = std::numbers::pi;

// A 30 deg cone of the outer surface: flat bottom z = -20 tan 30 for r < 10, wall up to r = 30,
// flange z = 0 to r = 40.
double cone_z(double r) {
  const double t = std::tan(30.0 * kPi / 180.0);
  if (r < 10.0) return -20.0 * t;
  if (r < 30.0) return -(30.0 - r) * t;
  return 0.0;
}

// Points uniform in r in [0, 40] and in theta, z = cone_z(r) + N(0, sigma).
std::vector<Eigen::Vector3d> cone_cloud(unsigned seed, int n, double sigma) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ur(0.0, 40.0), ut(0.0, 2.0 * kPi);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i) {
    const double r = ur(rng), t = ut(rng);
    out.emplace_back(r * std::cos(t), r * std::sin(t), cone_z(r) + noise(rng));
  }
  return out;
}

TEST(ScanSection, QuantilesInterpolateBetweenOrderStatistics) {
  const std::vector<double> v{1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_DOUBLE_EQ(sorted_quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(sorted_quantile(v, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(sorted_quantile(v, 0.05), 1.2);
  EXPECT_DOUBLE_EQ(sorted_quantile(v, 0.95), 4.8);
  EXPECT_DOUBLE_EQ(sorted_quantile(v, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(sorted_quantile({7.0}, 0.3), 7.0);
}

TEST(ScanSection, RadiusBinsRecoverAConeAndTheBandHoldsNinetyPercent) {
  const double sigma = 0.05;
  const auto cloud = cone_cloud(1, 200000, sigma);
  ScanSectionOptions o;
  o.bin = 0.5;
  const ScanSection s = average_scan_section(cloud, o);
  ASSERT_EQ(s.bins.size(), 80u);
  EXPECT_EQ(s.points_used, 200000);
  double worst = 0.0;
  for (const auto& b : s.bins) {
    if (b.lower < 10.0 && b.upper > 10.0) continue;  // none: 10 and 30 are bin limits
    // A linear surface over the bin: the mean point lies on it (noise: sigma / sqrt(2500)).
    worst = std::max(worst, std::abs(b.mean.y() - cone_z(b.mean.x())));
  }
  EXPECT_LT(worst, 0.005);
  // Flat bins: the band is +-1.645 sigma (normal noise), within the sampling error.
  for (const auto& b : s.bins) {
    if (b.upper <= 10.0 || b.lower >= 30.0) {
      EXPECT_NEAR(b.band_high.y() - b.band_low.y(), 2.0 * 1.6449 * sigma, 0.12 * 2.0 * 1.6449 * sigma);
      EXPECT_NEAR(b.spread_std, sigma, 0.1 * sigma);
    }
    EXPECT_NEAR(b.inside, 0.9, 0.01);
  }
  // A second cloud: about 90 % of its points fall inside the band of their bin (wall bins
  // included: there the band also spans the slope across the bin).
  const auto fresh = cone_cloud(2, 100000, sigma);
  int in = 0, total = 0;
  for (const auto& p : fresh) {
    const double r = p.head<2>().norm();
    const auto& b = s.bins[static_cast<std::size_t>(std::min(79.0, std::floor(r / 0.5)))];
    ++total;
    in += p.z() >= b.band_low.y() && p.z() <= b.band_high.y() ? 1 : 0;
  }
  const double coverage = static_cast<double>(in) / total;
  std::printf("coverage of a fresh cloud: %.4f\n", coverage);
  EXPECT_NEAR(coverage, 0.90, 0.01);
}

TEST(ScanSection, ShiftsByHalfTheThicknessVerticallyOrAlongTheNormal) {
  const auto cloud = cone_cloud(3, 100000, 0.02);
  ScanSectionOptions o;
  o.bin = 1.0;
  const ScanSection plain = average_scan_section(cloud, o);
  o.shift = ScanShift::vertical;
  o.shift_thickness = 1.5;  // the thesis's vwall sheet: 0.75 mm
  const ScanSection up = average_scan_section(cloud, o);
  o.shift = ScanShift::normal;
  const ScanSection normal = average_scan_section(cloud, o);
  ASSERT_EQ(plain.bins.size(), up.bins.size());
  const double a = 30.0 * kPi / 180.0;
  for (std::size_t i = 0; i < plain.bins.size(); ++i) {
    const Eigen::Vector2d dv = up.bins[i].mean - plain.bins[i].mean, dn = normal.bins[i].mean - plain.bins[i].mean;
    EXPECT_NEAR(dv.x(), 0.0, 1e-12);
    EXPECT_NEAR(dv.y(), 0.75, 1e-12);
    EXPECT_NEAR((up.bins[i].band_high - plain.bins[i].band_high - dv).norm(), 0.0, 1e-12);
    EXPECT_NEAR(dn.norm(), 0.75, 1e-12);
    const double lo = plain.bins[i].lower;
    if (lo >= 12.0 && lo <= 27.0) {  // wall, neighbours on the wall: normal (-sin a, cos a)
      EXPECT_NEAR(dn.x(), -0.75 * std::sin(a), 5e-3);
      EXPECT_NEAR(dn.y(), 0.75 * std::cos(a), 5e-3);
    } else if (lo <= 8.0 || lo >= 31.0) {
      EXPECT_NEAR(dn.y(), 0.75, 1e-4);
    }
  }
}

TEST(ScanSection, AngleBinsFollowAVerticalWall) {
  // A cup: vertical wall r = 20 for z in [-20, 0], bottom z = -20; noise normal to the surface.
  // Radius bins cannot resolve the wall; rays from the origin (footnote 4) can.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.03);
  const auto cup = [&](int n) {
    std::vector<Eigen::Vector3d> out;
    for (int i = 0; i < n; ++i) {
      const double t = 2.0 * kPi * u(rng);
      double r = 0.0, z = 0.0;
      if (u(rng) < 0.5) {
        r = 20.0 + noise(rng);
        z = -20.0 * u(rng);
      } else {
        r = 20.0 * std::sqrt(u(rng));
        z = -20.0 + noise(rng);
      }
      out.emplace_back(r * std::cos(t), r * std::sin(t), z);
    }
    return out;
  };
  const auto cloud = cup(200000);
  ScanSectionOptions o;
  o.binning = ScanBinning::angle;
  o.bin = 1.0;
  const ScanSection s = average_scan_section(cloud, o);
  EXPECT_EQ(s.bins.size(), 90u);  // phi from 90 to 180 deg
  for (const auto& b : s.bins) {
    if (b.upper <= 134.0) {
      EXPECT_NEAR(b.mean.x(), 20.0, 0.01) << b.lower;  // on the wall
    }
    if (b.lower >= 136.0 && b.upper < 179.0) {
      EXPECT_NEAR(b.mean.y(), -20.0, 0.01) << b.lower;  // on the bottom
    }
    // The band lies on the ray through the mean point.
    const Eigen::Vector2d m = b.mean.normalized();
    EXPECT_NEAR(m.x() * b.band_low.y() - m.y() * b.band_low.x(), 0.0, 1e-9);
  }
  // A fresh cup: 90 % of its points lie inside the band (distance from the origin) of their bin.
  int in = 0, total = 0;
  for (const auto& p : cup(100000)) {
    const double r = p.head<2>().norm(), phi = std::atan2(r, p.z()) * 180.0 / kPi;
    const int k = static_cast<int>(std::floor(phi)) - 90;
    if (k < 0 || k >= 90) continue;
    const auto& b = s.bins[static_cast<std::size_t>(k)];
    const double rho = std::hypot(r, p.z());
    ++total;
    in += rho >= b.band_low.norm() && rho <= b.band_high.norm() ? 1 : 0;
  }
  EXPECT_NEAR(static_cast<double>(in) / total, 0.90, 0.01);
  // Normal shift on the wall: towards the axis.
  o.shift = ScanShift::normal;
  o.shift_thickness = 1.0;
  const ScanSection shifted = average_scan_section(cloud, o);
  EXPECT_NEAR(shifted.bins[20].mean.x() - s.bins[20].mean.x(), -0.5, 2e-3);
}

using test::temp_path;

TEST(ScanSection, MalformedCloudsNameFileLineAndValue) {
  const fs::path f = temp_path("bad.csv");
  std::ofstream(f) << "# scan\nx [mm],y [mm],z [mm]\n1,2,3\n4,abc,6\n";
  try {
    read_scan_cloud(f.string());
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), f.string());
    EXPECT_EQ(e.key(), "line 4, column y");
    EXPECT_EQ(e.value(), "abc");
  }
  std::ofstream(f) << "x,y\n1,2\n";
  try {
    read_scan_cloud(f.string());
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.value(), "z");
    EXPECT_NE(std::string(e.what()).find("columns: x, y"), std::string::npos) << e.what();
  }
  std::ofstream(f) << "x,y,z\n1,2,3\n4,5\n";
  try {
    read_scan_cloud(f.string());
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "line 3");
  }
  fs::remove(f);
  ScanSectionOptions o;
  o.bin = 0.0;
  EXPECT_EQ(o.validate(), "bin = 0: must be > 0");
  o.bin = 1.0;
  EXPECT_THROW(average_scan_section({{1.0, 0.0, 0.0}}, o), std::invalid_argument);  // fewer than 5 points in every bin
}

}  // namespace
}  // namespace spifit::inverse
