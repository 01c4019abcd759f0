#pragma once
// Checkpoints of a shell model (forward/io/binary_archive.hpp), bit-exact: load factor, nodal
// positions and directors, every element's sections, the work of the nodal loads, and the
// committed state of each contribution (the tool and its copies with their contact point
// states), and in a run with sensitivities the derivatives of that state (FeModel::
// save_sensitivities) in a section of their own. A model is restored into one built the same way (mesh, thickness points, the same
// contributions added); the iterate and trial configurations are reset to the committed one.
namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::model {

class FeModel;

void save_model_state(io::BinaryWriter& w, const FeModel& model);
// io::ArchiveError on any size or layout mismatch (another mesh, other contributions).
void load_model_state(io::BinaryReader& r, FeModel* model);

}  // namespace spifit::model
