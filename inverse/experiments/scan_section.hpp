#pragma once
// Laser-scan processing as the thesis did it (thesis §8.2.1 and its footnotes 4, 5):
// a point cloud of the part's outer surface, centred on the cone axis (z axis), is averaged
// into one cross section with a 90 % band, then shifted by half the thickness to compare with
// the simulated mid-surface.
//
// Binning. The thesis groups "the points having approximately the same angle" between the z
// axis and the line from the origin to the point (footnote 4). Two binnings:
//  - radius (default): bins of width `bin` mm in r = sqrt(x^2 + y^2); the section point of a
//    bin is the mean (r, z) of its points; the band is across the section in z. Simple, but a
//    wall steeper than the bin can resolve (vwall's 90 deg stage) mixes heights.
//  - angle (footnote 4): bins of width `bin` deg in the angle phi between +z and the line from
//    the origin (0, 0, origin_z) to the point (phi = atan2(r, z - origin_z)); the section point
//    is the mean (r, z); the band lies along the ray from the origin through it, in the
//    distance rho of the points from the origin. Rays cross vertical walls; a flat flange at
//    the origin's height collapses into one bin.
// Band. The thesis gives "the 90 % confidence interval of these points" and plots it as the
// variability of the measurement (§8.2.1): a band meant to hold 90 % of the points, not a
// confidence interval of the mean. It is taken here as the empirical 5 % and 95 % quantiles
// (linear interpolation between order statistics) of the spread coordinate (z, or rho), which
// holds 90 % of the points whatever their distribution; the standard deviation is given too
// (mean +- 1.645 sigma is the same band for normal noise).
// Shift. The thesis shifted the outer-surface section by half the initial thickness (0.75 mm)
// to compare it with the mid-surface (footnote 5: with material projected vertically, as the
// sine law assumes, the vertical distance between the outer surface and the mid-surface is
// t0/2 everywhere, also on the wall): `vertical` moves every bin by +T/2 in z. `normal` moves
// it by T/2 along the section's unit normal on the tool side (from the neighbouring bin means:
// (-sin alpha, cos alpha) on a wall of angle alpha, towards the axis on a vertical wall): right
// for a thickness T measured normal to the wall.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace spifit::inverse {

// A measurement CSV (inverse/experiments/measurement.hpp: '#' comments, a header) with columns x, y, z
// [mm]; other columns are ignored. Throws io::InputError naming the file, line and value.
std::vector<Eigen::Vector3d> read_scan_cloud(const std::string& path);

enum class ScanBinning { radius, angle };
enum class ScanShift { none, vertical, normal };

struct ScanSectionOptions {
  ScanBinning binning = ScanBinning::radius;
  double bin = 0.5;            // mm (radius) or deg (angle), > 0
  double origin_z = 0.0;       // angle binning: the origin (0, 0, origin_z)
  int min_points = 5;          // bins with fewer points are left out
  double band = 0.90;          // fraction of the points inside the band, in (0, 1)
  ScanShift shift = ScanShift::none;
  double shift_thickness = 0.0;  // T: the section moves by T/2 (negative: the other way)
  // Empty when valid, else "OPTION = VALUE: what is wrong" (option names as the CLI's).
  std::string validate() const;
};

struct ScanBin {
  double lower = 0.0, upper = 0.0;  // bin limits (mm or deg)
  int points = 0;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();       // (r, z), shifted
  Eigen::Vector2d band_low = Eigen::Vector2d::Zero();   // (r, z) at the lower quantile, shifted
  Eigen::Vector2d band_high = Eigen::Vector2d::Zero();  // (r, z) at the upper quantile, shifted
  double spread_std = 0.0;  // standard deviation of z (radius binning) or rho (angle binning)
  double inside = 0.0;      // fraction of the bin's points within [low, high] of the spread coordinate
};

struct ScanSection {
  std::vector<ScanBin> bins;  // non-empty bins with >= min_points points, by increasing r (radius) or phi (angle)
  int points = 0, points_used = 0, bins_left_out = 0;
};

// Throws std::invalid_argument for invalid options or when no bin has min_points points.
ScanSection average_scan_section(const std::vector<Eigen::Vector3d>& cloud, const ScanSectionOptions& options);

// The q-quantile (q in [0, 1]) of sorted values, linear between order statistics (sorted[0] at
// q = 0, sorted[n - 1] at q = 1).
double sorted_quantile(const std::vector<double>& sorted, double q);

// section.csv (docs/reference/file-formats.md "Scan section").
std::string scan_section_csv(const ScanSection& s, const ScanSectionOptions& options);

}  // namespace spifit::inverse
