#pragma once
// The state of solver::ExplicitSolver at an output point: everything that decides how its run
// goes on, saved bit-exactly in an explicit run's checkpoint (scenes/common/run_checkpoint.hpp).
// A run restored from it takes the same steps as one never interrupted: the same velocities and
// accelerations (contact forces of the MST included), the same step size until the next
// re-estimate, which falls on the same step (steps % recheck_every), and the same counters.
#include <Eigen/Core>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::solver {

struct ExplicitState {
  bool started = false;        // the first acceleration has been computed (run() does not redo it)
  Eigen::VectorXd v, a;        // reduced velocity and acceleration
  double damping_work = 0.0;   // work of the damping forces so far [N mm]
  Eigen::VectorXd damping_force;  // reduced damping force of the last step (empty: none), paired with half the next move
  double lambda = 0.0;         // load factor reached: an output point
  double time = 0.0;           // simulated time [s]
  long steps = 0, cut_steps = 0;
  double min_step = 0.0, max_step = 0.0;  // step sizes taken so far [s] (0: none yet)
  double step_bound = 0.0;     // stable step of the last re-estimate [s]
  int outputs = 0;             // output points passed
};

void save_explicit_state(io::BinaryWriter& w, const ExplicitState& s);
// io::ArchiveError for negative counts or a velocity and acceleration of different sizes.
ExplicitState load_explicit_state(io::BinaryReader& r);

}  // namespace spifit::solver
