#pragma once
// State of one integration point, and the status a constitutive update reports instead of throwing
// (docs/design/numerics-material.md, "Status instead of exceptions"; MGIS/MFront's integrate -> ok /
// failed + suggested step factor).
#include "forward/material/scalar.hpp"

#include <Eigen/Core>

namespace spifit::material {

template <typename T, int Dim>
struct MaterialState {
  using Vec = Eigen::Matrix<T, Dim, 1>;
  Vec stress = Vec::Zero();          // Kirchhoff stress [MPa], tensor components
  Vec plastic_strain = Vec::Zero();  // logarithmic, engineering shear
  // Back-stress [MPa]. In plane stress (Dim = 3) this is the shifted in-plane back-stress
  // X~ = (Xxx - Xzz, Xyy - Xzz, Xxy) that enters the yield function; Xzz is kept below.
  Vec back_stress = Vec::Zero();
  T back_stress_zz = T(0.0);  // plane stress only
  T eqps = T(0.0);            // equivalent plastic strain, work-conjugate to sigma_eq (eq. 3.2)
  T plastic_work = T(0.0);    // sum of sigma . d eps_p [MJ/m^3 = MPa]
  // Yield stress at eqps, kept by the return mapping so that the next update's elastic check
  // needs no pow (bit for bit the value it would compute). Negative: not known (a fresh state,
  // or one read from a checkpoint); the return mapping then computes it.
  T flow_stress = T(-1.0);

  // Every scalar through f, e.g. to values or to other derivative slots.
  template <typename U, typename Fn>
  MaterialState<U, Dim> map(Fn f) const {
    MaterialState<U, Dim> o;
    for (int i = 0; i < Dim; ++i) {
      o.stress(i) = f(stress(i));
      o.plastic_strain(i) = f(plastic_strain(i));
      o.back_stress(i) = f(back_stress(i));
    }
    o.back_stress_zz = f(back_stress_zz);
    o.eqps = f(eqps);
    o.plastic_work = f(plastic_work);
    o.flow_stress = f(flow_stress);
    return o;
  }
};

template <typename T, int Dim>
MaterialState<double, Dim> values_of(const MaterialState<T, Dim>& s) {
  return s.template map<double>([](const T& x) { return value_of(x); });
}

enum class UpdateStatus { ok, failed };

struct UpdateResult {
  UpdateStatus status = UpdateStatus::ok;
  double suggested_scale = 1.0;  // < 1 on failure: retry with this fraction of the increment
  int iterations = 0;
  bool plastic = false;
  const char* reason = "";
  bool ok() const { return status == UpdateStatus::ok; }
};

}  // namespace spifit::material
