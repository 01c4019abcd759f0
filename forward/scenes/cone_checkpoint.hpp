#pragma once
// Checkpoints of a cone run (docs/cone-scene.md, "Checkpoints and resume"). DIR/checkpoint/
// state.bin holds everything that decides how the run goes on: the model's committed state
// (nodal positions and directors, every layer of every section, the real tool and its copies,
// their contact point states) and the Newton solver's stepping state (load factor, next
// increment, growth ceiling, predictor, totals); what the outputs need to continue (force.csv
// rows, the samples of the contour means, peaks, contour wall times, VTU steps); and the
// contents of the scene file and material card that produced it, so that a resume with other
// inputs is refused. Binary and bit-exact (forward/io/binary_archive.hpp): a run resumed from
// it ends with the same numbers, bit for bit, as one never interrupted.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone_observables.hpp"
#include "forward/scenes/cone_scene.hpp"
#include "forward/solver/newton_state.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace spifit::model {
class ShellModel;
}

namespace spifit::scene {

// The output bookkeeping of a cone run at a committed increment.
struct ConeRunLog {
  std::vector<std::vector<double>> force_rows;  // force.csv rows so far
  std::vector<ForceSample> samples;             // travel and forces (contour means)
  Eigen::Vector3d peak = Eigen::Vector3d::Zero(), peak_polar = Eigen::Vector3d::Zero();
  int increments = 0;                           // committed increments
  int contours_done = 0;                        // completed contours (sections written)
  double max_penetration = 0.0;
  double max_surface_penetration = 0.0;
  std::vector<double> contour_wall;             // wall seconds at each completed contour
  double wall_seconds = 0.0;                    // wall time of the run up to the checkpoint
  std::vector<std::pair<double, std::string>> vtu_steps;  // vtu/sheet.pvd entries (time, file)
  // Further per-increment outputs kept in memory, by name (rows of numbers).
  std::map<std::string, std::vector<std::vector<double>>> tables;
};

// The inputs of a run by content: scene file and material card (read when the run starts).
struct ConeInputs {
  std::string scene_file, scene_text, card_file, card_text;
};
// Throws io::InputError naming a file that cannot be read.
ConeInputs read_cone_inputs(const ConeScene& scene);

// DIR/checkpoint/state.bin
std::filesystem::path cone_checkpoint_path(const io::OutputDirectory& out);

// Writes the checkpoint atomically (a temporary file in DIR/checkpoint/, then renamed over
// state.bin): a run killed while writing keeps the previous checkpoint. Returns its size in
// bytes. The model and the solver state must be at the same committed increment.
std::size_t write_cone_checkpoint(const io::OutputDirectory& out, const ConeInputs& inputs, const model::ShellModel& model,
                                  const solver::NewtonState& newton, const ConeRunLog& log);

// Loads the checkpoint into a model set up from the same scene (mesh, tool and copies, as
// run_cone_scene builds it); the inputs are those of the resumed run. Throws io::InputError naming DIR/checkpoint/state.bin when it is
// missing, of another format or layout version, truncated or corrupted, written for another
// scene file or material card (their contents differ), or for a model of another size.
void read_cone_checkpoint(const io::OutputDirectory& out, const ConeInputs& inputs, model::ShellModel* model,
                          solver::NewtonState* newton, ConeRunLog* log);

}  // namespace spifit::scene
