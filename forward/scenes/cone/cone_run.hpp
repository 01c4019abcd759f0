#pragma once
// Running a cone scene (cone_scene.hpp) on the FE-run skeleton (common/fe_run.hpp): the disc or
// pie clamped at its rim, the cyclic ties and virtual tools of a pie, the contour path as the
// load, the marks at the ends of the contours.
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/cone/cone_result.hpp"
#include "forward/scenes/cone/cone_scene.hpp"

namespace spifit::scene {

// With files: DIR/summary.json, DIR/force.csv, DIR/contours.csv, DIR/energies.csv,
// DIR/sections/, sections.csv, stages.csv, history.csv, DIR/vtu/ and the checkpoints.
// Numerical failure: status "failed" with where and why; partial outputs kept. io::InputError
// for a checkpoint that cannot be resumed.
ConeResult run_cone_scene(const ConeScene& scene, const RunFiles& files = {}, const RunControl& control = {});

}  // namespace spifit::scene
