#include "forward/model/sheet_model.hpp"

#include "forward/mesh/extruded_sheet.hpp"
#include "forward/model/solid_family.hpp"
#include "forward/model/shell_model.hpp"

#include <stdexcept>

namespace spifit::model {

const std::vector<std::string>& sheet_element_names() {
  static const std::vector<std::string> names = {"shell", "brick", "solid_shell"};
  return names;
}

std::unique_ptr<FeModel> make_sheet_model(const mesh::Mesh& mid, double thickness, const material::MaterialParams<double>& material,
                                          const SheetModelSpec& spec, mesh::Mesh* solid) {
  if (spec.element == "shell") return std::make_unique<ShellModel>(mid, thickness, material, spec.shell);
  if (spec.element == "brick" || spec.element == "solid_shell") {
    const bool brick = spec.element == "brick";
    const int layers = brick ? spec.layers : 1;
    if (layers < 1) throw std::invalid_argument("a brick sheet needs at least one layer, got " + std::to_string(layers));
    if (!(thickness > 0.0)) throw std::invalid_argument("thickness must be > 0, got " + std::to_string(thickness));
    *solid = mesh::extrude_sheet(mid, thickness, layers);
    SolidOptions options;
    options.element = brick ? SolidElementKind::brick : SolidElementKind::solid_shell;
    options.material_axis = spec.shell.shell.material_axis;
    options.material_axes = spec.shell.material_axes;
    options.hourglass = spec.hourglass;
    options.enhanced_tolerance = spec.enhanced_tolerance;
    options.thickness_rule = element::make_thickness_rule(spec.shell.shell.thickness_rule, spec.shell.shell.thickness_points);
    options.layers = layers;
    return std::make_unique<FeModel>(*solid, std::make_unique<SolidFamily>(*solid, material, options));
  }
  std::string known;
  for (const std::string& n : sheet_element_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown sheet element '" + spec.element + "' (known: " + known + ")");
}

}  // namespace spifit::model
