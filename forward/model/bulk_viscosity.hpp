#pragma once
// Bulk viscosity of the explicit scheme (docs/design/explicit.md, "Bulk viscosity"), as explicit
// codes damp the ringing of the highest modes: a viscous in-plane stress s (the same in every
// in-plane direction, over the element's thickness) against the rate of the element's area,
//   rate = (dA/dt) / A,   s = rho L (b1 c rate + b2^2 L rate |rate|  [rate < 0 only]),
// rho the element's scaled density, c its plane-stress wave speed sqrt(E / (rho (1 - nu^2))),
// L its characteristic length (area over the longer diagonal). The linear term (b1) damps the
// element's breathing mode by about the fraction b1 of critical; the quadratic term (b2)
// resists fast compression only. Its power s h dA/dt is never negative: it dissipates, and that
// work is part of the energy account's damping. The area is the diagonals' one, A = |d1 x d2| / 2,
// whose gradient gives the nodal forces s h dA/dx exactly. It shortens the stable step to
// (sqrt(1 + xi^2) - xi) of the undamped one, xi = b1 + b2^2 L |min(0, rate)| / c: explicit_mass
// takes the linear part, current_time_step the quadratic one at the last rates.
#include "forward/element/quad_shape.hpp"
#include "forward/solver/dof_constraints.hpp"

#include <Eigen/Core>

#include <vector>

namespace spifit::model {

class ShellModel;

// A quad's area by its diagonals, |(x3 - x1) x (x4 - x2)| / 2 (its projection on its mean plane),
// and, when asked, the area's gradient with respect to each corner.
double diagonal_area(const element::NodeVectors& x, element::NodeVectors* gradient = nullptr);

// An element's characteristic length from its corners and diagonal area: the area over the
// longer diagonal (the explicit scheme's element length).
double characteristic_length(const element::NodeVectors& x, double area);

// The fraction of an undamped stable step that stays stable with the fraction xi of critical
// damping in the highest mode: sqrt(1 + xi^2) - xi.
double damped_step_fraction(double xi);

class BulkViscosity {
 public:
  // density, wave_speed: per element, at its scaled density [t/mm^3, mm/s]. linear, quadratic:
  // b1, b2 (solver::ExplicitOptions). std::invalid_argument for sizes that do not fit the model.
  BulkViscosity(const ShellModel& model, const solver::DofConstraints& constraints, std::vector<double> density, std::vector<double> wave_speed,
                double linear, double quadratic);

  // The viscous forces at the model's committed configuration for the reduced velocity v, with
  // the sign of internal forces (full DOF vector, translations only). Keeps each element's rate.
  Eigen::VectorXd forces(const Eigen::VectorXd& v);

  // The viscous stress of element e at an area rate [MPa; rate in 1/s] and characteristic length [mm].
  double stress(int e, double rate, double length) const;
  // Element e's area rate in the last forces() [1/s].
  double rate(int e) const { return rate_[static_cast<std::size_t>(e)]; }
  // The part of element e's stable step with the linear term's damping alone (the steps of
  // explicit_mass) that stays stable at the last rate: below 1 in fast compression.
  double compression_fraction(int e) const;

 private:
  const ShellModel& model_;
  const solver::DofConstraints& constraints_;
  std::vector<double> density_, wave_speed_;
  double linear_, quadratic_;
  std::vector<double> rate_;
};

}  // namespace spifit::model
