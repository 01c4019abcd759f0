#include "forward/scenes/benchmark/shell_benchmark_scene.hpp"

#include "forward/scenes/benchmark/shell_benchmark_inputs.hpp"
#include "forward/scenes/common/scene_inputs.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/mesh/vtu_writer.hpp"
#include "forward/model/model_vtu.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace spifit::scene {
namespace {

using json = nlohmann::json;

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
  const auto& inputs = shell_benchmark_inputs();
  sc->allow_only(inputs.keys_of("scene"));
  if (sc->string("kind") != "shell_benchmark") sc->fail("kind", "expected \"shell_benchmark\"");
  ShellBenchmarkScene s;
  s.file = path;
  // Types, ranges and choices of every key; the values are read below.
  read_input_tables(root, inputs, {"scene", "solver", "output"}, s);
  s.name = sc->string("name", std::filesystem::path(path).stem().string());
  s.description = sc->string("description", "");
  s.setup.benchmark = sc->string("benchmark");
  s.setup.mesh = sc->integer("mesh", 0);
  s.setup.thickness_points = sc->integer("thickness_points", 0);
  if (sc->has("thickness_rule")) {
    if (!element::thickness_rule_from_string(sc->string("thickness_rule"), &s.setup.thickness_rule))
      sc->fail("thickness_rule", "not a value of scene.thickness_rule");
    if (s.setup.thickness_rule == element::ThicknessRuleKind::surface && s.setup.thickness_points > 0 &&
        (s.setup.thickness_points < 3 || s.setup.thickness_points % 2 == 0))
      sc->fail("thickness_points", "the surface rule needs an odd count from 3 to 11");
  }
  if (const auto so = root.table("solver")) {
    auto number = [&](const char* key, std::optional<double>* dst) {
      if (so->has(key)) *dst = so->number(key);
    };
    number("initial_increment", &s.initial_increment);
    number("min_increment", &s.min_increment);
    number("max_increment", &s.max_increment);
    number("force_tolerance", &s.force_tolerance);
    number("displacement_tolerance", &s.displacement_tolerance);
    if (so->has("max_iterations")) s.max_iterations = so->integer("max_iterations", 0);
    if (so->has("line_search")) s.line_search = so->boolean("line_search", false);
    if (so->has("linear_solver")) {
      solver::LinearSolverKind k{};
      if (!solver::linear_solver_from_string(so->string("linear_solver"), &k)) so->fail("linear_solver", "not a value of solver.linear_solver");
      s.linear_solver = k;
    }
  }
  if (const auto out = root.table("output")) {
    s.vtu = out->boolean("vtu", true);
    s.vtu_every = out->integer("vtu_every", 0);
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

json ShellBenchmarkResult::to_json() const {
  json s = inputs;
  add_status(s);
  s["message"] = message;
  const solver::NewtonCounters& c = counters;
  s["solver"] = {{"increments", c.increments}, {"iterations", c.iterations}, {"cutbacks", c.cutbacks},
                 {"factorisations", c.factorisations()}, {"symbolic_analyses", c.symbolic_analyses},
                 {"linear_solver", linear_solver},
                 {"cholmod_factorisations", c.cholmod_factorisations}, {"umfpack_factorisations", c.umfpack_factorisations},
                 {"load_factor", load_factor}};
  if (!ok()) return s;
  s["value"] = value;
  s["relative_error"] = value / reference - 1.0;
  if (!details.is_null()) s["details"] = details;
  return s;
}

std::string ShellBenchmarkResult::brief_report() const {
  char buf[400];
  if (!ok()) return name + " failed: " + message;
  std::snprintf(buf, sizeof buf, "%-28s %-26s value %.6g  reference %.6g  error %+.3f %%  (%d elements, %d increments, %d iterations, %.3f s)",
                name.c_str(), benchmark.c_str(), value, reference, 100.0 * (value / reference - 1.0), elements, counters.increments,
                counters.iterations, wall_seconds);
  return buf;
}

namespace {

json benchmark_inputs(const ShellBenchmarkScene& scene, const ShellBenchmark& b) {
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
  return s;
}

}  // namespace

ShellBenchmarkResult run_shell_benchmark_scene(const ShellBenchmarkScene& scene, const RunFiles& files, const RunControl& control) {
  ShellBenchmark b = make_shell_benchmark(scene.setup);
  const solver::NewtonOptions o = solver_options(scene, b);
  if (const std::string err = o.validate(); !err.empty()) throw io::InputError(scene.file, "solver", "", err);
  ShellBenchmarkResult out;
  out.inputs = benchmark_inputs(scene, b);
  out.name = scene.name;
  out.benchmark = b.benchmark;
  out.reference = b.reference;
  out.elements = b.model->num_elements();
  out.warnings = b.model->warnings();
  out.linear_solver = solver::to_string(o.linear_solver);
  json running = out.inputs;
  running["status"] = "running";
  files.write("summary.json", running.dump(2) + "\n");

  std::unique_ptr<mesh::PvdCollection> pvd;
  if (scene.vtu && files.enabled()) {
    std::filesystem::create_directories(files.directory()->path() / "vtu");
    files.directory()->record();  // vtu/ in the manifest
    pvd = std::make_unique<mesh::PvdCollection>(files.directory()->path() / "vtu", "shell");
    pvd->write_step(0.0, *b.mesh, model::vtu_frame(*b.model));  // the initial state
  }
  // increments.csv keeps its short number formats (a convergence report, not data to read back).
  std::string inc = "# spifit shell benchmark " + scene.name + ": Newton convergence per increment\n"
                    "increment,load_factor,increment_size,iterations,line_searches,final_relative_residual\n";
  const auto write_increments = [&] { files.write("increments.csv", inc); };
  int written = -1;
  const auto t0 = std::chrono::steady_clock::now();
  solver::NewtonSolver solver(*b.model, *b.constraints, o);
  const solver::NewtonSummary r = solver.solve(1.0, [&](const solver::IncrementReport& ir) {
    const double residual = ir.residual_norms.empty() ? 0.0 : ir.residual_norms.back();
    out.increments.add_row({double(ir.index), ir.lambda, ir.increment, double(ir.iterations), double(ir.line_searches), residual});
    char row[160];
    std::snprintf(row, sizeof row, "%d,%.10g,%.6g,%d,%d,%.3e\n", ir.index, ir.lambda, ir.increment, ir.iterations, ir.line_searches, residual);
    inc += row;
    write_increments();
    if (pvd && scene.vtu_every > 0 && ir.index % scene.vtu_every == 0) {
      pvd->write_step(ir.lambda, *b.mesh, model::vtu_frame(*b.model));
      written = ir.index;
    }
    if (control.progress) {
      char line[120];
      std::snprintf(line, sizeof line, "increment %d: load factor %.4f, %d iterations", ir.index, ir.lambda, ir.iterations);
      control.progress({ProgressEvent::Kind::increment, line, ir.lambda, ir.lambda});
    }
    return true;
  });
  if (pvd && written != static_cast<int>(r.history.size()) && !r.history.empty())
    pvd->write_step(r.lambda, *b.mesh, model::vtu_frame(*b.model));  // the last converged state
  write_increments();
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.counters = r.counters;
  out.load_factor = r.lambda;
  out.message = r.message;
  out.status = r.converged ? RunStatus::ok : RunStatus::failed;
  if (r.converged) {
    out.value = b.value(*b.model);
    if (b.details) out.details = b.details(*b.model);
  }
  files.write("summary.json", out.to_json().dump(2) + "\n");
  return out;
}

}  // namespace spifit::scene
