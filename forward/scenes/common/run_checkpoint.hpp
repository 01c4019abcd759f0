#pragma once
// Checkpoints of an FE run (docs/design/architecture.md, "Checkpoints and resume"). DIR/checkpoint/
// state.bin holds everything that decides how the run goes on: the model's committed state
// (nodal positions and directors, every layer of every section, the tool and its copies with
// their contact point states), the Newton solver's stepping state (load factor, next increment,
// growth ceiling, predictor, counters) or, for an explicit run, its dynamics (mass and time-step
// state, solver, MST; explicit_dynamics.hpp), the run's bookkeeping (increments, marks reached,
// wall times), each observer's state (the rows of its series, VTU steps), and the contents of the
// files that produced the run (scene, card, G-code), so that a resume with other inputs is
// refused. Binary and bit-exact (forward/io/binary_archive.hpp): a run resumed from it ends with
// the same numbers, bit for bit, as one never interrupted.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/run_observer.hpp"
#include "forward/solver/newton_state.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::model {
class FeModel;
}

namespace spifit::scene {

// The inputs of a run by content: its kind and each input file's role ("scene", "material
// card", "G-code"), path and contents.
struct RunInput {
  std::string role, path, text;
};
struct RunInputs {
  std::string kind;
  std::vector<RunInput> files;
};
// files: (role, path); an empty path is skipped. Throws io::InputError naming a file that
// cannot be read.
RunInputs read_run_inputs(const std::string& kind, const std::vector<std::pair<std::string, std::string>>& files);
// A run with sensitivities: the parameters it differentiates with respect to, as one more input
// (role "sensitivities", text "swift.K,contact.friction"), so that a checkpoint holding their
// derivatives resumes only with the same parameters in the same order.
RunInput sensitivity_input(const std::vector<std::string>& names);

// The skeleton's bookkeeping at a committed increment.
struct RunLog {
  int increments = 0;                  // committed increments
  int marks_reached = 0;
  std::vector<double> mark_wall;       // wall seconds when each mark was reached
  double wall_seconds = 0.0;           // wall time of the run up to the checkpoint
};

// DIR/checkpoint/state.bin
std::filesystem::path run_checkpoint_path(const io::OutputDirectory& out);

using Observers = std::vector<std::unique_ptr<RunObserver>>;

// The state of an explicit run's time integration (ExplicitDynamics), saved in place of the
// Newton solver's.
class CheckpointPart {
 public:
  virtual ~CheckpointPart() = default;
  virtual void save(io::BinaryWriter& w) const = 0;
  // io::ArchiveError when the saved state does not fit the run (another model size, other options).
  virtual void restore(io::BinaryReader& r) = 0;
};

// Writes the checkpoint atomically (a temporary file in DIR/checkpoint/, then renamed over
// state.bin): a run killed while writing keeps the previous checkpoint. Returns its size in
// bytes. The model and the solver state must be at the same committed increment. The scheme's
// state: the Newton solver's (implicit runs; dynamics null) or the dynamics (explicit runs;
// newton null).
std::size_t write_run_checkpoint(const io::OutputDirectory& out, const RunInputs& inputs, const model::FeModel& model,
                                 const solver::NewtonState* newton, const CheckpointPart* dynamics, const RunLog& log,
                                 const Observers& observers);

// Loads the checkpoint into a model and observers set up from the same scene (as the run builds
// them); the inputs are those of the resumed run. Throws io::InputError naming
// DIR/checkpoint/state.bin when it is missing, of another format or layout version, truncated or
// corrupted, written for another kind, scene file, material card or G-code (their contents
// differ), for a model of another size, by a run of the other scheme, or (dynamics) with other
// explicit options. The scheme's state goes to newton (implicit runs) or dynamics (explicit).
void read_run_checkpoint(const io::OutputDirectory& out, const RunInputs& inputs, model::FeModel* model,
                         solver::NewtonState* newton, CheckpointPart* dynamics, RunLog* log, const Observers& observers);

}  // namespace spifit::scene
