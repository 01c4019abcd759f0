#pragma once
// The derivatives of a shell section's layers with respect to a run's parameters (direct
// differentiation, docs/design/sensitivities.md), stored flat: per layer, each field a committed
// state carries into the next increment with `slots` derivatives, and nothing else (no values:
// the section's double states hold them). A run with p parameters keeps p slots, or p + 3 while
// the layers are linearised in their strains, rather than a Jet of eight per field: the Jet
// passes read and write a third to a ninth of the memory.
//
// Fields, in the order checkpoints write them: for i = 0, 1, 2 the stress, plastic strain, back
// stress and log strain component i; then the out-of-plane back stress, the equivalent plastic
// strain and the plastic work. The flow stress's derivatives are not kept: the law recomputes
// them from eqps when a step is plastic.
#include "forward/material/material_state.hpp"
#include "forward/material/sensitivity_scalar.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace spifit::element {

class LayerDerivatives {
 public:
  static constexpr int kFields = 15;

  LayerDerivatives() = default;
  LayerDerivatives(int layers, int slots)
      : layers_(layers), slots_(slots), data_(static_cast<std::size_t>(layers) * kFields * static_cast<std::size_t>(slots), 0.0) {}

  int layers() const { return layers_; }
  int slots() const { return slots_; }
  bool empty() const { return layers_ == 0; }
  void swap(LayerDerivatives& o) noexcept {
    std::swap(layers_, o.layers_);
    std::swap(slots_, o.slots_);
    data_.swap(o.data_);
  }
  double* at(int layer, int field) { return data_.data() + offset(layer, field); }
  const double* at(int layer, int field) const { return data_.data() + offset(layer, field); }

  // Calls f(field, x) for the fields of a state and log strain, in the table's order.
  template <typename State, typename Eps, typename F>
  static void each_field(State& s, Eps& eps, F&& f) {
    for (int i = 0; i < 3; ++i) {
      f(4 * i, s.stress(i));
      f(4 * i + 1, s.plastic_strain(i));
      f(4 * i + 2, s.back_stress(i));
      f(4 * i + 3, eps(i));
    }
    f(12, s.back_stress_zz);
    f(13, s.eqps);
    f(14, s.plastic_work);
  }

  // The value v with the first slots of the field's derivatives on the Jet J (zero past them).
  template <typename J>
  J seeded(int layer, int field, double v) const {
    J out(v);
    const int n = std::min(slots_, static_cast<int>(J::DIMENSION));
    const double* d = at(layer, field);
    for (int k = 0; k < n; ++k) out.v(k) = d[k];
    return out;
  }
  // Layer `layer`'s state on the Jets J, its values those of `values`. The flow stress keeps its
  // value (when known) without derivatives: the law reads it for the elastic check alone, and a
  // plastic step recomputes it from eqps with its derivatives. An elastic step so takes no pow
  // on Jets.
  template <typename J>
  material::MaterialState<J, 3> seeded_state(int layer, const material::MaterialState<double, 3>& values) const {
    double v[kFields];
    const Eigen::Vector3d no_eps = Eigen::Vector3d::Zero();
    each_field(values, no_eps, [&](int f, const double& x) { v[f] = x; });
    material::MaterialState<J, 3> s;
    Eigen::Matrix<J, 3, 1> eps;  // the log strain's are the caller's (seeded)
    each_field(s, eps, [&](int f, J& x) { x = seeded<J>(layer, f, v[f]); });
    s.flow_stress = J(values.flow_stress >= 0.0 ? values.flow_stress : -1.0);
    return s;
  }
  // Writes the first slots of a Jet's derivatives into a field (zero past the Jet's slots).
  template <typename J>
  void store(int layer, int field, const J& x) {
    double* d = at(layer, field);
    const int n = std::min(slots_, static_cast<int>(J::DIMENSION));
    for (int k = 0; k < n; ++k) d[k] = x.v(k);
    for (int k = n; k < slots_; ++k) d[k] = 0.0;
  }
  template <typename J>
  void store(int layer, const material::MaterialState<J, 3>& s, const Eigen::Matrix<J, 3, 1>& eps) {
    each_field(s, eps, [&](int f, const J& x) { store(layer, f, x); });
  }
  // A layer's derivatives on eight-slot Jets (values zero), for checks.
  material::MaterialState<material::SensitivityScalar, 3> state(int layer) const {
    material::MaterialState<material::SensitivityScalar, 3> s;
    Eigen::Matrix<material::SensitivityScalar, 3, 1> eps;
    each_field(s, eps, [&](int f, material::SensitivityScalar& x) { x = seeded<material::SensitivityScalar>(layer, f, 0.0); });
    s.flow_stress = material::SensitivityScalar(0.0);
    return s;
  }

 private:
  int layers_ = 0, slots_ = 0;
  std::vector<double> data_;
  std::size_t offset(int layer, int field) const {
    return (static_cast<std::size_t>(layer) * kFields + static_cast<std::size_t>(field)) * static_cast<std::size_t>(slots_);
  }
};

}  // namespace spifit::element
