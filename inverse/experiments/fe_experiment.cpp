#include "inverse/experiments/fe_experiment.hpp"

#include "inverse/runs/fe_evaluation_job.hpp"
#include "inverse/experiments/measurement_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::inverse {
namespace {

constexpr const char* kAbscissae[] = {"depth", "travel", "time"};
constexpr const char* kComponents[] = {"fx", "fy", "fz", "fr", "ftheta"};

// x of a tool position: tip depth below the initial top surface (the tip path's z = 0 is the
// top surface: the centre sits t/2 + R above the mid-surface), travel or time.
double abscissa(const std::string& x, const Eigen::Vector3d& centre, double travel, double time, double thickness, double radius) {
  if (x == "depth") return 0.5 * thickness + radius - centre.z();
  if (x == "travel") return travel;
  return time;
}

double component(const std::string& y, const Eigen::Vector3d& centre, const Eigen::Vector3d& f) {
  if (y == "fx") return f.x();
  if (y == "fy") return f.y();
  if (y == "fz") return f.z();
  const double theta = std::atan2(centre.y(), centre.x());
  const double c = std::cos(theta), s = std::sin(theta);
  return y == "fr" ? c * f.x() + s * f.y() : -s * f.x() + c * f.y();
}

// Residuals of measured (xs, ys) against the simulated curve c, interpolated linearly at xs;
// false when an xs lies outside c (never extrapolate). With drdp (row-major, `columns` per
// residual) also their derivatives from c's: at a fixed measured x, y = y_a + (y_b - y_a) u with
// u = (x - x_a) / (x_b - x_a), so dy = dy_a + (dy_b - dy_a) u - (y_b - y_a) ((1 - u) dx_a + u dx_b) / (x_b - x_a)
// (no dx: the abscissa does not move, as a force curve's depth); false when c has none.
bool curve_residuals(const ForceCurve& c, const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& sqrt_w,
                     double scale, double* r, std::vector<double>* simulated, int columns = 0, double* drdp = nullptr) {
  const auto n = static_cast<Eigen::Index>(c.x.size());
  if (drdp && (c.dy.rows() != n || c.dy.cols() != columns || (c.dx.rows() != 0 && c.dx.rows() != n))) return false;
  std::size_t seg = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double x = xs[i];
    if (c.x.size() < 2 || x < c.x.front() - 1e-9 || x > c.x.back() + 1e-9) return false;
    while (seg + 2 < c.x.size() && c.x[seg + 1] < x) ++seg;
    const double raw = (x - c.x[seg]) / (c.x[seg + 1] - c.x[seg]);
    const double u = std::clamp(raw, 0.0, 1.0);
    const double y = c.y[seg] + (c.y[seg + 1] - c.y[seg]) * u;
    r[i] = sqrt_w[i] * (y - ys[i]) / scale;
    if (simulated) (*simulated)[i] = y;
    if (!drdp) continue;
    const auto a = static_cast<Eigen::Index>(seg), b = a + 1;
    Eigen::RowVectorXd dy = c.dy.row(a) + (c.dy.row(b) - c.dy.row(a)) * u;
    if (c.dx.rows() == n && raw == u)  // inside the segment: u moves with its ends
      dy -= (c.y[seg + 1] - c.y[seg]) * ((1.0 - u) * c.dx.row(a) + u * c.dx.row(b)) / (c.x[seg + 1] - c.x[seg]);
    for (int k = 0; k < columns; ++k) drdp[i * static_cast<std::size_t>(columns) + static_cast<std::size_t>(k)] = sqrt_w[i] * dy(k) / scale;
  }
  return true;
}

// The FE experiments' common part: the run at a point (from the shared runs) and conditioning.
class FeExperiment : public Experiment {
 public:
  explicit FeExperiment(const FeExperimentBase& b) : scene_(b.scene), runs_(b.runs) {
    name_ = b.name;
    weight_ = b.weight;
    noise_given_ = b.noise > 0;
  }
  bool residuals(const material::MaterialParams<Jet>&, Jet*) const override { return false; }
  bool supports_jets() const override { return false; }
  int parallel_evaluations() const override { return runs_->pool() ? runs_->pool()->workers() : 0; }
  std::string scene_file() const override { return scene_->file(); }
  // Against the scene's scales: an FE run is too dear to make for a plausibility check.
  MagnitudeCheck check_magnitudes(const ParameterPoint& start) const final {
    const ExperimentCurve a = axes();
    return fe_magnitudes(a.y_name, a.y_unit, measured_values(), *scene_, start.material);
  }
  int exact_columns() const final { return columns_; }
  void set_exact_columns(int columns) final {
    if (!differentiable()) Experiment::set_exact_columns(columns);
    columns_ = columns;
  }
  bool residuals(const ParameterPoint& p, double* r) const final {
    std::vector<double> v;
    if (!evaluate(p, &v)) return false;
    std::copy_n(v.begin(), num_residuals(), r);
    return true;
  }
  bool residuals_and_derivatives(const ParameterPoint& p, double* r, double* drdp) const final {
    std::vector<double> v;
    if (columns_ == 0 || !evaluate(p, &v)) return false;
    const auto m = static_cast<std::ptrdiff_t>(num_residuals());
    std::copy(v.begin(), v.begin() + m, r);
    std::copy(v.begin() + m, v.end(), drdp);
    return true;
  }

 protected:
  // The residuals at p, followed by their derivatives (row-major) when the experiment takes exact
  // ones: kept from an earlier (killed) fit when the runs keep evaluations, else computed (and kept).
  bool evaluate(const ParameterPoint& p, std::vector<double>* v) const {
    count_evaluation();
    const std::size_t size = static_cast<std::size_t>(num_residuals()) * static_cast<std::size_t>(1 + columns_);
    EvaluationCache* cache = runs_->evaluations();
    const std::string key = cache ? point_key(p) : std::string();
    if (cache) {
      if (const auto e = cache->find(name_, key); e && (!e->ok || e->residuals.size() == size)) {
        *v = e->residuals;
        return e->ok;
      }
    }
    v->assign(size, 0.0);
    const bool ok = runs_->pool() ? compute_elsewhere(p, v->data()) : compute(p, v->data());
    if (cache) cache->add(name_, key, {ok, ok ? *v : std::vector<double>{}});
    return ok;
  }
  // The residuals, then (exact_columns() > 0) their derivatives, row-major.
  virtual bool compute(const ParameterPoint& p, double* r) const = 0;
  virtual std::vector<double> measured_values() const = 0;
  // On a worker of the runs' pool: the same numbers compute() gives, computed there, with those
  // of the other experiments on this scene file (one job per scene file and point).
  bool compute_elsewhere(const ParameterPoint& p, double* r) const {
    FeEvaluationAnswer a;
    try {
      a = decode_fe_answer(runs_->shared_answer(scene_->file() + " " + point_key(p), [&] {
        std::string bytes = runs_->pool()->run(fe_evaluation_job(name_, p));
        const FeEvaluationAnswer first = decode_fe_answer(bytes);
        runs_->add_remote(first.runs, first.failures);  // once per answer
        return bytes;
      }));
    } catch (const std::exception& e) {
      a.error = std::string("no answer: ") + e.what();
    }
    const FeEvaluationAnswer::Residuals* mine = nullptr;
    for (const auto& e : a.experiments)
      if (e.experiment == name_) mine = &e;
    if (!a.error.empty() || !mine) {  // a failed evaluation, named among the fit's failures
      const std::string why = a.error.empty() ? "the answer has no residuals of " + name_ : a.error;
      runs_->add_remote({}, {{scene_->file(), describe_point(p, runs_->base()), "a worker could not evaluate " + name_ + ": " + why, false}});
      return false;
    }
    if (!mine->ok || mine->values.size() != static_cast<std::size_t>(num_residuals()) * static_cast<std::size_t>(1 + columns_)) return false;
    std::copy(mine->values.begin(), mine->values.end(), r);
    return true;
  }
  std::shared_ptr<const scene::SceneResult> run_at(const ParameterPoint& p) const {
    auto r = runs_->result(*scene_, p, name_);
    return r && r->ok() ? r : nullptr;
  }
  std::shared_ptr<const scene::Scene> scene_;
  std::shared_ptr<SceneRuns> runs_;
  int columns_ = 0;
};

class FeScalarExperiment final : public FeExperiment {
 public:
  explicit FeScalarExperiment(FeScalarSpec s) : FeExperiment(s), s_(std::move(s)) {
    kind_ = "fe_scalar";
    scale_ = s_.noise > 0 ? s_.noise : (s_.value != 0.0 ? std::abs(s_.value) : 1.0);
  }
  int num_residuals() const override { return 1; }
  ExperimentCurve axes() const override { return {"", s_.observable->name, "", s_.observable->unit, {}, {}, {}, {}, {}}; }
  ExperimentCurve compare(const ParameterPoint& p) const override {
    ExperimentCurve c{"", s_.observable->name, "", s_.observable->unit, {0.0}, {s_.value}, {}, {}, {}};
    double r = 0.0, sim = 0.0;
    if (eval(p, &r, &sim)) c.simulated = {sim};
    return c;
  }

  bool differentiable() const override { return static_cast<bool>(s_.observable->derivatives); }

 private:
  bool compute(const ParameterPoint& p, double* r) const override { return eval(p, r, nullptr); }
  std::vector<double> measured_values() const override { return {s_.value}; }
  // r[0], then (exact_columns() > 0) its derivatives r[1 ..].
  bool eval(const ParameterPoint& p, double* r, double* simulated) const {
    const auto res = run_at(p);
    if (!res) return false;
    const double v = s_.observable->value(*res, s_.options);
    if (!std::isfinite(v)) return false;
    r[0] = std::sqrt(s_.weight) * (v - s_.value) / scale_;
    if (simulated) *simulated = v;
    if (columns_ > 0 && !simulated) {
      const std::vector<double> d = s_.observable->derivatives(*res, s_.options);
      if (static_cast<int>(d.size()) != columns_) return false;
      for (int k = 0; k < columns_; ++k) r[1 + k] = std::sqrt(s_.weight) * d[static_cast<std::size_t>(k)] / scale_;
    }
    return true;
  }
  FeScalarSpec s_;
};

// A measured curve (xs, ys) against a curve the run gives: force curves and sections.
class CurveFeExperiment : public FeExperiment {
 public:
  struct Curve {
    std::string x, y, x_unit, y_unit;
    std::vector<double> xs, ys, point_weights;
  };
  CurveFeExperiment(const FeExperimentBase& b, const char* kind, Curve c) : FeExperiment(b), c_(std::move(c)) {
    kind_ = kind;
    const CurveConditioning k = curve_conditioning(c_.ys, b.noise, b.noise_relative, b.weight, c_.point_weights);
    scale_ = k.scale;
    noise_given_ = k.noise_given;
    sqrt_w_ = k.sqrt_weights;
    residual_weights_ = k.weights;
  }
  int num_residuals() const override { return static_cast<int>(c_.xs.size()); }
  ExperimentCurve axes() const override { return {c_.x, c_.y, c_.x_unit, c_.y_unit, {}, {}, {}, {}, {}}; }
  ExperimentCurve compare(const ParameterPoint& p) const override {
    ExperimentCurve c{c_.x, c_.y, c_.x_unit, c_.y_unit, c_.xs, c_.ys, {}, {}, {}};
    std::vector<double> r(c_.xs.size()), sim(c_.xs.size());
    if (eval(p, r.data(), &sim)) c.simulated = sim;
    return c;
  }

 protected:
  // The simulated curve of a run at p (empty: the run does not give it).
  virtual ForceCurve simulated(const scene::SceneResult& r, const ParameterPoint& p) const = 0;

 private:
  bool compute(const ParameterPoint& p, double* r) const override { return eval(p, r, nullptr); }
  std::vector<double> measured_values() const override { return c_.ys; }
  bool eval(const ParameterPoint& p, double* r, std::vector<double>* sim) const {
    const auto res = run_at(p);
    return res && curve_residuals(simulated(*res, p), c_.xs, c_.ys, sqrt_w_, scale_, r, sim, columns_,
                                  columns_ > 0 && !sim ? r + c_.xs.size() : nullptr);
  }
  Curve c_;
  std::vector<double> sqrt_w_;
};

// A curve experiment whose simulated curve a function gives.
class FunctionCurveExperiment final : public CurveFeExperiment {
 public:
  FunctionCurveExperiment(const FeExperimentBase& b, const char* kind, FeCurve c, SimulatedCurve f, bool differentiable)
      : CurveFeExperiment(b, kind, {c.x, c.y, c.x_unit, c.y_unit, std::move(c.xs), std::move(c.ys), std::move(c.point_weights)}),
        f_(std::move(f)),
        differentiable_(differentiable) {}

 private:
  ForceCurve simulated(const scene::SceneResult& r, const ParameterPoint& p) const override { return f_(r, p); }
  bool differentiable() const override { return differentiable_; }
  SimulatedCurve f_;
  bool differentiable_;
};

class ForceCurveExperiment final : public CurveFeExperiment {
 public:
  explicit ForceCurveExperiment(const ForceCurveSpec& s)
      : CurveFeExperiment(s, "force_curve", {s.x, s.y, force_curve_abscissa_unit(s.x), s.y_unit, s.xs, s.ys, s.point_weights}),
        x_(s.x),
        y_(s.y),
        thickness_(s.scene->input("sheet.thickness")),
        radius_(s.scene->input("tool.radius")),
        start_(s.scene->tool_centre_path()->at_distance(0.0)) {}

 private:
  ForceCurve simulated(const scene::SceneResult& r, const ParameterPoint& p) const override {
    const scene::ToolForceHistory* force = r.tool_force();
    if (!force) return {};
    // The scene inputs of p may move the tool (tool.radius) or the sheet (sheet.thickness); the
    // tool path lifts the tip by t/2 + R, so its start moves with them.
    const double t = input_at(p, "sheet.thickness", thickness_), radius = input_at(p, "tool.radius", radius_);
    const Eigen::Vector3d start = start_ + Eigen::Vector3d(0.0, 0.0, 0.5 * (t - thickness_) + (radius - radius_));
    ForceCurve c = force_curve(*force, start, t, radius, x_, y_);
    if (exact_columns() > 0 && !add_force_curve_derivatives(r, y_, &c)) return {};
    return c;
  }
  bool differentiable() const override { return true; }
  static double input_at(const ParameterPoint& p, const char* name, double fallback) {
    for (const auto& [n, v] : p.scene)
      if (n == name) return v;
    return fallback;
  }
  std::string x_, y_;
  double thickness_ = 0.0, radius_ = 0.0;
  Eigen::Vector3d start_ = Eigen::Vector3d::Zero();
};

class SectionExperiment final : public CurveFeExperiment {
 public:
  explicit SectionExperiment(const SectionSpec& s)
      : CurveFeExperiment(s, "section", {s.x, s.y, "mm", "mm", s.xs, s.ys, s.point_weights}), point_(s.point), x_(s.x), y_(s.y) {}

 private:
  ForceCurve simulated(const scene::SceneResult& r, const ParameterPoint&) const override { return section_curve(r, point_, x_, y_); }
  bool differentiable() const override { return true; }  // z and the thickness
  std::string point_, x_, y_;
};

}  // namespace

namespace {

class ContourMeansExperiment final : public CurveFeExperiment {
 public:
  explicit ContourMeansExperiment(const ContourMeansSpec& s)
      : CurveFeExperiment(s, "contour_means", {"contour", s.y, "", s.y.find("_over_") == std::string::npos ? "N" : "", s.contours, s.ys, s.point_weights}),
        y_(s.y) {}

 private:
  ForceCurve simulated(const scene::SceneResult& r, const ParameterPoint&) const override {
    scene::ResultCurve m = r.contour_means(y_);
    for (double v : m.y)
      if (!std::isfinite(v)) return {};  // a contour without samples: nothing to compare
    return m;
  }
  bool differentiable() const override { return true; }  // ConeResult::contour_means' dy
  std::string y_;
};

}  // namespace

std::unique_ptr<Experiment> make_contour_means_experiment(ContourMeansSpec spec) { return std::make_unique<ContourMeansExperiment>(spec); }

std::unique_ptr<Experiment> make_fe_curve_experiment(const FeExperimentBase& base, const char* kind, FeCurve curve, SimulatedCurve simulated,
                                                     bool differentiable) {
  return std::make_unique<FunctionCurveExperiment>(base, kind, std::move(curve), std::move(simulated), differentiable);
}

std::unique_ptr<Experiment> make_section_experiment(SectionSpec spec) { return std::make_unique<SectionExperiment>(spec); }
bool is_section_abscissa(const std::string& x) { return x == "x" || x == "x0"; }
bool is_section_response(const std::string& y) { return y == "z" || y == "thickness"; }

ForceCurve section_curve(const scene::SceneResult& r, const std::string& point, const std::string& x, const std::string& y) {
  return r.path_section(point, x, y);
}

std::unique_ptr<Experiment> make_fe_scalar_experiment(FeScalarSpec spec) { return std::make_unique<FeScalarExperiment>(std::move(spec)); }
std::unique_ptr<Experiment> make_force_curve_experiment(ForceCurveSpec spec) { return std::make_unique<ForceCurveExperiment>(spec); }

const char* force_curve_abscissa_names() { return "depth, travel, time"; }
bool is_force_curve_abscissa(const std::string& x) {
  return std::any_of(std::begin(kAbscissae), std::end(kAbscissae), [&](const char* a) { return x == a; });
}
const char* force_curve_abscissa_unit(const std::string& x) { return x == "time" ? "s" : "mm"; }
const char* force_component_names() { return "fx, fy, fz, fr, ftheta"; }
bool is_force_component(const std::string& y) {
  return std::any_of(std::begin(kComponents), std::end(kComponents), [&](const char* c) { return y == c; });
}

ForceCurve force_curve(const scene::ToolForceHistory& h, const Eigen::Vector3d& start, double thickness, double tool_radius,
                       const std::string& x, const std::string& y) {
  if (!is_force_curve_abscissa(x)) throw std::invalid_argument(std::string("unknown force curve abscissa ").append(x));
  if (!is_force_component(y)) throw std::invalid_argument(std::string("unknown force component ").append(y));
  ForceCurve c;
  c.x.push_back(abscissa(x, start, 0.0, 0.0, thickness, tool_radius));
  c.y.push_back(0.0);  // the tool starts off the sheet, or just touching it
  for (const auto& s : h.samples()) {
    const double v = abscissa(x, s.centre, s.travel, s.time, thickness, tool_radius);
    if (!(v > c.x.back())) break;  // x stops increasing: the curve ends
    c.x.push_back(v);
    c.y.push_back(component(y, s.centre, s.force));
  }
  return c;
}

bool add_force_curve_derivatives(const scene::SceneResult& r, const std::string& y, ForceCurve* c) {
  const scene::ToolForceHistory* force = r.tool_force();
  const auto n = static_cast<Eigen::Index>(c->x.size());
  if (!force || n < 1 || static_cast<std::size_t>(n - 1) > force->samples().size()) return false;
  for (Eigen::Index j = 1; j < n; ++j) {  // row 0: the path's start, zero force
    const auto sample = static_cast<std::size_t>(j - 1);
    const Eigen::Matrix<double, 3, Eigen::Dynamic> d = r.force_sensitivity(sample);
    if (d.cols() == 0) return false;
    if (j == 1) c->dy = Eigen::MatrixXd::Zero(n, d.cols());
    for (Eigen::Index k = 0; k < d.cols(); ++k) c->dy(j, k) = component(y, force->samples()[sample].centre, d.col(k));
  }
  return true;
}

std::pair<double, double> force_curve_range(const toolpath::ToolPath& centre, double thickness, double tool_radius, const std::string& x) {
  if (x == "travel") return {0.0, centre.length()};
  if (x == "time") return {0.0, centre.duration()};
  // depth: linear along each segment, so the waypoints give where it stops increasing.
  const auto& w = centre.waypoints();
  const double first = abscissa("depth", w.front().position, 0, 0, thickness, tool_radius);
  double last = first;
  for (std::size_t i = 1; i < w.size(); ++i) {
    if (w[i].position == w[i - 1].position) continue;  // a zero-length segment
    const double d = abscissa("depth", w[i].position, 0, 0, thickness, tool_radius);
    if (!(d > last)) break;
    last = d;
  }
  return {first, last};
}

}  // namespace spifit::inverse
