#include "forward/scenes/material_point/material_point_kind.hpp"

#include "forward/scenes/common/table_scene.hpp"
#include "forward/scenes/material_point/material_point_inputs.hpp"
#include "forward/scenes/material_point/material_point_scene.hpp"

#include <cmath>

namespace spifit::scene {
namespace {

class MaterialPointSceneFile final : public TableScene<MaterialPointScene> {
 public:
  MaterialPointSceneFile(std::string kind, MaterialPointScene s, const io::InputTable<MaterialPointScene>* table)
      : TableScene(std::move(kind), std::move(s), table) {}
  std::vector<std::string> input_files() const override { return {data_.file, data_.card.file}; }
  std::unique_ptr<Scene> clone() const override { return std::make_unique<MaterialPointSceneFile>(*this); }
  std::unique_ptr<SceneResult> run(const RunFiles& files, const RunControl& control) const override {
    (void)control;  // one material point: no progress, nothing to resume
    return std::make_unique<MaterialPointSceneResult>(run_material_point_scene(data_, files));
  }
};

using Curve = MaterialPointResult<double>;

Observable metric(const char* name, const char* unit, const char* doc, std::function<double(const Curve&)> f) {
  return {name, unit, doc, Observable::Needs::nothing, false, [f = std::move(f)](const SceneResult& r, const ObservableOptions&) {
            const Curve& c = dynamic_cast<const MaterialPointSceneResult&>(r).result;
            return !c.ok || c.curve.empty() ? kNaN : f(c);
          }};
}

std::vector<Observable> material_point_observables() {
  return {
      metric("r_value", "", "Lankford coefficient at the scene's r_value_strain (tensile)",
             [](const Curve& c) { return c.r_value ? *c.r_value : kNaN; }),
      metric("yield_stress", "MPa", "offset yield stress (tensile)",
             [](const Curve& c) { return c.offset_yield_stress ? *c.offset_yield_stress : kNaN; }),
      metric("initial_yield_stress", "MPa", "stress at the first yield", [](const Curve& c) { return c.yield_events.empty() ? kNaN : c.yield_events.front().stress; }),
      metric("reverse_yield_stress", "MPa", "stress at the first yield after the first reversal", [](const Curve& c) {
        for (const auto& e : c.yield_events)
          if (e.segment == 1) return e.stress;
        return kNaN;
      }),
      metric("final_stress", "MPa", "stress at the end of the strain path", [](const Curve& c) { return c.curve.back().stress; }),
      metric("max_abs_stress", "MPa", "largest |stress| along the curve", [](const Curve& c) {
        double m = 0.0;
        for (const auto& p : c.curve) m = std::max(m, std::abs(p.stress));
        return m;
      }),
      metric("final_eqps", "", "equivalent plastic strain at the end", [](const Curve& c) { return c.curve.back().eqps; }),
      metric("final_thickness_strain", "", "thickness strain at the end", [](const Curve& c) { return c.curve.back().thickness_strain; }),
  };
}

SceneKind material_point_kind(MaterialPointKind kind, const char* doc) {
  SceneKind k;
  k.name = to_string(kind);
  k.family = "material_point";
  k.doc = doc;
  k.parallel_sweeps = true;
  k.jets = true;
  k.read = [](const std::string& file) -> std::unique_ptr<Scene> {
    MaterialPointScene s = read_material_point_scene(file);
    std::string name = to_string(s.setup.kind);
    const auto* table = &material_point_inputs(s.setup.kind);
    return std::make_unique<MaterialPointSceneFile>(std::move(name), std::move(s), table);
  };
  k.inputs = material_point_inputs(kind).infos();
  k.observables = material_point_observables();
  return k;
}

}  // namespace

std::vector<SceneKind> material_point_kinds() {
  return {material_point_kind(MaterialPointKind::tensile, "uniaxial stress at an angle to the rolling direction, plane stress (App. C)"),
          material_point_kind(MaterialPointKind::shear, "simple shear in the sheet plane (App. C)"),
          material_point_kind(MaterialPointKind::bauschinger, "simple shear with reversals (§C.3.1)"),
          material_point_kind(MaterialPointKind::plane_strain, "plane strain tension (a check of the yield locus)"),
          material_point_kind(MaterialPointKind::biaxial, "biaxial stress at a given ratio (a check of the yield locus)")};
}

}  // namespace spifit::scene
