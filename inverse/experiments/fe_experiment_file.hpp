#pragma once
// An [[experiment]] of a fit file on an FE scene (indent, indent_line, line, cone, ...): a force
// curve (data, x, y) or a scalar observable of the scene kind (observable, value, window or
// contours). Schema in docs/reference/file-formats.md; errors name the file, key and value.
#include "forward/io/toml_reader.hpp"
#include "inverse/experiments/fe_experiment.hpp"

#include <memory>
#include <string>

namespace spifit::inverse {

// e: the [[experiment]] table of fit file `path`; scene: read from its file (its card is
// replaced by the fit's); noise and weight already read and checked.
std::unique_ptr<Experiment> read_fe_experiment(const io::TomlTable& e, const std::string& path, FeExperimentBase base);

// The keys an FE [[experiment]] may hold.
const std::vector<std::string>& fe_experiment_keys();

}  // namespace spifit::inverse
