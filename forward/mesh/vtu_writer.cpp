#include "forward/mesh/vtu_writer.hpp"

#include "forward/io/atomic_file.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace spifit::mesh {

namespace {
void append_numbers(std::ostringstream& os, const std::vector<double>& v) {
  char buf[32];
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.17g", v[i]);
    os << (i % 6 == 0 ? "\n          " : " ") << buf;
  }
  os << "\n";
}
void append_fields(std::ostringstream& os, const std::vector<VtuField>& fields, std::size_t count, const char* where) {
  for (const auto& f : fields) {
    if (f.components != 1 && f.components != 3) throw std::invalid_argument("VTU field " + f.name + ": 1 or 3 components");
    if (f.values.size() != count * f.components)
      throw std::invalid_argument(std::string("VTU ") + where + " field " + f.name + " has " + std::to_string(f.values.size()) +
                                  " values, expected " + std::to_string(count * f.components));
    os << "        <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\"" << f.components
       << "\" format=\"ascii\">";
    append_numbers(os, f.values);
    os << "        </DataArray>\n";
  }
}
}  // namespace

std::string vtu_text(const Mesh& m, const VtuFrame& frame) {
  const auto& pts = frame.points.empty() ? m.nodes : frame.points;
  if (pts.size() != m.nodes.size()) throw std::invalid_argument("VTU: point count differs from the mesh");
  const std::size_t cells = m.quads.size() + m.hexes.size();
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << pts.size() << "\" NumberOfCells=\"" << cells << "\">\n";
  os << "      <PointData>\n";
  append_fields(os, frame.point_data, pts.size(), "point");
  os << "      </PointData>\n      <CellData>\n";
  append_fields(os, frame.cell_data, cells, "cell");
  os << "      </CellData>\n      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">";
  std::vector<double> xyz;
  for (const auto& p : pts) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  append_numbers(os, xyz);
  os << "        </DataArray>\n      </Points>\n      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
  for (const auto& q : m.quads) os << " " << q[0] << " " << q[1] << " " << q[2] << " " << q[3];
  for (const auto& h : m.hexes)
    for (int v : h) os << " " << v;
  os << "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for (std::size_t e = 0; e < m.quads.size(); ++e) os << " " << 4 * (e + 1);
  for (std::size_t e = 0; e < m.hexes.size(); ++e) os << " " << 4 * m.quads.size() + 8 * (e + 1);
  os << "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n         ";
  for (std::size_t e = 0; e < m.quads.size(); ++e) os << " 9";   // VTK_QUAD
  for (std::size_t e = 0; e < m.hexes.size(); ++e) os << " 12";  // VTK_HEXAHEDRON
  os << "\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return os.str();
}

PvdCollection::PvdCollection(std::filesystem::path dir, std::string stem) : dir_(std::move(dir)), stem_(std::move(stem)) {}

void PvdCollection::write_step(double time, const Mesh& m, const VtuFrame& frame) {
  char name[64];
  std::snprintf(name, sizeof name, "_%06d.vtu", static_cast<int>(entries_.size()));
  const std::string file = stem_ + name;
  io::write_file_atomic(dir_ / file, vtu_text(m, frame));
  entries_.emplace_back(time, file);
  write_collection();
}

void PvdCollection::restore(std::vector<std::pair<double, std::string>> entries) {
  entries_ = std::move(entries);
  write_collection();
}

void PvdCollection::write_collection() const {
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  char t[32];
  for (const auto& [tm, f] : entries_) {
    std::snprintf(t, sizeof t, "%.17g", tm);
    os << "    <DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << f << "\"/>\n";
  }
  os << "  </Collection>\n</VTKFile>\n";
  io::write_file_atomic(dir_ / (stem_ + ".pvd"), os.str());
}

}  // namespace spifit::mesh
