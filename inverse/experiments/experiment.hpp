#pragma once
// An experiment = a scene + what is measured + how residuals are weighted (docs/design/identification.md).
// The identification sees the forward model only through this interface: parameter values
// in, conditioned residuals out. Material-point experiments evaluate with Jets (exact
// derivatives); FE experiments (fe_experiment.hpp) report supports_jets() = false and are
// differentiated through their runs (exact_columns()) or by central differences (numeric_cost.hpp).
#include "forward/material/material_params.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"
#include "inverse/runs/parameter_point.hpp"

#include <ceres/jet.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace spifit::inverse {

constexpr int kJetSize = 8;  // derivative slots per pass (Ceres DynamicAutoDiffCostFunction stride)
using Jet = ceres::Jet<double, kJetSize>;

// Compared quantity for reports: abscissa, measured and simulated values.
struct ExperimentCurve {
  std::string x_name, y_name, x_unit, y_unit;
  std::vector<double> x, measured, simulated;
  std::string x_words, y_words;  // what the axes show, e.g. "shear strain γ"; "": the names
};

// Whether measured values are plausible for their experiment (measurement_plausibility.hpp):
// level 0 fine, 1 odd but possible (a note with the fit), 2 implausible (an input error naming
// the data file: most often a wrong unit in its header).
struct MagnitudeCheck {
  int level = 0;
  std::string message;  // what was compared, in words
};

class Experiment {
 public:
  virtual ~Experiment() = default;
  const std::string& name() const { return name_; }
  const std::string& kind() const { return kind_; }
  double weight() const { return weight_; }
  // What multiplies the square of residual i besides the noise: the experiment's weight times
  // the point's (a weight column). A residual divided by its square root is (simulated -
  // measured) / its noise, what fit_assessment.hpp compares with the stated noise.
  double residual_weight(int i) const {
    return i >= 0 && i < static_cast<int>(residual_weights_.size()) ? residual_weights_[static_cast<std::size_t>(i)] : weight_;
  }
  double scale() const { return scale_; }  // the conditioning divisor (noise or range)
  bool noise_given() const { return noise_given_; }  // scale is a stated measurement noise
  virtual int num_residuals() const = 0;
  // Residuals = sqrt(weights) * (simulated - measured) / scale. False: the forward run failed.
  virtual bool residuals(const ParameterPoint& p, double* r) const = 0;
  // With Jets (material parameters only); an experiment without supports_jets() returns false.
  virtual bool residuals(const material::MaterialParams<Jet>& m, Jet* r) const = 0;
  virtual bool supports_jets() const { return true; }
  // FE experiments whose runs carry exact derivatives (direct differentiation,
  // docs/design/sensitivities.md): the number of fit parameters they are taken with respect to,
  // the fit's free ones in its order (0: none; Jets or central differences).
  virtual int exact_columns() const { return 0; }
  // The residuals and their derivatives with respect to the free parameters' physical values,
  // drdp row-major (num_residuals() x exact_columns()). False: the forward run failed, or the
  // experiment has no exact derivatives.
  virtual bool residuals_and_derivatives(const ParameterPoint& p, double* r, double* drdp) const {
    (void)p, (void)r, (void)drdp;
    return false;
  }
  // FE experiments: whether its residuals can take exact derivatives from runs with
  // sensitivities (a force curve, a section's z), and to take them from now on with respect to
  // `columns` parameters (the runs of its scene file must carry them: SceneRuns::differentiate).
  virtual bool differentiable() const { return false; }
  virtual void set_exact_columns(int columns) {
    (void)columns;
    throw std::logic_error("experiment " + name_ + " has no exact derivatives");
  }
  // How a fit differentiates it: "jets", "exact" (through the FE run) or "central" (differences
  // of whole runs).
  std::string jacobian() const { return supports_jets() ? "jets" : exact_columns() > 0 ? "exact" : "central"; }
  // How many evaluations of this experiment may usefully run at once beyond this process's
  // threads: the workers of the FE runs' pool (0: none).
  virtual int parallel_evaluations() const { return 0; }
  // FE experiments: the scene file whose runs it reads ("" for material points); experiments on
  // one scene file share each run.
  virtual std::string scene_file() const { return ""; }
  // Measured vs simulated at p (for reports); empty simulated values if the run failed.
  virtual ExperimentCurve compare(const ParameterPoint& p) const = 0;
  // Names and units of the compared quantities, without running anything.
  virtual ExperimentCurve axes() const = 0;
  // The measured values against what a forming engineer expects of this experiment: by default
  // their largest magnitude against the simulated one at `start` (compare_magnitudes; cheap for
  // material points); FE experiments compare with the scales of their scene instead, without a run.
  virtual MagnitudeCheck check_magnitudes(const ParameterPoint& start) const;
  // How often residuals were asked for so far (with doubles or Jets; an FE experiment's answers
  // from a resumed fit's kept evaluations included). compare() does not count.
  long evaluations() const { return evaluations_.load(std::memory_order_relaxed); }

 protected:
  void count_evaluation() const { evaluations_.fetch_add(1, std::memory_order_relaxed); }
  std::string name_, kind_;
  double weight_ = 1.0, scale_ = 1.0;
  bool noise_given_ = false;
  std::vector<double> residual_weights_;  // per residual; empty: weight_ for every one

 private:
  mutable std::atomic<long> evaluations_{0};
};

// A curve measured on a material-point scene: y(x) with x an abscissa of the simulated curve
// (strain, cumulative_strain for curves that reverse, or increment).
struct CurveExperimentSpec {
  std::string name;
  scene::MaterialPointScene scene;
  std::string x, y;           // column names in the data file and in the simulated curve
  std::vector<double> xs, ys, point_weights;
  std::string x_unit, y_unit;
  double noise = 0.0;         // measurement standard deviation of y; 0: use the range of y
  double noise_relative = 0.0;  // > 0: the standard deviation of each y is this fraction of |y|
  double weight = 1.0;
};
std::unique_ptr<Experiment> make_curve_experiment(CurveExperimentSpec spec);

// How the residuals of a measured curve ys are conditioned (material-point and FE curves alike):
// the divisor `scale` (the stated noise, or the range of ys; 1 with a relative noise) and the
// square roots of the point weights, divided by each point's standard deviation rel * max(|y_i|,
// 1e-3 max|y|) with a relative noise (a y of zero would otherwise weigh infinitely).
struct CurveConditioning {
  double scale = 1.0;
  bool noise_given = false;
  std::vector<double> sqrt_weights;
  std::vector<double> weights;  // per point: weight x point weight (no noise in it)
};
CurveConditioning curve_conditioning(const std::vector<double>& ys, double noise, double noise_relative, double weight,
                                     const std::vector<double>& point_weights);

// A scalar measured on a material-point scene (r_value, yield_stress, initial_yield_stress,
// reverse_yield_stress, final_stress).
struct ScalarExperimentSpec {
  std::string name;
  scene::MaterialPointScene scene;
  std::string observable;
  double value = 0.0, noise = 0.0, weight = 1.0;
  std::string source;  // provenance, e.g. "thesis App. C.1"
};
std::unique_ptr<Experiment> make_scalar_experiment(ScalarExperimentSpec spec);

// A table of scalars measured on a material-point scene: row i runs the scene with its input x
// (e.g. scene.angle) at xs[i] and compares the observable with ys[i]; one residual per row,
// conditioned as a curve's (curve_conditioning).
struct ScalarTableExperimentSpec {
  std::string name;
  std::vector<scene::MaterialPointSetup> setups;  // one per row, the row's x set
  std::string observable, x, x_unit, y_unit;      // x: the data column (a scene input's key)
  std::vector<double> xs, ys, point_weights;
  double noise = 0.0, noise_relative = 0.0, weight = 1.0;
  std::string source;
};
std::unique_ptr<Experiment> make_scalar_table_experiment(ScalarTableExperimentSpec spec);
const char* scalar_observable_names();
bool is_scalar_observable(const std::string& name);

}  // namespace spifit::inverse
