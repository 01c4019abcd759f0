#include "forward/scenes/shell_benchmark_scene.hpp"

#include "forward/io/csv_writer.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/io/vtu_writer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace spifit::scene {
namespace {

using json = nlohmann::json;

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The benchmark's solver defaults with the scene's [solver] overrides.
solver::NewtonOptions solver_options(const ShellBenchmarkScene& scene, const ShellBenchmark& b) {
  solver::NewtonOptions o = b.solver;
  if (scene.initial_increment) o.initial_increment = *scene.initial_increment;
  if (scene.min_increment) o.min_increment = *scene.min_increment;
  if (scene.max_increment) o.max_increment = *scene.max_increment;
  if (scene.force_tolerance) o.force_tolerance = *scene.force_tolerance;
  if (scene.displacement_tolerance) o.displacement_tolerance = *scene.displacement_tolerance;
  if (scene.max_iterations) o.max_iterations = *scene.max_iterations;
  if (scene.line_search) o.line_search = *scene.line_search;
  if (scene.linear_solver) o.linear_solver = *scene.linear_solver;
  if (b.linear) {
    o.linear = true;
    o.initial_increment = o.max_increment = 1.0;
    o.min_increment = std::min(o.min_increment, 1.0);
  }
  return o;
}

}  // namespace

ShellBenchmarkScene read_shell_benchmark_scene(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"scene", "solver", "output"});
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  sc->allow_only({"kind", "name", "description", "benchmark", "mesh", "thickness_points", "thickness_rule"});
  if (sc->string("kind") != "shell_benchmark") sc->fail("kind", "expected \"shell_benchmark\"");
  ShellBenchmarkScene s;
  s.file = path;
  s.name = sc->string("name", std::filesystem::path(path).stem().string());
  s.description = sc->string("description", "");
  s.setup.benchmark = sc->string("benchmark");
  const auto names = shell_benchmark_names();
  if (std::find(names.begin(), names.end(), s.setup.benchmark) == names.end())
    sc->fail("benchmark", "unknown benchmark (known: " + join(names) + ")");
  s.setup.mesh = sc->integer("mesh", 0);
  if (sc->has("mesh") && !(s.setup.mesh >= 1 && s.setup.mesh <= 1000)) sc->fail("mesh", "must be an integer in [1, 1000]");
  s.setup.thickness_points = sc->integer("thickness_points", 0);
  if (sc->has("thickness_points") && !(s.setup.thickness_points >= element::kMinThicknessPoints &&
                                       s.setup.thickness_points <= element::kMaxThicknessPoints))
    sc->fail("thickness_points", "unsupported number of thickness points (1 to 11)");
  if (sc->has("thickness_rule")) {
    if (!element::thickness_rule_from_string(sc->string("thickness_rule"), &s.setup.thickness_rule))
      sc->fail("thickness_rule", "expected \"gauss\" or \"surface\"");
    if (s.setup.thickness_rule == element::ThicknessRuleKind::surface && s.setup.thickness_points > 0 &&
        (s.setup.thickness_points < 3 || s.setup.thickness_points % 2 == 0))
      sc->fail("thickness_points", "the surface rule needs an odd count from 3 to 11");
  }
  if (const auto so = root.table("solver")) {
    so->allow_only({"initial_increment", "min_increment", "max_increment", "max_iterations", "force_tolerance",
                    "displacement_tolerance", "line_search", "linear_solver"});
    auto positive = [&](const char* key, std::optional<double>* dst) {
      if (!so->has(key)) return;
      const double v = so->number(key);
      if (!(v > 0.0 && v <= 1.0)) so->fail(key, "must lie in (0, 1]");
      *dst = v;
    };
    positive("initial_increment", &s.initial_increment);
    positive("min_increment", &s.min_increment);
    positive("max_increment", &s.max_increment);
    positive("force_tolerance", &s.force_tolerance);
    positive("displacement_tolerance", &s.displacement_tolerance);
    if (so->has("max_iterations")) {
      const int n = so->integer("max_iterations", 0);
      if (n < 1 || n > 1000) so->fail("max_iterations", "must be an integer in [1, 1000]");
      s.max_iterations = n;
    }
    if (so->has("line_search")) s.line_search = so->boolean("line_search", false);
    if (so->has("linear_solver")) {
      solver::LinearSolverKind k{};
      if (!solver::linear_solver_from_string(so->string("linear_solver"), &k))
        so->fail("linear_solver", "expected \"auto\", \"umfpack\" or \"cholmod\"");
      s.linear_solver = k;
    }
  }
  if (const auto out = root.table("output")) {
    out->allow_only({"vtu", "vtu_every"});
    s.vtu = out->boolean("vtu", true);
    s.vtu_every = out->integer("vtu_every", 0);
    if (s.vtu_every < 0) out->fail("vtu_every", "must be >= 0 (0: the final state only)");
  }
  // Builds the model once to report mesh and setting errors before any output is touched.
  try {
    const ShellBenchmark b = make_shell_benchmark(s.setup);
    if (const std::string err = solver_options(s, b).validate(); !err.empty())
      root.fail("solver", err + " (benchmark defaults: initial " + std::to_string(b.solver.initial_increment) + ", max " +
                              std::to_string(b.solver.max_increment) + ")");
  } catch (const std::invalid_argument& e) {
    sc->fail(sc->has("mesh") ? "mesh" : "benchmark", e.what());
  }
  return s;
}

ShellSceneReport run_shell_benchmark_scene(const ShellBenchmarkScene& scene, const io::OutputDirectory& out, bool progress) {
  ShellSceneReport rep;
  ShellBenchmark b = make_shell_benchmark(scene.setup);
  const solver::NewtonOptions o = solver_options(scene, b);
  if (const std::string err = o.validate(); !err.empty()) throw io::InputError(scene.file, "solver", "", err);

  json s;
  s["scene"] = scene.name;
  s["scene_file"] = scene.file;
  s["kind"] = "shell_benchmark";
  s["benchmark"] = b.benchmark;
  s["description"] = scene.description;
  s["quantity"] = b.quantity;
  s["reference"] = b.reference;
  s["reference_source"] = b.source;
  s["analysis"] = b.linear ? "linear" : "nonlinear";
  s["mesh"] = {{"elements", b.model->num_elements()}, {"nodes", b.model->num_nodes()}, {"dofs", b.model->num_dofs()},
               {"reduced_dofs", b.constraints->num_reduced()}, {"thickness", b.thickness},
               {"thickness_points", b.model->element(0).section(0).layers()},
               {"thickness_rule", element::to_string(b.thickness_rule)},
               {"max_thickness_over_length", b.model->max_thickness_over_length()}};
  s["warnings"] = b.model->warnings();
  s["status"] = "running";
  out.write_file("summary.json", s.dump(2) + "\n");

  std::unique_ptr<io::PvdCollection> pvd;
  if (scene.vtu) {
    std::filesystem::create_directories(out.path() / "vtu");
    pvd = std::make_unique<io::PvdCollection>(out.path() / "vtu", "shell");
    pvd->write_step(0.0, *b.mesh, b.model->vtu_frame());  // the initial state
  }
  std::ostringstream inc;
  inc << "# spifit shell benchmark " << scene.name << ": Newton convergence per increment\n"
      << "increment,load_factor,increment_size,iterations,line_searches,final_relative_residual\n";
  const auto write_increments = [&] { out.write_file("increments.csv", inc.str()); };
  int written = -1;
  const auto t0 = std::chrono::steady_clock::now();
  solver::NewtonSolver solver(*b.model, *b.constraints, o);
  const solver::NewtonSummary r = solver.solve(1.0, [&](const solver::IncrementReport& ir) {
    char line[160];
    std::snprintf(line, sizeof line, "%d,%.10g,%.6g,%d,%d,%.3e\n", ir.index, ir.lambda, ir.increment, ir.iterations,
                  ir.line_searches, ir.residual_norms.empty() ? 0.0 : ir.residual_norms.back());
    inc << line;
    write_increments();
    if (pvd && scene.vtu_every > 0 && ir.index % scene.vtu_every == 0) {
      pvd->write_step(ir.lambda, *b.mesh, b.model->vtu_frame());
      written = ir.index;
    }
    if (progress) std::fprintf(stderr, "  increment %d: load factor %.4f, %d iterations\n", ir.index, ir.lambda, ir.iterations);
    return true;
  });
  if (pvd && written != static_cast<int>(r.history.size()) && !r.history.empty())
    pvd->write_step(r.lambda, *b.mesh, b.model->vtu_frame());  // the last converged state
  write_increments();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  s["wall_seconds"] = wall;
  const solver::NewtonCounters& c = r.counters;
  s["solver"] = {{"increments", c.increments}, {"iterations", c.iterations}, {"cutbacks", c.cutbacks},
                 {"factorisations", c.factorisations()}, {"symbolic_analyses", c.symbolic_analyses},
                 {"linear_solver", solver::to_string(o.linear_solver)},
                 {"cholmod_factorisations", c.cholmod_factorisations}, {"umfpack_factorisations", c.umfpack_factorisations},
                 {"load_factor", r.lambda}};
  s["message"] = r.message;
  if (!r.converged) {
    s["status"] = "failed";
    out.write_file("summary.json", s.dump(2) + "\n");
    rep.ok = false;
    rep.summary = s;
    return rep;
  }
  const double value = b.value(*b.model);
  s["status"] = "ok";
  s["value"] = value;
  s["relative_error"] = value / b.reference - 1.0;
  if (b.details) s["details"] = b.details(*b.model);
  out.write_file("summary.json", s.dump(2) + "\n");
  rep.summary = s;
  return rep;
}

}  // namespace spifit::scene
