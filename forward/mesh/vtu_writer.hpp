#pragma once
// ParaView output: an unstructured grid of quads and hexahedra in VTK XML (.vtu, ASCII, Float64)
// with point and cell data arrays, and a .pvd collection listing the steps with their times.
// Files are written atomically.
#include "forward/mesh/mesh.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::mesh {

struct VtuField {
  std::string name;
  int components = 1;           // 1 (scalar) or 3 (vector)
  std::vector<double> values;   // size = components x (nodes or cells)
};

struct VtuFrame {
  std::vector<Eigen::Vector3d> points;  // current coordinates (defaults to the mesh nodes)
  std::vector<VtuField> point_data, cell_data;
};

// The VTU text; throws std::invalid_argument when an array has the wrong size.
std::string vtu_text(const Mesh& m, const VtuFrame& frame);

class PvdCollection {
 public:
  // Steps go to DIR/STEM_NNNNNN.vtu; the collection to DIR/STEM.pvd (rewritten at every step,
  // so a killed run leaves a valid collection of the steps written so far).
  PvdCollection(std::filesystem::path dir, std::string stem);
  void write_step(double time, const Mesh& m, const VtuFrame& frame);
  int steps() const { return static_cast<int>(entries_.size()); }
  // Steps written so far (time, file name in DIR); restore() continues a collection from them
  // (a resumed run): the .pvd is rewritten to list exactly them, the next step gets the next
  // number.
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }
  void restore(std::vector<std::pair<double, std::string>> entries);

 private:
  std::filesystem::path dir_;
  std::string stem_;
  std::vector<std::pair<double, std::string>> entries_;
  void write_collection() const;
};

}  // namespace spifit::mesh
