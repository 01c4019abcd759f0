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

Observable with_sample_derivatives(Observable o, int k, SamplePick pick) {
  o.derivatives = [k, pick = std::move(pick)](const SceneResult& r, const ObservableOptions&) {
    const auto& fe = dynamic_cast<const FeSceneResult&>(r);
    const std::optional<std::size_t> i = pick(fe.force);
    if (!i) return std::vector<double>{};
    const Eigen::Matrix<double, 3, Eigen::Dynamic> d = fe.force_sensitivity(*i);
    std::vector<double> out(static_cast<std::size_t>(d.cols()));
    for (Eigen::Index c = 0; c < d.cols(); ++c) out[static_cast<std::size_t>(c)] = d(k, c);
    return out;
  };
  return o;
}

std::vector<Observable> fe_run_observables() {
  return {
      with_sample_derivatives(fe_scalar("peak_fz", "N", "largest |Fz| over the run (signed)", [](const FeSceneResult& r) { return r.force.peak().z(); }), 2,
                              [](const ToolForceHistory& h) { return peak_sample(h, 2); }),
      with_sample_derivatives(fe_scalar("final_fz", "N", "Fz at the end of the path", [](const FeSceneResult& r) { return r.force.final_force().z(); }), 2,
                              [](const ToolForceHistory& h) { return last_sample(h); }),
      fe_scalar("max_penetration", "mm", "deepest contact point over the run", [](const FeSceneResult& r) { return r.force.max_penetration(); }),
      fe_scalar("newton_iterations", "", "Newton iterations of the run",
                [](const FeSceneResult& r) { return static_cast<double>(r.run.counters.iterations); }, true),
      fe_scalar("increments", "", "committed increments of the run",
                [](const FeSceneResult& r) { return static_cast<double>(r.run.counters.increments); }, true),
  };
}

}  // namespace spifit::scene
