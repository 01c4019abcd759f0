// Reading a cone scene file (schema: docs/reference/file-formats.md "Cone scene", docs/design/cone.md).
// The run is in cone_run.cpp.
#include "forward/scenes/cone/cone_scene.hpp"

#include "forward/scenes/common/scene_inputs.hpp"
#include "forward/scenes/common/sheet_element_inputs.hpp"
#include "forward/scenes/cone/cone_inputs.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace spifit::scene {
namespace {

using io::TomlTable;

// Table and key of each ConePathOptions field, for the errors of check_cone_path_options.
struct OptionKey {
  const char* option;
  const char* key;  // dotted scene key
};
constexpr OptionKey kOptionKeys[] = {
    {"wall_angle_deg", "cone.wall_angle"},   {"stepdown", "cone.stepdown"},
    {"contours", "cone.contours"},           {"top_radius", "cone.top_radius"},
    {"thickness", "sheet.thickness"},        {"tool_radius", "tool.radius"},
    {"pie_angle_deg", "cone.pie_angle"},     {"stepdown_angle_deg", "cone.stepdown_angle"},
    {"ramp_angle_deg", "cone.ramp_angle"},   {"feed", "tool.feed"},
    {"lift", "cone.lift"},                   {"chord_tolerance", "cone.chord_tolerance"},
    {"approach_clearance", "cone.approach_clearance"},
};

// check_cone_path_options's message "cone path: OPTION = VALUE must ..." as a violation on the
// scene key of OPTION.
InputViolation path_violation(const std::string& prefix, const std::invalid_argument& e) {
  std::string msg = e.what();
  const std::string head = "cone path: ";
  if (msg.rfind(head, 0) == 0) msg = msg.substr(head.size());
  const std::string option = msg.substr(0, msg.find(' '));
  for (const auto& k : kOptionKeys)
    if (option == k.option) {
      const std::size_t eq = msg.find(" = ");
      const std::size_t end = msg.find(' ', eq + 3);
      const std::string value = eq == std::string::npos ? "" : msg.substr(eq + 3, end - eq - 3);
      return {k.key, value, prefix + msg};
    }
  return {"cone", "", prefix + msg};
}

// Preset stages (thesis §4.1.2, §8.1, §9.1) with the preset's default pie angle.
std::vector<toolpath::ConePathOptions> preset_stages(const std::string& preset, double* default_pie) {
  std::vector<toolpath::ConePathOptions> stages;
  if (preset == "cone50") stages = {toolpath::cone50()};
  else if (preset == "cone70") stages = {toolpath::cone70()};
  else if (preset == "vwall") stages = toolpath::vwall_stages();
  else stages = {toolpath::ConePathOptions{}};  // explicit geometry: the fields stay 0 until given
  *default_pie = stages.front().pie_angle_deg;  // cone50 90, cone70 45, vwall and explicit 360
  return stages;
}

void read_cone_table(const TomlTable& root, ConeScene& s) {
  const auto ct = root.table("cone");
  double default_pie = 360.0;
  if (ct) {
    ct->allow_only(cone_inputs().keys_of("cone"));
    s.preset = ct->string("preset", "");
    if (!s.preset.empty() && s.preset != "cone50" && s.preset != "cone70" && s.preset != "vwall")
      ct->fail("preset", "unknown preset (known: cone50, cone70, vwall; or leave it out and give the geometry)");
  }
  s.stages = preset_stages(s.preset, &default_pie);
  s.pie_angle = default_pie;
  if (!ct) return;
  cone_inputs().read(*ct, "cone", s);  // types, ranges and choices of every key
  if (ct->has("pie_angle")) {
    s.pie_angle = ct->number("pie_angle");
    const double pies = 360.0 / s.pie_angle;
    if (std::abs(pies - std::round(pies)) > 1e-9 * pies)
      ct->fail("pie_angle", "360 / pie_angle must be an integer (the pie stands for every pie of the sheet)");
  }
  if (ct->has("stages")) {
    if (s.preset != "vwall") ct->fail("stages", "only the vwall preset has stages");
    s.stages.resize(static_cast<std::size_t>(ct->integer("stages", 5)));
  }
  for (const char* key : {"wall_angle", "stepdown_angle"})
    if (s.preset == "vwall" && ct->has(key)) ct->fail(key, "vwall sets it per stage (thesis §8.1.1)");
  for (auto& o : s.stages) {
    o.contours = ct->integer("contours", o.contours);
    o.wall_angle_deg = ct->number("wall_angle", o.wall_angle_deg);
    o.stepdown = ct->number("stepdown", o.stepdown);
    o.top_radius = ct->number("top_radius", o.top_radius);
    o.stepdown_angle_deg = ct->number("stepdown_angle", o.stepdown_angle_deg);
    o.ramp_angle_deg = ct->number("ramp_angle", o.ramp_angle_deg);
    o.lift = ct->number("lift", o.lift);
    o.chord_tolerance = ct->number("chord_tolerance", o.chord_tolerance);
    o.approach_clearance = ct->number("approach_clearance", o.approach_clearance);
    o.counter_clockwise = ct->boolean("counter_clockwise", o.counter_clockwise);
  }
}

// Defaults that follow the preset: the thickness, the clamp radius (top radius + 1.5 mm, an
// assumption: docs/design/cone.md) and the tool radius.
void preset_defaults(ConeScene& s) {
  s.thickness = s.stages.front().thickness;  // the preset's (0 without a preset: required)
  double top = 0.0;
  for (const auto& o : s.stages) top = std::max(top, o.top_radius);
  s.clamp_radius = top + 1.5;
  s.tool_radius = s.stages.front().tool_radius > 0.0 ? s.stages.front().tool_radius : 5.0;
}

// The tables the input table reads ([sheet], [tool], [contact], [solver], [output]) over the
// preset's defaults.
void read_tables(const TomlTable& root, ConeScene& s) {
  preset_defaults(s);
  read_input_tables(root, cone_inputs(), {"sheet", "tool", "contact", "solver", "output"}, s);
}

// [output] history_element = { r = ..., theta = ... }: a point of the initial sheet (needs the
// clamp radius and pie angle, read before).
void read_history_element(const TomlTable& h, ConeScene& s) {
  h.allow_only({"r", "theta"});
  ConeScene::HistoryPoint p;
  p.r = h.number("r");
  p.theta_deg = h.number("theta");
  if (!(p.r >= 0.0 && p.r <= s.clamp_radius)) h.fail("r", "must lie in [0, clamp_radius = " + io::format_number(s.clamp_radius) + "] mm");
  if (!(p.theta_deg >= 0.0 && p.theta_deg <= s.pie_angle)) h.fail("theta", "must lie in [0, pie_angle = " + io::format_number(s.pie_angle) + "] deg");
  s.history_element = p;
}

void read_output_extras(const TomlTable& root, ConeScene& s) {
  const auto o = root.table("output");
  if (!o) return;
  if (const auto h = o->table("history_element")) read_history_element(*h, s);
  if (o->has("steady_state")) {
    const std::vector<double> r = o->number_list("steady_state");
    const int total = cone_scene_contours(s);
    if (r.size() != 2 || r[0] != std::floor(r[0]) || r[1] != std::floor(r[1]) || !(r[0] >= 1 && r[0] <= r[1] && r[1] <= total))
      o->fail("steady_state", "must be [from, to]: whole contour numbers with 1 <= from <= to <= " + std::to_string(total) +
                                  " (the path's contours)");
    s.steady_state = std::make_pair(static_cast<int>(r[0]), static_cast<int>(r[1]));
  }
}

// Each stage's path options (checked; errors on the scene key of the offending option).
InputViolation stage_violation(const ConeScene& s) {
  const std::vector<toolpath::ConePathOptions> stages = cone_scene_stages(s);
  for (std::size_t i = 0; i < stages.size(); ++i) {
    try {
      toolpath::check_cone_path_options(stages[i]);
    } catch (const std::invalid_argument& e) {
      return path_violation(stages.size() > 1 ? "stage " + std::to_string(i + 1) + ": " : "", e);
    }
  }
  return {};
}

// A coarsened centre stays out of the tool's reach: inside the last contour's touching radius
// less the tool radius. The explicit scheme's diagonal mass has no hanging nodes.
InputViolation coarsening_violation(const ConeScene& s) {
  using io::format_number;
  if (s.mesh.coarse_inside <= 0.0) return {};
  if (s.explicit_scheme)
    return {"sheet.coarse_inside", format_number(s.mesh.coarse_inside),
            "a coarsened centre is for the implicit scheme (the explicit lumped mass has no hanging nodes): set it to 0"};
  double reach = std::numeric_limits<double>::infinity();
  for (const auto& o : cone_scene_stages(s)) reach = std::min(reach, toolpath::cone_contour_touch_radius(o, o.contours) - o.tool_radius);
  if (s.mesh.coarse_inside > reach)
    return {"sheet.coarse_inside", format_number(s.mesh.coarse_inside),
            "must not exceed the last contour's touching radius less the tool radius, " + format_number(reach) + " mm"};
  return {};
}

// The mesh must exist and a shell's elements must not be too short for the thickness (ShellModel's
// limit t/l <= 3): checked before the run so that the error comes before any output.
InputViolation mesh_violation(const ConeScene& s) {
  mesh::Mesh m;
  try {
    m = cone_scene_mesh(s);
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).find("coarse_inside") != std::string::npos)
      return {"sheet.coarse_inside", io::format_number(s.mesh.coarse_inside), e.what()};
    return {"sheet", "", std::string("cannot mesh the sheet: ") + e.what()};
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& q : m.quads)
    for (std::size_t i = 0; i < 4; ++i)
      shortest = std::min(shortest, (m.nodes[static_cast<std::size_t>(q[(i + 1) % 4])] - m.nodes[static_cast<std::size_t>(q[i])]).norm());
  if (s.element == "shell" && s.thickness / shortest > 3.0)
    return {"sheet.elements_per_45deg", std::to_string(s.mesh.elements_per_45deg),
            "the shortest element edge " + io::format_number(shortest) + " mm is below a third of the thickness (sheet.thickness = " +
                io::format_number(s.thickness) + "; the shell's limit t/l <= 3): fewer elements or a thinner sheet"};
  return {};
}

}  // namespace

bool is_cone_kind(const std::string& kind) { return kind == "cone"; }

ConeScene read_cone_scene(const std::string& path) {
  const auto root = TomlTable::parse_file(path);
  root.allow_only({"scene", "cone", "sheet", "tool", "contact", "solver", "output"});
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  sc->allow_only(cone_inputs().keys_of("scene"));
  ConeScene s;
  s.file = path;
  if (!is_cone_kind(sc->string("kind"))) sc->fail("kind", "expected cone");
  read_scene_header(*sc, path, s);
  read_cone_table(root, s);
  read_tables(root, s);
  read_output_extras(root, s);
  settle_sheet_element(root, path, s);
  if (const InputViolation v = cone_scene_error(s)) throw io::InputError(path, v.key, v.value, v.message);
  return s;
}

SheetAndTool cone_sheet_and_tool(const ConeScene& s) {
  SheetAndTool st;
  st.thickness = s.thickness;
  st.sheet_size = 2.0 * s.clamp_radius;
  st.size_key = "sheet.clamp_radius";
  st.tool_radius = s.tool_radius;
  st.penalty = s.contact.penalty;
  st.feed = s.feed;
  st.card = &s.card;
  return st;
}

InputViolation cone_scene_error(const ConeScene& s) {
  using io::format_number;
  if (const InputViolation v = sheet_and_tool_error(cone_sheet_and_tool(s))) return v;
  if (s.thickness_rule == element::ThicknessRuleKind::surface && (s.thickness_points < 3 || s.thickness_points % 2 == 0))
    return {"sheet.thickness_rule", "\"surface\"", "the surface rule needs an odd number of thickness points >= 3"};
  double top = 0.0;
  for (const auto& o : s.stages) top = std::max(top, o.top_radius);
  if (!(s.clamp_radius > top))
    return {"sheet.clamp_radius", format_number(s.clamp_radius), "must be larger than the cone's top radius " + format_number(top) + " mm"};
  if (!(s.mesh.core_radius < s.clamp_radius))
    return {"sheet.core_radius", format_number(s.mesh.core_radius), "must lie in [0, clamp_radius) (0: automatic)"};
  if (!(s.mesh.ring_start < s.clamp_radius))
    return {"sheet.ring_start", format_number(s.mesh.ring_start), "must lie in [0, clamp_radius) (0: no circular layers)"};
  if (InputViolation v = solid_sheet_violation(s)) return v;
  if (s.element != "shell" && s.history_element)
    return {"output.history_element", "", "the element history is the shell's (layer strains and curvatures of its mid-surface): "
                                          "remove it with sheet.element = \"" + s.element + "\""};
  if (InputViolation v = stage_violation(s)) return v;
  if (InputViolation v = scheme_violation(s)) return v;
  if (InputViolation v = coarsening_violation(s)) return v;
  return mesh_violation(s);
}

std::vector<toolpath::ConePathOptions> cone_scene_stages(const ConeScene& scene) {
  std::vector<toolpath::ConePathOptions> stages = scene.stages;
  for (auto& o : stages) {
    o.thickness = scene.thickness;
    o.tool_radius = scene.tool_radius;
    o.feed = scene.feed;
    o.pie_angle_deg = scene.pie_angle;
  }
  return stages;
}

mesh::Mesh cone_scene_mesh(const ConeScene& scene) {
  mesh::DiscOptions o = scene.mesh;
  o.radius = scene.clamp_radius;
  o.angle_deg = scene.pie_angle;
  return mesh::disc_mesh(o);
}

int cone_scene_contours(const ConeScene& scene) {
  int total = 0;
  for (const auto& st : scene.stages) total += st.contours;
  return total;
}

toolpath::ConePath cone_scene_path(const ConeScene& scene) {
  const std::vector<toolpath::ConePathOptions> stages = cone_scene_stages(scene);
  if (stages.size() == 1) return toolpath::annotated_cone_path(stages.front());
  double safe_z = 0.0;  // every stage starts and ends at its approach height
  for (const auto& o : stages) safe_z = std::max(safe_z, toolpath::cone_approach_centre_z(o));
  return toolpath::annotated_multistage_cone_path(stages, safe_z);
}

}  // namespace spifit::scene
