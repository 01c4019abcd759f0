#pragma once
// The part of summary.json every FE run shares: increments, Newton iterations, cut-backs,
// factorisations, the time split, stabilised increments, the travel reached, the tool's peak and
// final force and penetration, the energy account, the marks and checkpoints.
#include "forward/model/model_energies.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/force_ripple.hpp"
#include "forward/scenes/common/tool_force_history.hpp"

#include <nlohmann/json.hpp>

namespace spifit::scene {

nlohmann::json vector_json(const Eigen::Vector3d& v);

// energies_units: e.g. "N mm (= mJ), the modelled pie only".
void add_fe_run_summary(nlohmann::json& j, const FeRunOutcome& run, const ToolForceHistory& force, const ForceRipple& ripple,
                        const model::ModelEnergies& energies, const std::string& energies_units);

}  // namespace spifit::scene
