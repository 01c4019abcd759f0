#pragma once
// Running a forming scene (indent, indent_line, line) on the FE-run skeleton
// (common/fe_run.hpp): a square sheet (or its half with symmetry conditions on y = 0) clamped
// on its edges, the tool along its path, sections at the named points.
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/forming/forming_result.hpp"
#include "forward/scenes/forming/forming_scene.hpp"

namespace spifit::scene {

// With files: DIR/summary.json, DIR/force.csv (every increment), DIR/energies.csv,
// DIR/sections/section_<P>.csv, DIR/vtu/ and checkpoints. Numerical failure: status "failed"
// with where and why; partial outputs kept. io::InputError for a checkpoint that cannot be
// resumed; std::invalid_argument for a mesh the shell rejects.
FormingResult run_forming_scene(const FormingScene& scene, const RunFiles& files = {}, const RunControl& control = {});

}  // namespace spifit::scene
