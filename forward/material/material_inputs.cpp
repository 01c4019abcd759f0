#include "forward/material/material_inputs.hpp"

#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"

namespace spifit::material {
namespace {

using io::Range;

MaterialInput param(const char* name, MaterialField f, const char* unit, Range range, const char* doc, const char* card_key,
                    std::vector<MaterialField> tied = {}) {
  return {io::InputInfo{name, io::InputType::real, unit, range, {}, doc, true}, f, std::move(tied), card_key};
}

MaterialField field(MaterialField::Kind k) { return MaterialField{k}; }

std::vector<MaterialInput> make_inputs() {
  const Range positive = Range::positive();
  std::vector<MaterialInput> out{
      param("elastic.E", field(MaterialField::E), "MPa", positive, "Young's modulus", "elastic.E"),
      param("elastic.nu", field(MaterialField::nu), "", Range{-1.0, 0.5, true, true}, "Poisson's ratio", "elastic.nu"),
      param("hill.F", field(MaterialField::F), "", Range::any(), "Hill 1948 F (thesis eq. 3.5, with the factor 1/2)", "hill.F"),
      param("hill.G", field(MaterialField::G), "", Range::any(), "Hill 1948 G; a fit with G + H = 2 sets H = 2 - G", "hill.G"),
      param("hill.H", field(MaterialField::H), "", Range::any(), "Hill 1948 H", "hill.H"),
      param("hill.N", field(MaterialField::N), "", positive, "Hill 1948 N (in-plane shear); sets L and M too (N = L = M)", "hill.N",
            {field(MaterialField::L), field(MaterialField::M)}),
  };
  for (const YieldFunctionInfo& law : yield_functions()) {
    for (int i = 0; i < static_cast<int>(law.coefficients.size()); ++i) {
      const LawCoefficient& c = law.coefficients[static_cast<std::size_t>(i)];
      const std::string name = law.name + "." + c.key;
      out.push_back({io::InputInfo{name, io::InputType::real, c.unit, c.range, {}, c.doc, true}, MaterialField{MaterialField::yield, law.id, i}, {}, name});
    }
  }
  for (const HardeningLawInfo& law : hardening_laws()) {
    for (int i = 0; i < static_cast<int>(law.coefficients.size()); ++i) {
      const HardeningCoefficient& c = law.coefficients[static_cast<std::size_t>(i)];
      const std::string name = law.name + "." + c.key;
      out.push_back({io::InputInfo{name, io::InputType::real, c.unit, c.range, {}, c.doc, true}, MaterialField{MaterialField::hardening, law.id, i}, {}, name});
    }
  }
  for (const KinematicLawInfo& law : kinematic_laws()) {
    for (int i = 0; i < static_cast<int>(law.coefficients.size()); ++i) {
      const LawCoefficient& c = law.coefficients[static_cast<std::size_t>(i)];
      out.push_back({io::InputInfo{law.input_prefix + "." + c.key, io::InputType::real, c.unit, c.range, {}, c.doc, true},
                     MaterialField{MaterialField::kinematic, law.id, i}, {}, law.name + "." + c.key});
    }
  }
  return out;
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

bool input_in_use(const MaterialParams<double>& p, const MaterialInput& in) {
  switch (in.field.kind) {
    case MaterialField::hardening: return p.plastic && holds_input(p, in);
    case MaterialField::kinematic: return holds_input(p, in);
    default: return holds_input(p, in);
  }
}

std::string why_not_held(const MaterialParams<double>& p, const MaterialInput& in) {
  if (holds_input(p, in)) return {};
  auto names_of = [](const std::string& prefix, const std::vector<LawCoefficient>& cs) {
    std::string names;
    for (const auto& c : cs) names += (names.empty() ? "" : ", ") + prefix + "." + c.key;
    return names;
  };
  if (in.field.kind == MaterialField::yield) {
    if (!p.yield.active()) return in.info.name + " is not a parameter of this card: its yield function is Hill 1948 (hill.F, hill.G, hill.H, hill.N)";
    const YieldFunctionInfo& law = yield_function(p.yield.law);
    return in.info.name + " is not a parameter of this card: its yield function is " + law.name + " (" + names_of(law.name, law.coefficients) + ")";
  }
  if (in.field.kind != MaterialField::hardening && in.field.kind != MaterialField::kinematic) {  // Hill's, on a card with another function
    const YieldFunctionInfo& law = yield_function(p.yield.law);
    return in.info.name + " is not a parameter of this card: its yield function is " + law.name + " (" + names_of(law.name, law.coefficients) + ")";
  }
  if (in.field.kind == MaterialField::kinematic) {
    if (!p.kinematic.active()) return in.info.name + " is not a parameter of this card: it has no kinematic hardening (" + kinematic_table_list() + ")";
    const KinematicLawInfo& law = kinematic_law(p.kinematic.law);
    std::string names;
    for (const auto& c : law.coefficients) names += (names.empty() ? "" : ", ") + law.input_prefix + "." + c.key;
    return in.info.name + " is not a parameter of this card: its kinematic law is " + law.name + " (" + names + ")";
  }
  const HardeningLawInfo& law = hardening_law(p.hardening.law);
  std::string names;
  for (const auto& c : law.coefficients) names += (names.empty() ? "" : ", ") + law.name + "." + c.key;
  return in.info.name + " is not a parameter of this card: its hardening law is " + law.name + " (" + names + ")";
}

std::vector<io::InputInfo> material_input_infos() {
  std::vector<io::InputInfo> out;
  for (const auto& m : material_inputs()) out.push_back(m.info);
  return out;
}

}  // namespace spifit::material
