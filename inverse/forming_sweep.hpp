#pragma once
// Sweeps of the FE forming scenes (indent, indent_line, line): scene keys as inputs (contact
// penalty and friction, tool radius, increments, mesh), force metrics from summary.json and
// force.csv, and sequential runs writing DIR/points/NNN/ (schema: docs/file-formats.md).
#include "forward/io/toml_reader.hpp"
#include "inverse/sweep.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

// Metrics of forming sweeps; the window metrics (mean_*, ripple_fz) need [sweep] window.
const char* forming_metric_names();
bool is_forming_metric(const std::string& name);
bool is_window_metric(const std::string& name);

// Scene keys a forming sweep can vary (besides the material parameters of parameters.hpp).
const char* forming_scene_key_names();
bool is_forming_scene_key(const std::string& name);
bool is_integer_forming_key(const std::string& name);

// The scene's own value of an input (its base point) and the scene with an input set.
double forming_input_value(const scene::FormingScene& s, const std::string& name);
void set_forming_input(scene::FormingScene& s, const std::string& name, double value);

// Why a value cannot be used for an input of this scene, as the scene reader would say it
// (contact::ContactOptions::validate, positive lengths, mesh limits, material card
// validation); empty when it can.
std::string forming_input_error(const scene::FormingScene& base, const std::string& name, double value);

// Checks one [inputs."NAME"] table's values (table: that table; values: as read). Throws
// io::InputError naming the sweep file, inputs.NAME and the value.
void check_forming_input(const io::TomlTable& table, const scene::FormingScene& base, const std::string& name,
                         const std::vector<double>& values);

// Reads [sweep] window = [from_mm, to_mm] (st: the [sweep] table) into setup.window and
// checks that window metrics have a window.
void read_forming_window(const io::TomlTable& st, const std::vector<std::string>& metrics, FormingSweepSetup& setup);

// Metrics of one finished run: from its summary (peak/final force, penetration, counts) and
// DIR/force.csv (window metrics; travel = time x feed). NaN where unavailable.
std::vector<double> forming_metrics(const nlohmann::json& summary, const std::string& force_csv, const FormingSweepSetup& setup,
                                    const std::vector<std::string>& metrics);

// Runs every grid point one after another (DIR/points/NNN/), then the sensitivity runs
// (DIR/sensitivities/base, NAME_up, NAME_down) when spec.sensitivities.
SweepResult run_forming_sweep(const SweepSpec& spec, const io::OutputDirectory& out, bool progress);

}  // namespace spifit::inverse
