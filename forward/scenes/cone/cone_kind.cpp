#include "forward/scenes/cone/cone_kind.hpp"

#include "forward/scenes/common/fe_run_observables.hpp"
#include "forward/scenes/common/table_scene.hpp"
#include "forward/scenes/cone/cone_inputs.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_sensitivities.hpp"

namespace spifit::scene {
namespace {

class ConeSceneFile final : public TableScene<ConeScene> {
 public:
  explicit ConeSceneFile(ConeScene s) : TableScene("cone", std::move(s), &cone_inputs()) {}
  std::vector<std::string> input_files() const override { return {data_.file, data_.card.file}; }
  std::unique_ptr<Scene> clone() const override { return std::make_unique<ConeSceneFile>(*this); }
  std::unique_ptr<SceneResult> run(const RunFiles& files, const RunControl& control) const override {
    return std::make_unique<ConeResult>(run_cone_scene(data_, files, control));
  }
  std::optional<toolpath::ToolPath> tool_centre_path() const override { return cone_scene_path(data_).path; }
  int contours() const override { return cone_scene_contours(data_); }

 protected:
  std::string check_inputs() const override { return cone_scene_error(data_).text(); }

 public:
  std::vector<std::string> input_warnings() const override { return sheet_and_tool_warnings(cone_sheet_and_tool(data_)); }
};

const ConeResult& cone(const SceneResult& r) { return dynamic_cast<const ConeResult&>(r); }

Observable scalar(const char* name, const char* unit, const char* doc, std::function<double(const ConeResult&)> f, bool counts = false) {
  return {name, unit, doc, Observable::Needs::nothing, counts,
          [f = std::move(f)](const SceneResult& r, const ObservableOptions&) { return f(cone(r)); }};
}

std::vector<double> row(const ForceDerivatives& d, int k) {
  std::vector<double> out(static_cast<std::size_t>(d.cols()));
  for (Eigen::Index c = 0; c < d.cols(); ++c) out[static_cast<std::size_t>(c)] = d(k, c);
  return out;
}

// The run's peak of polar component k (ConeResult::peak_polar), with its sample's derivatives.
Observable peak_polar(const char* name, const char* doc, int k) {
  Observable o = scalar(name, "N", doc, [k](const ConeResult& r) { return r.peak_polar(k); });
  o.derivatives = [k](const SceneResult& r, const ObservableOptions&) {
    const std::optional<std::size_t> i = peak_polar_sample(cone(r), k);
    return i ? row(polar_sensitivity(cone(r), *i), k) : std::vector<double>{};
  };
  return o;
}

// f of the steady state's polar components over the contour range of the sweep or fit ([from,
// to], 1-based), and df/dp from their derivatives and f's gradient.
Observable steady(const char* name, const char* unit, const char* doc, std::function<double(const Eigen::Vector3d&)> f,
                  std::function<Eigen::RowVector3d(const Eigen::Vector3d&)> gradient) {
  Observable o{name, unit, doc, Observable::Needs::contours, false, [f](const SceneResult& r, const ObservableOptions& options) {
                 const SteadyState s = steady_state(cone(r).contours, options.contours->first, options.contours->second);
                 return s.contours == 0 ? kNaN : f(s.polar);
               }};
  o.derivatives = [gradient = std::move(gradient)](const SceneResult& r, const ObservableOptions& options) {
    const SteadyState s = steady_state(cone(r).contours, options.contours->first, options.contours->second);
    const auto d = steady_state_sensitivity(cone(r), options.contours->first, options.contours->second);
    if (s.contours == 0 || !d) return std::vector<double>{};
    const Eigen::RowVectorXd g = gradient(s.polar) * d->polar;
    return std::vector<double>(g.data(), g.data() + g.size());
  };
  return o;
}

Observable steady_component(const char* name, const char* doc, int k) {
  return steady(name, "N", doc, [k](const Eigen::Vector3d& p) { return p(k); },
                [k](const Eigen::Vector3d&) { return Eigen::RowVector3d::Unit(k); });
}

// polar component k over Fz.
Observable steady_ratio(const char* name, const char* doc, int k) {
  return steady(name, "", doc, [k](const Eigen::Vector3d& p) { return p(k) / p.z(); },
                [k](const Eigen::Vector3d& p) {
                  Eigen::RowVector3d g = Eigen::RowVector3d::Zero();
                  g(k) = 1.0 / p.z();
                  g(2) = -p(k) / (p.z() * p.z());
                  return g;
                });
}

std::vector<Observable> cone_observables() {
  Observable depth = scalar("centre_depth", "mm", "depth of the part centre (axis node, mid-surface) at the end of the last stage (stages.csv)",
                            [](const ConeResult& r) { return r.stages.empty() ? kNaN : r.stages.column("centre_depth").back(); });
  depth.derivatives = [](const SceneResult& r, const ObservableOptions&) {
    const Eigen::RowVectorXd& d = cone(r).centre_depth_sensitivity;
    return std::vector<double>(d.data(), d.data() + d.size());
  };
  std::vector<Observable> list{
      peak_polar("peak_fr", "largest |Fr| over the run (signed)", 0),
      peak_polar("peak_ftheta", "largest |Ftheta| over the run (signed)", 1),
      steady_component("steady_fr", "mean of the contour means of Fr over the contour range", 0),
      steady_component("steady_ftheta", "mean of the contour means of Ftheta over the contour range", 1),
      steady_component("steady_fz", "mean of the contour means of Fz over the contour range", 2),
      steady_ratio("steady_fr_over_fz", "Fr / Fz of the steady state over the contour range", 0),
      steady_ratio("steady_ftheta_over_fz", "Ftheta / Fz of the steady state over the contour range (friction)", 1),
      scalar("max_surface_penetration", "mm", "deepest point of the tool-side surface over the run",
             [](const ConeResult& r) { return r.force.max_surface_penetration(); }),
      std::move(depth),
      scalar("contours_completed", "", "contours the run completed", [](const ConeResult& r) { return double(r.run.marks_reached); }, true),
  };
  for (Observable& f : fe_run_observables()) list.push_back(std::move(f));
  return list;
}

}  // namespace

SceneKind cone_kind() {
  SceneKind k;
  k.name = "cone";
  k.family = "cone";
  k.doc = "a cone formed contour by contour on a disc or a pie with cyclic ties (thesis §4.1.2, §8, §9)";
  k.resumable = true;
  k.fe_run = true;
  k.sensitivities = true;
  k.read = [](const std::string& file) -> std::unique_ptr<Scene> { return std::make_unique<ConeSceneFile>(read_cone_scene(file)); };
  k.inputs = cone_inputs().infos();
  k.observables = cone_observables();
  return k;
}

}  // namespace spifit::scene
