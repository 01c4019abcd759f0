#pragma once
// What watches an FE run (fe_run.hpp): after every committed increment each observer records
// what it needs into its part of the typed result (tool force, energies, sections, element
// history, VTU steps) and writes its files when told to. Observers are added by the scene kind;
// the run calls them in the order they were added.
#include "forward/scenes/common/progress.hpp"
#include "forward/solver/newton_solver.hpp"

#include <Eigen/Core>

#include <string>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::model {
class FeModel;
class ToolContact;
}  // namespace spifit::model

namespace spifit::scene {

// A named point of a run, reached when the tool's travel gets there: a named point of a tool
// path (B, C, ...), the end of a cone's contour. Marks decide when sections are taken and
// checkpoints written.
struct Mark {
  double travel = 0.0;  // mm along the path
  std::string name;
  int index = 0;        // position in the scene's list of marks
};

// What an explicit run adds at an output point (the "increments" of an explicit run are its
// output intervals): the steps, the kinetic energy and the damping's work, and the tool force
// filtered over the interval (the instantaneous force of an explicit run rings with the
// sheet's vibrations; fe_run_explicit.cpp, IntervalForceFit).
struct DynamicsView {
  int steps = 0;               // in this interval
  long total_steps = 0;
  double time_step = 0.0;      // s
  double kinetic = 0.0;        // N mm
  double damping_work = 0.0;   // N mm, so far
  double contact_work = 0.0;   // MST contact: the work of its forces on the sheet so far [N mm] (the external work)
  Eigen::Vector3d filtered_tool_force = Eigen::Vector3d::Zero();  // BY the sheet ON the tool at the output point [N]
};

// The committed state after an increment, as observers see it.
struct IncrementView {
  const solver::IncrementReport& report;
  int increment = 0;         // committed increments of the run so far, this one included
  double lambda = 0.0;       // load factor
  double travel = 0.0;       // mm along the tool path
  double time = 0.0;         // s
  double wall_seconds = 0.0; // since the run started (a resumed run: its first part included)
  const model::FeModel& model;
  const model::ToolContact& tool;
  const ProgressSink& progress;
  const DynamicsView* dynamics;  // explicit runs; null for implicit ones
};

// Why an observer is asked to write its files: after an increment, a second or more after its
// last periodic write, at a mark, at the end of the run.
enum class WriteReason { increment, periodic, mark, end };

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // Identifies the observer's state in a checkpoint.
  virtual std::string name() const = 0;
  // A fresh run (not a resumed one) starts from the model's initial state.
  virtual void at_start(const model::FeModel& model) { (void)model; }
  virtual void after_increment(const IncrementView& v) = 0;
  // A mark reached by this increment (called after after_increment, mark by mark).
  virtual void at_mark(const Mark& m, const IncrementView& v) {
    (void)m;
    (void)v;
  }
  // The run has ended (converged or failed, not stopped), at the given time [s].
  virtual void at_end(const model::FeModel& model, double time) {
    (void)model;
    (void)time;
  }
  // Writes the observer's files (the run's RunFiles, given at construction) for this reason.
  virtual void write(WriteReason reason) { (void)reason; }
  // The observer's state at a checkpoint, and its restoration into a new observer.
  virtual void save(io::BinaryWriter& w) const { (void)w; }
  virtual void restore(io::BinaryReader& r) { (void)r; }
};

}  // namespace spifit::scene
