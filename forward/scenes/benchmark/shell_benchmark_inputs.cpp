#include "forward/scenes/benchmark/shell_benchmark_inputs.hpp"

#include "forward/scenes/common/scene_inputs.hpp"

namespace spifit::scene {
namespace {

using io::InputType;
using io::Range;

io::InputTable<ShellBenchmarkScene> make_table() {
  io::InputTable<ShellBenchmarkScene> t;
  // The reader handles every key (most are overrides of a benchmark's own default); the table
  // checks their types, ranges and choices.
  add_scene_inputs(t, {"shell_benchmark"}, SceneMaterialKey::none);
  const auto key = [&t](const char* name, InputType type, const char* unit, Range range, const char* doc,
                        std::vector<std::string> choices = {}) { t.custom({name, {}, unit, range, std::move(choices), doc, false}, type); };
  key("scene.benchmark", InputType::text, "", {}, "the benchmark (required)", shell_benchmark_names());
  key("scene.mesh", InputType::integer, "", Range::closed(1, 1000), "elements per side or along the length (default: the benchmark's)");
  key("scene.thickness_points", InputType::integer, "", Range::closed(1, 11), "points through the thickness (default: the benchmark's)");
  key("scene.thickness_rule", InputType::text, "", {}, "through-thickness rule (surface: an odd count from 3)", {"gauss", "surface"});
  key("solver.initial_increment", InputType::real, "", Range{0.0, 1.0, true, false}, "first increment of the load factor");
  key("solver.min_increment", InputType::real, "", Range{0.0, 1.0, true, false}, "smallest increment before the run fails");
  key("solver.max_increment", InputType::real, "", Range{0.0, 1.0, true, false}, "largest increment");
  key("solver.max_iterations", InputType::integer, "", Range::closed(1, 1000), "Newton iterations before a cut-back");
  key("solver.force_tolerance", InputType::real, "", Range{0.0, 1.0, true, false}, "relative residual force of a converged increment");
  key("solver.displacement_tolerance", InputType::real, "", Range{0.0, 1.0, true, false}, "relative last correction of a converged increment");
  key("solver.line_search", InputType::boolean, "", {}, "energy line search");
  key("solver.linear_solver", InputType::text, "", {}, "sparse solver", {"auto", "umfpack", "cholmod"});
  key("output.vtu", InputType::boolean, "", {}, "write vtu/shell.pvd (default true)");
  key("output.vtu_every", InputType::integer, "", Range::non_negative(), "increments between VTU steps (0: the final state only)");
  return t;
}

}  // namespace

const io::InputTable<ShellBenchmarkScene>& shell_benchmark_inputs() {
  static const io::InputTable<ShellBenchmarkScene> table = make_table();
  return table;
}

}  // namespace spifit::scene
