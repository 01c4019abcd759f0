#include "inverse/fit/fe_evaluation_worker.hpp"

#include "inverse/runs/fe_evaluation_job.hpp"
#include "inverse/fit/fit_file.hpp"

#include <stdexcept>

namespace spifit::inverse {

JobHandler fe_evaluation_handler(const FitProblem& problem) {
  return [&problem](const std::string& job) {
    FeEvaluationAnswer a;
    try {
      SceneRuns& runs = *problem.scene_runs;
      const FeEvaluationJob asked_for = decode_fe_evaluation_job(job, runs.base());
      const std::string& name = asked_for.experiment;
      const ParameterPoint& p = asked_for.point;
      const Experiment* asked = nullptr;
      for (const auto& x : problem.experiments)
        if (x->name() == name) asked = x.get();
      if (!asked || asked->scene_file().empty()) throw std::runtime_error("no FE experiment " + name + " in the worker's fit file");
      const std::size_t logged = runs.run_log().size(), failed = runs.failures().size();
      for (const auto& x : problem.experiments) {
        if (x->scene_file() != asked->scene_file()) continue;
        // The residuals, then their exact derivatives when the experiment takes them.
        const std::size_t m = static_cast<std::size_t>(x->num_residuals()), q = static_cast<std::size_t>(x->exact_columns());
        FeEvaluationAnswer::Residuals e{x->name(), false, std::vector<double>(m * (1 + q))};
        e.ok = q > 0 ? x->residuals_and_derivatives(p, e.values.data(), e.values.data() + m) : x->residuals(p, e.values.data());
        if (!e.ok) e.values.clear();
        a.experiments.push_back(std::move(e));
      }
      const auto log = runs.run_log();
      const auto failures = runs.failures();
      a.runs.assign(log.begin() + static_cast<std::ptrdiff_t>(logged), log.end());
      a.failures.assign(failures.begin() + static_cast<std::ptrdiff_t>(failed), failures.end());
    } catch (const std::exception& e) {
      a.experiments.clear();
      a.error = e.what();
    }
    return encode_answer(a);
  };
}

}  // namespace spifit::inverse
