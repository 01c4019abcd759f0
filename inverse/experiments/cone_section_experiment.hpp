#pragma once
// A cone's radial section as an FE experiment (docs/reference/file-formats.md "Fit file"; docs/design/cone.md
// "Shape, stage and element observables"): the section a cone run takes after a completed
// contour, the mid-surface height z or the thickness against the current radius r or the initial
// radius r0, compared with measured (r, y) by interpolating the simulated section at the measured
// r, as the sections of forming scenes are (fe_experiment.hpp, SectionSpec). The data may be a
// `spifit scan` section.csv: its columns r [mm], z [mm] and std [mm].
#include "forward/io/toml_reader.hpp"
#include "forward/scenes/common/scene.hpp"
#include "forward/scenes/common/scene_result.hpp"
#include "inverse/experiments/fe_experiment.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::inverse {

struct ConeSectionSpec : FeExperimentBase {
  int contour = 1;               // the section after this contour (1-based, path order over all stages)
  std::string x = "r", y = "z";  // r | r0; z | thickness
  std::vector<double> xs, ys, point_weights;
};
std::unique_ptr<Experiment> make_cone_section_experiment(ConeSectionSpec spec);
bool is_cone_section_abscissa(const std::string& x);
bool is_cone_section_response(const std::string& y);

// y against x of the section after `contour` (1-based, path order), nodes ordered by x; empty when
// the run has not taken it or x does not increase along it (a fold): SceneResult::contour_section.
ForceCurve cone_section_curve(const scene::SceneResult& r, int contour, const std::string& x, const std::string& y);

// section = "last" | "contour K" on a scene with contours (Scene::contours() > 0: its sections
// are radial, taken after each contour, out to its sheet.clamp_radius); e: the [[experiment]] table of fit file
// `path`. data: columns x and y [mm]; noise_column: per-point standard deviations [mm] instead
// of noise or noise_relative. Errors name the file, key and value.
std::unique_ptr<Experiment> read_cone_section_experiment(const io::TomlTable& e, const std::string& path, FeExperimentBase base);

}  // namespace spifit::inverse
