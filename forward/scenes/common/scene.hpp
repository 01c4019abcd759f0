#pragma once
// Scene kinds and scenes, whatever the model: a scene read from its file can be run (with or
// without files), its named inputs read and set, and its typed result read through the kind's
// observables. `spifit run`, sweeps, synthetic data and fits work through this interface and
// the registry (scene_registry.hpp), so that a new kind is a folder plus one registration line
// (docs/design/architecture.md).
#include "forward/io/named_inputs.hpp"
#include "forward/material/material_card.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/scene_result.hpp"
#include "forward/toolpath/tool_path.hpp"

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace spifit::scene {

// A scene read from its file.
class Scene {
 public:
  virtual ~Scene() = default;
  virtual const std::string& kind() const = 0;
  virtual const std::string& name() const = 0;
  virtual const std::string& file() const = 0;
  // Files the run reads (scene, card, G-code), which must not lie inside its output directory.
  virtual std::vector<std::string> input_files() const = 0;
  virtual std::unique_ptr<Scene> clone() const = 0;
  // Runs the scene; with files, writes its outputs (summary.json last). Numerical failure is a
  // status of the result; io::InputError for inputs the run cannot use (a resume without a
  // valid checkpoint, a kind that cannot resume).
  virtual std::unique_ptr<SceneResult> run(const RunFiles& files, const RunControl& control) const = 0;
  // The material card the scene uses; null for a scene with a material of its own (a shell
  // benchmark), whose inputs then hold no material parameters.
  virtual const material::MaterialCard* card() const = 0;
  virtual material::MaterialCard* card() = 0;
  // The path of the tool centre of a scene with a tool (nothing for the others): what a fit
  // checks measured travels and depths against before anything runs.
  virtual std::optional<toolpath::ToolPath> tool_centre_path() const { return std::nullopt; }
  // The path points where the run takes a section y = 0 (forming scenes' [output] sections).
  virtual std::vector<std::string> section_points() const { return {}; }
  // The contours of a cone's path (all stages): contour numbers run from 1 to it. 0 for kinds
  // without contours.
  virtual int contours() const { return 0; }
  // What is legal but physically odd about the inputs (sheet_tool_checks.hpp), one sentence
  // each: what a command tells the user before it runs the scene.
  virtual std::vector<std::string> input_warnings() const { return {}; }

  // Named inputs: the kind's own (its InputTable) and the card's parameters (material_inputs).
  // input: std::invalid_argument for a name that is neither. set_input: "" when set, else why
  // the value cannot be used (nothing set); std::invalid_argument for an unknown name.
  double input(const std::string& name) const;
  std::string set_input(const std::string& name, double value);

 protected:
  // The kind's own numeric inputs (the material's are handled here): value and setter, or
  // std::invalid_argument for a name the kind does not have.
  virtual double own_input(const std::string& name) const = 0;
  virtual std::string set_own_input(const std::string& name, double value) = 0;
  virtual bool has_own_input(const std::string& name) const = 0;
  // Checks across inputs after a change (a half model's even element count, the mesh), "" if fine.
  virtual std::string check_inputs() const { return {}; }
};

// What an observable needs besides the result: a window of tool travel [mm] (forming scenes),
// a range of contours (cones).
struct ObservableOptions {
  std::optional<std::array<double, 2>> window;
  std::optional<std::pair<int, int>> contours;
};

// An observable's value where the run does not provide it.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A scalar that sweeps and fits read off a result (NaN where the run does not provide it).
struct Observable {
  enum class Needs { nothing, window, contours };
  std::string name, unit, doc;
  Needs needs = Needs::nothing;
  // A failed run's value: counts (iterations, increments) keep theirs; forces and shapes are NaN.
  bool counts_failed_runs = false;
  std::function<double(const SceneResult&, const ObservableOptions&)> value;
  // Its derivatives with respect to the parameters of a run with sensitivities
  // (RunControl::sensitivities, in their order); null for an observable without them (counts,
  // the penetration), and empty from a result without sensitivities.
  std::function<std::vector<double>(const SceneResult&, const ObservableOptions&)> derivatives = {};
};

struct SceneKind {
  std::string name;    // the [scene] kind of its files
  std::string family;  // material_point, shell_benchmark, forming, cone
  std::string doc;     // one line
  bool resumable = false;        // checkpoints and --resume
  bool fe_run = false;           // an FE run with a tool: force.csv, energies.csv, vtu/ and the run report
  bool sensitivities = false;    // exact parameter derivatives of the tool force (spifit run --sensitivities)
  bool jets = false;             // runs on ceres::Jet scalars (material points): fits evaluate it in process with exact derivatives
  bool parallel_sweeps = false;  // sweep points run side by side (each run serial)
  std::function<std::unique_ptr<Scene>(const std::string& file)> read;  // io::InputError naming file, key, value
  std::vector<io::InputInfo> inputs;  // the kind's own (the card's parameters come from material_inputs)
  std::vector<Observable> observables;
  const Observable* find_observable(const std::string& observable) const;
};

}  // namespace spifit::scene
