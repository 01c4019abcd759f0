#include "forward/scenes/common/scene.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_inputs.hpp"

#include <stdexcept>

namespace spifit::scene {

double Scene::input(const std::string& name) const {
  if (has_own_input(name)) return own_input(name);
  const auto* m = material::find_material_input(name);
  if (m && card()) {
    if (const std::string why = material::why_not_held(card()->params, *m); !why.empty()) throw std::invalid_argument(why);
    return material::material_field(card()->params, m->field);
  }
  throw std::invalid_argument("unknown input " + name + " of scene kind " + kind());
}

std::string Scene::set_input(const std::string& name, double value) {
  if (has_own_input(name)) {
    const double before = own_input(name);
    if (std::string why = set_own_input(name, value); !why.empty()) return why;
    if (std::string why = check_inputs(); !why.empty()) {
      set_own_input(name, before);
      return why;
    }
    return {};
  }
  const material::MaterialInput* m = material::find_material_input(name);
  if (!m || !card()) throw std::invalid_argument("unknown input " + name + " of scene kind " + kind());
  if (std::string why = m->info.check(value); !why.empty()) return why;
  if (std::string why = material::why_not_held(card()->params, *m); !why.empty()) return why;
  material::MaterialCard c = *card();
  material::set_material_input(c.params, *m, value);
  try {
    material::validate_material_card(c);
  } catch (const io::InputError& e) {
    return "invalid card " + c.name + ": " + e.key() + (e.value().empty() ? "" : " = " + e.value()) + ": " + e.message();
  }
  *card() = std::move(c);
  return {};
}

const Observable* SceneKind::find_observable(const std::string& observable) const {
  for (const auto& o : observables)
    if (o.name == observable) return &o;
  return nullptr;
}

}  // namespace spifit::scene
