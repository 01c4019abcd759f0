#pragma once
// What a solid element of a sheet offers its family (model/solid_family.hpp): forces and tangent
// at its eight corners, a committed state, and what the outputs read of it. The one-point brick
// (brick8.hpp) and the solid-shell (solid_shell8.hpp) implement it.
#include "forward/element/hex8_stiffness.hpp"
#include "forward/element/solid_point.hpp"

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::element {

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
};

}  // namespace spifit::element
