#pragma once
// What a solid element of a sheet offers its family (model/solid_family.hpp): forces and tangent
// at its eight corners, a committed state, and what the outputs read of it. The one-point brick
// (brick8.hpp) and the solid-shell (solid_shell8.hpp) implement it, with their parameter
// sensitivities (docs/design/sensitivities.md, "Solids").
#include "forward/element/hex8_stiffness.hpp"
#include "forward/element/solid_point.hpp"

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::element {

// Derivatives of the 24 corner DOFs (or forces) with respect to the run's parameters.
using HexSensitivities = Eigen::Matrix<double, 24, material::kSensitivitySlots>;

class SolidElement {
 public:
  virtual ~SolidElement() = default;
  // Internal forces (24: ux uy uz per corner) and their tangent at the current corners x (VTK
  // order; corners 0-3 the bottom face); f, K may be null. A failed status leaves the committed
  // state alone and suggests a smaller step.
  virtual PointStatus evaluate(const HexCorners& x, HexVector* f, HexMatrix* K) = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;

  // Committed extent along the sheet normal over the reference one.
  virtual double thickness_ratio() const = 0;
  // Committed stored energy (with any stabilisation's work) and plastic work [N mm].
  virtual double elastic_energy() const = 0;
  virtual double plastic_work() const = 0;
  // Largest equivalent plastic strain over the integration points, and the volume average of the
  // Kirchhoff-like stress in the material frame (Voigt).
  virtual double max_eqps() const = 0;
  virtual Voigt6 mean_stress() const = 0;

  virtual void save_state(io::BinaryWriter& w) const = 0;
  virtual void load_state(io::BinaryReader& r) = 0;

  // Direct differentiation, at the corners x of the converged iterate. enable_sensitivities: the
  // committed state's derivatives start from the reference state's (zero), with respect to the
  // parameters seeded in `law` (count of them). sensitivities: with du null, the pseudo-load
  // (the forces' derivatives at fixed corners) into *load; with du (the corners' derivatives),
  // the trial derivatives that commit() keeps. Called in that order at a converged iterate.
  virtual void enable_sensitivities(const SolidSensitivityLaw& law, int count) = 0;
  virtual PointStatus sensitivities(const HexCorners& x, const SolidSensitivityLaw& law, const HexSensitivities* du, HexSensitivities* load) = 0;
  // The committed thickness_ratio()'s derivatives.
  virtual const material::SensitivityRow& thickness_ratio_sensitivity() const = 0;
  // Whether the last evaluate()'s tangent was exact (SolidPoint::tangent_was_exact at every
  // point), and the switch that makes the next evaluations' tangents exact without changing the
  // state they leave (SolidPoint::set_exact_tangents).
  virtual bool tangent_was_exact() const = 0;
  virtual void set_exact_tangents(bool exact) = 0;
  // The committed derivatives, slots 0 .. count - 1 (checkpoints).
  virtual void save_sensitivities(io::BinaryWriter& w, int count) const = 0;
  virtual void load_sensitivities(io::BinaryReader& r, int count) = 0;
};

}  // namespace spifit::element
