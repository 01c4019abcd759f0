#pragma once
// The element families a forming scene can model its sheet with, in one place: the shell on the
// sheet's mid-surface, one-point bricks on the solid sheet extruded from it in layers, or
// solid-shells, one through the thickness ([sheet] element and layers of the scenes;
// docs/design/numerics-solid.md). A new family adds
// its name to sheet_element_names() and its construction to make_sheet_model.
#include "forward/element/brick8.hpp"
#include "forward/element/solid_shell8.hpp"
#include "forward/material/material_params.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/shell_family.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::model {

struct SheetModelSpec {
  std::string element = "shell";       // one of sheet_element_names()
  int layers = 1;                      // bricks through the thickness
  ShellModelOptions shell;             // the shell's options; its material axes serve every family,
                                       // its thickness rule the solid-shell
  element::HourglassOptions hourglass;  // the brick's stabilisation
  // The solid-shell's enhanced strains' Newton tolerance.
  double enhanced_tolerance = element::SolidShell8::kDefaultEnhancedTolerance;
};

// "shell", "brick", "solid_shell": the scenes' [sheet] element choices.
const std::vector<std::string>& sheet_element_names();

// The model of a sheet of the given thickness whose mid-surface mesh is `mid`. Solids are built
// on mesh::extrude_sheet(mid, thickness, layers), kept in *solid, which must outlive the model
// (and `mid` for the shell). std::invalid_argument for an unknown element, layers < 1, or what
// the family refuses (naming the element).
std::unique_ptr<FeModel> make_sheet_model(const mesh::Mesh& mid, double thickness, const material::MaterialParams<double>& material,
                                          const SheetModelSpec& spec, mesh::Mesh* solid);

}  // namespace spifit::model
