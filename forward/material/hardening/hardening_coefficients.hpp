#pragma once
// The coefficients of an isotropic hardening law, held by MaterialParams whatever the law: the
// law's index in the registry (hardening_laws.hpp) and its coefficients in the order the law
// declares them. Templated on the scalar type, so that ceres::Jet carries exact parameter
// derivatives through any law.
#include "forward/io/named_inputs.hpp"

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

// One coefficient as a law declares it: its key in the law's card table (also the second part of
// its fit and sweep name, "swift.K"), unit, valid values and a one-line description.
struct HardeningCoefficient {
  const char* key;
  const char* unit;
  io::Range range;
  const char* doc;
};

}  // namespace spifit::material
