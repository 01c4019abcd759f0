#include "forward/scenes/common/failure_words.hpp"

namespace spifit::scene {
namespace {

struct Cause {
  const char* marker;  // a phrase of the solver's message
  const char* words;   // what it means for the sheet, and what to change
};

// First match wins: the element-level causes before the iteration-level ones they lead to.
const Cause kCauses[] = {
    {"non-positive metric",
     "an element was turned inside out where the tool pushes (stretched or sheared beyond what its shape can take): take smaller "
     "increments (solver.travel_per_increment), a finer mesh under the tool, or more contact points (contact.points)"},
    {"non-finite strain", "the sheet's deformation ran away under the tool: take smaller increments (solver.travel_per_increment)"},
    {"non-finite element forces", "the sheet's deformation ran away under the tool: take smaller increments (solver.travel_per_increment)"},
    {"trial stress", "the material law was handed a strain step it cannot hold (the sheet ran away): take smaller increments"},
    {"return mapping", "the material law could not follow a strain step this large: take smaller increments (solver.travel_per_increment)"},
    {"invalid state", "the material law could not follow a strain step this large: take smaller increments (solver.travel_per_increment)"},
    {"linear solver",
     "the sheet lost its stiffness and could move without resistance (a support missing, or an element that gave way): check the "
     "clamping and the mesh, or take smaller increments"},
    {"diverg",
     "the sheet's equilibrium could not be found after the tool's step (the step changed the contact or the plastic zone too much): "
     "take smaller increments (solver.travel_per_increment), or allow more iterations (solver.max_iterations)"},
    {"no convergence in",
     "the sheet's equilibrium was not reached within the allowed iterations: allow more (solver.max_iterations) or take smaller "
     "increments (solver.travel_per_increment)"},
    {"unstable", "the explicit scheme became unstable: a smaller solver.time_step_safety, or more mass scaling"},
};

}  // namespace

std::string failure_in_words(const std::string& solver) {
  for (const Cause& c : kCauses)
    if (solver.find(c.marker) != std::string::npos) return std::string(c.words) + " (solver: " + solver + ")";
  return solver;
}

}  // namespace spifit::scene
