#pragma once
// The parameter derivatives of a cone run's force observables (a run with
// RunControl::sensitivities): the polar components turn with the tool's polar angle, which the
// parameters do not move, so their derivatives are the Cartesian ones turned likewise; contour
// means and the steady state are means of the samples' derivatives over the same samples.
#include "forward/scenes/cone/cone_result.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <optional>

namespace spifit::scene {

using ForceDerivatives = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // rows: components, columns: parameters

// d(Fr, Ftheta, Fz)/dp at force sample i; no columns without sensitivities.
ForceDerivatives polar_sensitivity(const ConeResult& r, std::size_t i);

// The sample whose polar component k (0 r, 1 theta, 2 z) is the run's peak (ConeResult::peak_polar:
// the first of the largest magnitudes); none when every sample is zero.
std::optional<std::size_t> peak_polar_sample(const ConeResult& r, int k);

// d/dp of steady_state(r.contours, from, to): polar (rows r, theta, z) and Cartesian; none
// without sensitivities or when no contour of the range has samples.
struct SteadyStateDerivatives {
  ForceDerivatives polar, force;
};
std::optional<SteadyStateDerivatives> steady_state_sensitivity(const ConeResult& r, int from, int to);

}  // namespace spifit::scene
