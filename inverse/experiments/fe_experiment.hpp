#pragma once
// Experiments on FE scenes (indent, indent_line, line, cone, ...; docs/design/identification.md, "Fits
// on FE scenes"): a tool-force curve against tool-tip depth, tool travel or time, or a scalar
// observable of the scene kind (peak_fz, mean_fx over a travel window, steady_ftheta_over_fz
// over a contour range, ...). The runs come from the fit's SceneRuns (one per parameter point,
// shared by the experiments on the same scene); derivatives come through the runs (force curves
// and sections' z, when the fit's runs carry sensitivities) or from central differences.
#include "forward/scenes/common/fe_scene_result.hpp"
#include "forward/scenes/common/scene.hpp"
#include "inverse/experiments/experiment.hpp"
#include "inverse/runs/scene_runs.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spifit::inverse {

// What every FE experiment names: the scene (its card is replaced by the fit's), the runs it
// shares, and the conditioning.
struct FeExperimentBase {
  std::string name;
  std::shared_ptr<const scene::Scene> scene;
  std::shared_ptr<SceneRuns> runs;
  double noise = 0.0;  // measurement standard deviation; 0: the range of the data (curve) or |value|
  double noise_relative = 0.0;  // curves: > 0, each y's standard deviation is this fraction of |y|
  double weight = 1.0;
};

struct FeScalarSpec : FeExperimentBase {
  const scene::Observable* observable = nullptr;  // of the scene's kind
  scene::ObservableOptions options;                // window or contours when it needs them
  double value = 0.0;
  std::string source;
};
std::unique_ptr<Experiment> make_fe_scalar_experiment(FeScalarSpec spec);

// A force component against an abscissa of the tool's motion.
struct ForceCurveSpec : FeExperimentBase {
  std::string x = "depth", y = "fz";  // force_curve_abscissa_names(), force_component_names()
  std::vector<double> xs, ys, point_weights;
  std::string y_unit = "N";
};
std::unique_ptr<Experiment> make_force_curve_experiment(ForceCurveSpec spec);

// A measured curve (xs, ys in the units x_unit, y_unit) against the curve `simulated` gives from a
// run at a parameter point (empty: the run does not give it), interpolated at xs; for experiments
// defined in files of their own (cone sections, cone_section_experiment.hpp).
struct FeCurve {
  std::string x, y, x_unit, y_unit;
  std::vector<double> xs, ys, point_weights;
};
// A simulated curve, with the derivatives of a run with sensitivities (ResultCurve::dx, dy).
using ForceCurve = scene::ResultCurve;
using SimulatedCurve = std::function<ForceCurve(const scene::SceneResult&, const ParameterPoint&)>;
// differentiable: `simulated` gives the curve's derivatives in a run with sensitivities (the fit's
// exact Jacobian); else the experiment's columns come from central differences.
std::unique_ptr<Experiment> make_fe_curve_experiment(const FeExperimentBase& base, const char* kind, FeCurve curve, SimulatedCurve simulated,
                                                     bool differentiable = false);

// A section y = 0 of a forming scene at a named path point (its [output] sections): the
// mid-surface height z or the thickness against x (deformed) or x0 (initial), mm.
struct SectionSpec : FeExperimentBase {
  std::string point;
  std::string x = "x", y = "z";  // x | x0; z | thickness
  std::vector<double> xs, ys, point_weights;
};
std::unique_ptr<Experiment> make_section_experiment(SectionSpec spec);
bool is_section_abscissa(const std::string& x);
bool is_section_response(const std::string& y);

// The central-third means of a cone's contours (thesis §8.3) against the contour number: a force
// component (fr, ftheta, fz in the polar frame; fx, fy, fz Cartesian) or a ratio
// (ftheta_over_fz, fr_over_fz).
struct ContourMeansSpec : FeExperimentBase {
  std::string y = "ftheta";
  std::vector<double> contours, ys, point_weights;
};
std::unique_ptr<Experiment> make_contour_means_experiment(ContourMeansSpec spec);

// depth (of the tool tip below the initial top surface, mm), travel (mm along the path), time (s).
const char* force_curve_abscissa_names();
bool is_force_curve_abscissa(const std::string& x);
const char* force_curve_abscissa_unit(const std::string& x);
// fx, fy, fz (global), fr, ftheta (polar about the z axis at the tool centre's angle).
const char* force_component_names();
bool is_force_component(const std::string& y);

// The tool force component y against x over a run, starting at the path's start (zero force)
// and ending where x stops increasing (a depth curve ends where the tool stops going down).
// thickness and tool_radius place the tool tip; start is the tool centre at the path's start.
ForceCurve force_curve(const scene::ToolForceHistory& h, const Eigen::Vector3d& start, double thickness, double tool_radius,
                       const std::string& x, const std::string& y);

// The range [x at the start, x where it stops increasing] of an abscissa along a tool centre path.
// The derivatives dy of c (a force_curve of component y) from the run's force sensitivities
// (SceneResult::force_sensitivities); false when the run holds none for c's samples.
bool add_force_curve_derivatives(const scene::SceneResult& r, const std::string& y, ForceCurve* c);

std::pair<double, double> force_curve_range(const toolpath::ToolPath& centre, double thickness, double tool_radius, const std::string& x);

// The section's y against x at a named path point (SceneResult::path_section); empty when the
// result has no section at `point` or x does not increase along it.
ForceCurve section_curve(const scene::SceneResult& r, const std::string& point, const std::string& x, const std::string& y);

}  // namespace spifit::inverse
