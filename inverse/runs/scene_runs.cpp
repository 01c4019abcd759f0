#include "inverse/runs/scene_runs.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_inputs.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

namespace spifit::inverse {
namespace {

// Enough points for every evaluation of one iteration (the point, 2p perturbations, a few
// trial steps) of several scenes; older results are dropped.
constexpr std::size_t kCachedRuns = 256;

// The scene file and the point.
std::string key_of(const scene::Scene& scene, const ParameterPoint& p) { return scene.file() + " " + point_key(p); }

// The value for key, made by make() once however many threads ask at once; the newest kCachedRuns
// keys are kept (a dropped entry still being made lives on in its readers). An exception of
// make() reaches every reader of the key.
template <typename T, typename Make>
T once_per_key(std::mutex& mutex, std::map<std::string, std::shared_future<T>>& entries, std::deque<std::string>& order,
               const std::string& key, Make&& make) {
  std::promise<T> promise;
  std::shared_future<T> entry;
  bool mine = false;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = entries.find(key); it != entries.end()) {
      entry = it->second;
    } else {
      entry = promise.get_future().share();
      entries.emplace(key, entry);
      order.push_back(key);
      while (order.size() > kCachedRuns) {
        entries.erase(order.front());
        order.pop_front();
      }
      mine = true;
    }
  }
  if (mine) {
    try {
      promise.set_value(make());
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return entry.get();
}

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
  for (const auto& m : material::material_inputs())
    if (material::holds_input(p.material, m)) add(material::material_field(p.material, m.field));
  for (const auto& [name, v] : p.scene) {
    key += " " + name;
    add(v);
  }
  return key;
}

std::string describe_point(const ParameterPoint& p, const material::MaterialParams<double>& card) {
  std::string out;
  for (const auto& m : material::material_inputs()) {
    if (!material::holds_input(p.material, m) || !material::holds_input(card, m)) continue;
    const double v = material::material_field(p.material, m.field);
    if (v != material::material_field(card, m.field)) out += (out.empty() ? "" : " ") + m.info.name + "=" + io::format_number(v);
  }
  for (const auto& [name, v] : p.scene) out += (out.empty() ? "" : " ") + name + "=" + io::format_number(v);
  return out.empty() ? "the card's values" : out;
}

std::shared_ptr<const scene::SceneResult> SceneRuns::result(const scene::Scene& scene, const ParameterPoint& p, const std::string& experiment) {
  return once_per_key(mutex_, cache_, order_, key_of(scene, p), [&] { return run(scene, p, experiment); });
}

std::shared_ptr<const scene::SceneResult> SceneRuns::run(const scene::Scene& scene, const ParameterPoint& p, const std::string& experiment) {
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
  auto attempt = [&](bool retry) -> std::shared_ptr<const scene::SceneResult> {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++runs_;
    }
    const auto t0 = std::chrono::steady_clock::now();
    std::shared_ptr<const scene::SceneResult> r;
    try {
      scene::RunControl control;
      control.time_limit_seconds = time_limit_;
      if (const auto d = derivatives_.find(scene.file()); d != derivatives_.end()) {
        control.sensitivities = d->second.names;
        control.sensitivity_h_follows_g = d->second.h_follows_g;
      }
      r = sc->run(scene::RunFiles(), control);
    } catch (const std::exception& e) {
      failure.message += std::string(failure.message.empty() ? "" : "; ") + e.what();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      log_.push_back({scene.file(), experiment, seconds, retry, r && r->ok()});
    }
    if (on_run_) on_run_(seconds);
    return r;
  };
  std::shared_ptr<const scene::SceneResult> r = attempt(false);
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
  r = attempt(true);
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

void SceneRuns::differentiate(const std::string& scene, std::vector<std::string> names, bool h_follows_g) {
  std::lock_guard<std::mutex> lock(mutex_);
  derivatives_[scene] = {std::move(names), h_follows_g};
}

void SceneRuns::add_remote(const std::vector<Run>& runs, const std::vector<Failure>& failures) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    runs_ += static_cast<long>(runs.size());
    log_.insert(log_.end(), runs.begin(), runs.end());
    failures_.insert(failures_.end(), failures.begin(), failures.end());
  }
  if (on_run_)
    for (const auto& r : runs) on_run_(r.seconds);
}

std::string SceneRuns::shared_answer(const std::string& key, const std::function<std::string()>& ask) {
  return once_per_key(mutex_, answers_, answer_order_, key, ask);
}

long SceneRuns::runs() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return runs_;
}

std::vector<SceneRuns::Failure> SceneRuns::failures() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return failures_;
}

std::vector<SceneRuns::Run> SceneRuns::run_log() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return log_;
}

std::vector<SceneFileRuns> scene_file_runs(const std::vector<SceneRuns::Run>& log, const std::vector<SceneRuns::Failure>& failures) {
  std::vector<SceneFileRuns> out;
  std::vector<std::vector<double>> seconds;
  auto of = [&](const std::string& scene) -> std::size_t {
    for (std::size_t i = 0; i < out.size(); ++i)
      if (out[i].scene == scene) return i;
    out.push_back({scene, 0, 0, 0, 0.0, std::numeric_limits<double>::quiet_NaN()});
    seconds.emplace_back();
    return out.size() - 1;
  };
  for (const auto& r : log) {
    const std::size_t i = of(r.scene);
    ++out[i].runs;
    if (r.retry) ++out[i].retried;
    out[i].seconds += r.seconds;
    seconds[i].push_back(r.seconds);
  }
  for (const auto& f : failures)
    if (!f.recovered) ++out[of(f.scene)].failures;
  for (std::size_t i = 0; i < out.size(); ++i) {
    auto& s = seconds[i];
    if (s.empty()) continue;
    std::sort(s.begin(), s.end());
    const std::size_t n = s.size();
    out[i].median_seconds = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  }
  return out;
}

}  // namespace spifit::inverse
