#include "forward/scenes/forming_scene.hpp"

#include "forward/io/csv_writer.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/io/vtu_writer.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/scene_tables.hpp"
#include "forward/toolpath/gcode.hpp"
#include "forward/toolpath/tool_path.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>

namespace spifit::scene {
namespace {

using json = nlohmann::json;

// Thesis defaults per kind.
void set_defaults(FormingScene& s) {
  if (s.kind == "indent") {
    // §7.1: 10 x 10 mm, t = 0.3, edges clamped, R = 5 at the centre, 2 mm after 1 s from first touch.
    s.length = 10.0; s.thickness = 0.3; s.elements = 10; s.half = false;
    s.radius = 5.0; s.feed = 2.0;
    s.path = {{"A", {0.0, 0.0, 0.0}}, {"B", {0.0, 0.0, -2.0}}};
    s.travel_per_increment = 0.05;
    // No predictor: from K_p = 1e6 up it led Newton into states it could not leave even with
    // 1e-5 of the step (docs/contact.md); this small model gains nothing from it anyway.
    s.extrapolate = false;
  } else {
    // §3.2: 182 x 182 mm, t = 1.2, 50 x 50 regular mesh (3.64 mm), edges clamped, R = 5,
    // A (-50, 0) above the sheet, B at 5 mm depth, C after +100 mm, D at 10 mm, E back -100 mm.
    s.length = 182.0; s.thickness = 1.2; s.elements = 50; s.half = true;
    s.radius = 5.0; s.feed = 10.0;
    s.path = {{"A", {-50.0, 0.0, 0.0}}, {"B", {-50.0, 0.0, -5.0}}};
    if (s.kind == "line") {
      s.path.push_back({"C", {50.0, 0.0, -5.0}});
      s.path.push_back({"D", {50.0, 0.0, -10.0}});
      s.path.push_back({"E", {-50.0, 0.0, -10.0}});
      s.sections = {"C", "E"};
    }
    s.travel_per_increment = 0.5;
  }
}

// The tool-tip path of a G-code program. The position before the first move is unknown to
// the program, so an opening rapid (G00) only places the tool: the path starts at its end
// point instead of at the reader's default start (the origin).
toolpath::ToolPath gcode_tip_path(const std::string& file) {
  toolpath::ToolPath p = toolpath::read_gcode(file);
  const auto& w = p.waypoints();
  if (w.size() > 2 && w[1].feed == 0.0) return toolpath::ToolPath(std::vector<toolpath::Waypoint>(w.begin() + 1, w.end()), p.rapid_feed());
  return p;
}

// Load factors where a G-code path turns by more than 15 degrees (and its end): the solver
// stops there as it does at the named points of a built-in path, so that both give the same
// increments (arc chords turn by far less and are not stops).
std::vector<std::pair<double, std::string>> corner_stops(const toolpath::ToolPath& path) {
  const auto& w = path.waypoints();
  const std::vector<double> dist = path.waypoint_distances();
  const double L = path.length();
  std::vector<std::pair<double, std::string>> stops;
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i < w.size(); ++i) {
    const Eigen::Vector3d seg = w[i].position - w[i - 1].position;
    if (seg.norm() < 1e-12) continue;
    const Eigen::Vector3d dir = seg.normalized();
    if (previous.squaredNorm() > 0.0 && previous.dot(dir) < std::cos(15.0 * std::numbers::pi / 180.0) && dist[i - 1] > 0.0)
      stops.emplace_back(dist[i - 1] / L, "line " + std::to_string(w[i - 1].source_line));
    previous = dir;
  }
  stops.emplace_back(1.0, "end");
  return stops;
}

}  // namespace

bool is_forming_kind(const std::string& kind) { return kind == "indent" || kind == "indent_line" || kind == "line"; }

FormingScene read_forming_scene(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"scene", "sheet", "tool", "path", "contact", "solver", "output"});
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  sc->allow_only({"kind", "name", "description", "material"});
  FormingScene s;
  s.file = path;
  s.kind = sc->string("kind");
  if (!is_forming_kind(s.kind)) sc->fail("kind", "expected indent, indent_line or line");
  set_defaults(s);
  s.name = sc->string("name", std::filesystem::path(path).stem().string());
  s.description = sc->string("description", "");
  s.card = read_scene_material(*sc, path);

  auto positive = [](const io::TomlTable& t, const char* key, double* v) {
    if (!t.has(key)) return;
    *v = t.number(key);
    if (!(*v > 0.0 && std::isfinite(*v))) t.fail(key, "must be > 0");
  };
  if (const auto sh = root.table("sheet")) {
    sh->allow_only({"length", "thickness", "elements", "half", "grading", "thickness_points"});
    positive(*sh, "length", &s.length);
    positive(*sh, "thickness", &s.thickness);
    positive(*sh, "grading", &s.grading);
    s.elements = sh->integer("elements", s.elements);
    if (s.elements < 2 || s.elements > 2000) sh->fail("elements", "must be an integer in [2, 2000]");
    s.half = sh->boolean("half", s.half);
    if (s.half && s.elements % 2 != 0) sh->fail("elements", "a half model needs an even number of elements across");
    s.thickness_points = sh->integer("thickness_points", s.thickness_points);
    if (s.thickness_points < 1 || s.thickness_points > 11) sh->fail("thickness_points", "unsupported number of thickness points (1 to 11)");
  }
  if (const auto tl = root.table("tool")) {
    tl->allow_only({"radius", "feed", "gcode", "spin"});
    positive(*tl, "radius", &s.radius);
    positive(*tl, "feed", &s.feed);
    s.spin = tl->number("spin", 0.0);
    if (!(std::abs(s.spin) <= 1e5)) tl->fail("spin", "must be a rotation speed in rev/min with |spin| <= 1e5");
    if (tl->has("gcode")) {
      std::filesystem::path gp(tl->string("gcode"));
      if (gp.is_relative()) gp = std::filesystem::path(path).parent_path() / gp;
      if (!std::filesystem::exists(gp)) tl->fail("gcode", "G-code file not found at " + gp.lexically_normal().string());
      s.gcode = gp.lexically_normal().string();
      s.sections.clear();
    }
  }
  const auto points = root.table_array("path");
  if (!points.empty()) {
    if (!s.gcode.empty()) points.front().fail("x", "give either [tool] gcode or [[path]] points, not both");
    s.path.clear();
    for (const auto& p : points) {
      p.allow_only({"name", "x", "y", "z"});
      std::string fallback = "P";
      fallback += std::to_string(s.path.size());
      s.path.push_back({p.string("name", fallback), {p.number("x"), p.number("y"), p.number("z")}});
    }
    if (s.path.size() < 2) points.front().fail("x", "a path needs at least 2 points");
    if (!root.table("output") || !root.table("output")->has("sections")) s.sections.clear();
  }
  if (const auto ct = root.table("contact")) {
    ct->allow_only({"penalty", "friction", "tangential_penalty", "points", "surface"});
    read_contact_table(*ct, &s.contact);
  }
  if (const auto so = root.table("solver")) {
    read_solver_table(*so, {s.travel_per_increment, s.max_iterations, s.linear_solver, s.extrapolate, s.line_search,
                            s.force_tolerance, s.displacement_tolerance, s.divergence_after});
  }
  if (const auto o = root.table("output")) {
    o->allow_only({"vtu_every", "sections"});
    s.vtu_every = o->integer("vtu_every", 0);
    if (s.vtu_every < 0) o->fail("vtu_every", "must be >= 0");
    if (o->has("sections")) {
      s.sections = o->string_list("sections");
      for (const auto& n : s.sections)
        if (std::none_of(s.path.begin(), s.path.end(), [&](const PathPoint& p) { return p.name == n; }))
          o->fail("sections", "no path point named \"" + n + "\"");
    }
  }
  // The tool must start outside the sheet and reach it.
  const double half_length = 0.5 * s.length;
  auto over_sheet = [&](const Eigen::Vector3d& tip) { return std::abs(tip.x()) < half_length && std::abs(tip.y()) < half_length; };
  std::vector<Eigen::Vector3d> tips;
  if (!s.gcode.empty()) {
    const toolpath::ToolPath gp = gcode_tip_path(s.gcode);
    for (const auto& w : gp.waypoints()) tips.push_back(w.position);
  } else {
    for (const auto& p : s.path) tips.push_back(p.tip);
  }
  // Path errors are reported on the key that holds the path.
  const auto path_error = [&](const std::string& message) {
    if (!s.gcode.empty()) root.table("tool")->fail("gcode", message);
    if (!points.empty()) points.front().fail("z", message);
    sc->fail("kind", message + " (default path of this kind)");
  };
  if (tips.front().z() < -1e-9 && over_sheet(tips.front())) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the tool starts inside the sheet: its tip is %.4g mm below the top surface", -tips.front().z());
    path_error(buf);
  }
  if (std::none_of(tips.begin(), tips.end(), [&](const Eigen::Vector3d& t) { return t.z() < 0.0 && over_sheet(t); }))
    path_error("the tool path never goes below the sheet's top surface over the sheet");
  return s;
}

FormingReport run_forming_scene(const FormingScene& scene, const io::OutputDirectory& out, bool progress) {
  FormingReport rep;
  mesh::SquareSheetOptions so;
  so.length_x = so.length_y = scene.length;
  so.nx = so.ny = scene.elements;
  so.half = scene.half;
  so.grading_x = so.grading_y = scene.grading;
  const mesh::Mesh mesh = mesh::square_sheet(so);
  model::ShellModelOptions mo;
  mo.shell.thickness_points = scene.thickness_points;
  model::ShellModel model(mesh, scene.thickness, scene.card.params, mo);

  // The tool centre path: the tip path lifted by the top surface (t/2) and the radius.
  const Eigen::Vector3d lift(0.0, 0.0, 0.5 * scene.thickness + scene.radius);
  std::vector<double> marks;  // path distance of each named point
  toolpath::ToolPath path = [&] {
    if (!scene.gcode.empty()) return gcode_tip_path(scene.gcode).translated(lift);
    std::vector<Eigen::Vector3d> pts;
    for (const auto& p : scene.path) pts.push_back(p.tip + lift);
    return toolpath::ToolPath::from_points(pts, scene.feed);
  }();
  const double L = path.length();
  if (scene.gcode.empty()) marks = path.waypoint_distances();
  // Spin [rad per unit load factor] = omega [rad/s] x travel time L / feed [s].
  const double spin_per_load_factor = scene.spin * 2.0 * std::numbers::pi / 60.0 * L / scene.feed;
  model.set_tool(scene.radius, [path, L](double lambda) { return path.at_distance(lambda * L); }, scene.contact, spin_per_load_factor);

  solver::DofConstraints c(model.num_dofs());
  for (int n : mesh.node_sets.at("boundary"))
    for (int k = 0; k < 6; ++k) c.prescribe(model::ShellModel::dof(n, k));
  if (scene.half)
    for (int n : mesh.node_sets.at("symmetry_y0"))
      for (int k : {1, 3, 5})
        if (!c.prescribed(model::ShellModel::dof(n, k))) c.prescribe(model::ShellModel::dof(n, k));
  model.use_nodal_rotation_frames(&c);  // drilling rotations out of the system
  c.finalize();

  const solver::NewtonOptions o = tool_newton_options(scene, L);

  json s;
  s["scene"] = scene.name;
  s["scene_file"] = scene.file;
  s["kind"] = scene.kind;
  s["description"] = scene.description;
  s["material"] = scene.card.name;
  s["model"] = {{"elements", model.num_elements()}, {"nodes", model.num_nodes()}, {"half", scene.half},
                {"thickness", scene.thickness}, {"length", scene.length}, {"thickness_points", scene.thickness_points}};
  s["tool"] = {{"radius", scene.radius}, {"travel", L}, {"feed", scene.feed}, {"spin_rpm", scene.spin}, {"gcode", scene.gcode}};
  s["contact"] = {{"penalty", scene.contact.penalty},
                  {"friction", scene.contact.friction},
                  {"points", scene.contact.points},
                  {"surface", scene.contact.surface == contact::ContactOptions::Surface::phong ? "phong" : "flat"}};
  s["warnings"] = model.warnings();
  s["status"] = "running";
  out.write_file("summary.json", s.dump(2) + "\n");

  std::unique_ptr<io::PvdCollection> pvd;
  std::filesystem::create_directories(out.path() / "vtu");
  pvd = std::make_unique<io::PvdCollection>(out.path() / "vtu", "sheet");
  pvd->write_step(0.0, mesh, model.vtu_frame());

  // Force BY the sheet ON the tool; a half model carries half of Fx and Fz.
  const double mirror = scene.half ? 2.0 : 1.0;
  io::CsvTable force({"time [s]", "tool_x [mm]", "tool_y [mm]", "tool_z [mm]", "Fx [N]", "Fy [N]", "Fz [N]",
                      "max_penetration [mm]", "iterations"});
  std::ostringstream header;
  header << "# spifit " << scene.kind << " scene " << scene.name << ": force BY the sheet ON the tool; tool = centre position"
         << (scene.half ? "; half model, forces mirrored to the full sheet" : "") << "\n";
  Eigen::Vector3d peak = Eigen::Vector3d::Zero();
  double max_pen = 0.0;
  int increments = 0, vtu_steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  auto on_increment = [&](const solver::IncrementReport& ir) {
    ++increments;
    const Eigen::Vector3d f = model.tool_force();
    const Eigen::Vector3d full(mirror * f.x(), scene.half ? 0.0 : f.y(), mirror * f.z());
    const double pen = model.contact_summary().max_penetration;
    max_pen = std::max(max_pen, pen);
    for (int i = 0; i < 3; ++i)
      if (std::abs(full(i)) > std::abs(peak(i))) peak(i) = full(i);
    const Eigen::Vector3d tc = model.tool().centre;
    force.add_row({ir.lambda * L / scene.feed, tc.x(), tc.y(), tc.z(), full.x(), full.y(), full.z(), pen, static_cast<double>(ir.iterations)});
    out.write_file("force.csv", header.str() + force.str());
    if (scene.vtu_every > 0 && increments % scene.vtu_every == 0) {
      pvd->write_step(ir.lambda * L / scene.feed, mesh, model.vtu_frame());
      ++vtu_steps;
    }
    if (progress) std::fprintf(stderr, "  increment %d: travel %.2f / %.2f mm, Fz %.2f N, %d iterations\n", increments, ir.lambda * L, L, full.z(), ir.iterations);
    return true;
  };
  auto write_section = [&](const std::string& name) {
    std::vector<std::pair<double, int>> line;
    for (int n = 0; n < model.num_nodes(); ++n)
      if (std::abs(mesh.nodes[static_cast<std::size_t>(n)].y()) < 1e-9) line.emplace_back(mesh.nodes[static_cast<std::size_t>(n)].x(), n);
    std::sort(line.begin(), line.end());
    const std::vector<double> h = model.nodal_thickness();
    io::CsvTable sec({"x0 [mm]", "x [mm]", "y [mm]", "z [mm]", "thickness [mm]"});
    for (const auto& [x0, n] : line) {
      const Eigen::Vector3d& p = model.position(n);
      sec.add_row({x0, p.x(), p.y(), p.z(), h[static_cast<std::size_t>(n)]});
    }
    std::filesystem::create_directories(out.path() / "sections");
    out.write_file("sections/section_" + name + ".csv",
                   "# spifit " + scene.name + ": section y = 0 (mid-surface) at path point " + name + "\n" + sec.str());
  };

  solver::NewtonSolver solver(model, c, o);
  solver::NewtonSummary total;
  total.converged = true;
  // Solve segment by segment so that the named path points are reached exactly.
  std::vector<std::pair<double, std::string>> stops;
  if (scene.gcode.empty())
    for (std::size_t i = 1; i < scene.path.size(); ++i) stops.emplace_back(marks[i] / L, scene.path[i].name);
  else
    stops = corner_stops(path);
  double lambda = 0.0;
  for (const auto& [target, name] : stops) {
    if (target <= lambda + 1e-12) continue;
    const solver::NewtonSummary r = solver.solve(lambda, target, on_increment);
    total.counters.iterations += r.counters.iterations;
    total.counters.cutbacks += r.counters.cutbacks;
    total.counters.cholmod_factorisations = r.counters.cholmod_factorisations;  // the solver counts over its life
    total.counters.umfpack_factorisations = r.counters.umfpack_factorisations;
    total.counters.element_seconds = r.counters.element_seconds;  // cumulative over the solver's life
    total.counters.scatter_seconds = r.counters.scatter_seconds;
    total.counters.linear_seconds = r.counters.linear_seconds;
    if (!r.converged) {
      total.converged = false;
      total.message = r.message;
      total.lambda = r.lambda;
      break;
    }
    lambda = target;
    total.lambda = lambda;
    if (std::find(scene.sections.begin(), scene.sections.end(), name) != scene.sections.end()) write_section(name);
  }
  if (increments > 0 && (scene.vtu_every == 0 || increments % scene.vtu_every != 0))
    pvd->write_step(total.lambda * L / scene.feed, mesh, model.vtu_frame());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Eigen::Vector3d f = model.tool_force();
  s["wall_seconds"] = wall;
  s["increments"] = increments;
  s["newton_iterations"] = total.counters.iterations;
  s["cutbacks"] = total.counters.cutbacks;
  s["profile_seconds"] = {{"elements", total.counters.element_seconds}, {"assembly", total.counters.scatter_seconds},
                          {"linear_solver", total.counters.linear_seconds}};
  s["factorisations"] = total.counters.factorisations();
  s["factorisations_by_solver"] = {{"cholmod", total.counters.cholmod_factorisations}, {"umfpack", total.counters.umfpack_factorisations}};
  s["travel_reached"] = total.lambda * L;
  s["peak_force"] = {peak.x(), peak.y(), peak.z()};
  s["final_force"] = {mirror * f.x(), scene.half ? 0.0 : f.y(), mirror * f.z()};
  s["max_penetration"] = max_pen;
  s["units"] = {{"force", "N, by the sheet on the tool"}, {"length", "mm"}, {"time", "s (travel / feed)"}};
  rep.ok = set_run_status(s, total.converged, total.lambda * L, total.message);
  out.write_file("summary.json", s.dump(2) + "\n");
  rep.summary = s;
  return rep;
}

}  // namespace spifit::scene
