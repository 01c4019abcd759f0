#include "forward/model/model_archive.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/fe_model.hpp"

namespace spifit::model {

void save_model_state(io::BinaryWriter& w, const FeModel& model) {
  w.section("shell_model");
  w.i64(model.num_nodes());
  w.i64(model.num_elements());
  w.f64(model.load_factor());
  w.vec3s(model.positions());
  w.vec3s(model.directors());
  w.f64(model.load_work());
  w.section("elements");
  model.family().save_state(w);
  w.section("contributions");
  w.i64(static_cast<std::int64_t>(model.contributions().size()));
  for (const auto& c : model.contributions()) {
    w.string(c->name());
    c->save_state(w);
  }
  if (model.sensitivity_count() > 0) {  // a run with sensitivities only: a plain run's state is as it was
    w.section("sensitivities");
    model.save_sensitivities(w);
  }
}

void load_model_state(io::BinaryReader& r, FeModel* model) {
  r.section("shell_model");
  r.expect_count("nodes", model->num_nodes());
  r.expect_count("elements", model->num_elements());
  const double lambda = r.f64();
  std::vector<Eigen::Vector3d> x = r.vec3s(), d = r.vec3s();
  if (x.size() != static_cast<std::size_t>(model->num_nodes()) || d.size() != x.size())
    throw io::ArchiveError("nodal positions or directors of another model size");
  const double load_work = r.f64();
  r.section("elements");
  model->family_state().load_state(r);
  r.section("contributions");
  r.expect_count("model contributions", static_cast<std::int64_t>(model->contributions().size()));
  for (const auto& c : model->contributions()) {
    const std::string name = r.string();
    if (name != c->name()) throw io::ArchiveError("contribution \"" + name + "\" in the state where the model has \"" + c->name() + "\"");
    c->load_state(r);
  }
  model->restore_committed(lambda, std::move(x), std::move(d), load_work);
  if (model->sensitivity_count() > 0) {
    r.section("sensitivities");
    model->load_sensitivities(r);
  }
}

}  // namespace spifit::model
