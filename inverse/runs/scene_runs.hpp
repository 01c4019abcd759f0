#pragma once
// The forward runs of the FE scenes of a fit (docs/design/identification.md, "Fits on FE scenes"): one
// run per scene and parameter point, however many experiments read it and however many
// threads ask at once (the pattern of Ceres's EvaluationCallback: one simulation per point,
// read by every residual block on it). A run that fails is retried once with half the tool
// travel per increment (unless it ran out of its time limit); what still fails is listed (fit.json "failed_runs") and its
// experiments report a failed evaluation, which the optimisers survive.
#include "forward/scenes/common/scene.hpp"
#include "inverse/runs/evaluation_cache.hpp"
#include "inverse/runs/job_pool.hpp"
#include "inverse/runs/parameter_point.hpp"

#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace spifit::inverse {

class SceneRuns {
 public:
  struct Failure {
    std::string scene;    // scene file
    std::string point;    // the parameter values, "swift.K=150 contact.friction=0.12"
    std::string message;  // why (both attempts)
    bool recovered = false;  // the retry with smaller increments ran
  };
  // One forward run, as it ended (a retry is a run of its own).
  struct Run {
    std::string scene;       // scene file
    std::string experiment;  // the experiment whose evaluation asked for the point first
    double seconds = 0.0;    // wall time
    bool retry = false;      // the second attempt, with half the increment
    bool ok = false;
  };

  // base: the fit's starting card (failures name the parameters that differ from it);
  // time_limit: seconds of wall time one run may take (0: no limit; a run past it is a failure,
  // not retried).
  explicit SceneRuns(material::MaterialParams<double> base, double time_limit = 0.0) : base_(std::move(base)), time_limit_(time_limit) {}

  // The typed result of `scene` at p: the scene with the fit's card (p.material replaces the
  // card's parameters) and p's scene inputs. Null when the run failed twice or p's inputs
  // cannot be set on the scene. Thread-safe; a point already run (or running) is not run again.
  // experiment: who asks (its runs are counted for it when it asks first).
  std::shared_ptr<const scene::SceneResult> result(const scene::Scene& scene, const ParameterPoint& p,
                                                   const std::string& experiment = "");

  // The runs of scene file `scene` carry exact derivatives with respect to `names` (the fit's
  // free parameters: the card's and contact.penalty; RunControl::sensitivities), hill.G moving
  // H = 2 - G when h_follows_g. Set before the runs start.
  void differentiate(const std::string& scene, std::vector<std::string> names, bool h_follows_g);

  // Evaluations kept on disk for a resume (null: none); the FE experiments read and add to it.
  void keep_evaluations(std::shared_ptr<EvaluationCache> cache) { evaluations_ = std::move(cache); }
  EvaluationCache* evaluations() const { return evaluations_.get(); }

  // Other processes that evaluate the FE experiments (null: this one does, fe_evaluation_job.hpp):
  // their runs and failures come back with each answer and are added here (add_remote).
  void use_pool(std::shared_ptr<JobPool> pool) { pool_ = std::move(pool); }
  JobPool* pool() const { return pool_.get(); }
  void add_remote(const std::vector<Run>& runs, const std::vector<Failure>& failures);
  // The pool's answer for key (a scene file and a point): ask() runs once per key, however many
  // experiments on that scene want it and however many threads ask at once, as result() runs a
  // scene once.
  std::string shared_answer(const std::string& key, const std::function<std::string()>& ask);
  const material::MaterialParams<double>& base() const { return base_; }

  // Told of every run that ends, here or (add_remote) on a worker: its wall seconds. Set it
  // before the runs start.
  void on_run(std::function<void(double seconds)> f) { on_run_ = std::move(f); }

  long runs() const;                   // forward runs made (retries included)
  std::vector<Failure> failures() const;  // in the order they happened
  std::vector<Run> run_log() const;       // every run made, in the order they ended

 private:
  using Entry = std::shared_future<std::shared_ptr<const scene::SceneResult>>;
  std::shared_ptr<const scene::SceneResult> run(const scene::Scene& scene, const ParameterPoint& p, const std::string& experiment);
  material::MaterialParams<double> base_;
  double time_limit_ = 0.0;
  struct Derivatives {
    std::vector<std::string> names;
    bool h_follows_g = false;
  };
  std::map<std::string, Derivatives> derivatives_;  // by scene file
  std::shared_ptr<EvaluationCache> evaluations_;
  std::shared_ptr<JobPool> pool_;
  mutable std::mutex mutex_;  // the readers above are const and lock it too
  std::map<std::string, Entry> cache_;
  std::deque<std::string> order_;  // keys, oldest first (the cache keeps the newest)
  std::vector<Failure> failures_;
  std::map<std::string, std::shared_future<std::string>> answers_;
  std::deque<std::string> answer_order_;
  std::vector<Run> log_;
  long runs_ = 0;
  std::function<void(double)> on_run_;
};

// The runs of one scene file of a fit: runs made (retries included), points that failed (after
// their retry, or whose inputs the scene refused), runs that were retries, and their wall time.
struct SceneFileRuns {
  std::string scene;
  long runs = 0, failures = 0, retried = 0;
  double seconds = 0.0;         // summed over the runs (side by side on several threads: more than the fit's wall time)
  double median_seconds = 0.0;  // of one run; NaN without runs
};
// Per scene file, in the order the files first ran or failed.
std::vector<SceneFileRuns> scene_file_runs(const std::vector<SceneRuns::Run>& log, const std::vector<SceneRuns::Failure>& failures);

// The exact bits of every value of p (the card's parameters, then the scene inputs by name): the
// key of a run and of a kept evaluation.
std::string point_key(const ParameterPoint& p);

// "swift.K=150 contact.friction=0.12": the material parameters of p that differ from the
// card's and p's scene inputs (for messages).
std::string describe_point(const ParameterPoint& p, const material::MaterialParams<double>& card);

}  // namespace spifit::inverse
