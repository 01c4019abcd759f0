#pragma once
// One 3D integration point of a solid element in logarithmic strain space
// (docs/design/numerics-solid.md, "Large strain"): the Green-Lagrange strain E of the element in
// its material frame gives eps = ln(I + 2E) / 2 (log_strain_3d.hpp), the 3D return mapping
// (Hill 1948 with the card's hardening laws, no plane-stress assumption) integrates the
// increment eps - eps_committed into the Kirchhoff-like stress T conjugate to eps, and
//   S = (d eps / dE)^T T,   dS/dE = (d eps / dE)^T D (d eps / dE) + T . d2 eps / dE2
// are the second Piola-Kirchhoff stress and its exact tangent (D the consistent tangent).
#include "forward/element/log_strain_3d.hpp"
#include "forward/material/material_point.hpp"

#include <string>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::element {

struct PointStatus {
  bool ok = true;
  std::string reason;
  double suggested_scale = 1.0;  // < 1: retry the increment with this fraction
};

// A Green strain whose metric C = I + 2E is positive definite; otherwise a failed status that
// asks for a smaller step ("element turned inside out").
PointStatus admissible_green_strain(const Voigt6& green);

class SolidPoint {
 public:
  using Law = material::ReturnMapping<double, 6>;
  using State = material::MaterialState<double, 6>;

  explicit SolidPoint(const Law& law);

  // Trial update at the Green strain `green` (material frame, engineering shears). S, tangent
  // may be null. Refuses a metric that is not positive definite.
  PointStatus update(const Voigt6& green, Voigt6* S, Voigt6x6* tangent);
  // Trial update at the log strain eps itself (the caller forms it, e.g. with a modified
  // volumetric part): the stress T conjugate to eps and the consistent tangent dT/d eps; either
  // may be null.
  PointStatus update_log(const Voigt6& eps, Voigt6* T, Voigt6x6* tangent);
  void commit();
  void revert();

  const State& committed() const { return point_.committed(); }
  const State& trial() const { return point_.trial(); }
  const Voigt6& log_strain() const { return eps_; }
  // The consistent tangent d T / d eps of the committed state (the elastic matrix until the
  // first plastic increment).
  const Voigt6x6& consistent_tangent() const { return tangent_; }
  const Voigt6x6& committed_law_elastic_matrix() const { return point_.law().elastic_matrix(); }
  // Stored elastic energy density T . D_e^-1 T / 2 and plastic work density of the committed
  // state [N mm / mm^3].
  double elastic_energy_density() const;
  double plastic_work_density() const { return point_.committed().plastic_work; }

  // Bit-exact committed state: material state, log strain, consistent tangent.
  void save_state(io::BinaryWriter& w) const;
  void load_state(io::BinaryReader& r);

 private:
  material::MaterialPoint<double, 6> point_;
  Voigt6 eps_ = Voigt6::Zero(), eps_trial_ = Voigt6::Zero();
  Voigt6x6 tangent_, tangent_trial_;  // consistent d T / d eps at the committed / trial state
};

}  // namespace spifit::element
