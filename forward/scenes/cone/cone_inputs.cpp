#include "forward/scenes/cone/cone_inputs.hpp"

#include "forward/scenes/common/scene_inputs.hpp"
#include "forward/scenes/common/sheet_element_inputs.hpp"
#include "forward/scenes/common/tool_scene_inputs.hpp"

namespace spifit::scene {
namespace {

using io::InputType;
using io::Range;
using Table = io::InputTable<ConeScene>;

void add_scene_and_cone(Table& t) {
  add_scene_inputs(t, {"cone"}, SceneMaterialKey::optional);
  t.custom({"cone.preset", {}, "", {}, {"cone50", "cone70", "vwall"}, "the thesis's cones (default: geometry given below)", false}, InputType::text);
  t.custom({"cone.stages", {}, "", Range::closed(1, 5), {}, "vwall: the first 1 to 5 stages (50, 60, 70, 80, 90 deg)", false}, InputType::integer);
  t.custom({"cone.contours", {}, "", Range::at_least(1), {}, "contours (per stage)", false}, InputType::integer);
  t.custom({"cone.pie_angle", {}, "deg", Range{0.0, 360.0, true, false}, {}, "pie angle gamma; 360 / gamma an integer; 360: full disc", false},
           InputType::real);
  t.custom({"cone.wall_angle", {}, "deg", Range{0.0, 90.0, true, false}, {}, "wall angle from the horizontal", false}, InputType::real);
  t.custom({"cone.stepdown", {}, "mm", Range::positive(), {}, "depth between contours", false}, InputType::real);
  t.custom({"cone.top_radius", {}, "mm", Range::positive(), {}, "radius of the CAD surface at the initial top surface", false}, InputType::real);
  t.custom({"cone.stepdown_angle", {}, "deg", {}, {}, "polar angle where the tool steps down (full disc)", false}, InputType::real);
  t.custom({"cone.ramp_angle", {}, "deg", Range::positive(), {}, "angle of the stepdown ramp (full disc)", false}, InputType::real);
  t.custom({"cone.lift", {}, "mm", Range::positive(), {}, "tool lift between contours of a pie", false}, InputType::real);
  t.custom({"cone.chord_tolerance", {}, "mm", Range::positive(), {}, "largest chord deviation of the contour polylines", false}, InputType::real);
  t.custom({"cone.approach_clearance", {}, "mm", Range::non_negative(), {}, "height of the approach above the sheet", false}, InputType::real);
  t.custom({"cone.counter_clockwise", {}, "", {}, {}, "direction of travel seen from above", false}, InputType::boolean);
}

void add_mesh(Table& t) {
  t.integer({"sheet.elements_per_45deg", {}, "", Range::closed(2, 2000), {}, "elements along the rim per 45 deg", true},
            [](ConeScene& s) -> int& { return s.mesh.elements_per_45deg; });
  t.real({"sheet.core_radius", {}, "mm", Range::non_negative(), {}, "radius of the O-grid core (0: automatic); < clamp_radius", false},
         [](ConeScene& s) -> double& { return s.mesh.core_radius; });
  t.integer({"sheet.radial_elements", {}, "", Range::closed(0, 100000), {}, "elements across the ring (0: about square at the rim)", false},
            [](ConeScene& s) -> int& { return s.mesh.radial_elements; });
  t.real({"sheet.radial_grading", {}, "", Range::positive(), {}, "outer over inner ring element size", false},
         [](ConeScene& s) -> double& { return s.mesh.radial_grading; });
  t.real({"sheet.band_inner", {}, "mm", Range::non_negative(), {}, "inner radius of a denser band", false},
         [](ConeScene& s) -> double& { return s.mesh.band_inner; });
  t.real({"sheet.band_outer", {}, "mm", Range::non_negative(), {}, "outer radius of the band (> band_inner activates it)", false},
         [](ConeScene& s) -> double& { return s.mesh.band_outer; });
  t.real({"sheet.band_factor", {}, "", Range::positive(), {}, "element density multiplier in the band", false},
         [](ConeScene& s) -> double& { return s.mesh.band_factor; });
  t.real({"sheet.max_sector_deg", {}, "deg", {}, {"45", "90"}, "largest O-grid sub-sector: 45 or 90", false},
         [](ConeScene& s) -> double& { return s.mesh.max_sector_deg; });
  t.real({"sheet.ring_start", {}, "mm", Range::non_negative(), {}, "circular layers from here to the rim (0: none); < clamp_radius", false},
         [](ConeScene& s) -> double& { return s.mesh.ring_start; });
  t.integer({"sheet.transition_elements", {}, "", Range::closed(0, 100000), {}, "layers from the kite to ring_start (0: about square)", false},
            [](ConeScene& s) -> int& { return s.mesh.transition_elements; });
  t.real({"sheet.rim_ring_width", {}, "mm", Range::non_negative(), {}, "radial width of the outermost ring (0: none)", false},
         [](ConeScene& s) -> double& { return s.mesh.rim_ring_width; });
  t.real({"sheet.coarse_inside", {}, "mm", Range::non_negative(), {},
          "half the elements around the centre inside this radius, hanging nodes at it (0: none); inside the last contour less the tool radius", false},
         [](ConeScene& s) -> double& { return s.mesh.coarse_inside; });
}

void add_sheet(Table& t) {
  t.real({"sheet.thickness", {}, "mm", Range::positive(), {}, "initial sheet thickness (default: the preset's)", true},
         [](ConeScene& s) -> double& { return s.thickness; });
  t.real({"sheet.clamp_radius", {}, "mm", Range::positive(), {}, "radius of the clamp = the mesh's rim; > the top radius (default: top + 1.5)", false},
         [](ConeScene& s) -> double& { return s.clamp_radius; });
  t.boolean({"sheet.clamp_rotations", {}, "", {}, {}, "clamp the rim's rotations too (thesis: translations only); solids: every node of the "
              "rim's columns, else their mid-surface only", false},
            [](ConeScene& s) -> bool& { return s.clamp_rotations; });
  add_mesh(t);
  t.integer({"sheet.thickness_points", {}, "", Range::closed(1, 11), {}, "integration points through the thickness (shells and solid-shells)", true},
            [](ConeScene& s) -> int& { return s.thickness_points; });
  add_sheet_element_inputs(t);
  t.real({"sheet.hourglass_stiffness", {}, "", Range::closed(0.0, 1.0), {},
          "> 0: one in-plane point per element (about a quarter of the material updates), with this fraction of the elastic "
          "section stiffness on the strains' variation over the element (hourglass control); 0: 2 x 2 points", true},
         [](ConeScene& s) -> double& { return s.hourglass_stiffness; });
  t.text({"sheet.thickness_rule", {}, "", {}, {"gauss", "surface"}, "through-thickness rule (surface: Simpson with the surface points)", false},
         {[](const ConeScene& s) -> std::string { return element::to_string(s.thickness_rule); },
          [](ConeScene& s, const std::string& v) { return element::thickness_rule_from_string(v, &s.thickness_rule); }});
  t.text({"sheet.material_axes", {}, "", {}, {"fixed", "polar"}, "rolling direction x everywhere, or radial in every element", false},
         {[](const ConeScene& s) -> std::string { return model::to_string(s.material_axes); },
          [](ConeScene& s, const std::string& v) { return model::material_axes_from_string(v, &s.material_axes); }});
}

void add_solver_and_output(Table& t) {
  t.integer({"solver.move_increments", {}, "", Range::closed(0, 1000), {}, "increments per move between pie contours (0: by travel)", false},
            [](ConeScene& s) -> int& { return s.move_increments; });
  add_output_inputs(t, "completed contours");
  t.custom({"output.history_element", {}, "", {}, {}, "{ r = mm, theta = deg }: the element nearest to this point writes history.csv", false},
           InputType::table);
  t.custom({"output.steady_state", {}, "", {}, {}, "[from, to]: contour range of the steady-state means (thesis §9.3: [60, 80])", false},
           InputType::list);
}

Table make_table() {
  Table t;
  add_scene_and_cone(t);
  add_sheet(t);
  add_tool_inputs(t, &ConeScene::tool_radius);
  add_contact_inputs(t);
  t.boolean({"contact.virtual_tools", {}, "", {}, {}, "pies: copies of the tool at +-gamma (thesis Fig. 8.4)", false},
            [](ConeScene& s) -> bool& { return s.virtual_tools; });
  add_solver_inputs(t);
  add_solver_and_output(t);
  return t;
}

}  // namespace

const io::InputTable<ConeScene>& cone_inputs() {
  static const Table table = make_table();
  return table;
}

}  // namespace spifit::scene
