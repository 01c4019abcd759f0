#pragma once
// A fit file (TOML, schema in docs/reference/file-formats.md): the starting card, the named free and
// fixed parameters with bounds, the experiments and the optimiser settings.
#include "inverse/experiments/experiment.hpp"
#include "inverse/fit/parameters.hpp"
#include "inverse/runs/scene_runs.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::inverse {

struct FitSettings {
  std::string algorithm = "levenberg_marquardt";  // levenberg_marquardt | dogleg
  int max_iterations = 200;
  double function_tolerance = 1e-14;
  double parameter_tolerance = 1e-12;
  double gradient_tolerance = 1e-14;
  // Stop once the relative offset (relative_offset.hpp) at an accepted point is at most this:
  // the Gauss-Newton step left is below sqrt(p) times it in standard errors (0: not used).
  double offset_tolerance = 0.0;
  double run_time_limit = 0.0;  // s of wall time one FE forward run may take (0: no limit)
  // FE experiments' Jacobian: "exact" (through runs with sensitivities; refused where a scene
  // cannot give them), "central" (differences of whole runs), or "" (the fit file does not say:
  // exact for each scene file that can be differentiated, central for the others).
  std::string jacobian;
};

// The defaults of a fit with FE experiments (unless the fit file states them): an FE run's cost
// wobbles from one evaluation to the next by about 1e-11 of itself at the solution (the Newton
// tolerances), so the tolerances above would keep Levenberg-Marquardt stepping on that noise
// (docs/design/identification.md, "Stopping"); they stop on the relative offset instead, at 1e-3.
FitSettings fe_fit_settings();

struct FitProblem {
  std::string name, description, file;
  std::unique_ptr<ParameterSet> parameters;
  std::vector<std::shared_ptr<Experiment>> experiments;
  FitSettings settings;
  // Also fit each experiment alone and compare (conflicts); a fit file's default: true with
  // material-point experiments only, false with any FE experiment.
  bool per_experiment = false;
  int multistart = 1;           // number of starts (1: the initial point only)
  std::vector<std::string> notes;  // reading remarks shown with the result (e.g. renormalised Hill)
  // The forward runs of the FE experiments (null without any): shared by the experiments on
  // one scene, with the failures of the fit.
  std::shared_ptr<SceneRuns> scene_runs;
  // Every file the fit reads (fit file, card, scenes and what they read, data): what a resume
  // checks has not changed, and what must not lie in the output directory.
  std::vector<std::string> input_files;
  // The measurement files of the experiments (a fitted card's provenance), in fit-file order.
  std::vector<std::string> data_files;
};

// Throws io::InputError naming file, key and value (unknown parameter, bad bounds, missing
// data column, measured abscissa outside the simulated range, ...).
// jacobian: "exact" or "central" overrides [fit] jacobian (spifit fit --jacobian); "" keeps it.
FitProblem read_fit_file(const std::string& path, const std::string& jacobian = "");

}  // namespace spifit::inverse
