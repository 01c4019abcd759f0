#include "forward/scenes/cone/cone_sensitivities.hpp"

#include <cmath>

namespace spifit::scene {

namespace {

// Cartesian derivatives turned into (r, theta, z) at the tool centre's polar angle.
ForceDerivatives turned(ForceDerivatives d, const Eigen::Vector3d& centre) {
  for (Eigen::Index k = 0; k < d.cols(); ++k) d.col(k) = polar_components(d.col(k), centre);  // linear in the force
  return d;
}

}  // namespace

ForceDerivatives polar_sensitivity(const ConeResult& r, std::size_t i) { return turned(r.force_sensitivity(i), r.force.samples()[i].centre); }

std::optional<std::size_t> peak_polar_sample(const ConeResult& r, int k) {
  std::optional<std::size_t> at;
  double peak = 0.0;
  const auto& samples = r.force.samples();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double v = polar_components(samples[i].force, samples[i].centre)(k);
    if (std::abs(v) > std::abs(peak)) peak = v, at = i;
  }
  return at;
}

std::optional<SteadyStateDerivatives> steady_state_sensitivity(const ConeResult& r, int from, int to) {
  const auto& samples = r.force.samples();
  std::optional<SteadyStateDerivatives> out;
  int contours = 0;
  for (std::size_t k = 0; k < r.contours.size(); ++k) {
    const int c = static_cast<int>(k) + 1;
    const ContourMean& m = r.contours[k];
    if (c < from || c > to || m.samples == 0) continue;
    SteadyStateDerivatives mean;
    int n = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!m.span.central_third(samples[i].travel)) continue;
      const ForceDerivatives cartesian = r.force_sensitivity(i);
      if (cartesian.cols() == 0) return std::nullopt;
      if (n == 0) mean = {ForceDerivatives::Zero(3, cartesian.cols()), ForceDerivatives::Zero(3, cartesian.cols())};
      mean.force += cartesian;
      mean.polar += turned(cartesian, samples[i].centre);
      ++n;
    }
    if (n != m.samples) return std::nullopt;  // not the samples the mean was taken over
    if (!out) out = SteadyStateDerivatives{ForceDerivatives::Zero(3, mean.force.cols()), ForceDerivatives::Zero(3, mean.force.cols())};
    out->force += mean.force / n;
    out->polar += mean.polar / n;
    ++contours;
  }
  if (!out) return std::nullopt;
  out->force /= contours;
  out->polar /= contours;
  return out;
}

}  // namespace spifit::scene
