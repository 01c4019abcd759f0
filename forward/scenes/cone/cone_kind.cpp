#include "forward/scenes/cone/cone_kind.hpp"

#include "forward/scenes/common/fe_run_observables.hpp"
#include "forward/scenes/common/table_scene.hpp"
#include "forward/scenes/cone/cone_inputs.hpp"
#include "forward/scenes/cone/cone_run.hpp"

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

// The steady state over the contour range of the sweep or fit ([from, to], 1-based).
Observable steady(const char* name, const char* doc, std::function<double(const SteadyState&)> f) {
  return {name, "N", doc, Observable::Needs::contours, false, [f = std::move(f)](const SceneResult& r, const ObservableOptions& o) {
            const SteadyState s = steady_state(cone(r).contours, o.contours->first, o.contours->second);
            return s.contours == 0 ? kNaN : f(s);
          }};
}

std::vector<Observable> cone_observables() {
  std::vector<Observable> list{
      scalar("peak_fr", "N", "largest |Fr| over the run (signed)", [](const ConeResult& r) { return r.peak_polar.x(); }),
      scalar("peak_ftheta", "N", "largest |Ftheta| over the run (signed)", [](const ConeResult& r) { return r.peak_polar.y(); }),
      steady("steady_fr", "mean of the contour means of Fr over the contour range", [](const SteadyState& s) { return s.polar.x(); }),
      steady("steady_ftheta", "mean of the contour means of Ftheta over the contour range", [](const SteadyState& s) { return s.polar.y(); }),
      steady("steady_fz", "mean of the contour means of Fz over the contour range", [](const SteadyState& s) { return s.polar.z(); }),
      {"steady_fr_over_fz", "", "Fr / Fz of the steady state over the contour range", Observable::Needs::contours, false,
       [](const SceneResult& r, const ObservableOptions& o) {
         const SteadyState s = steady_state(cone(r).contours, o.contours->first, o.contours->second);
         return s.contours == 0 ? kNaN : s.polar.x() / s.polar.z();
       }},
      {"steady_ftheta_over_fz", "", "Ftheta / Fz of the steady state over the contour range (friction)", Observable::Needs::contours, false,
       [](const SceneResult& r, const ObservableOptions& o) {
         const SteadyState s = steady_state(cone(r).contours, o.contours->first, o.contours->second);
         return s.contours == 0 ? kNaN : s.polar.y() / s.polar.z();
       }},
      scalar("max_surface_penetration", "mm", "deepest point of the tool-side surface over the run",
             [](const ConeResult& r) { return r.force.max_surface_penetration(); }),
      scalar("centre_depth", "mm", "depth of the part centre (axis node, mid-surface) at the end of the last stage (stages.csv)",
             [](const ConeResult& r) { return r.stages.empty() ? kNaN : r.stages.column("centre_depth").back(); }),
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
  k.read = [](const std::string& file) -> std::unique_ptr<Scene> { return std::make_unique<ConeSceneFile>(read_cone_scene(file)); };
  k.inputs = cone_inputs().infos();
  k.observables = cone_observables();
  return k;
}

}  // namespace spifit::scene
