#pragma once
// The worker's side of a fit's FE evaluations over processes (fe_evaluation_job.hpp has the
// messages): answers a job from the fit problem the worker read itself.
#include "inverse/runs/job_pool.hpp"

namespace spifit::inverse {

struct FitProblem;

// The worker's side: evaluates the experiments of `problem` (read from the same fit file as rank
// 0's) on the job's experiment's scene file at its point, on this process's own SceneRuns (no
// cache, no pool).
JobHandler fe_evaluation_handler(const FitProblem& problem);

}  // namespace spifit::inverse
