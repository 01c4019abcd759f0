#pragma once
// The record of one fit as `spifit fit` stores it in DIR/fit.json (docs/reference/file-formats.md): plain
// data, written by inverse/fit/fit_output.cpp and read by the reports. Numbers that fit.json holds
// as null (not finite, not computed) are NaN here; keys that a fit.json of an older spifit may
// lack are std::optional where the readers tell "absent" from a value.
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace spifit::inverse {

struct FitRecord {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  // parameters.NAME: a free parameter.
  struct Parameter {
    std::string name;
    double value = kNaN, initial = kNaN, lower = kNaN, upper = kNaN;
    bool log_scale = false;
    // std_error, ci95 and identifiable are present together (absent when the fit computed no
    // uncertainty).
    bool has_uncertainty = false;
    double std_error = kNaN, ci95_lower = kNaN, ci95_upper = kNaN;
    bool identifiable = true;
  };
  // fixed.NAME: a number, or a text such as "2 - hill.G" (then expression is not empty).
  struct FixedParameter {
    std::string name;
    double value = kNaN;
    std::string expression;
  };
  // correlation: names (the free parameters in fit order) and the matrix.
  struct Correlation {
    std::vector<std::string> names;
    std::vector<std::vector<double>> matrix;
  };
  // uncertainty: sizes and the scaled singular values (uncertainty.hpp).
  struct UncertaintySummary {
    std::optional<int> residuals, parameters, dof;
    double sse = kNaN, sigma2 = kNaN, t_quantile_975 = kNaN, condition_number = kNaN;
    double relative_offset = kNaN;  // at the solution (absent from older records)
    std::vector<double> singular_values_scaled;
  };
  // per_experiment[i]: the fit of one experiment alone (conflicts.hpp).
  struct AloneValue {
    std::string parameter;
    double value = kNaN, ci95_lower = kNaN, ci95_upper = kNaN;
    bool identifiable = true;
  };
  struct Alone {
    std::string experiment;
    bool usable = true;
    std::vector<AloneValue> parameters;
  };
  // multistart (present in fit.json only when starts > 1).
  struct Spread {
    std::string parameter;
    double min = kNaN, max = kNaN;
  };
  struct StartSolution {
    bool usable = false;
    double cost = kNaN;
    std::vector<double> start, values;
  };
  struct MultiStart {
    int starts = 1, best_start = -1, starts_at_best_cost = -1;  // -1: not given
    std::vector<Spread> spread_at_best_cost;
    std::vector<StartSolution> solutions;
  };
  // experiments[i]: costs, the divisor of the residuals and the axes of the data file.
  struct Experiment {
    std::string name, kind;  // curve, scalar (material points); force_curve, section, contour_means, fe_scalar (FE)
    int points = 0;
    double cost = kNaN, rms = kNaN;
    double scale = kNaN;              // divisor of the residuals (noise, or range / |value|)
    std::optional<bool> noise_given;  // whether scale is a stated noise
    // With a stated noise: the rms of (simulated - measured) / noise without the weights, over
    // the points of nonzero weight, and how many (absent from a fit.json of an older spifit).
    double noise_rms = kNaN;
    std::optional<int> noise_points;
    double weight = 1.0;
    std::string x, y, x_unit, y_unit;
    std::string x_words, y_words;  // what the axes show ("shear strain γ"); "": from x and y
    std::string data_file;  // relative to DIR, e.g. experiments/NAME.csv
    // Forward runs (absent from a fit.json of an older spifit): evaluations of the residuals;
    // FE experiments: the scene runs they asked for first and those runs' summed wall seconds.
    std::optional<long> evaluations, scene_runs;
    double run_seconds = kNaN;
    // How the fit differentiated it: jets, exact (through the FE runs) or central (differences of
    // whole runs); "" in a fit.json of an older spifit.
    std::string jacobian;
    // information_share: per free parameter (in the order of parameters) this experiment's
    // share of its Fisher information at the solution; empty when fit.json has none.
    std::vector<double> information_share;
  };

  std::string spifit_version;
  std::string name;  // key "fit"
  std::string fit_file, algorithm, termination, cost_definition;
  std::optional<unsigned> seed;
  std::optional<bool> usable;
  std::vector<std::string> not_usable;  // key "not_usable_because": why usable is false (absent when usable)
  std::optional<int> iterations;
  std::optional<long> forward_runs;
  double wall_seconds = kNaN, cost_initial = kNaN, cost_final = kNaN;
  std::vector<double> cost_history;
  std::vector<Parameter> parameters;  // in fit order (correlation.names first)
  std::vector<FixedParameter> fixed;
  Correlation correlation;
  UncertaintySummary uncertainty;
  std::vector<std::string> warnings, conflicts;
  // Remarks from reading the fit file (a renormalised Hill card, measured values 10-100 times off,
  // a scene's plausibility warnings): key "notes" (a fit.json of an older spifit has them among
  // its warnings).
  std::vector<std::string> notes;
  std::vector<Alone> per_experiment;
  MultiStart multistart;
  std::vector<Experiment> experiments;
  // FE experiments: forward runs of their scenes, and the runs that failed or were retried.
  struct FailedRun {
    std::string scene, point, message;
    bool recovered = false;
  };
  std::optional<long> scene_runs;
  std::vector<FailedRun> failed_runs;
  // runs_by_scene: per FE scene file its runs (retries included), failed points, retried runs,
  // and their wall time (summed; the median of one run).
  struct SceneFile {
    std::string scene;
    long runs = 0, failures = 0, retried = 0;
    double seconds = kNaN, median_seconds = kNaN;
  };
  std::vector<SceneFile> runs_by_scene;
};

// fit.json's object. Its dump(2) plus a newline is the file `spifit fit` writes.
nlohmann::json to_json(const FitRecord& record);

// Reads a fit.json object. Throws io::InputError naming `file` and the key path (for example
// parameters.swift.K.value) when a key has the wrong type or `parameters` / `experiments` are
// missing. Keys it does not know are ignored; multistart is read leniently.
FitRecord fit_record_from_json(const nlohmann::json& j, const std::string& file);

// Reads and parses the file; io::InputError when it cannot be read or is not valid JSON.
FitRecord read_fit_record(const std::filesystem::path& file);

}  // namespace spifit::inverse
