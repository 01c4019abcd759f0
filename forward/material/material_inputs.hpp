#pragma once
// The named parameters of the material law (Hill 1948 + Swift + Armstrong-Frederick or Ziegler,
// material_params.hpp): the names a fit, a sweep and the documentation use ("swift.K"), the key
// of the card file that holds each ("swift.K" = key K of table [swift]; the Armstrong-Frederick
// constants are "af.CX", "af.Xsat" in table [armstrong_frederick]), its unit, the values a card
// accepts one parameter at a time (the Hill convexity is validate_material_card's), and the
// parameters it sets with it (hill.N sets L and M: N = L = M). One table, one switch over the
// fields: material_field() works on any scalar type (Jets for exact derivatives).
#include "forward/io/named_inputs.hpp"
#include "forward/material/material_params.hpp"

#include <string>
#include <vector>

namespace spifit::material {

enum class MaterialField { E, nu, F, G, H, L, M, N, K, eps0, n, CX, Xsat, CA, GA };

struct MaterialInput {
  io::InputInfo info;             // name "swift.K", unit, range, doc
  MaterialField field;
  std::vector<MaterialField> tied;  // set to the same value (hill.N: L, M)
  std::string card_key;           // table.key in the card file
};

// In a fixed order (elastic, Hill, Swift, Armstrong-Frederick, Ziegler).
const std::vector<MaterialInput>& material_inputs();
const MaterialInput* find_material_input(const std::string& name);
// The InputInfo of every parameter (for listings and the documentation).
std::vector<io::InputInfo> material_input_infos();

template <typename T>
T& material_field(MaterialParams<T>& p, MaterialField f) {
  switch (f) {
    case MaterialField::E: return p.E;
    case MaterialField::nu: return p.nu;
    case MaterialField::F: return p.F;
    case MaterialField::G: return p.G;
    case MaterialField::H: return p.H;
    case MaterialField::L: return p.L;
    case MaterialField::M: return p.M;
    case MaterialField::N: return p.N;
    case MaterialField::K: return p.K;
    case MaterialField::eps0: return p.eps0;
    case MaterialField::n: return p.n;
    case MaterialField::CX: return p.CX;
    case MaterialField::Xsat: return p.Xsat;
    case MaterialField::CA: return p.CA;
    case MaterialField::GA: return p.GA;
  }
  return p.E;
}

template <typename T>
const T& material_field(const MaterialParams<T>& p, MaterialField f) {
  return material_field(const_cast<MaterialParams<T>&>(p), f);
}

// Sets a parameter and the ones tied to it.
template <typename T>
void set_material_input(MaterialParams<T>& p, const MaterialInput& in, const T& v) {
  material_field(p, in.field) = v;
  for (MaterialField t : in.tied) material_field(p, t) = v;
}

}  // namespace spifit::material
