#pragma once
// Synthetic measurements (twin experiments): a material-point scene run with a known card,
// sampled every k increments, with seeded Gaussian noise on the response. The CSV header
// says it is synthetic and how it was made (command, card, noise, seed).
#include "forward/scenes/common/scene.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"

#include <cstdint>
#include <random>
#include <string>

namespace spifit::inverse {

struct SyntheticOptions {
  std::string x = "strain", y = "stress";
  double noise = 0.0;       // standard deviation of the added noise (units of y)
  std::uint64_t seed = 1;
  int every = 1;            // keep every k-th increment (the initial point is skipped)
  std::string command;      // the command line, recorded in the header
};

// Throws std::runtime_error if the scene fails; io::InputError for unknown columns.
std::string synthetic_measurement_csv(const scene::MaterialPointScene& scene, const SyntheticOptions& options);

// The same for an FE scene (indent, indent_line, line, cone, ...): its tool-force component
// options.y (fx, fy, fz, fr, ftheta) against options.x (depth, travel, time) from the start of
// the path to where x stops increasing (fe_experiment.hpp), every k-th increment.
std::string synthetic_force_curve_csv(const scene::Scene& scene, const SyntheticOptions& options);

// The section y = 0 of a forming scene at path point `point` (options.y: z or thickness against
// options.x: x or x0), every k-th node.
std::string synthetic_section_csv(const scene::Scene& scene, const std::string& point, const SyntheticOptions& options);

// A cone's central-third contour means (options.y: contour_mean_names()) against the contour.
std::string synthetic_contour_means_csv(const scene::Scene& scene, const SyntheticOptions& options);

// Standard normal deviates: std::mt19937_64 (its sequence is fixed by the C++ standard) and
// Box-Muller written out (std::normal_distribution differs between standard libraries), so
// the same seed gives the same numbers everywhere.
class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}
  double next();

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace spifit::inverse
