#pragma once
// The coefficients of an isotropic hardening law, held by MaterialParams whatever the law: the
// law's index in the registry (hardening_laws.hpp) and its coefficients in the order the law
// declares them. Templated on the scalar type, so that ceres::Jet carries exact parameter
// derivatives through any law.
#include "forward/material/law_coefficient.hpp"

#include <array>

namespace spifit::material {

inline constexpr int kMaxHardeningCoefficients = 8;

template <typename T>
struct Hardening {
  int law = 0;  // index in HardeningLawList (0: Swift)
  std::array<T, kMaxHardeningCoefficients> c{};

  T& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  const T& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
};

// One coefficient as a law declares it (law_coefficient.hpp).
using HardeningCoefficient = LawCoefficient;

}  // namespace spifit::material
