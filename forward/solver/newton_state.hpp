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

// The direct differentiation's solves after each converged increment (a problem with
// sensitivities; summary.json "sensitivity_solves").
struct SensitivitySolveStats {
  int increments = 0;
  int gmres_solves = 0, gmres_iterations = 0;  // right-hand sides GMRES solved, its back-substitutions (all tries)
  int factorisations = 0;                      // of the exact tangent, where GMRES did not converge or had no factor
  double solve_seconds = 0.0;                  // wall time of the solves and factorisations
};

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
  // A problem with sensitivities: their solves so far (stored only then).
  bool sensitivities = false;
  SensitivitySolveStats sensitivity_solves;
};

// Bit-exact (forward/io/binary_archive.hpp); load throws io::ArchiveError. sensitivities: the
// state was saved with s.sensitivities (a run with sensitivities); the reader must say so.
void save_newton_state(io::BinaryWriter& w, const NewtonState& s);
NewtonState load_newton_state(io::BinaryReader& r, bool sensitivities = false);

}  // namespace spifit::solver
