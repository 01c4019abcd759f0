#pragma once
// Through-thickness integration of one shell integration point (docs/design/numerics-shell.md).
//
// The layer at zeta in [-1, 1] has the in-plane Green-Lagrange strain E(zeta) = e + z kappa
// (material frame, engineering shear), z = zeta h / 2 with h the thickness at the start of
// the increment. Each layer is a plane-stress material point working in logarithmic strain
// space: eps = ln(I + 2E) / 2, Kirchhoff-like stress T conjugate to eps from the return
// mapping, and S = (d eps/dE)^T T conjugate to E. Resultants per unit reference area
// (Total Lagrangian, reference thickness h0):
//   N = sum_l w_l h0/2 S_l,  M = sum_l w_l h0/2 z_l S_l.
// The section tangent contains the consistent material tangent and the second derivative of
// the logarithm. After a converged increment the thickness is updated at constant volume,
// h = h0 / sqrt(det(I + 2e)) (thesis §9.2.2), and the layers' reference log strains are
// re-evaluated with the new lever arm, so the bending strain accumulates with the current
// thickness and the next increment starts without a spurious strain jump.
#include "forward/element/layer_derivatives.hpp"
#include "forward/element/thickness_rule.hpp"
#include "forward/material/material_point.hpp"
#include "forward/material/sensitivity_scalar.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::element {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Sens = material::SensitivityScalar;
using SensLaw = material::ReturnMapping<Sens, 3>;
using FourSlotLaw = material::ReturnMapping<material::FourSlotScalar, 3>;
using SixSlotLaw = material::ReturnMapping<material::SixSlotScalar, 3>;
using Vec3S = Eigen::Matrix<Sens, 3, 1>;
using Vec6S = Eigen::Matrix<Sens, 6, 1>;

// The seeded law on the narrowest Jets that hold `count` parameters and a layer's three strain
// slots, for ShellSection::pseudo_resultants (none when it takes all of them).
struct NarrowLaws {
  NarrowLaws() = default;
  NarrowLaws(const material::MaterialParams<Sens>& law, const material::ReturnMappingOptions& options, int count);
  std::unique_ptr<FourSlotLaw> four;
  std::unique_ptr<SixSlotLaw> six;
};

// Energies per unit reference area of a section's committed state [N mm / mm^2].
struct SectionEnergy {
  double elastic = 0.0;  // sum_l w_l h0/2 x T . C^-1 T / 2 (plane-stress elasticity of the layers)
  double plastic = 0.0;  // sum_l w_l h0/2 x plastic work (sum of T . d eps_p)
};

struct SectionStatus {
  bool ok = true;
  int layer = -1;                // failing layer (bottom = 0)
  std::string reason;
  double suggested_scale = 1.0;  // < 1: retry the increment with this fraction
};

class ShellSection {
 public:
  using Law = material::ReturnMapping<double, 3>;

  ShellSection(const Law& law, const ThicknessRule& rule, double thickness0);

  // Trial update from the committed state. resultant = (N, M); tangent = d(N, M)/d(e, kappa).
  SectionStatus update(const Vec3& e, const Vec3& kappa, Vec6* resultant, Mat6* tangent);
  void commit();
  void revert();
  // false: a residual alone leaves the layers' consistent tangents out (explicit runs, where no
  // tangent is ever assembled); the committed tangent is then stale. true by default.
  void set_layer_tangents(bool keep) { keep_tangents_ = keep; }
  // A layer starting an increment at rest (no strain change) gives Newton its last converged
  // consistent tangent rather than the one of the zero step; the last update's tangent was then
  // not the exact derivative of its resultants where the two differ (tangent_was_exact false).
  // set_exact_tangents(true): updates give the exact tangent, and leave the state (trial layers,
  // and the tangent the next increment starts from) as they would otherwise.
  bool tangent_was_exact() const { return tangent_exact_; }
  void set_exact_tangents(bool exact) { exact_tangents_ = exact; }
  // Committed state for checkpoints (forward/io/binary_archive.hpp), bit-exact: thickness,
  // membrane strain, and per layer the material state, log strain and consistent tangent.
  // load_state resets the trial state to it; io::ArchiveError on a layer-count mismatch.
  void save_state(io::BinaryWriter& w) const;
  void load_state(io::BinaryReader& r);

  // Direct differentiation (docs/design/sensitivities.md). Once enabled, the section keeps
  // beside its committed state that state's derivatives with respect to the parameters of a
  // run (zero at the start: the initial state depends on none of them), and commit() advances
  // them from the trial derivatives of the increment's last update_sensitivities() (a commit
  // without one is a std::logic_error). revert() discards the trial derivatives. The section
  // keeps `slots` derivatives: a run's parameters, in slots 0 .. slots - 1.
  void enable_sensitivities(int slots = material::kSensitivitySlots);
  bool sensitivities_enabled() const { return !sens_.empty(); }
  // The resultants (N, M) at the strains (e, kappa), whose derivatives are the strains' own,
  // integrated from the committed state and its derivatives by `law`: the section's law with
  // the parameters seeded (material::seeded_params). With constant strains the resultants'
  // derivatives are the pseudo-resultants of the direct differentiation, d (N, M) / d p at
  // fixed strains; with the strains' derivatives, the layers' trial derivatives follow. The
  // section's double trial state is left as it is.
  SectionStatus update_sensitivities(const SensLaw& law, const Vec3S& e, const Vec3S& kappa, Vec6S* resultant);
  // The pseudo-resultants (update_sensitivities at constant strains), with `count` parameters in
  // slots 0 .. count - 1 and each layer linearised in its strain: slots count .. count + 2 carry
  // the derivatives with respect to the layer's Green-Lagrange strain (count + 3 <=
  // kSensitivitySlots), so that advance_sensitivities() gives the layers' trial derivatives for
  // any strain derivatives without integrating again (count <= the slots enabled). The resultant's slots from count on are
  // zero. With `narrow` holding a law whose slots take them, the pass runs on its narrower Jets:
  // the same derivatives, at less cost.
  SectionStatus pseudo_resultants(const SensLaw& law, const NarrowLaws* narrow, const Vec3& e, const Vec3& kappa, int count, Vec6S* resultant);
  // After pseudo_resultants() at the same strains: the layers' trial derivatives for strains with
  // the derivatives of e and kappa (what update_sensitivities(law, e, kappa, ...) gives, to
  // round-off: the Jet pass is linear in its seeds).
  void advance_sensitivities(const Vec3S& e, const Vec3S& kappa);
  bool linearised() const { return linear_count_ >= 0; }
  // The committed derivatives for checkpoints, bit-exact: the thickness's and each layer's
  // (state and log strain), slots 0 .. count - 1 (the others are zero). load_sensitivities
  // resets the trial derivatives to them; io::ArchiveError on a layer-count mismatch.
  void save_sensitivities(io::BinaryWriter& w, int count) const;
  void load_sensitivities(io::BinaryReader& r, int count);
  // Derivatives of the committed thickness, and of a layer's committed state (values zero; the
  // flow stress's are not kept: the law recomputes it from eqps).
  const material::SensitivityRow& thickness_sensitivity() const { return dh_; }
  material::MaterialState<Sens, 3> layer_state_sensitivity(int l) const { return sens_.state(l); }

  double reference_thickness() const { return h0_; }
  double thickness() const { return h_; }  // committed, constant-volume
  int layers() const { return static_cast<int>(points_.size()); }
  const material::MaterialState<double, 3>& layer_state(int l) const { return points_[static_cast<std::size_t>(l)].committed(); }
  const material::MaterialState<double, 3>& layer_trial_state(int l) const { return points_[static_cast<std::size_t>(l)].trial(); }
  const Vec3& layer_log_strain(int l) const { return eps_[static_cast<std::size_t>(l)]; }
  const Vec3& membrane_green_strain() const { return e_committed_; }
  SectionEnergy energy() const;

 private:
  const ThicknessRule* rule_;
  double h0_, h_;
  bool keep_tangents_ = true;
  bool exact_tangents_ = false, tangent_exact_ = true;
  Eigen::Matrix3d compliance_;  // inverse of the law's plane-stress elastic matrix
  std::vector<material::MaterialPoint<double, 3>> points_;
  std::vector<Vec3> eps_, eps_trial_;  // layer log strains (committed, trial)
  // Material tangent of the last update (trial) and at the converged state (committed). A
  // zero strain increment from a plastic state reuses the committed consistent tangent
  // instead of the elastic one, so that the first iteration of an increment starts from the
  // elastic-plastic stiffness (as Abaqus does).
  std::vector<Eigen::Matrix3d> tangent_, tangent_trial_;
  Vec3 e_committed_ = Vec3::Zero(), e_trial_ = Vec3::Zero(), kappa_trial_ = Vec3::Zero();
  // Direct differentiation: per layer the derivatives of the material state and of the log
  // strain (committed, trial, and pseudo_resultants()'s linearisation with the strain's three
  // slots), of the thickness, and the trial strains with their derivatives.
  LayerDerivatives sens_, sens_trial_, linear_;
  material::SensitivityRow dh_ = material::SensitivityRow::Zero();
  Vec3S e_sens_ = Vec3S::Zero(), kappa_sens_ = Vec3S::Zero();
  bool sens_trial_set_ = false;
  int linear_count_ = -1;  // >= 0: the trial derivatives hold pseudo_resultants()'s linearisation
  void commit_sensitivities();
  template <typename J>
  void commit_thickness();
  // update_sensitivities' pass over the layers; strain_slot >= 0 seeds each layer's strain there.
  SectionStatus integrate_sensitivities(const SensLaw& law, const Vec3S& e, const Vec3S& kappa, int strain_slot, Vec6S* resultant);
  // Its body, on the Jets of `law` (the slots past theirs come back zero).
  template <typename J>
  SectionStatus integrate_layers(const material::ReturnMapping<J, 3>& law, const Vec3S& e, const Vec3S& kappa, int strain_slot, Vec6S* resultant);
};

}  // namespace spifit::element
