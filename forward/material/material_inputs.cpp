#include "forward/material/material_inputs.hpp"

namespace spifit::material {
namespace {

using io::Range;

MaterialInput param(const char* name, MaterialField f, const char* unit, Range range, const char* doc, const char* card_key,
                    std::vector<MaterialField> tied = {}) {
  return {io::InputInfo{name, io::InputType::real, unit, range, {}, doc, true}, f, std::move(tied), card_key};
}

std::vector<MaterialInput> make_inputs() {
  const Range positive = Range::positive(), non_negative = Range::non_negative();
  return {
      param("elastic.E", MaterialField::E, "MPa", positive, "Young's modulus", "elastic.E"),
      param("elastic.nu", MaterialField::nu, "", Range{-1.0, 0.5, true, true}, "Poisson's ratio", "elastic.nu"),
      param("hill.F", MaterialField::F, "", Range::any(), "Hill 1948 F (thesis eq. 3.5, with the factor 1/2)", "hill.F"),
      param("hill.G", MaterialField::G, "", Range::any(), "Hill 1948 G; a fit with G + H = 2 sets H = 2 - G", "hill.G"),
      param("hill.H", MaterialField::H, "", Range::any(), "Hill 1948 H", "hill.H"),
      param("hill.N", MaterialField::N, "", positive, "Hill 1948 N (in-plane shear); sets L and M too (N = L = M)", "hill.N",
            {MaterialField::L, MaterialField::M}),
      param("swift.K", MaterialField::K, "MPa", positive, "Swift sigma_F = K (eps0 + p)^n: strength coefficient (eq. 3.7)", "swift.K"),
      param("swift.eps0", MaterialField::eps0, "", positive, "Swift prestrain eps0", "swift.eps0"),
      param("swift.n", MaterialField::n, "", Range{0.0, 1.0, false, true}, "Swift hardening exponent (0: perfectly plastic)", "swift.n"),
      param("af.CX", MaterialField::CX, "", non_negative, "Armstrong-Frederick rate C_X (eq. 3.8)", "armstrong_frederick.CX"),
      param("af.Xsat", MaterialField::Xsat, "MPa", non_negative, "Armstrong-Frederick saturation X_sat", "armstrong_frederick.Xsat"),
      param("ziegler.CA", MaterialField::CA, "MPa", non_negative, "Ziegler C_A (eq. 3.9)", "ziegler.CA"),
      param("ziegler.GA", MaterialField::GA, "", non_negative, "Ziegler G_A", "ziegler.GA"),
  };
}

}  // namespace

const std::vector<MaterialInput>& material_inputs() {
  static const std::vector<MaterialInput> inputs = make_inputs();
  return inputs;
}

const MaterialInput* find_material_input(const std::string& name) {
  for (const auto& m : material_inputs())
    if (m.info.name == name) return &m;
  return nullptr;
}

std::vector<io::InputInfo> material_input_infos() {
  std::vector<io::InputInfo> out;
  for (const auto& m : material_inputs()) out.push_back(m.info);
  return out;
}

}  // namespace spifit::material
