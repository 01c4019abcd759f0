#pragma once
// The stepping state of a NewtonSolver between two increments: what, together with the
// problem's committed state, determines how a run continues (checkpoints and resume,
// NewtonSolver::state / set_state / resume). Counters and profile times travel with it so
// that the totals of a resumed run are those of an uninterrupted one.
#include "forward/solver/newton_counters.hpp"

#include <Eigen/Core>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::solver {

struct NewtonState {
  double lambda = 0.0;           // last committed load factor
  double increment = 0.0;        // size of the next increment to try
  double ceiling = 0.0;          // growth ceiling (stays below a size that failed recently)
  // Predictor: free part of the last converged increment (full DOF vector; empty without the
  // predictor) and its load-factor size.
  Eigen::VectorXd last_increment;
  double last_increment_size = 0.0;
  // Stabilisation (NewtonOptions::stabilisation): the damping factor in force (0: off) and the
  // converged increments it still lasts.
  double damping = 0.0;
  int stabilised_left = 0;
  NewtonCounters counters;       // totals so far (NewtonSummary::counters)
};

// Bit-exact (forward/io/binary_archive.hpp); load throws io::ArchiveError.
void save_newton_state(io::BinaryWriter& w, const NewtonState& s);
NewtonState load_newton_state(io::BinaryReader& r);

}  // namespace spifit::solver
