#include "inverse/runs/fe_evaluation_job.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/material/material_inputs.hpp"

#include <stdexcept>

namespace spifit::inverse {

namespace {

// Jobs and answers as binary archives (exact bits, a checksum, and the kind and version: a worker
// of another spifit version is refused, not misread).
constexpr const char* kJobKind = "fe-evaluation-job";
constexpr const char* kAnswerKind = "fe-evaluation-answer";
constexpr std::uint32_t kVersion = 1;

void write_point(io::BinaryWriter& w, const ParameterPoint& p) {
  std::vector<double> m;
  for (const auto& in : material::material_inputs())
    if (material::holds_input(p.material, in)) m.push_back(material::material_field(p.material, in.field));
  w.f64s(m);
  w.i64(static_cast<std::int64_t>(p.scene.size()));
  for (const auto& [name, v] : p.scene) {
    w.string(name);
    w.f64(v);
  }
}

ParameterPoint read_point(io::BinaryReader& r, const material::MaterialParams<double>& base) {
  ParameterPoint p;
  p.material = base;
  // The point's law is the base card's: the values of the inputs it holds, in registry order.
  std::vector<const material::MaterialInput*> inputs;
  for (const auto& in : material::material_inputs())
    if (material::holds_input(base, in)) inputs.push_back(&in);
  const std::vector<double> m = r.f64s();
  if (m.size() != inputs.size()) throw std::runtime_error("job: a point of another spifit version");
  for (std::size_t i = 0; i < m.size(); ++i) material::material_field(p.material, inputs[i]->field) = m[i];
  for (std::int64_t i = 0, n = r.i64(); i < n; ++i) {
    std::string name = r.string();
    p.scene.emplace_back(std::move(name), r.f64());
  }
  return p;
}

}  // namespace

std::string fe_evaluation_job(const std::string& experiment, const ParameterPoint& p) {
  io::BinaryWriter w(kJobKind, kVersion);
  w.string(experiment);
  write_point(w, p);
  return w.finish();
}

std::string encode_answer(const FeEvaluationAnswer& a) {
  io::BinaryWriter w(kAnswerKind, kVersion);
  w.string(a.error);
  w.i64(static_cast<std::int64_t>(a.experiments.size()));
  for (const auto& e : a.experiments) {
    w.string(e.experiment);
    w.boolean(e.ok);
    w.f64s(e.values);
  }
  w.i64(static_cast<std::int64_t>(a.runs.size()));
  for (const auto& r : a.runs) {
    w.string(r.scene);
    w.string(r.experiment);
    w.f64(r.seconds);
    w.boolean(r.retry);
    w.boolean(r.ok);
  }
  w.i64(static_cast<std::int64_t>(a.failures.size()));
  for (const auto& f : a.failures) {
    w.string(f.scene);
    w.string(f.point);
    w.string(f.message);
    w.boolean(f.recovered);
  }
  return w.finish();
}

FeEvaluationAnswer decode_fe_answer(const std::string& bytes) {
  io::BinaryReader r(bytes, kAnswerKind, kVersion);
  FeEvaluationAnswer a;
  a.error = r.string();
  for (std::int64_t i = 0, n = r.i64(); i < n; ++i) {
    FeEvaluationAnswer::Residuals e;
    e.experiment = r.string();
    e.ok = r.boolean();
    e.values = r.f64s();
    a.experiments.push_back(std::move(e));
  }
  for (std::int64_t i = 0, n = r.i64(); i < n; ++i) {
    SceneRuns::Run run;
    run.scene = r.string();
    run.experiment = r.string();
    run.seconds = r.f64();
    run.retry = r.boolean();
    run.ok = r.boolean();
    a.runs.push_back(run);
  }
  for (std::int64_t i = 0, n = r.i64(); i < n; ++i) {
    SceneRuns::Failure f;
    f.scene = r.string();
    f.point = r.string();
    f.message = r.string();
    f.recovered = r.boolean();
    a.failures.push_back(f);
  }
  r.finish();
  return a;
}

std::string failed_fe_answer(const std::string& why) {
  FeEvaluationAnswer a;
  a.error = why;
  return encode_answer(a);
}

FeEvaluationJob decode_fe_evaluation_job(const std::string& bytes, const material::MaterialParams<double>& base) {
  io::BinaryReader r(bytes, kJobKind, kVersion);
  FeEvaluationJob job;
  job.experiment = r.string();
  job.point = read_point(r, base);
  return job;
}

}  // namespace spifit::inverse
