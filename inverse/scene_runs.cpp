#include "inverse/scene_runs.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_inputs.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace spifit::inverse {
namespace {

// Enough points for every evaluation of one iteration (the point, 2p perturbations, a few
// trial steps) of several scenes; older results are dropped.
constexpr std::size_t kCachedRuns = 256;

// The scene file and the point.
std::string key_of(const scene::Scene& scene, const ParameterPoint& p) { return scene.file() + " " + point_key(p); }

}  // namespace

std::string point_key(const ParameterPoint& p) {
  std::string key;
  auto add = [&key](double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    char buf[24];
    std::snprintf(buf, sizeof buf, "%s%016llx", key.empty() ? "" : " ", static_cast<unsigned long long>(bits));
    key += buf;
  };
  for (const auto& m : material::material_inputs()) add(material::material_field(p.material, m.field));
  for (const auto& [name, v] : p.scene) {
    key += " " + name;
    add(v);
  }
  return key;
}

std::string describe_point(const ParameterPoint& p, const material::MaterialParams<double>& card) {
  std::string out;
  for (const auto& m : material::material_inputs()) {
    const double v = material::material_field(p.material, m.field);
    if (v != material::material_field(card, m.field)) out += (out.empty() ? "" : " ") + m.info.name + "=" + io::format_number(v);
  }
  for (const auto& [name, v] : p.scene) out += (out.empty() ? "" : " ") + name + "=" + io::format_number(v);
  return out.empty() ? "the card's values" : out;
}

std::shared_ptr<const scene::SceneResult> SceneRuns::result(const scene::Scene& scene, const ParameterPoint& p) const {
  const std::string key = key_of(scene, p);
  std::promise<std::shared_ptr<const scene::SceneResult>> promise;
  Entry entry;
  bool mine = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = cache_.find(key); it != cache_.end()) {
      entry = it->second;
    } else {
      entry = promise.get_future().share();
      cache_.emplace(key, entry);
      order_.push_back(key);
      while (order_.size() > kCachedRuns) {  // a dropped entry still being run lives on in its readers
        cache_.erase(order_.front());
        order_.pop_front();
      }
      mine = true;
    }
  }
  if (mine) promise.set_value(run(scene, p));
  return entry.get();
}

std::shared_ptr<const scene::SceneResult> SceneRuns::run(const scene::Scene& scene, const ParameterPoint& p) const {
  Failure failure{scene.file(), describe_point(p, base_), {}, false};
  auto fail = [&](const std::string& why) -> std::shared_ptr<const scene::SceneResult> {
    failure.message = why;
    std::lock_guard<std::mutex> lock(mutex_);
    failures_.push_back(failure);
    return nullptr;
  };
  std::unique_ptr<scene::Scene> sc = scene.clone();
  if (!sc->card()) return fail("the scene has a material of its own: a fit cannot set its card");
  sc->card()->params = p.material;
  for (const auto& [name, v] : p.scene) {
    std::string why;
    try {
      why = sc->set_input(name, v);
    } catch (const std::invalid_argument& e) {
      why = e.what();
    }
    if (!why.empty()) return fail(name + " = " + io::format_number(v) + ": " + why);
  }
  auto attempt = [&]() -> std::shared_ptr<const scene::SceneResult> {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++runs_;
    }
    try {
      scene::RunControl control;
      control.time_limit_seconds = time_limit_;
      std::shared_ptr<const scene::SceneResult> r = sc->run(scene::RunFiles(), control);
      return r;
    } catch (const std::exception& e) {
      failure.message += std::string(failure.message.empty() ? "" : "; ") + e.what();
      return nullptr;
    }
  };
  std::shared_ptr<const scene::SceneResult> r = attempt();
  if (r && r->ok()) return r;
  if (r) failure.message += (failure.message.empty() ? "" : "; ") + r->message;
  if (r && r->status == scene::RunStatus::timed_out) return fail(failure.message);  // smaller increments would take longer
  // Once more with half the largest increment (the scene's own cut-backs have not sufficed).
  constexpr const char* kIncrement = "solver.travel_per_increment";
  double travel = 0.0;
  try {
    travel = sc->input(kIncrement);
  } catch (const std::invalid_argument&) {
    return fail(failure.message);
  }
  if (!sc->set_input(kIncrement, 0.5 * travel).empty()) return fail(failure.message);
  r = attempt();
  if (r && r->ok()) {
    failure.recovered = true;
    failure.message = "retried with " + std::string(kIncrement) + " = " + io::format_number(0.5 * travel) + " after: " + failure.message;
    std::lock_guard<std::mutex> lock(mutex_);
    failures_.push_back(failure);
    return r;
  }
  if (r) failure.message += "; with " + std::string(kIncrement) + " = " + io::format_number(0.5 * travel) + ": " + r->message;
  return fail(failure.message);
}

long SceneRuns::runs() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return runs_;
}

std::vector<SceneRuns::Failure> SceneRuns::failures() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return failures_;
}

}  // namespace spifit::inverse
