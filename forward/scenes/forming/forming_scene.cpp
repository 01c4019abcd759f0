#include "forward/scenes/forming/forming_scene.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/mesh/mesh_quality.hpp"
#include "forward/mesh/segment_distance.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/common/scene_inputs.hpp"
#include "forward/scenes/common/sheet_element_inputs.hpp"
#include "forward/scenes/forming/forming_inputs.hpp"
#include "forward/scenes/forming/forming_path.hpp"
#include "forward/toolpath/tool_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace spifit::scene {
namespace {

// Thesis defaults per kind (§7.1 for indent; §4.1.1, §7.2 and §7.3 for the line test; the
// path A -> E is an assumption: docs/design/contact.md).
void set_defaults(FormingScene& s) {
  if (s.kind == "indent") {
    // §7.1: 10 x 10 mm, t = 0.3, edges clamped, R = 5 at the centre, 2 mm after 1 s from first touch.
    s.length = 10.0; s.thickness = 0.3; s.elements = 10; s.half = false;
    s.radius = 5.0; s.feed = 2.0;
    s.path = {{"A", {0.0, 0.0, 0.0}}, {"B", {0.0, 0.0, -2.0}}};
    s.travel_per_increment = 0.05;
    // No predictor: from K_p = 1e6 up it led Newton into states it could not leave even with
    // 1e-5 of the step (docs/design/decisions.md); this small model gains nothing from it anyway.
    s.extrapolate = false;
  } else {
    // 182 x 182 mm, t = 1.2, 50 x 50 regular mesh (3.64 mm, §7.3), edges clamped, R = 5,
    // A (-50, 0) above the sheet, B at 5 mm depth, C after +100 mm, D at 10 mm, E back -100 mm
    // (§4.1.1: two 100 mm lines at 5 and 10 mm depth).
    s.length = 182.0; s.thickness = 1.2; s.elements = 50; s.half = true;
    s.radius = 5.0; s.feed = 10.0;
    s.path = {{"A", {-50.0, 0.0, 0.0}}, {"B", {-50.0, 0.0, -5.0}}};
    if (s.kind == "line") {
      s.path.push_back({"C", {50.0, 0.0, -5.0}});
      s.path.push_back({"D", {50.0, 0.0, -10.0}});
      s.path.push_back({"E", {-50.0, 0.0, -10.0}});
      s.sections = {"C", "E"};
    }
    s.travel_per_increment = 0.5;
  }
}

// [tool] gcode: the program's path relative to the scene file (it replaces the default path).
void read_gcode(const io::TomlTable& tl, const std::string& scene_file, FormingScene& s) {
  if (!tl.has("gcode")) return;
  std::filesystem::path gp(tl.string("gcode"));
  if (gp.is_relative()) gp = std::filesystem::path(scene_file).parent_path() / gp;
  if (!std::filesystem::exists(gp)) tl.fail("gcode", "G-code file not found at " + gp.lexically_normal().string());
  s.gcode = gp.lexically_normal().string();
  s.sections.clear();
}

void read_path_points(const io::TomlTable& root, const std::vector<io::TomlTable>& points, FormingScene& s) {
  if (points.empty()) return;
  if (!s.gcode.empty()) points.front().fail("x", "give either [tool] gcode or [[path]] points, not both");
  s.path.clear();
  const std::vector<std::string> keys = forming_inputs().keys_of("path");
  for (const auto& p : points) {
    p.allow_only(keys);
    std::string fallback = "P";
    fallback += std::to_string(s.path.size());
    s.path.push_back({p.string("name", fallback), {p.number("x"), p.number("y"), p.number("z")}});
  }
  if (s.path.size() < 2) points.front().fail("x", "a path needs at least 2 points");
  if (!root.table("output") || !root.table("output")->has("sections")) s.sections.clear();
}

void read_sections(const io::TomlTable& o, FormingScene& s) {
  if (!o.has("sections")) return;
  s.sections = o.string_list("sections");
  for (const auto& n : s.sections)
    if (std::none_of(s.path.begin(), s.path.end(), [&](const PathPoint& p) { return p.name == n; }))
      o.fail("sections", "no path point named \"" + n + "\"");
}

// The tool tip's waypoints: the G-code program's or the path points.
std::vector<Eigen::Vector3d> tip_points(const FormingScene& s) {
  std::vector<Eigen::Vector3d> tips;
  if (!s.gcode.empty()) {
    const toolpath::ToolPath gp = gcode_tip_path(s.gcode);
    for (const auto& w : gp.waypoints()) tips.push_back(w.position);
  } else {
    for (const auto& p : s.path) tips.push_back(p.tip);
  }
  return tips;
}

// The thickness over the shortest element edge against the shell's limit; the error names the
// keys that set the mesh and what to change.
InputViolation thickness_violation(const FormingScene& s) {
  mesh::Mesh m;
  try {
    m = forming_sheet_mesh(s);
  } catch (const std::invalid_argument& e) {
    return {"sheet", "", std::string("cannot mesh the sheet: ") + e.what()};
  }
  const double limit = model::ShellModelOptions{}.max_thickness_over_length;
  const mesh::MeshQuality q = mesh::mesh_quality(m, s.thickness);
  if (!(q.max_thickness_over_length > limit)) return {};
  using io::format_number;
  return {"sheet.thickness", format_number(s.thickness),
          "over the shortest element edge, " + format_number(q.min_edge) + " mm (sheet.length = " + format_number(s.length) +
              " / sheet.elements = " + std::to_string(s.elements) + (s.grading != 1.0 ? ", sheet.grading = " + format_number(s.grading) : "") +
              "), t/l = " + format_number(std::round(q.max_thickness_over_length * 1000.0) / 1000.0) + " exceeds the shell's limit " +
              format_number(limit) + ": fewer elements or a thinner sheet"};
}

}  // namespace

mesh::Mesh forming_sheet_mesh(const FormingScene& s) {
  mesh::SquareSheetOptions so;
  so.length_x = so.length_y = s.length;
  so.nx = so.ny = s.elements;
  so.half = s.half;
  so.grading_x = so.grading_y = s.grading;
  so.coarse_levels = s.coarse_levels;
  if (s.coarse_levels > 0) {
    // The pieces of the tip's path that reach below the sheet's top surface.
    std::vector<std::array<Eigen::Vector2d, 2>> pieces;
    const std::vector<Eigen::Vector3d> tips = tip_points(s);
    for (std::size_t k = 0; k + 1 < tips.size(); ++k)
      if (std::min(tips[k].z(), tips[k + 1].z()) < 0.0) pieces.push_back({tips[k].head<2>(), tips[k + 1].head<2>()});
    const double band = s.fine_band;
    so.keep_fine = [pieces, band](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
      return std::any_of(pieces.begin(), pieces.end(),
                         [&](const auto& p) { return mesh::rectangle_segment_distance(lo, hi, p[0], p[1]) <= band; });
    };
  }
  return mesh::square_sheet(so);
}

bool is_forming_kind(const std::string& kind) { return kind == "indent" || kind == "indent_line" || kind == "line"; }

SheetAndTool forming_sheet_and_tool(const FormingScene& s) {
  SheetAndTool st;
  st.thickness = s.thickness;
  st.sheet_size = s.length;
  st.size_key = "sheet.length";
  st.tool_radius = s.radius;
  st.penalty = s.contact.penalty;
  st.feed = s.feed;
  st.card = &s.card;
  return st;
}

InputViolation forming_scene_error(const FormingScene& s) {
  if (const InputViolation v = sheet_and_tool_error(forming_sheet_and_tool(s))) return v;
  if (s.half && s.elements % 2 != 0)
    return {"sheet.elements", std::to_string(s.elements), "a half model needs an even number of elements across"};
  if (const InputViolation v = solid_sheet_violation(s)) return v;
  if (s.element == "shell")
    if (const InputViolation v = thickness_violation(s)) return v;
  if (const InputViolation v = scheme_violation(s)) return v;
  if (s.coarse_levels > 0 && s.explicit_scheme)
    return {"sheet.coarse_levels", std::to_string(s.coarse_levels),
            "a coarsened sheet is for the implicit scheme (the explicit lumped mass has no hanging nodes): set it to 0"};
  // The tool must start outside the sheet and reach it.
  const double half_length = 0.5 * s.length;
  auto over_sheet = [&](const Eigen::Vector3d& tip) { return std::abs(tip.x()) < half_length && std::abs(tip.y()) < half_length; };
  const std::vector<Eigen::Vector3d> tips = tip_points(s);
  const std::string key = s.gcode.empty() ? "path" : "tool.gcode";
  if (tips.front().z() < -1e-9 && over_sheet(tips.front())) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the tool starts inside the sheet: its tip is %.4g mm below the top surface", -tips.front().z());
    return {key, "", buf};
  }
  if (std::none_of(tips.begin(), tips.end(), [&](const Eigen::Vector3d& t) { return t.z() < 0.0 && over_sheet(t); }))
    return {key, "", "the tool path never goes below the sheet's top surface over the sheet"};
  return {};
}

FormingScene read_forming_scene(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"scene", "sheet", "tool", "path", "contact", "solver", "output"});
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  const auto& inputs = forming_inputs();
  sc->allow_only(inputs.keys_of("scene"));
  FormingScene s;
  s.file = path;
  s.kind = sc->string("kind");
  if (!is_forming_kind(s.kind)) sc->fail("kind", "expected indent, indent_line or line");
  set_defaults(s);
  read_scene_header(*sc, path, s);
  read_input_tables(root, inputs, {"sheet", "tool", "contact", "solver", "output"}, s);
  if (const auto tl = root.table("tool")) read_gcode(*tl, path, s);
  const auto points = root.table_array("path");
  read_path_points(root, points, s);
  if (const auto o = root.table("output")) read_sections(*o, s);
  settle_sheet_element(root, path, s);
  const InputViolation v = forming_scene_error(s);
  if (!v) return s;
  if (v.key == "tool.gcode") root.table("tool")->fail("gcode", v.message);
  if (v.key == "path" && !points.empty()) points.front().fail("z", v.message);
  if (v.key == "path") sc->fail("kind", v.message + " (default path of this kind)");
  throw io::InputError(path, v.key, v.value, v.message);
}

}  // namespace spifit::scene
