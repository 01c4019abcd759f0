#include "forward/model/brick_family.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/mesh/vtu_writer.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/material_axes.hpp"
#include "forward/model/model_energies.hpp"

#include <cmath>
#include <stdexcept>

namespace spifit::model {

namespace {
element::HexCorners corners(const mesh::Hex& h, const std::vector<Eigen::Vector3d>& xs) {
  element::HexCorners x;
  for (std::size_t I = 0; I < 8; ++I) x[I] = xs[static_cast<std::size_t>(h[I])];
  return x;
}
}  // namespace

BrickFamily::BrickFamily(const mesh::Mesh& mesh, const material::MaterialParams<double>& material, const BrickOptions& options)
    : mesh_(&mesh), law_(material), layers_(options.layers) {
  if (!mesh.quads.empty()) throw std::invalid_argument("the brick needs a mesh of hexahedra; this one has " + std::to_string(mesh.quads.size()) + " quadrilaterals");
  const int ne = static_cast<int>(mesh.hexes.size());
  if (ne == 0) throw std::invalid_argument("the mesh has no hexahedron");
  if (options.layers < 1) throw std::invalid_argument("a brick sheet needs at least one layer, got " + std::to_string(options.layers));
  if (ne % options.layers != 0)
    throw std::invalid_argument(std::to_string(ne) + " hexahedra are not " + std::to_string(options.layers) + " equal layers");
  if (!(options.material_axis.allFinite() && options.material_axis.norm() > 0.0)) throw std::invalid_argument("the rolling direction must be a non-zero vector");
  elements_.reserve(static_cast<std::size_t>(ne));
  height0_.reserve(static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    const mesh::Hex& h = mesh.hexes[static_cast<std::size_t>(e)];
    for (int i : h)
      if (i < 0 || i >= mesh.num_nodes()) throw std::invalid_argument("element " + std::to_string(e) + " refers to node " + std::to_string(i) + " out of range");
    const element::HexCorners X = corners(h, mesh.nodes);
    Eigen::Vector3d bottom = Eigen::Vector3d::Zero(), top = Eigen::Vector3d::Zero();
    for (std::size_t I = 0; I < 4; ++I) {
      bottom += 0.25 * X[I];
      top += 0.25 * X[I + 4];
    }
    const double height = (top - bottom).norm();
    if (!(height > 0.0)) throw std::invalid_argument("element " + std::to_string(e) + " has no height between its bottom and top faces");
    const Eigen::Vector3d n = (top - bottom) / height;
    const Eigen::Vector3d a = options.material_axes == ShellModelOptions::MaterialAxes::polar
                                  ? polar_material_axis(0.5 * (bottom + top), options.material_axis)
                                  : Eigen::Vector3d(options.material_axis);
    const Eigen::Vector3d in_plane = a - a.dot(n) * n;
    if (!(in_plane.norm() > 1e-6 * a.norm()))
      throw std::invalid_argument("element " + std::to_string(e) + ": the rolling direction lies along the sheet normal");
    Eigen::Matrix3d axes;
    axes.col(0) = in_plane.normalized();
    axes.col(1) = n.cross(axes.col(0));
    axes.col(2) = n;
    try {
      elements_.emplace_back(X, axes, law_, options.hourglass);
    } catch (const std::invalid_argument& err) {
      throw std::invalid_argument("element " + std::to_string(e) + ": " + err.what());
    }
    height0_.push_back(height);
  }
}

std::vector<int> BrickFamily::element_nodes(int e) const {
  const mesh::Hex& h = mesh_->hexes[static_cast<std::size_t>(e)];
  return {h.begin(), h.end()};
}

solver::ElementEvaluation BrickFamily::evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) {
  element::HexVector f;
  element::HexMatrix k;
  const element::BrickStatus s = elements_[static_cast<std::size_t>(e)].evaluate(corners(mesh_->hexes[static_cast<std::size_t>(e)], in.x), &f, ke ? &k : nullptr);
  solver::ElementEvaluation out;
  if (!s.ok) {
    out.ok = false;
    out.reason = s.reason;
    out.suggested_scale = s.suggested_scale;
    out.where = "brick element " + std::to_string(e);
    return out;
  }
  *re = f;
  if (ke) *ke = k;
  return out;
}

void BrickFamily::commit() {
  for (auto& el : elements_) el.commit();
}

void BrickFamily::revert() {
  for (auto& el : elements_) el.revert();
}

double BrickFamily::element_thickness(int e) const {
  const int per_layer = num_elements() / layers_;
  const int q = e % per_layer;
  double h = 0.0;
  for (int l = 0; l < layers_; ++l) {
    const auto k = static_cast<std::size_t>(l * per_layer + q);
    h += height0_[k] * elements_[k].thickness_ratio();
  }
  return h;
}

void BrickFamily::add_energies(const FeModel&, ModelEnergies* energies) const {
  for (const auto& el : elements_) {
    energies->elastic += el.reference_volume() * el.point().elastic_energy_density() + el.hourglass_energy();
    energies->plastic += el.reference_volume() * el.point().plastic_work_density();
  }
}

void BrickFamily::add_vtu_data(const FeModel&, mesh::VtuFrame* frame) const {
  mesh::VtuField eqps{"eqps", 1, {}}, thickness{"thickness", 1, {}};
  mesh::VtuField s11{"stress_11", 1, {}}, s22{"stress_22", 1, {}}, s33{"stress_33", 1, {}};
  for (int e = 0; e < num_elements(); ++e) {
    const auto& st = elements_[static_cast<std::size_t>(e)].point().committed();
    eqps.values.push_back(st.eqps);
    thickness.values.push_back(element_thickness(e));
    s11.values.push_back(st.stress(0));
    s22.values.push_back(st.stress(1));
    s33.values.push_back(st.stress(2));
  }
  for (auto* f : {&eqps, &thickness, &s11, &s22, &s33}) frame->cell_data.push_back(std::move(*f));
}

void BrickFamily::save_state(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(elements_.size()));
  for (const auto& el : elements_) el.save_state(w);
}

void BrickFamily::load_state(io::BinaryReader& r) {
  r.expect_count("brick elements", static_cast<std::int64_t>(elements_.size()));
  for (auto& el : elements_) el.load_state(r);
}

}  // namespace spifit::model
