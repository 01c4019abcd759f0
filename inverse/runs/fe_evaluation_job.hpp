#pragma once
// A fit's FE evaluation as a job for another process (job_pool.hpp): an experiment's name and
// the parameter point (the card's parameters and the scene inputs, exact bits). The answer holds
// the residuals of every experiment on that experiment's scene file at the point (they share the
// run, as in one process) and the forward runs (and failures) made, which the fit's own
// SceneRuns adds to its log.
#include "inverse/runs/parameter_point.hpp"
#include "inverse/runs/scene_runs.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

struct FeEvaluationAnswer {
  struct Residuals {
    std::string experiment;
    bool ok = false;
    std::vector<double> values;  // the residuals, then their exact derivatives (row-major) when the experiment takes them
  };
  std::vector<Residuals> experiments;  // in the fit file's order
  std::vector<SceneRuns::Run> runs;
  std::vector<SceneRuns::Failure> failures;
  std::string error;  // the job could not be evaluated at all (an unknown experiment: a bug)
};

std::string fe_evaluation_job(const std::string& experiment, const ParameterPoint& p);
std::string encode_answer(const FeEvaluationAnswer& a);
FeEvaluationAnswer decode_fe_answer(const std::string& bytes);
// The answer of a job that could not be evaluated (why: e.g. its process died twice): a failed
// evaluation, listed among the fit's failures.
std::string failed_fe_answer(const std::string& why);

// A job as the worker reads it: the experiment asked for and the point, whose law is the base
// card's (the worker reads the same fit file).
struct FeEvaluationJob {
  std::string experiment;
  ParameterPoint point;
};
FeEvaluationJob decode_fe_evaluation_job(const std::string& bytes, const material::MaterialParams<double>& base);

}  // namespace spifit::inverse
