#include "forward/scenes/forming/forming_kind.hpp"

#include "forward/scenes/common/fe_run_observables.hpp"
#include "forward/scenes/common/table_scene.hpp"
#include "forward/scenes/forming/forming_inputs.hpp"
#include "forward/scenes/forming/forming_path.hpp"
#include "forward/scenes/forming/forming_run.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace spifit::scene {
namespace {

class FormingSceneFile final : public TableScene<FormingScene> {
 public:
  FormingSceneFile(std::string kind, FormingScene s) : TableScene(std::move(kind), std::move(s), &forming_inputs()) {}
  std::vector<std::string> input_files() const override {
    std::vector<std::string> f{data_.file, data_.card.file};
    if (!data_.gcode.empty()) f.push_back(data_.gcode);
    return f;
  }
  std::unique_ptr<Scene> clone() const override { return std::make_unique<FormingSceneFile>(*this); }
  std::unique_ptr<SceneResult> run(const RunFiles& files, const RunControl& control) const override {
    return std::make_unique<FormingResult>(run_forming_scene(data_, files, control));
  }
  std::optional<toolpath::ToolPath> tool_centre_path() const override { return forming_centre_path(data_); }
  std::vector<std::string> section_points() const override { return data_.sections; }
  std::vector<std::string> input_warnings() const override { return sheet_and_tool_warnings(forming_sheet_and_tool(data_)); }

 protected:
  std::string check_inputs() const override { return forming_scene_error(data_).text(); }
};

const FormingResult& forming(const SceneResult& r) { return dynamic_cast<const FormingResult&>(r); }

// Force statistics over the samples whose travel lies in the window.
struct WindowStats {
  double sum[3] = {0.0, 0.0, 0.0};
  double min_fz = std::numeric_limits<double>::infinity(), max_fz = -std::numeric_limits<double>::infinity();
  std::size_t rows = 0;
};

WindowStats window_stats(const ToolForceHistory& h, const std::array<double, 2>& w) {
  WindowStats s;
  for (const auto& x : h.samples()) {
    if (x.travel < w[0] || x.travel > w[1]) continue;
    for (int k = 0; k < 3; ++k) s.sum[k] += x.force(k);
    s.min_fz = std::min(s.min_fz, x.force.z());
    s.max_fz = std::max(s.max_fz, x.force.z());
    ++s.rows;
  }
  return s;
}

// Per parameter, the derivatives of force component k summed over the samples in the window,
// with the samples of its largest and smallest value (what ripple_fz needs); none without
// sensitivities or samples.
struct WindowDerivatives {
  Eigen::RowVectorXd sum, at_max, at_min;
  std::size_t rows = 0;
};
std::optional<WindowDerivatives> window_derivatives(const FormingResult& r, const std::array<double, 2>& w, int k) {
  WindowDerivatives out;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  const auto& samples = r.force.samples();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].travel < w[0] || samples[i].travel > w[1]) continue;
    const Eigen::Matrix<double, 3, Eigen::Dynamic> d = r.force_sensitivity(i);
    if (d.cols() == 0) return std::nullopt;
    if (out.rows == 0) out.sum = out.at_max = out.at_min = Eigen::RowVectorXd::Zero(d.cols());
    out.sum += d.row(k);
    const double f = samples[i].force(k);
    if (f > hi) hi = f, out.at_max = d.row(k);  // as std::max keeps the first of equals
    if (f < lo) lo = f, out.at_min = d.row(k);
    ++out.rows;
  }
  if (out.rows == 0) return std::nullopt;
  return out;
}

std::vector<double> as_vector(const Eigen::RowVectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

Observable force_component(const char* name, const char* doc, int k, bool peak) {
  Observable o{name, "N", doc, Observable::Needs::nothing, false, [k, peak](const SceneResult& r, const ObservableOptions&) {
                 const auto& f = forming(r).force;
                 return peak ? f.peak()(k) : f.final_force()(k);
               }};
  if (peak) return with_sample_derivatives(std::move(o), k, [k](const ToolForceHistory& h) { return peak_sample(h, k); });
  return with_sample_derivatives(std::move(o), k, [](const ToolForceHistory& h) { return last_sample(h); });
}

Observable window_mean(const char* name, const char* doc, int k) {
  Observable o{name, "N", doc, Observable::Needs::window, false, [k](const SceneResult& r, const ObservableOptions& options) {
                 const WindowStats s = window_stats(forming(r).force, *options.window);
                 return s.rows == 0 ? kNaN : s.sum[k] / static_cast<double>(s.rows);
               }};
  o.derivatives = [k](const SceneResult& r, const ObservableOptions& options) {
    const auto d = window_derivatives(forming(r), *options.window, k);
    return d ? as_vector(d->sum / static_cast<double>(d->rows)) : std::vector<double>{};
  };
  return o;
}

// (max - min) / mean of Fz over the window.
Observable ripple_fz() {
  Observable o{"ripple_fz", "", "(max - min) / mean of Fz over the travel window", Observable::Needs::window, false,
               [](const SceneResult& r, const ObservableOptions& options) {
                 const WindowStats s = window_stats(forming(r).force, *options.window);
                 return s.rows == 0 ? kNaN : (s.max_fz - s.min_fz) / (s.sum[2] / static_cast<double>(s.rows));
               }};
  o.derivatives = [](const SceneResult& r, const ObservableOptions& options) {
    const WindowStats s = window_stats(forming(r).force, *options.window);
    const auto d = window_derivatives(forming(r), *options.window, 2);
    if (!d || s.rows == 0) return std::vector<double>{};
    const double n = static_cast<double>(s.rows), mean = s.sum[2] / n;
    return as_vector((d->at_max - d->at_min) / mean - (s.max_fz - s.min_fz) / (mean * mean) * (d->sum / n));
  };
  return o;
}

std::vector<Observable> forming_observables() {
  std::vector<Observable> o{
      force_component("peak_fx", "largest |Fx| over the run (signed)", 0, true),
      force_component("final_fx", "Fx at the end of the path", 0, false),
      window_mean("mean_fx", "mean Fx over the travel window", 0),
      window_mean("mean_fy", "mean Fy over the travel window", 1),
      window_mean("mean_fz", "mean Fz over the travel window", 2),
      ripple_fz(),
  };
  for (Observable& f : fe_run_observables()) o.push_back(std::move(f));
  return o;
}

SceneKind forming_kind(const char* name, const char* doc) {
  SceneKind k;
  k.name = name;
  k.family = "forming";
  k.doc = doc;
  k.resumable = true;
  k.fe_run = true;
  k.sensitivities = true;
  k.read = [](const std::string& file) -> std::unique_ptr<Scene> {
    FormingScene s = read_forming_scene(file);
    std::string kind = s.kind;
    return std::make_unique<FormingSceneFile>(std::move(kind), std::move(s));
  };
  k.inputs = forming_inputs().infos();
  k.observables = forming_observables();
  return k;
}

}  // namespace

std::vector<SceneKind> forming_kinds() {
  return {forming_kind("indent", "the small clamped square of thesis §7.1 pushed at its centre (penalty study)"),
          forming_kind("indent_line", "the line-test sheet indented to 5 mm (point B): the indent test of the identification"),
          forming_kind("line", "the line test: indent, a 100 mm line, deeper, back (thesis §4.1.1, §7.3)")};
}

}  // namespace spifit::scene
