#pragma once
// The scalar of direct differentiation (docs/design/sensitivities.md): a ceres::Jet whose
// derivative slots are the parameters a run differentiates with respect to, one slot each, so
// that one pass through the return mapping (and the element above it) carries every
// parameter's derivative. A value of this type is (value, d value / d p_1 .. p_slots).
#include "forward/material/material_inputs.hpp"
#include "forward/material/material_params.hpp"
#include "forward/material/material_state.hpp"

#include <ceres/jet.h>

#include <Eigen/Core>

#include <vector>

namespace spifit::material {

constexpr int kSensitivitySlots = 8;  // parameters per run
using SensitivityScalar = ceres::Jet<double, kSensitivitySlots>;
using SensitivityRow = Eigen::Matrix<double, 1, kSensitivitySlots>;

// The value v with derivatives d.
inline SensitivityScalar with_derivatives(double v, const SensitivityRow& d) {
  SensitivityScalar s(v);
  s.v = d.transpose();
  return s;
}
inline SensitivityRow derivatives_of(const SensitivityScalar& s) { return s.v.transpose(); }

// Narrower scalars for the pass that costs most, the sections' return mapping, when a run's
// parameters and a layer's three strain slots fit in fewer slots (up to three parameters): the
// Jet arithmetic scales with the slots. Slot k of a narrowed value is slot k of the full one; the
// slots beyond are zero on the way back.
using FourSlotScalar = ceres::Jet<double, 4>;  // one parameter
using SixSlotScalar = ceres::Jet<double, 6>;   // two or three

template <int N>
ceres::Jet<double, N> narrowed(const SensitivityScalar& s) {
  static_assert(N <= kSensitivitySlots);
  ceres::Jet<double, N> out(s.a);
  out.v = s.v.template head<N>();
  return out;
}
template <int N>
SensitivityScalar widened(const ceres::Jet<double, N>& s) {
  static_assert(N <= kSensitivitySlots);
  SensitivityScalar out(s.a);
  out.v.template head<N>() = s.v;
  return out;
}
template <>
inline SensitivityScalar narrowed<kSensitivitySlots>(const SensitivityScalar& s) { return s; }
template <>
inline SensitivityScalar widened<kSensitivitySlots>(const SensitivityScalar& s) { return s; }

// Whether a seeded law has derivatives in a slot from `count` on (narrowing it would drop them).
inline bool seeded_beyond(const MaterialParams<SensitivityScalar>& law, int count) {
  bool beyond = false;
  law.map<double>([&](const SensitivityScalar& x) {
    for (int k = count < 0 ? 0 : count; k < kSensitivitySlots; ++k) beyond = beyond || x.v(k) != 0.0;
    return 0.0;
  });
  return beyond;
}

// The seeded parameters with their first N slots.
template <int N>
MaterialParams<ceres::Jet<double, N>> narrowed_params(const MaterialParams<SensitivityScalar>& p) {
  return p.template map<ceres::Jet<double, N>>([](const SensitivityScalar& x) { return narrowed<N>(x); });
}

// A parameter's seed: the derivative slots of one field of MaterialParams (a parameter sets its
// field and the fields tied to it with the same row; hill.G with normalise_hill also sets H = 2 - G
// with the negated row).
struct FieldSeed {
  MaterialField field;
  SensitivityRow d;
};

// The parameters p as sensitivity scalars with the seeds' derivatives (all others constant).
inline MaterialParams<SensitivityScalar> seeded_params(const MaterialParams<double>& p, const std::vector<FieldSeed>& seeds) {
  MaterialParams<SensitivityScalar> out = p.cast<SensitivityScalar>();
  for (const FieldSeed& s : seeds) material_field(out, s.field).v += s.d.transpose();
  return out;
}

}  // namespace spifit::material
