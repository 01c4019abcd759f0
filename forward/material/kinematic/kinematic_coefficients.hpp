#pragma once
// The kinematic hardening of a card, held by MaterialParams whatever the law: the law's index in
// the registry (kinematic_laws.hpp; -1: none, isotropic hardening only) and its coefficients in
// the order the law declares them. Templated on the scalar type (Jets).
#include "forward/material/law_coefficient.hpp"

#include <array>

namespace spifit::material {

inline constexpr int kMaxKinematicCoefficients = 4;

template <typename T>
struct Kinematic {
  int law = -1;  // index in KinematicLawList; -1: none
  std::array<T, kMaxKinematicCoefficients> c{};

  bool active() const { return law >= 0; }
  T& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  const T& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
};

// What a kinematic law contributes to one return-mapping step of equivalent plastic strain dl
// (return_mapping.hpp): the shifted stress xi = sigma - X solves
//   (a I + q (C + e A) P) xi = sigma_tr - m X0,
// with a, e, m and their derivatives in dl (isotropic hardening: a = 1, e = 0, m = 1).
template <typename T>
struct KinematicStep {
  T a = T(1.0), da = T(0.0), e = T(0.0), de = T(0.0), m = T(1.0), dm = T(0.0);
};

}  // namespace spifit::material
