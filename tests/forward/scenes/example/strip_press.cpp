#include "tests/forward/scenes/example/strip_press.hpp"

#include "forward/io/named_inputs.hpp"
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/scenes/common/fe_run_summary.hpp"
#include "forward/scenes/common/force_log.hpp"
#include "forward/scenes/common/scene_tables.hpp"
#include "forward/scenes/common/table_scene.hpp"
#include "forward/scenes/common/tool_scene_inputs.hpp"

#include <filesystem>

namespace spifit::example {
namespace {

using io::Range;

// 1. The named inputs: one table drives the reader, sweeps and `spifit inputs`.
const io::InputTable<StripPress>& inputs() {
  static const io::InputTable<StripPress> table = [] {
    io::InputTable<StripPress> t;
    t.custom({"scene.kind", {}, "", {}, {"strip_press"}, "the scene kind", false}, io::InputType::text);
    t.custom({"scene.material", {}, "", {}, {}, "material card, relative to the scene file", false}, io::InputType::text);
    t.real({"strip.length", {}, "mm", Range::positive(), {}, "span between the clamped ends", true},
           [](StripPress& s) -> double& { return s.length; });
    t.real({"strip.width", {}, "mm", Range::positive(), {}, "width of the strip", false}, [](StripPress& s) -> double& { return s.width; });
    t.real({"strip.thickness", {}, "mm", Range::positive(), {}, "sheet thickness", true},
           [](StripPress& s) -> double& { return s.thickness; });
    t.integer({"strip.elements", {}, "", Range::closed(2, 400), {}, "elements along the length (even)", true},
              [](StripPress& s) -> int& { return s.elements; });
    t.real({"tool.radius", {}, "mm", Range::positive(), {}, "tool radius", true}, [](StripPress& s) -> double& { return s.tool_radius; });
    t.real({"tool.depth", {}, "mm", Range::positive(), {}, "depth of the tool tip below the top surface at the end", true},
           [](StripPress& s) -> double& { return s.depth; });
    scene::add_contact_inputs(t);
    t.real({"solver.travel_per_increment", {}, "mm", Range::positive(), {}, "tool travel per increment", false},
           [](StripPress& s) -> double& { return s.travel_per_increment; });
    return t;
  }();
  return table;
}

StripPress read(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"scene", "strip", "tool", "contact", "solver"});
  StripPress s;
  s.file = path;
  s.name = std::filesystem::path(path).stem().string();
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  sc->allow_only(inputs().keys_of("scene"));
  s.card = scene::read_scene_material(*sc, path);
  for (const char* table : {"strip", "tool", "contact", "solver"})
    if (const auto t = root.table(table)) {
      t->allow_only(inputs().keys_of(table));
      inputs().read(*t, table, s);
    }
  if (s.elements % 2 != 0) root.table("strip")->fail("elements", "must be even (a node at mid-span)");
  return s;
}

// 2. The typed result: the skeleton's outcome, the force history and the new observable's value.
class StripPressResult final : public scene::SceneResult {
 public:
  std::string name;
  scene::FeRunOutcome run;
  scene::ToolForceHistory force;
  double mid_deflection = 0.0;  // mm, downwards > 0
  nlohmann::json to_json() const override {
    nlohmann::json j{{"scene", name}, {"kind", "strip_press"}, {"mid_deflection", mid_deflection}};
    add_status(j);
    scene::add_fe_run_summary(j, run, force, {}, {}, "N mm");
    return j;
  }
  std::string brief_report() const override {
    return name + ": peak Fz " + std::to_string(force.peak().z()) + " N, mid-span deflection " + std::to_string(mid_deflection) + " mm";
  }
};

// 3. The run: mesh, constraints, tool path and observers on the FE-run skeleton.
StripPressResult run(const StripPress& s, const scene::RunFiles& files, const scene::RunControl& control) {
  const double top = 0.5 * s.thickness + s.tool_radius, mid = 0.5 * s.length;
  scene::FeRunSetup f(toolpath::ToolPath::from_points({{mid, 0.0, top + 0.5}, {mid, 0.0, top - s.depth}}, s.feed));
  f.kind = "strip_press";
  f.name = s.name;
  f.input_files = {{"scene", s.file}, {"material card", s.card.file}};
  f.mesh = mesh::strip(s.length, s.width, s.elements, std::max(1, static_cast<int>(s.width / 2.0)));
  f.thickness = s.thickness;
  f.material = s.card.params;
  f.tool_radius = s.tool_radius;
  f.contact = s.contact;
  f.load_map = scene::LoadMap::linear(f.tool_path.length());
  f.time_of_travel = [feed = s.feed](double travel) { return travel / feed; };
  f.constraints = [](model::FeModel& m) {  // both ends clamped
    solver::DofConstraints c(m.num_dofs());
    for (const char* set : {"clamped", "tip"})
      for (int n : m.mesh().node_sets.at(set))
        for (int k = 0; k < m.node_dofs(n); ++k) c.prescribe(m.node_dof(n, k));
    m.use_nodal_rotation_frames(&c);
    c.finalize();
    return c;
  };
  f.newton.initial_increment = f.newton.max_increment = std::min(1.0, s.travel_per_increment / f.tool_path.length());
  f.newton.min_increment = 1e-4 * f.newton.initial_increment;
  scene::FeRun fe(std::move(f), files, control);
  scene::ForceLogFormat format;
  format.columns = {{"time", "s"}, {"Fz", "N"}};
  format.comment = "# strip_press " + s.name + ": force by the strip on the tool";
  format.row = [](const scene::ToolForceSample& x) { return std::vector<double>{x.time, x.force.z()}; };
  auto& force = fe.add_observer(std::make_unique<scene::ForceLog>(format, fe.files()));
  StripPressResult r;
  r.name = s.name;
  r.run = fe.run({{"scene", s.name}, {"kind", "strip_press"}});
  r.status = r.run.status;
  r.message = r.run.message;
  r.wall_seconds = r.run.wall_seconds;
  r.force = force.history();
  for (int n = 0; n < fe.model().num_nodes(); ++n)  // the deepest node of the mid-span line
    if (std::abs(fe.model().mesh().nodes[static_cast<std::size_t>(n)].x() - mid) < 1e-9)
      r.mid_deflection = std::max(r.mid_deflection, -fe.model().displacement(n).z());
  files.write("summary.json", r.to_json().dump(2) + "\n");
  return r;
}

class StripPressScene final : public scene::TableScene<StripPress> {
 public:
  explicit StripPressScene(StripPress s) : TableScene("strip_press", std::move(s), &inputs()) {}
  std::vector<std::string> input_files() const override { return {data_.file, data_.card.file}; }
  std::unique_ptr<scene::Scene> clone() const override { return std::make_unique<StripPressScene>(*this); }
  std::unique_ptr<scene::SceneResult> run(const scene::RunFiles& files, const scene::RunControl& control) const override {
    return std::make_unique<StripPressResult>(example::run(data_, files, control));
  }
};

}  // namespace

// 4. The kind: name, reader, inputs and observables (the new one: mid_deflection).
scene::SceneKind strip_press_kind() {
  scene::SceneKind k;
  k.name = "strip_press";
  k.family = "example";
  k.doc = "a strip clamped at both ends, pressed at mid-span (the worked example of docs/design/architecture.md)";
  k.read = [](const std::string& file) -> std::unique_ptr<scene::Scene> { return std::make_unique<StripPressScene>(read(file)); };
  k.inputs = inputs().infos();
  const auto of = [](const scene::SceneResult& r) -> const StripPressResult& { return dynamic_cast<const StripPressResult&>(r); };
  k.observables = {{"peak_fz", "N", "largest |Fz| on the tool", scene::Observable::Needs::nothing, false,
                    [of](const scene::SceneResult& r, const scene::ObservableOptions&) { return of(r).force.peak().z(); }},
                   {"mid_deflection", "mm", "deepest deflection of the mid-span line", scene::Observable::Needs::nothing, false,
                    [of](const scene::SceneResult& r, const scene::ObservableOptions&) { return of(r).mid_deflection; }}};
  return k;
}

}  // namespace spifit::example
