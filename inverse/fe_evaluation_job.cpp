#include "inverse/fe_evaluation_job.hpp"

#include "forward/material/material_inputs.hpp"
#include "inverse/fit_file.hpp"
#include "inverse/job_message.hpp"

#include <stdexcept>

namespace spifit::inverse {

namespace {

void write_point(MessageWriter& w, const ParameterPoint& p) {
  std::vector<double> m;
  for (const auto& in : material::material_inputs()) m.push_back(material::material_field(p.material, in.field));
  w.numbers(m);
  w.integer(static_cast<std::int64_t>(p.scene.size()));
  for (const auto& [name, v] : p.scene) w.text(name).number(v);
}

ParameterPoint read_point(MessageReader& r, const material::MaterialParams<double>& base) {
  ParameterPoint p;
  p.material = base;
  const auto& inputs = material::material_inputs();
  const std::vector<double> m = r.numbers();
  if (m.size() != inputs.size()) throw std::runtime_error("job message: a point of another spifit version");
  for (std::size_t i = 0; i < m.size(); ++i) material::material_field(p.material, inputs[i].field) = m[i];
  const std::int64_t n = r.integer();
  for (std::int64_t i = 0; i < n; ++i) {
    std::string name = r.text();
    p.scene.emplace_back(std::move(name), r.number());
  }
  return p;
}

}  // namespace

std::string fe_evaluation_job(const std::string& experiment, const ParameterPoint& p) {
  MessageWriter w;
  w.text(experiment);
  write_point(w, p);
  return w.bytes();
}

std::string encode_answer(const FeEvaluationAnswer& a) {
  MessageWriter w;
  w.text(a.error).integer(static_cast<std::int64_t>(a.experiments.size()));
  for (const auto& e : a.experiments) w.text(e.experiment).integer(e.ok ? 1 : 0).numbers(e.values);
  w.integer(static_cast<std::int64_t>(a.runs.size()));
  for (const auto& r : a.runs) w.text(r.scene).text(r.experiment).number(r.seconds).integer(r.retry ? 1 : 0).integer(r.ok ? 1 : 0);
  w.integer(static_cast<std::int64_t>(a.failures.size()));
  for (const auto& f : a.failures) w.text(f.scene).text(f.point).text(f.message).integer(f.recovered ? 1 : 0);
  return w.bytes();
}

FeEvaluationAnswer decode_fe_answer(const std::string& bytes) {
  MessageReader r(bytes);
  FeEvaluationAnswer a;
  a.error = r.text();
  for (std::int64_t i = 0, n = r.integer(); i < n; ++i) {
    FeEvaluationAnswer::Residuals e;
    e.experiment = r.text();
    e.ok = r.integer() != 0;
    e.values = r.numbers();
    a.experiments.push_back(std::move(e));
  }
  for (std::int64_t i = 0, n = r.integer(); i < n; ++i) {
    SceneRuns::Run run;
    run.scene = r.text();
    run.experiment = r.text();
    run.seconds = r.number();
    run.retry = r.integer() != 0;
    run.ok = r.integer() != 0;
    a.runs.push_back(run);
  }
  for (std::int64_t i = 0, n = r.integer(); i < n; ++i) {
    SceneRuns::Failure f;
    f.scene = r.text();
    f.point = r.text();
    f.message = r.text();
    f.recovered = r.integer() != 0;
    a.failures.push_back(f);
  }
  return a;
}

std::string failed_fe_answer(const std::string& why) {
  FeEvaluationAnswer a;
  a.error = why;
  return encode_answer(a);
}

JobHandler fe_evaluation_handler(const FitProblem& problem) {
  return [&problem](const std::string& job) {
    FeEvaluationAnswer a;
    try {
      MessageReader r(job);
      const std::string name = r.text();
      const SceneRuns& runs = *problem.scene_runs;
      const ParameterPoint p = read_point(r, runs.base());
      const Experiment* asked = nullptr;
      for (const auto& x : problem.experiments)
        if (x->name() == name) asked = x.get();
      if (!asked || asked->scene_file().empty()) throw std::runtime_error("no FE experiment " + name + " in the worker's fit file");
      const std::size_t logged = runs.run_log().size(), failed = runs.failures().size();
      for (const auto& x : problem.experiments) {
        if (x->scene_file() != asked->scene_file()) continue;
        FeEvaluationAnswer::Residuals e{x->name(), false, std::vector<double>(static_cast<std::size_t>(x->num_residuals()))};
        e.ok = x->residuals(p, e.values.data());
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
