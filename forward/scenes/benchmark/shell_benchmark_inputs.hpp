#pragma once
// The keys of a shell benchmark scene file (io/named_inputs.hpp), for the reader's key checks and
// the key reference: the benchmark, its mesh and thickness rule, overrides of the benchmark's
// solver defaults, and the VTU output. A benchmark brings its own material and geometry, so none
// of its keys is varied by sweeps.
#include "forward/io/named_inputs.hpp"
#include "forward/scenes/benchmark/shell_benchmark_scene.hpp"

namespace spifit::scene {

const io::InputTable<ShellBenchmarkScene>& shell_benchmark_inputs();

}  // namespace spifit::scene
