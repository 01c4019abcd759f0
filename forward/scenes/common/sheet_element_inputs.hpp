#pragma once
// The sheet's element family in a tool scene ([sheet] element, layers, hourglass_scale): the
// named inputs, the checks of the keys and options one family alone has, and what the reader
// settles after reading (the bricks' default layers). Declared on any scene struct with the
// members they name (forming_scene.hpp, cone_scene.hpp: element, layers, hourglass_scale,
// hourglass_stiffness, explicit_scheme, contact, card); docs/design/numerics-solid.md.
#include "forward/io/input_error.hpp"
#include "forward/io/named_inputs.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/material/material_card.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/model/sheet_model.hpp"
#include "forward/scenes/common/scene_tables.hpp"

#include <algorithm>
#include <string>

namespace spifit::scene {

// Bricks through the thickness when a brick sheet does not say (the thesis's brick simulations).
inline constexpr int kDefaultBrickLayers = 3;

template <typename Scene>
void add_sheet_element_inputs(io::InputTable<Scene>& t) {
  using io::Range;
  t.text({"sheet.element", {}, "", {}, model::sheet_element_names(),
          "the sheet's elements: shells on its mid-surface, one-point bricks in sheet.layers layers through the thickness, "
          "or solid-shells (one through the thickness, sheet.thickness_points along it)", false},
         {[](const Scene& s) -> std::string { return s.element; },
          [](Scene& s, const std::string& v) {
            const auto& names = model::sheet_element_names();
            if (std::find(names.begin(), names.end(), v) == names.end()) return false;
            s.element = v;
            return true;
          }});
  t.integer({"sheet.layers", {}, "", Range::closed(1, 16), {},
             "bricks through the thickness (sheet.element = \"brick\"; default 3, as the thesis's brick simulations)", false},
            [](Scene& s) -> int& { return s.layers; });
  t.real({"sheet.hourglass_scale", {}, "", Range::closed(0.0, 10.0), {},
          "bricks: factor on the hourglass stabilisation's stiffness (1: the incompatible-modes element's, on the centre's tangent)", true},
         [](Scene& s) -> double& { return s.hourglass_scale; });
}

// After the tables are read: a brick sheet has layers (kDefaultBrickLayers unless given), not
// thickness points (io::InputError naming the file and key).
template <typename Scene>
void settle_sheet_element(const io::TomlTable& root, const std::string& path, Scene& s) {
  if (s.element != "brick") return;
  const auto sheet = root.table("sheet");
  if (sheet && sheet->has("thickness_points"))
    throw io::InputError(path, "sheet.thickness_points", std::to_string(s.thickness_points),
                         "integration points through the thickness of shells and solid-shells; a brick sheet has sheet.layers instead");
  if (s.layers == 0) s.layers = kDefaultBrickLayers;
}

// The keys and options one family alone has, and a law the solids cannot take; none: empty.
template <typename Scene>
InputViolation solid_sheet_violation(const Scene& s) {
  if (s.element != "brick") {
    if (s.layers != 0)
      return {"sheet.layers", std::to_string(s.layers),
              s.element == "shell" ? "layers are for brick sheets: set sheet.element = \"brick\" or remove it"
                                   : "a solid-shell sheet has one element through the thickness (its points along it are sheet.thickness_points): remove it"};
    if (s.hourglass_scale != 1.0)
      return {"sheet.hourglass_scale", io::format_number(s.hourglass_scale),
              s.element == "shell" ? "the bricks' stabilisation factor; the shell's one-point option is sheet.hourglass_stiffness"
                                   : "the bricks' stabilisation factor; the solid-shell has no hourglass modes: remove it"};
  }
  if (s.element == "shell") return {};
  const std::string quoted = "\"" + s.element + "\"";
  if (s.hourglass_stiffness > 0.0)
    return {"sheet.hourglass_stiffness", io::format_number(s.hourglass_stiffness),
            "the shell's one-point option; the " + s.element + " has its own integration: remove it with sheet.element = " + quoted};
  if (s.explicit_scheme) return {"solver.scheme", "\"explicit\"", "the explicit scheme has shell elements only, not " + s.element + " elements"};
  if (s.contact.surface == contact::ContactOptions::Surface::phong)
    return {"contact.surface", "\"phong\"", "phong curves the facets with the shell's directors; solid elements take \"flat\""};
  if (s.card.params.yield.active())
    return {"sheet.element", quoted, "the material card " + s.card.file + " has a plane-stress yield function (" +
                                         material::yield_function_title(s.card.params.yield.law) + "); solid elements need a 3D law (Hill 1948)"};
  return {};
}

}  // namespace spifit::scene
