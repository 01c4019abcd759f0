#pragma once
// The named parameters of the material law (Hill 1948 + a hardening law of the registry +
// Armstrong-Frederick or Ziegler, material_params.hpp): the names a fit, a sweep and the
// documentation use ("swift.K"), the key of the card file that holds each ("swift.K" = key K of
// table [swift]; the Armstrong-Frederick constants are "af.CX", "af.Xsat" in table
// [armstrong_frederick]), its unit, the values a card accepts one parameter at a time (the Hill
// convexity is validate_material_card's), and the parameters it sets with it (hill.N sets L and M:
// N = L = M). The hardening laws' coefficients come from their registry
// (hardening/hardening_laws.hpp). material_field() works on any scalar type (Jets for exact
// derivatives).
#include "forward/io/named_inputs.hpp"
#include "forward/material/material_params.hpp"

#include <stdexcept>

#include <string>
#include <vector>

namespace spifit::material {

// A parameter's place in MaterialParams: a named field, or coefficient `slot` of hardening or
// kinematic law `law` (which must be the card's).
struct MaterialField {
  enum Kind : unsigned char { E, nu, F, G, H, L, M, N, hardening, kinematic, yield };
  Kind kind = E;
  int law = -1;  // hardening, kinematic, yield: the law's index in HardeningLawList, KinematicLawList, YieldFunctionList
  int slot = 0;  // hardening, kinematic: the coefficient's index in the law
};

struct MaterialInput {
  io::InputInfo info;             // name "swift.K", unit, range, doc
  MaterialField field;
  std::vector<MaterialField> tied;  // set to the same value (hill.N: L, M)
  std::string card_key;           // table.key in the card file
};

// In a fixed order: elastic, Hill, each registered yield function (Yld2000-2d), each hardening law in registry order (Swift first),
// Armstrong-Frederick, Ziegler.
const std::vector<MaterialInput>& material_inputs();
const MaterialInput* find_material_input(const std::string& name);
// The InputInfo of every parameter (for listings and the documentation).
std::vector<io::InputInfo> material_input_infos();

// Whether p holds a value for the input: elastic always, Hill when p has no registered yield
// function, a law's coefficients when it is p's yield function, hardening or kinematic law.
template <typename T>
bool holds_input(const MaterialParams<T>& p, const MaterialInput& in) {
  switch (in.field.kind) {
    case MaterialField::hardening: return in.field.law == p.hardening.law;
    case MaterialField::kinematic: return in.field.law == p.kinematic.law;
    case MaterialField::yield: return in.field.law == p.yield.law;
    case MaterialField::E:
    case MaterialField::nu: return true;
    default: return !p.yield.active();
  }
}
// Whether the card's laws use the input: holds_input, an elastic card no hardening coefficient,
// and only the kinematic law in use its constants.
bool input_in_use(const MaterialParams<double>& p, const MaterialInput& in);
// Why p cannot take a value of the input ("swift.K is not a parameter of this card: its hardening
// law is voce (voce.sigma0, voce.Q, voce.b)", "af.CX ...: it has no kinematic hardening"); empty
// when it can.
std::string why_not_held(const MaterialParams<double>& p, const MaterialInput& in);

template <typename T>
T& material_field(MaterialParams<T>& p, MaterialField f) {
  switch (f.kind) {
    case MaterialField::E: return p.E;
    case MaterialField::nu: return p.nu;
    case MaterialField::F: return p.F;
    case MaterialField::G: return p.G;
    case MaterialField::H: return p.H;
    case MaterialField::L: return p.L;
    case MaterialField::M: return p.M;
    case MaterialField::N: return p.N;
    case MaterialField::hardening:
      if (f.law != p.hardening.law) throw std::logic_error("a coefficient of another hardening law than the card's");
      return p.hardening[f.slot];
    case MaterialField::kinematic:
      if (f.law != p.kinematic.law) throw std::logic_error("a coefficient of another kinematic law than the card's");
      return p.kinematic[f.slot];
    case MaterialField::yield:
      if (f.law != p.yield.law) throw std::logic_error("a coefficient of another yield function than the card's");
      return p.yield[f.slot];
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
