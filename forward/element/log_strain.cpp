#include "forward/element/log_strain.hpp"

#include <ceres/jet.h>

namespace spifit::element {

LogStrain log_strain_with_derivatives(const Eigen::Vector3d& green) {
  using Inner = ceres::Jet<double, 3>;
  using Outer = ceres::Jet<Inner, 3>;
  Eigen::Matrix<Outer, 3, 1> g;
  for (int j = 0; j < 3; ++j) {
    Inner a(green(j), j);  // value and first-level seed
    g(j) = Outer(a, j);    // second-level seed
  }
  const Eigen::Matrix<Outer, 3, 1> eps = log_strain_of_green(g);
  LogStrain out;
  for (int i = 0; i < 3; ++i) {
    out.value(i) = eps(i).a.a;
    for (int j = 0; j < 3; ++j) {
      out.first(i, j) = eps(i).a.v(j);
      for (int k = 0; k < 3; ++k) out.second[static_cast<std::size_t>(i)](j, k) = eps(i).v(j).v(k);
    }
  }
  return out;
}

}  // namespace spifit::element
