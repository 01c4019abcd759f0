#include "forward/scenes/forming/forming_inputs.hpp"

#include "forward/scenes/common/scene_inputs.hpp"
#include "forward/scenes/common/sheet_element_inputs.hpp"
#include "forward/scenes/common/tool_scene_inputs.hpp"

namespace spifit::scene {
namespace {

using io::InputType;
using io::Range;

void add_scene_and_sheet(io::InputTable<FormingScene>& t) {
  add_scene_inputs(t, {"indent", "indent_line", "line"}, SceneMaterialKey::optional);
  t.real({"sheet.length", {}, "mm", Range::positive(), {}, "side of the square sheet, centred on the origin, clamped on its edges", true},
         [](FormingScene& s) -> double& { return s.length; });
  t.real({"sheet.thickness", {}, "mm", Range::positive(), {}, "initial sheet thickness", true},
         [](FormingScene& s) -> double& { return s.thickness; });
  t.integer({"sheet.elements", {}, "", Range::closed(2, 2000), {}, "elements across the full side (a half model: even)", true},
            [](FormingScene& s) -> int& { return s.elements; });
  t.boolean({"sheet.half", {}, "", {}, {}, "model the half y >= 0 with symmetry conditions on y = 0", false},
            [](FormingScene& s) -> bool& { return s.half; });
  t.real({"sheet.grading", {}, "", Range::positive(), {}, "ratio of the outer to the central element size (1: regular)", false},
         [](FormingScene& s) -> double& { return s.grading; });
  t.integer({"sheet.coarse_levels", {}, "", Range::closed(0, 4), {}, "coarsening away from the tool path: cells farther than sheet.fine_band "
             "from it merge into blocks of up to 2^k x 2^k (0: regular; implicit scheme only)", false},
            [](FormingScene& s) -> int& { return s.coarse_levels; });
  t.real({"sheet.fine_band", {}, "mm", Range::positive(), {}, "distance from the tool tip's path (below the sheet's top) within which "
          "cells keep the sheet.elements size when sheet.coarse_levels > 0", false},
         [](FormingScene& s) -> double& { return s.fine_band; });
  t.integer({"sheet.thickness_points", {}, "", Range::closed(1, 11), {}, "integration points through the thickness (shells and solid-shells)", true},
            [](FormingScene& s) -> int& { return s.thickness_points; });
  add_sheet_element_inputs(t);
  t.real({"sheet.hourglass_stiffness", {}, "", Range::closed(0.0, 1.0), {},
          "> 0: one in-plane point per element (about a quarter of the material updates), with this fraction of the elastic "
          "section stiffness on the strains' variation over the element (hourglass control); 0: 2 x 2 points", true},
         [](FormingScene& s) -> double& { return s.hourglass_stiffness; });
}

void add_output(io::InputTable<FormingScene>& t) {
  add_output_inputs(t, "named path points");
  t.custom({"output.sections", {}, "", {}, {}, "names of path points where the section y = 0 is written", false}, InputType::list);
}

io::InputTable<FormingScene> make_table() {
  io::InputTable<FormingScene> t;
  add_scene_and_sheet(t);
  add_tool_inputs(t, &FormingScene::radius);
  t.custom({"tool.gcode", {}, "", {}, {}, "G-code program of the tool tip, relative to the scene file (replaces [[path]])", false},
           InputType::text);
  t.custom({"path.name", {}, "", {}, {}, "[[path]] point name (sections are taken at named points)", false}, InputType::text);
  t.custom({"path.x", {}, "mm", {}, {}, "[[path]] tool tip x", false}, InputType::real);
  t.custom({"path.y", {}, "mm", {}, {}, "[[path]] tool tip y", false}, InputType::real);
  t.custom({"path.z", {}, "mm", {}, {}, "[[path]] tool tip z, from the sheet's initial top surface", false}, InputType::real);
  add_contact_inputs(t);
  add_solver_inputs(t);
  add_output(t);
  return t;
}

}  // namespace

const io::InputTable<FormingScene>& forming_inputs() {
  static const io::InputTable<FormingScene> table = make_table();
  return table;
}

}  // namespace spifit::scene
