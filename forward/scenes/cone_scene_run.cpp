// Running a cone scene: mesh, clamp, cyclic ties and virtual tools, the contour path as the
// load, outputs (docs/cone-scene.md).
#include "forward/io/csv_writer.hpp"
#include "forward/io/vtu_writer.hpp"
#include "forward/model/cyclic_symmetry.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/cone_checkpoint.hpp"
#include "forward/scenes/cone_load_map.hpp"
#include "forward/scenes/cone_observable_log.hpp"
#include "forward/scenes/cone_scene.hpp"
#include "forward/scenes/scene_tables.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <sstream>

namespace spifit::scene {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

bool is_pie(const ConeScene& s) { return s.pie_angle < 360.0; }

// Rim (= clamp radius) fixed in translation (and rotation on request); pie edges tied
// cyclically: the DOFs of edge_theta1 are those of edge_theta0 rotated by gamma, and the axis
// node moves along z only (tie_cyclic_edges). The rim node of edge_theta1 is a tied node: it
// is not clamped itself but follows its clamped partner on edge_theta0 (R 0 = 0).
solver::DofConstraints cone_constraints(const ConeScene& s, const mesh::Mesh& m, model::ShellModel* model) {
  solver::DofConstraints c(model->num_dofs());
  std::vector<char> slave(static_cast<std::size_t>(m.num_nodes()), 0);
  if (is_pie(s)) {
    model::tie_cyclic_edges(m, "edge_theta0", "edge_theta1", s.pie_angle, &c);
    for (int n : m.node_sets.at("edge_theta1")) slave[static_cast<std::size_t>(n)] = 1;
    for (int n : m.node_sets.at("axis")) slave[static_cast<std::size_t>(n)] = 0;
  }
  const int clamped = s.clamp_rotations ? 6 : 3;
  for (int n : m.node_sets.at("rim")) {
    if (slave[static_cast<std::size_t>(n)]) continue;
    for (int k = 0; k < clamped; ++k) c.prescribe(model::ShellModel::dof(n, k));
  }
  // Five unknowns at every node away from the ties and the clamp: the drilling rotations
  // leave the factorisation (docs/numerics-shell.md, "Nodal rotation frames").
  model->use_nodal_rotation_frames(&c);
  c.finalize();
  return c;
}

// Virtual tools of a pie (thesis Fig. 8.4): copies at +gamma and -gamma (one copy for 180).
std::vector<double> tool_copies(const ConeScene& s) {
  if (!is_pie(s) || !s.virtual_tools) return {};
  if (s.pie_angle == 180.0) return {180.0};
  return {s.pie_angle, -s.pie_angle};
}

std::vector<std::string> scene_warnings(const ConeScene& s, const ConeTrack& track, const model::ShellModel& model) {
  std::vector<std::string> w = model.warnings();
  if (!is_pie(s)) return w;
  if (!s.virtual_tools) w.emplace_back("virtual tools off: a tool footprint crossing a pie edge does not act on the other edge");
  // The copies at +-gamma see the neighbouring pies only: a footprint reaching further (near the
  // axis of a narrow pie) would be missed.
  const double r = track.min_axis_distance();
  const double reach = r * std::sin(std::min(s.pie_angle, 90.0) * std::numbers::pi / 180.0);
  if (s.virtual_tools && s.tool_radius >= reach) {
    char buf[240];
    std::snprintf(buf, sizeof buf, "the tool centre comes within %.3g mm of the axis, where its footprint may reach pies beyond the "
                  "neighbours (the virtual tools are at +-%.4g deg only)", r, s.pie_angle);
    w.emplace_back(buf);
  }
  return w;
}

json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

json summary_head(const ConeScene& s, const model::ShellModel& model, const ConeTrack& track, const std::vector<std::string>& warnings) {
  const auto& p = track.path().path;
  json j;
  j["scene"] = s.name;
  j["scene_file"] = s.file;
  j["kind"] = "cone";
  j["description"] = s.description;
  j["material"] = s.card.name;
  j["preset"] = s.preset;
  j["model"] = {{"elements", model.num_elements()},       {"nodes", model.num_nodes()},
                {"pie_angle", s.pie_angle},               {"clamp_radius", s.clamp_radius},
                {"clamp_rotations", s.clamp_rotations},   {"thickness", s.thickness},
                {"thickness_points", s.thickness_points}, {"thickness_rule", element::to_string(s.thickness_rule)},
                {"elements_per_45deg", s.mesh.elements_per_45deg},
                {"material_axes", model::to_string(s.material_axes)},
                {"virtual_tools_deg", model.tool_copies_deg()}};
  json stages = json::array();
  for (const auto& o : s.stages)
    stages.push_back({{"wall_angle", o.wall_angle_deg}, {"stepdown", o.stepdown}, {"contours", o.contours}, {"top_radius", o.top_radius}});
  j["path"] = {{"stages", stages}, {"length", p.length()}, {"duration", p.duration()}, {"waypoints", p.waypoints().size()},
               {"contours", track.contours().size()}};
  j["tool"] = {{"radius", s.tool_radius}, {"feed", s.feed}, {"spin_rpm", s.spin}};
  j["contact"] = {{"penalty", s.contact.penalty},
                  {"friction", s.contact.friction},
                  {"points", s.contact.points},
                  {"surface", s.contact.surface == contact::ContactOptions::Surface::phong ? "phong" : "flat"}};
  j["solver"] = {{"travel_per_increment", s.travel_per_increment}, {"move_increments", s.move_increments},
                 {"line_search", s.line_search},                   {"extrapolate", s.extrapolate},
                 {"estimate_next_correction", s.estimate_next_correction}, {"divergence_after", s.divergence_after},
                 {"stabilisation", s.stabilisation}};
  j["warnings"] = warnings;
  j["status"] = "running";
  return j;
}

// force.csv and contours.csv: rows kept in memory, files rewritten at most once per second of
// wall time, at every completed contour and at the end (a full cone has thousands of rows).
class ForceLog {
 public:
  ForceLog(const ConeScene& s, const ConeTrack& track, const io::OutputDirectory& out)
      : scene_(s), track_(track), out_(out),
        csv_({"time [s]", "tool_x [mm]", "tool_y [mm]", "tool_z [mm]", "theta [deg]", "Fx [N]", "Fy [N]", "Fz [N]", "Fr [N]",
              "Ftheta [N]", "stage", "contour", "move", "max_penetration [mm]", "iterations", "surface_penetration [mm]"}),
        energy_csv_({"travel [mm]", "external_work [N mm]", "elastic [N mm]", "plastic [N mm]", "transverse_shear [N mm]",
                     "contact_stored [N mm]", "friction_dissipation [N mm]", "contact_offset_release [N mm]",
                     "balance_error [N mm]"}) {}

  void add(double s, double time, const Eigen::Vector3d& centre, const Eigen::Vector3d& f, double penetration, int iterations,
           double surface_penetration, const model::ModelEnergies& en) {
    const Eigen::Vector3d fp = polar_components(f, centre);
    const toolpath::ConeSegment& seg = track_.segment_at(s);
    const double theta = std::atan2(centre.y(), centre.x()) * 180.0 / std::numbers::pi;
    std::vector<double> row{time, centre.x(), centre.y(), centre.z(), theta, f.x(), f.y(), f.z(), fp.x(), fp.y(), static_cast<double>(seg.stage),
                            static_cast<double>(seg.contour), static_cast<double>(static_cast<int>(seg.move)), penetration,
                            static_cast<double>(iterations), surface_penetration,
                            // energies.csv (kForceColumns onwards)
                            s, en.external_work, en.elastic, en.plastic, en.transverse_shear, en.contact_stored,
                            en.friction_dissipation, en.contact_offset_release, en.balance_error()};
    add_csv_rows(row);
    rows_.push_back(std::move(row));
    samples_.push_back({s, f, fp});
    for (int i = 0; i < 3; ++i) {
      if (std::abs(f(i)) > std::abs(peak_(i))) peak_(i) = f(i);
      if (std::abs(fp(i)) > std::abs(peak_polar_(i))) peak_polar_(i) = fp(i);
    }
  }
  void write(int contours_completed, bool now) {
    if (!now && Clock::now() - last_ < std::chrono::seconds(1)) return;
    last_ = Clock::now();
    out_.write_file("force.csv", "# spifit cone scene " + scene_.name +
                                     ": force BY the sheet ON the (real) tool, Cartesian and polar at the tool's polar angle theta; "
                                     "tool = centre; move: 0 start, 1 approach, 2 contour, 3 ramp, 4 lift, 5 move, 6 plunge, "
                                     "7 retract, 8 stage_change\n" + csv_.str());
    io::CsvTable means({"stage", "contour", "samples", "Fx [N]", "Fy [N]", "Fz [N]", "Fr [N]", "Ftheta [N]"});
    for (const auto& m : contour_means(track_, samples_, contours_completed))
      means.add_row({static_cast<double>(m.span.stage), static_cast<double>(m.span.contour), static_cast<double>(m.samples), m.force.x(),
                     m.force.y(), m.force.z(), m.polar.x(), m.polar.y()});
    out_.write_file("contours.csv", "# spifit cone scene " + scene_.name +
                                        ": mean force over the central third of each completed contour (by travel; thesis §8.3)\n" +
                                        means.str());
    out_.write_file("energies.csv", "# spifit cone scene " + scene_.name +
                                         ": energy account of the (pie) model after each increment (model::ModelEnergies), N mm; "
                                         "external work = the tool's and its copies' work on the sheet (trapezoidal rule); "
                                         "kinetic energy 0 (static implicit); balance_error = external_work - the other columns\n" +
                                         energy_csv_.str());
  }
  ContourMean contour_mean(int k) const { return contour_means(track_, samples_, k + 1).back(); }
  std::vector<ContourMean> means(int contours_completed) const { return contour_means(track_, samples_, contours_completed); }
  // Checkpoints: the rows, samples and peaks so far; restore() continues an empty log from them.
  void save(ConeRunLog* log) const {
    log->force_rows = rows_;
    log->samples = samples_;
    log->peak = peak_;
    log->peak_polar = peak_polar_;
  }
  void restore(const ConeRunLog& log) {
    for (const auto& row : log.force_rows) add_csv_rows(row);
    rows_ = log.force_rows;
    samples_ = log.samples;
    peak_ = log.peak;
    peak_polar_ = log.peak_polar;
  }
  const Eigen::Vector3d& peak() const { return peak_; }
  const Eigen::Vector3d& peak_polar() const { return peak_polar_; }

 private:
  static constexpr std::size_t kForceColumns = 16;  // the rest of a row goes to energies.csv
  void add_csv_rows(const std::vector<double>& row) {
    if (row.size() != kForceColumns + 9) throw std::logic_error("cone force log: row of " + std::to_string(row.size()) + " values");
    csv_.add_row(std::vector<double>(row.begin(), row.begin() + kForceColumns));
    energy_csv_.add_row(std::vector<double>(row.begin() + kForceColumns, row.end()));
  }
  const ConeScene& scene_;
  const ConeTrack& track_;
  const io::OutputDirectory& out_;
  io::CsvTable csv_, energy_csv_;
  std::vector<std::vector<double>> rows_;  // csv_'s and energy_csv_'s rows as numbers (checkpoints)
  std::vector<ForceSample> samples_;
  Eigen::Vector3d peak_ = Eigen::Vector3d::Zero(), peak_polar_ = Eigen::Vector3d::Zero();
  Clock::time_point last_{};
};

void finish_summary(json& j, const solver::NewtonSummary& r, int increments, const ConeTrack& track, const ConeLoadMap& map,
                    const model::ShellModel& model, const ForceLog& log) {
  const Eigen::Vector3d f = model.tool_force();
  j["increments"] = increments;
  const solver::NewtonCounters& c = r.counters;
  j["newton_iterations"] = c.iterations;
  j["cutbacks"] = c.cutbacks;
  j["factorisations"] = c.factorisations();
  j["factorisations_by_solver"] = {{"cholmod", c.cholmod_factorisations}, {"umfpack", c.umfpack_factorisations}};
  j["profile_seconds"] = {{"elements", c.element_seconds}, {"assembly", c.scatter_seconds}, {"linear_solver", c.linear_seconds}};
  // Increments accepted with viscous forces (NewtonOptions::stabilisation): their dissipated
  // work against the tool's work, and the largest out-of-balance one was accepted with.
  j["stabilised"] = {{"increments", c.stabilised_increments},
                     {"viscous_work", c.viscous_work},
                     {"viscous_work_over_tool_work", model.energies().external_work > 0.0 ? c.viscous_work / model.energies().external_work : 0.0},
                     {"max_viscous_force", c.max_viscous_force}};
  j["travel_reached"] = map.travel(r.lambda);
  j["contours_total"] = track.contours().size();
  j["contours_completed"] = track.completed(map.travel(r.lambda));
  j["peak_force"] = vec(log.peak());
  j["peak_polar_force"] = vec(log.peak_polar());
  j["final_force"] = vec(f);
  j["final_polar_force"] = vec(polar_components(f, model.tool().centre));
  j["units"] = {{"force", "N, by the sheet on the real tool (pies: not scaled by 360 / pie_angle)"},
                {"polar_force", "(r, theta, z) at the tool centre's polar angle"},
                {"length", "mm"},
                {"time", "s (travel / feed)"}};
}

}  // namespace

ConeReport run_cone_scene(const ConeScene& scene, const io::OutputDirectory& out, bool progress) {
  ConeRunOptions o;
  o.progress = progress;
  return run_cone_scene(scene, out, o);
}

ConeReport run_cone_scene(const ConeScene& scene, const io::OutputDirectory& out, const ConeRunOptions& options) {
  auto t0 = Clock::now();
  const bool progress = options.progress;
  const ConeInputs inputs = read_cone_inputs(scene);
  const mesh::Mesh mesh = cone_scene_mesh(scene);
  model::ShellModelOptions mo;
  mo.shell.thickness_points = scene.thickness_points;
  mo.shell.thickness_rule = scene.thickness_rule;
  mo.material_axes = scene.material_axes;
  model::ShellModel model(mesh, scene.thickness, scene.card.params, mo);
  const ConeTrack track(cone_scene_path(scene));
  const toolpath::ToolPath& path = track.path().path;
  const double length = path.length(), duration = path.duration();
  const ConeLoadMap map(track.path(), scene.travel_per_increment, scene.move_increments);
  // Spin [rad per unit load factor] = omega [rad/s] x the time per unit load factor where the
  // tool touches (the moves in the air, shortened by the map, turn it faster; no effect there).
  const double spin = scene.spin * 2.0 * std::numbers::pi / 60.0 * duration * map.effective_length() / length;
  model.set_tool(scene.tool_radius, [&path, &map](double lambda) { return path.at_distance(map.travel(lambda)); }, scene.contact, spin);
  model.set_tool_copies(tool_copies(scene));
  const solver::DofConstraints c = cone_constraints(scene, mesh, &model);
  solver::NewtonOptions newton_options = tool_newton_options(scene, map.effective_length());
  newton_options.estimate_next_correction = scene.estimate_next_correction;
  newton_options.stabilisation = scene.stabilisation;
  newton_options.breakpoints = map.breakpoints();
  solver::NewtonSolver solver(model, c, newton_options);

  // Resume: the checkpoint is read (and refused with an InputError) before any output is touched.
  ConeRunLog restored;
  if (options.resume) {
    solver::NewtonState newton;
    read_cone_checkpoint(out, inputs, &model, &newton, &restored);
    solver.set_state(newton);
    t0 -= std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(restored.wall_seconds));
  }

  json s = summary_head(scene, model, track, scene_warnings(scene, track, model));
  if (options.resume) s["resumed_at_contour"] = restored.contours_done;
  out.write_file("summary.json", s.dump(2) + "\n");
  std::filesystem::create_directories(out.path() / "vtu");
  io::PvdCollection pvd(out.path() / "vtu", "sheet");
  if (options.resume) pvd.restore(restored.vtu_steps);
  else pvd.write_step(0.0, mesh, model.vtu_frame());

  ForceLog log(scene, track, out);
  ConeObservableLog observables(scene, model, track, out);  // sections/, sections.csv, stages.csv, history.csv
  double max_pen = restored.max_penetration, max_surface_pen = restored.max_surface_penetration;
  int increments = restored.increments, done = restored.contours_done;
  std::vector<double> contour_wall = restored.contour_wall;  // wall seconds at the end of each completed contour
  if (options.resume) {
    // The rows a killed run wrote after its checkpoint are dropped here.
    log.restore(restored);
    log.write(done, true);
    observables.restore(restored);
    observables.write(true);
  }
  // Checkpoint at the committed state of a completed contour; the solver has chosen its next
  // increment already (NewtonSolver's callback), so its state is where the run goes on.
  int checkpoint_contours = done, checkpoints = 0;
  double checkpoint_seconds = 0.0;
  std::size_t checkpoint_bytes = 0;
  auto write_checkpoint = [&]() {
    const auto c0 = Clock::now();
    ConeRunLog cl;
    log.save(&cl);
    observables.save(&cl);
    cl.increments = increments;
    cl.contours_done = done;
    cl.max_penetration = max_pen;
    cl.max_surface_penetration = max_surface_pen;
    cl.contour_wall = contour_wall;
    cl.wall_seconds = std::chrono::duration<double>(c0 - t0).count();
    cl.vtu_steps = pvd.entries();
    checkpoint_bytes = write_cone_checkpoint(out, inputs, model, solver.state(), cl);
    const double dt = std::chrono::duration<double>(Clock::now() - c0).count();
    checkpoint_seconds += dt;
    ++checkpoints;
    checkpoint_contours = done;
    if (progress) std::fprintf(stderr, "  checkpoint after contour %d: %zu bytes in %.3f s\n", done, checkpoint_bytes, dt);
  };
  bool stopped = false;
  auto on_increment = [&](const solver::IncrementReport& ir) {
    ++increments;
    const double travel = map.travel(ir.lambda), time = travel / length * duration;
    const Eigen::Vector3d f = model.tool_force();
    const double pen = model.contact_summary().max_penetration;
    max_pen = std::max(max_pen, pen);
    const double surface_pen = model.surface_penetration();
    max_surface_pen = std::max(max_surface_pen, surface_pen);
    log.add(travel, time, model.tool().centre, f, pen, ir.iterations, surface_pen, model.energies());
    if (progress && ir.force_only)
      std::fprintf(stderr, "  increment %d at travel %.6f mm accepted on the force test alone at the minimum increment (relative residual %.3g)\n",
                   ir.index, travel, ir.residual_norms.empty() ? 0.0 : ir.residual_norms.back());
    if (progress && ir.damping > 0.0)
      std::fprintf(stderr,
                   "  increment %d at travel %.6f mm stabilised (damping factor %.3g): viscous work %.3g N mm, viscous force %.3g of the force scale\n",
                   ir.index, travel, ir.damping, ir.viscous_work, ir.viscous_force);
    const int now_done = track.completed(travel);
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    const bool contour_ended = done < now_done;
    for (; done < now_done; ++done) {
      contour_wall.push_back(wall);
      const ContourSpan& span = track.contours()[static_cast<std::size_t>(done)];
      observables.after_contour(span);
      if (progress) {
        const Eigen::Vector3d mean = log.contour_mean(done).polar;
        std::fprintf(stderr, "  contour %d/%zu (stage %d, contour %d) done, wall %.1f s: central-third mean (Fr, Ftheta, Fz) = (%.1f, %.1f, %.1f) N\n",
                     done + 1, track.contours().size(), span.stage, span.contour, wall, mean.x(), mean.y(), mean.z());
      }
    }
    observables.after_increment(travel, ir.lambda);
    observables.write(contour_ended);
    log.write(done, contour_ended);
    if (scene.vtu_every > 0 && increments % scene.vtu_every == 0) pvd.write_step(time, mesh, model.vtu_frame());
    if (scene.checkpoint_every > 0 && done >= checkpoint_contours + scene.checkpoint_every) write_checkpoint();
    if ((options.stop_after_contours > 0 && done >= options.stop_after_contours) ||
        (options.stop_after_increments > 0 && increments >= options.stop_after_increments)) {
      stopped = true;
      return false;
    }
    return true;
  };

  const solver::NewtonSummary r = options.resume ? solver.resume(1.0, on_increment) : solver.solve(0.0, 1.0, on_increment);
  if (stopped) {
    // As a kill may leave it: force.csv, contours.csv and the observables' files hold every
    // increment so far (rows after the last checkpoint included), no final VTU step.
    log.write(done, true);
    observables.write(true);
    s["status"] = "stopped";
    s["message"] = "stopped after " + std::to_string(increments) + " increments, " + std::to_string(done) + " contours (test option)";
    out.write_file("summary.json", s.dump(2) + "\n");
    ConeReport rep;
    rep.ok = false;
    rep.stopped = true;
    rep.summary = s;
    return rep;
  }
  if (increments > 0 && (scene.vtu_every == 0 || increments % scene.vtu_every != 0)) pvd.write_step(map.travel(r.lambda) / length * duration, mesh, model.vtu_frame());
  log.write(done, true);
  observables.write(true);
  finish_summary(s, r, increments, track, map, model, log);
  s["observables"] = observables.summary();
  if (scene.steady_state) {
    const auto [from, to] = *scene.steady_state;
    const SteadyState ss = steady_state(log.means(done), from, to);
    s["steady_state"] = {{"contours", {from, to}},
                         {"contours_used", ss.contours},
                         {"force", vec(ss.force)},
                         {"polar_force", vec(ss.polar)},
                         {"fr_over_fz", ss.polar.x() / ss.polar.z()},
                         {"definition", "mean of the central-third contour means of the completed contours in the range (thesis §9.3)"}};
  }
  {
    const model::ModelEnergies en = model.energies();
    s["energies"] = {{"external_work", en.external_work},
                     {"elastic", en.elastic},
                     {"plastic", en.plastic},
                     {"transverse_shear", en.transverse_shear},
                     {"contact_stored", en.contact_stored},
                     {"friction_dissipation", en.friction_dissipation},
                     {"contact_offset_release", en.contact_offset_release},
                     {"kinetic", en.kinetic},
                     {"balance_error", en.balance_error()},
                     {"relative_balance_error", en.external_work != 0.0 ? en.balance_error() / en.external_work : 0.0},
                     {"units", "N mm (= mJ), the modelled pie only"}};
  }
  s["max_penetration"] = max_pen;
  s["max_surface_penetration"] = max_surface_pen;
  if (const std::string w = contact::ShellContact::resolution_warning(max_pen, max_surface_pen, scene.contact.points); !w.empty())
    s["warnings"].push_back(w);
  s["contour_wall_seconds"] = contour_wall;
  s["checkpoints"] = {{"file", "checkpoint/state.bin"}, {"every_contours", scene.checkpoint_every}, {"written", checkpoints},
                      {"bytes", checkpoint_bytes}, {"write_seconds", checkpoint_seconds}};
  s["wall_seconds"] = std::chrono::duration<double>(Clock::now() - t0).count();
  ConeReport rep;
  rep.ok = set_run_status(s, r.converged, map.travel(r.lambda), r.message);
  out.write_file("summary.json", s.dump(2) + "\n");
  rep.summary = s;
  return rep;
}

}  // namespace spifit::scene
