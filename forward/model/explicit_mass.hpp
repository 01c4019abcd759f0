#pragma once
// The mass and the stable time step of a shell model for the explicit scheme
// (docs/design/explicit.md): Jetteur's diagonal mass matrix (thesis §6.2.3, eqs. 6.61-6.62: a
// node's share of the element mass on its translations, c times that on its rotations,
// c = max(t^2/12, S/18)), scaled as solver::ExplicitOptions says (global, rotational and
// selective mass scaling), and the stable step of every element from its largest frequency:
// the eigenvalue of its elastic tangent over its lumped mass (drilling rotations left out, they
// carry no force), plus the contact's penalty stiffness. By Irons' bound no frequency of the
// assembled model exceeds the largest element frequency, so safety x the smallest element step
// is stable.
#include "forward/solver/explicit_options.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::model {

class ShellModel;
class BulkViscosity;

struct ExplicitMassInputs {
  double density = 2.7e-9;           // t/mm^3
  double contact_stiffness = 0.0;    // largest contact penalty [N/mm^3] (0: no contact)
  solver::ExplicitOptions options;
};

struct ExplicitMass {
  Eigen::VectorXd diagonal;                 // per DOF of the model: translational mass [t], rotational inertia [t mm^2]
  std::vector<double> element_step;         // stable step of each element with its scaling (and the bulk viscosity's linear damping) [s]
  std::vector<double> element_length;       // each element's characteristic length at start-up (the recheck's reference) [mm]
  std::vector<double> element_factor;       // density factor of each element (mass_scaling, or more where selective)
  double time_step = 0.0;                   // safety x the smallest element_step [s]
  int smallest_element = 0;                 // the element with the smallest step
  double smallest_unscaled_step = 0.0;      // its step at the physical density [s]
  double mass = 0.0, added_mass = 0.0;      // physical sheet mass and the mass scaling added [t]
  int scaled_elements = 0;                  // elements that selective scaling touched
};

// At the model's committed state (evaluates every element's tangent there). Throws
// std::invalid_argument for a density <= 0 or invalid options.
ExplicitMass explicit_mass(ShellModel& model, const ExplicitMassInputs& inputs);

// Characteristic length of element e at the committed state: its area over its longer diagonal.
double element_length(const ShellModel& model, int e);

// The stable step now: each element's start-up step scaled by how its characteristic length
// changed since (thinning and shear shorten it) and, with a bulk viscosity, by its compression
// fraction at the last rates, times the safety factor.
double current_time_step(const ShellModel& model, const ExplicitMass& mass, double safety, const BulkViscosity* viscosity = nullptr);

// Checkpoints of an explicit run, bit-exact: a resumed run keeps the mass and the element steps
// and lengths of its start, not those of the deformed geometry it resumes from (which would
// change every step and the phase of the time step's re-estimates).
void save_explicit_mass(io::BinaryWriter& w, const ExplicitMass& mass);
// io::ArchiveError when the sizes do not fit a model of num_dofs DOFs and num_elements elements.
ExplicitMass load_explicit_mass(io::BinaryReader& r, int num_dofs, int num_elements);

// "element E (centre x, y, z), l = L mm" for messages.
std::string describe_element(const ShellModel& model, int e);

}  // namespace spifit::model
