#pragma once
// Material axes that turn with the polar angle (the [sheet] material_axes = "polar" of pie and
// disc models, docs/design/cone.md, "Material axes"), shared by the element families.
#include <Eigen/Core>

namespace spifit::model {

// The axis a = (a_r, a_theta, a_z) read in the polar frame (e_r, e_theta, z) at an element's
// reference centroid c; a itself at a centroid on the z axis.
Eigen::Vector3d polar_material_axis(const Eigen::Vector3d& c, const Eigen::Vector3d& a);

}  // namespace spifit::model
