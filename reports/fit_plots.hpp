#pragma once
// The plots of a fit report (docs/guide/reading-reports.md "Plots and gnuplot"): per curve experiment the
// data with the initial and fitted simulation, and the residuals; the scalar experiments as
// bars; the cost per iteration.
#include "inverse/fit/fit_record.hpp"
#include "reports/experiment_data.hpp"
#include "reports/fit_verdict.hpp"
#include "reports/plot_session.hpp"

#include <string>
#include <vector>

namespace spifit::reports {

// Images as the report links them ("plots/NAME.svg"); empty where none was written.
struct FitPlots {
  std::vector<std::string> fit, residuals;  // per experiment of the record
  std::string scalars, convergence;
};

// The label of an experiment's abscissa (or response) with its unit: the quantities of FE
// experiments in words ("tool travel [mm]", "Fz [N]", "contour mean Fθ / Fz"), the others by
// their names ("strain [-]"); fallback when the record names none.
std::string experiment_axis_label(const inverse::FitRecord::Experiment& e, bool abscissa, const std::string& fallback);

// NN_NAME_fit: measured points, initial (dashed) and fitted simulation; the initial curve is
// clipped when it spans more than 3 times the data. index: the experiment's position (1-based).
PlotSpec curve_fit_plot(int index, const inverse::FitRecord::Experiment& e, const ExperimentData& d);
// NN_NAME_residuals: (fitted - measured) / divisor, with lines at 0 and at +-1 sigma (noise given).
PlotSpec curve_residual_plot(int index, const inverse::FitRecord::Experiment& e, const ExperimentData& d, const ExperimentVerdict& v);
// scalars: one bar per scalar experiment with data; red bars in conflict. No series when none.
PlotSpec scalar_plot(const inverse::FitRecord& record, const std::vector<ExperimentData>& data, const FitVerdict& verdict);
// convergence: cost_history on a log scale.
PlotSpec convergence_plot(const inverse::FitRecord& record);

// Renders them in the order above (curves in experiment order). Plots with nothing to show
// (no data file, no scalar experiment, no cost history) are not attempted.
FitPlots render_fit_plots(const inverse::FitRecord& record, const std::vector<ExperimentData>& data, const FitVerdict& verdict,
                          PlotSession& session);

}  // namespace spifit::reports
