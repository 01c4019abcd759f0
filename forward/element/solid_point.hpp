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
#include "forward/material/sensitivity_scalar.hpp"

#include <memory>
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

// Direct differentiation of a solid point (docs/design/sensitivities.md, "Solids"): the law with
// its parameters seeded, the Jets of a Voigt vector and matrix, and a point's derivatives with
// respect to the run's parameters, one column per slot.
using SensLaw6 = material::ReturnMapping<material::SensitivityScalar, 6>;
using Voigt6S = Eigen::Matrix<material::SensitivityScalar, 6, 1>;
using Voigt6x6S = Eigen::Matrix<material::SensitivityScalar, 6, 6>;
using SensColumns6 = Eigen::Matrix<double, 6, material::kSensitivitySlots>;

// The seeded law of a run's derivative pass, and the same law on the narrowest Jets that hold its
// `count` parameters (two slots for one or two, four for three or four; none from five on): the
// points' Jet arithmetic scales with the slots (docs/design/sensitivities.md, "Cost"). Slot k of
// a narrow law is slot k of the full one, and its results come back with the other slots zero.
using TwoSlotLaw6 = material::ReturnMapping<ceres::Jet<double, 2>, 6>;
using FourSlotLaw6 = material::ReturnMapping<material::FourSlotScalar, 6>;
struct SolidSensitivityLaw {
  // std::logic_error when the law is seeded beyond its count's slots.
  explicit SolidSensitivityLaw(const material::MaterialParams<material::SensitivityScalar>& law, const material::ReturnMappingOptions& options = {},
                               int count = material::kSensitivitySlots);
  SensLaw6 full;
  std::unique_ptr<const TwoSlotLaw6> two;
  std::unique_ptr<const FourSlotLaw6> four;
};

// The first `count` columns of a derivative table (checkpoints), and back into a table of the
// same rows whose other columns become zero (io::ArchiveError, naming `what`, on another size).
void save_columns(io::BinaryWriter& w, const Eigen::MatrixXd& m, int count);
Eigen::MatrixXd read_columns(io::BinaryReader& r, const char* what, int rows, int count);
template <typename M>
void load_columns(io::BinaryReader& r, const char* what, int count, M* m) {
  m->setZero();
  m->leftCols(count) = read_columns(r, what, static_cast<int>(m->rows()), count);
}


struct SolidPointDerivatives {
  SensColumns6 stress = SensColumns6::Zero(), plastic_strain = SensColumns6::Zero(), back_stress = SensColumns6::Zero();
  SensColumns6 log_strain = SensColumns6::Zero();
  material::SensitivityRow eqps = material::SensitivityRow::Zero(), plastic_work = material::SensitivityRow::Zero();
  // The consistent tangent's, column-major (36 rows).
  Eigen::Matrix<double, 36, material::kSensitivitySlots> tangent = Eigen::Matrix<double, 36, material::kSensitivitySlots>::Zero();
};

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
  // A point starting an increment at rest (no strain change) gives Newton its last converged
  // consistent tangent instead of the zero step's (a better first iteration after a pause), which
  // is not the exact derivative of its stress where the two differ (tangent_was_exact false, for
  // the last update that asked for a tangent). set_exact_tangents(true): updates give the exact
  // tangent, and leave the state (the tangent kept for commit) as Newton's would.
  bool tangent_was_exact() const { return tangent_exact_; }
  void set_exact_tangents(bool exact) { exact_tangents_ = exact; }
  void commit();
  void revert();

  // Direct differentiation, once enabled (the committed state's derivatives start at zero and
  // follow commit() and revert()): the stress T at the log strain eps (the value of the last
  // update_log) with its derivatives, from the committed state's derivatives and the law's seeded
  // parameters. deps: the log strain's derivatives (the trial derivatives of the state, the log
  // strain and the consistent tangent are then kept for commit); null: eps held fixed (the
  // pseudo-stress). T may be null. Without tangent_derivatives the consistent tangent's
  // derivatives are neither formed nor kept (an element that does not build on the tangent).
  void enable_sensitivities(bool tangent_derivatives = true);
  bool sensitivities_enabled() const { return sensitivities_; }
  PointStatus sensitivities(const SolidSensitivityLaw& law, const Voigt6& eps, const SensColumns6* deps, Voigt6S* T);
  const SolidPointDerivatives& committed_derivatives() const { return d_; }
  // The committed derivatives, slots 0 .. count - 1 (checkpoints).
  void save_sensitivities(io::BinaryWriter& w, int count) const;
  void load_sensitivities(io::BinaryReader& r, int count);

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
  bool sensitivities_ = false, tangent_derivatives_ = true;
  SolidPointDerivatives d_, d_trial_;
  bool exact_tangents_ = false, tangent_exact_ = true;
  PointStatus integrate(const Voigt6& eps, Voigt6* T, Voigt6x6* tangent, bool tangent_wanted);
  template <int N>
  PointStatus sensitivities_on(const material::ReturnMapping<ceres::Jet<double, N>, 6>& law, const Voigt6& eps, const SensColumns6* deps, Voigt6S* T);
};

}  // namespace spifit::element
