#include "forward/scenes/common/fe_run_observables.hpp"

#include "forward/scenes/common/fe_scene_result.hpp"

#include <functional>

namespace spifit::scene {
namespace {

Observable fe_scalar(const char* name, const char* unit, const char* doc, std::function<double(const FeSceneResult&)> f, bool counts = false) {
  return {name, unit, doc, Observable::Needs::nothing, counts,
          [f = std::move(f)](const SceneResult& r, const ObservableOptions&) { return f(dynamic_cast<const FeSceneResult&>(r)); }};
}

}  // namespace

std::vector<Observable> fe_run_observables() {
  return {
      fe_scalar("peak_fz", "N", "largest |Fz| over the run (signed)", [](const FeSceneResult& r) { return r.force.peak().z(); }),
      fe_scalar("final_fz", "N", "Fz at the end of the path", [](const FeSceneResult& r) { return r.force.final_force().z(); }),
      fe_scalar("max_penetration", "mm", "deepest contact point over the run", [](const FeSceneResult& r) { return r.force.max_penetration(); }),
      fe_scalar("newton_iterations", "", "Newton iterations of the run",
                [](const FeSceneResult& r) { return static_cast<double>(r.run.counters.iterations); }, true),
      fe_scalar("increments", "", "committed increments of the run",
                [](const FeSceneResult& r) { return static_cast<double>(r.run.counters.increments); }, true),
  };
}

}  // namespace spifit::scene
