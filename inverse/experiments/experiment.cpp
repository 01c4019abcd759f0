#include "inverse/experiments/experiment.hpp"

#include "forward/scenes/material_point/curve_columns.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::inverse {

namespace {

// A material-point experiment: its residuals, with doubles or Jets, come from Derived::eval(card,
// residuals, simulated values or null), each call counted; curves and tables keep the weights of
// their conditioning.
template <typename Derived>
class MaterialPointExperiment : public Experiment {
 public:
  bool residuals(const ParameterPoint& p, double* r) const override {
    count_evaluation();
    return static_cast<const Derived&>(*this).eval(p.material, r, nullptr);
  }
  bool residuals(const material::MaterialParams<Jet>& m, Jet* r) const override {
    count_evaluation();
    return static_cast<const Derived&>(*this).eval(m, r, nullptr);
  }

 protected:
  void condition(const std::vector<double>& ys, double noise, double noise_relative, double weight, const std::vector<double>& point_weights) {
    const CurveConditioning c = curve_conditioning(ys, noise, noise_relative, weight, point_weights);
    scale_ = c.scale;
    noise_given_ = c.noise_given;
    sqrt_w_ = c.sqrt_weights;
    residual_weights_ = c.weights;
  }
  std::vector<double> sqrt_w_;
};

class CurveExperiment final : public MaterialPointExperiment<CurveExperiment> {
 public:
  explicit CurveExperiment(CurveExperimentSpec s) : s_(std::move(s)) {
    s_.scene.setup.want_r_value = false;  // a curve needs neither side run
    s_.scene.setup.want_offset_yield = false;
    name_ = s_.name;
    kind_ = "curve";
    weight_ = s_.weight;
    condition(s_.ys, s_.noise, s_.noise_relative, s_.weight, s_.point_weights);
  }
  int num_residuals() const override { return static_cast<int>(s_.xs.size()); }
  ExperimentCurve axes() const override {
    ExperimentCurve c{s_.x, s_.y, s_.x_unit, s_.y_unit, {}, {}, {}, {}, {}};
    c.x_words = scene::curve_column_words(s_.scene.setup.kind, s_.x);
    c.y_words = scene::curve_column_words(s_.scene.setup.kind, s_.y);
    return c;
  }
  ExperimentCurve compare(const ParameterPoint& p) const override {
    ExperimentCurve c = axes();
    c.x = s_.xs;
    c.measured = s_.ys;
    std::vector<double> sim(s_.xs.size());
    std::vector<double> r(s_.xs.size());
    if (eval(p.material, r.data(), &sim)) c.simulated = sim;
    return c;
  }

 private:
  friend class MaterialPointExperiment<CurveExperiment>;
  template <typename T>
  bool eval(const material::MaterialParams<T>& m, T* r, std::vector<double>* simulated) const {
    const auto res = scene::run_material_point(m, s_.scene.setup);
    if (!res.ok) return false;
    const auto& curve = res.curve;
    // Simulated abscissa (data, increasing; checked when the experiment was built).
    std::size_t seg = 0;
    for (std::size_t i = 0; i < s_.xs.size(); ++i) {
      const double x = s_.xs[i];
      while (seg + 2 < curve.size() && *scene::curve_abscissa(curve[seg + 1], s_.x) < x) ++seg;
      const double x0 = *scene::curve_abscissa(curve[seg], s_.x), x1 = *scene::curve_abscissa(curve[seg + 1], s_.x);
      const T y0 = *scene::curve_response(curve[seg], s_.y), y1 = *scene::curve_response(curve[seg + 1], s_.y);
      const double t = x1 > x0 ? (x - x0) / (x1 - x0) : 0.0;
      if (t < -1e-9 || t > 1.0 + 1e-9) return false;  // outside the simulated curve: never extrapolate
      const T y = y0 + (y1 - y0) * t;
      r[i] = sqrt_w_[i] * (y - s_.ys[i]) / scale_;
      if (simulated) (*simulated)[i] = value_of(y);
    }
    return true;
  }

  CurveExperimentSpec s_;
};

template <typename T>
std::optional<T> scalar_observable(const scene::MaterialPointResult<T>& r, const std::string& name) {
  if (name == "r_value") return r.r_value;
  if (name == "yield_stress") return r.offset_yield_stress;
  if (name == "initial_yield_stress") {
    if (r.yield_events.empty()) return std::nullopt;
    return r.yield_events.front().stress;
  }
  if (name == "reverse_yield_stress") {
    for (const auto& e : r.yield_events) if (e.segment == 1) return e.stress;
    return std::nullopt;
  }
  if (name == "final_stress") return r.curve.back().stress;
  return std::nullopt;
}

class ScalarExperiment final : public MaterialPointExperiment<ScalarExperiment> {
 public:
  explicit ScalarExperiment(ScalarExperimentSpec s) : s_(std::move(s)) {
    s_.scene.setup.want_r_value = s_.observable == "r_value";
    s_.scene.setup.want_offset_yield = s_.observable == "yield_stress";
    name_ = s_.name;
    kind_ = "scalar";
    weight_ = s_.weight;
    scale_ = s_.noise > 0 ? s_.noise : (s_.value != 0.0 ? std::abs(s_.value) : 1.0);
    noise_given_ = s_.noise > 0;
  }
  int num_residuals() const override { return 1; }
  ExperimentCurve axes() const override { return {"", s_.observable, "", "", {}, {}, {}, {}, {}}; }
  ExperimentCurve compare(const ParameterPoint& p) const override {
    ExperimentCurve c{"", s_.observable, "", "", {0.0}, {s_.value}, {}, {}, {}};
    double r = 0.0, sim = 0.0;
    if (eval(p.material, &r, &sim)) c.simulated = {sim};
    return c;
  }

 private:
  friend class MaterialPointExperiment<ScalarExperiment>;
  template <typename T>
  bool eval(const material::MaterialParams<T>& m, T* r, double* simulated) const {
    const auto res = scene::run_material_point(m, s_.scene.setup);
    if (!res.ok) return false;
    const auto v = scalar_observable(res, s_.observable);
    if (!v) return false;
    r[0] = std::sqrt(s_.weight) * (*v - s_.value) / scale_;
    if (simulated) *simulated = value_of(*v);
    return true;
  }
  ScalarExperimentSpec s_;
};

class ScalarTableExperiment final : public MaterialPointExperiment<ScalarTableExperiment> {
 public:
  explicit ScalarTableExperiment(ScalarTableExperimentSpec s) : s_(std::move(s)) {
    for (auto& setup : s_.setups) {
      setup.want_r_value = s_.observable == "r_value";
      setup.want_offset_yield = s_.observable == "yield_stress";
    }
    name_ = s_.name;
    kind_ = "scalar_table";
    weight_ = s_.weight;
    condition(s_.ys, s_.noise, s_.noise_relative, s_.weight, s_.point_weights);
  }
  int num_residuals() const override { return static_cast<int>(s_.ys.size()); }
  ExperimentCurve axes() const override { return {s_.x, s_.observable, s_.x_unit, s_.y_unit, {}, {}, {}, {}, {}}; }
  ExperimentCurve compare(const ParameterPoint& p) const override {
    ExperimentCurve c{s_.x, s_.observable, s_.x_unit, s_.y_unit, s_.xs, s_.ys, {}, {}, {}};
    std::vector<double> r(s_.ys.size()), sim(s_.ys.size());
    if (eval(p.material, r.data(), &sim)) c.simulated = sim;
    return c;
  }

 private:
  friend class MaterialPointExperiment<ScalarTableExperiment>;
  template <typename T>
  bool eval(const material::MaterialParams<T>& m, T* r, std::vector<double>* simulated) const {
    for (std::size_t i = 0; i < s_.setups.size(); ++i) {
      const auto res = scene::run_material_point(m, s_.setups[i]);
      if (!res.ok) return false;
      const auto v = scalar_observable(res, s_.observable);
      if (!v) return false;
      r[i] = sqrt_w_[i] * (*v - s_.ys[i]) / scale_;
      if (simulated) (*simulated)[i] = value_of(*v);
    }
    return true;
  }
  ScalarTableExperimentSpec s_;
};

}  // namespace

const char* scalar_observable_names() { return "r_value, yield_stress, initial_yield_stress, reverse_yield_stress, final_stress"; }
bool is_scalar_observable(const std::string& n) {
  return n == "r_value" || n == "yield_stress" || n == "initial_yield_stress" || n == "reverse_yield_stress" || n == "final_stress";
}

CurveConditioning curve_conditioning(const std::vector<double>& ys, double noise, double noise_relative, double weight,
                                     const std::vector<double>& point_weights) {
  CurveConditioning c;
  double largest = 0.0;
  for (double y : ys) largest = std::max(largest, std::abs(y));
  if (noise_relative > 0) {
    c.noise_given = true;
  } else if (noise > 0) {
    c.scale = noise;
    c.noise_given = true;
  } else if (!ys.empty()) {
    const auto [lo, hi] = std::minmax_element(ys.begin(), ys.end());
    if (*hi - *lo > 0) c.scale = *hi - *lo;
  }
  for (std::size_t i = 0; i < ys.size(); ++i) {
    c.weights.push_back(weight * (point_weights.empty() ? 1.0 : point_weights[i]));
    double w = std::sqrt(c.weights.back());
    if (noise_relative > 0) w /= noise_relative * std::max(std::abs(ys[i]), 1e-3 * largest);
    c.sqrt_weights.push_back(w);
  }
  return c;
}

std::unique_ptr<Experiment> make_curve_experiment(CurveExperimentSpec spec) {
  return std::make_unique<CurveExperiment>(std::move(spec));
}
std::unique_ptr<Experiment> make_scalar_experiment(ScalarExperimentSpec spec) {
  return std::make_unique<ScalarExperiment>(std::move(spec));
}
std::unique_ptr<Experiment> make_scalar_table_experiment(ScalarTableExperimentSpec spec) {
  return std::make_unique<ScalarTableExperiment>(std::move(spec));
}

}  // namespace spifit::inverse
