#pragma once
// Options of the explicit central-difference scheme (ExplicitSolver; docs/design/explicit.md):
// the scalings that trade inertia for speed (thesis §2.2.3: mass scaling and time scaling; §7.3:
// a rotational scaling on top), the damping, and the time-step rule.
#include <string>

namespace spifit::solver {

struct ExplicitOptions {
  // Density factor of every element (thesis §7.3.2: 1 .. 1e4). The stable time step grows with
  // its square root.
  double mass_scaling = 1.0;
  // Extra factor on the rotational inertia only (thesis §7.3.1 used 1000 with Li's matrix).
  double rotational_scaling = 1.0;
  // Selective mass scaling: the elements whose stable step is below this [s] get the density
  // that brings it there (on top of mass_scaling); the added mass is reported. 0: off.
  double target_time_step = 0.0;
  // The tool runs this many times faster than its feed: the simulated duration is the path's
  // time over time_scaling (rate-independent materials only, thesis §2.2.3).
  double time_scaling = 1.0;
  // Mass-proportional damping C = damping x M [1/s] (thesis eq. 5.1 with c2 = 0).
  double damping = 0.0;
  // Bulk viscosity of the membrane (model/bulk_viscosity.hpp): an in-plane pressure against the
  // element's area rate, linear in it (b1, the fraction of critical damping it gives the
  // highest mode) and quadratic in its compression (b2). 0: off.
  double bulk_viscosity_linear = 0.0;
  double bulk_viscosity_quadratic = 0.0;
  // Time step = safety x the smallest element bound (Irons: the largest element frequency
  // bounds the model's).
  double safety = 0.9;
  // A run that would need more steps than this stops at start-up (with the mass scaling that
  // would fit).
  double max_steps = 1e8;
  // Steps between the re-estimates of the stable step from the elements' current shape.
  int recheck_every = 100;
  // Empty when valid, else the first problem (key names as in the scene's [solver] table).
  std::string validate() const;
};

}  // namespace spifit::solver
