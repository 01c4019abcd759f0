#include "forward/scenes/material_point/material_point_scene.hpp"

#include "forward/io/csv_writer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace spifit::scene {

using nlohmann::json;

std::string curve_csv(const MaterialPointResult<double>& r) {
  io::CsvTable t({"increment", "segment", "strain", "cumulative_strain", "stress", "stress_kirchhoff", "eps_ll",
                  "eps_ww", "gamma_lw", "eps_zz", "sig_xx", "sig_yy", "sig_xy", "eps_p_xx", "eps_p_yy", "gamma_p_xy",
                  "eps_p_zz", "X_xx", "X_yy", "X_zz", "X_xy", "eqps"});
  for (const auto& p : r.curve) {
    t.add_row({double(p.increment), double(p.segment), p.control_strain, p.cumulative_strain, p.stress,
               p.stress_kirchhoff, p.strain_loading(0), p.strain_loading(1), p.strain_loading(2), p.thickness_strain,
               p.stress_material(0), p.stress_material(1), p.stress_material(2), p.plastic_strain(0),
               p.plastic_strain(1), p.plastic_strain(2), -(p.plastic_strain(0) + p.plastic_strain(1)),
               p.back_stress(0), p.back_stress(1), p.back_stress(2), p.back_stress(3), p.eqps});
  }
  return t.str();
}

namespace {

json base_summary(const MaterialPointScene& scene) {
  json s;
  s["spifit_version"] = SPIFIT_VERSION;
  s["kind"] = to_string(scene.setup.kind);
  s["scene"] = scene.name;
  s["scene_file"] = scene.file;
  s["material"] = scene.card.name;
  s["material_file"] = scene.card.file;
  s["angle_deg"] = scene.setup.angle_deg;
  s["strain_path"] = scene.setup.strain_path;
  s["increments_requested"] = scene.setup.increments;
  s["units"] = {{"stress", "MPa (true/Cauchy unless *_kirchhoff)"},
                {"strain", scene.setup.kind == MaterialPointKind::shear || scene.setup.kind == MaterialPointKind::bauschinger
                               ? "engineering shear strain gamma_lw (integral of 2 D_lw, axes fixed)"
                               : "logarithmic strain eps_ll"},
                {"wall_seconds", "s"}};
  return s;
}

void add_yield(json& s, const MaterialPointScene& scene, const MaterialPointResult<double>& r) {
  json yp = json::array();
  for (const auto& e : r.yield_events)
    yp.push_back({{"segment", e.segment}, {"strain", e.control_strain}, {"stress", e.stress}, {"stress_kirchhoff", e.stress_kirchhoff}});
  s["yield_points"] = yp;
  if (!r.yield_events.empty()) {
    s["initial_yield_stress"] = r.yield_events.front().stress;
    s["initial_yield_stress_kirchhoff"] = r.yield_events.front().stress_kirchhoff;
    s["initial_yield_strain"] = r.yield_events.front().control_strain;
  }
  for (const auto& e : r.yield_events) {
    if (e.segment == 1) {
      s["reverse_yield_stress"] = e.stress;
      break;
    }
  }
  if (scene.setup.kind == MaterialPointKind::tensile) {
    s["r_value_strain"] = scene.setup.r_value_strain;
    s["r_value"] = r.r_value ? json(*r.r_value) : json(nullptr);
    s["yield_offset_strain"] = scene.setup.offset_strain;
    s["yield_stress"] = r.offset_yield_stress ? json(*r.offset_yield_stress) : json(nullptr);
    s["yield_stress_kirchhoff"] = r.offset_yield_stress_kirchhoff ? json(*r.offset_yield_stress_kirchhoff) : json(nullptr);
    s["yield_stress_total_strain"] = r.offset_yield_stress ? json(r.offset_yield_strain) : json(nullptr);
  }
}

}  // namespace

json MaterialPointSceneResult::to_json() const {
  json s = base_summary(scene);
  add_status(s);
  const auto& r = result;
  s["increments"] = r.curve.empty() ? 0 : r.curve.back().increment;
  s["substeps"] = r.substeps;
  s["cutbacks"] = r.cutbacks;
  s["newton_iterations"] = r.newton_iterations;
  s["accuracy_limited_substeps"] = r.accuracy_limited_substeps;
  if (r.accuracy_limited_substeps > 0) {
    s["warning"] = std::to_string(r.accuracy_limited_substeps) +
                   " sub-steps exceeded the kinematic accuracy bound (max_substeps reached); raise [solver] max_substeps for accuracy";
  }
  if (!ok()) return s;
  const auto& last = r.curve.back();
  double max_stress = 0.0;
  for (const auto& p : r.curve) max_stress = std::max(max_stress, std::abs(p.stress));
  s["final_strain"] = last.control_strain;
  s["final_stress"] = last.stress;
  s["max_abs_stress"] = max_stress;
  s["final_eqps"] = last.eqps;
  s["final_thickness_strain"] = last.thickness_strain;
  add_yield(s, scene, r);
  return s;
}

std::string MaterialPointSceneResult::brief_report() const {
  char buf[400];
  int n = std::snprintf(buf, sizeof buf, "%-16s %-12s %-14s", scene.name.c_str(), to_string(scene.setup.kind).c_str(), scene.card.name.c_str());
  auto add = [&](const char* fmt, auto... v) {
    if (n >= 0 && static_cast<std::size_t>(n) < sizeof buf) n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), fmt, v...);
  };
  const auto& r = result;
  if (!ok() || r.curve.empty()) return std::string(buf) + "  failed: " + message;
  if (r.r_value) add("  r(%.2f) = %.4f", scene.setup.r_value_strain, *r.r_value);
  if (!r.yield_events.empty()) add("  sigma_y0 = %.3f", r.yield_events.front().stress);
  if (r.offset_yield_stress) add("  sigma_0.2 = %.3f", *r.offset_yield_stress);
  for (const auto& e : r.yield_events)
    if (e.segment == 1) {
      add("  reverse yield = %.3f", e.stress);
      break;
    }
  add("  final stress = %.3f MPa at strain %.3f  (%.2f ms, %d increments)", r.curve.back().stress, r.curve.back().control_strain,
      1e3 * wall_seconds, r.curve.back().increment);
  return buf;
}

MaterialPointSceneResult run_material_point_scene(const MaterialPointScene& scene, const RunFiles& files) {
  MaterialPointSceneResult out;
  out.scene = scene;
  json running = base_summary(scene);
  running["status"] = "running";
  files.write("summary.json", running.dump(2) + "\n");
  const auto t0 = std::chrono::steady_clock::now();
  try {
    out.result = run_material_point(scene.card.params, scene.setup);
  } catch (const std::exception& e) {
    out.result.ok = false;
    out.result.message = e.what();
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.status = out.result.ok ? RunStatus::ok : RunStatus::failed;
  out.message = out.result.message;
  if (files.enabled()) {
    if (out.ok()) files.write("curve.csv", curve_csv(out.result));
    else files.directory()->remove_file("curve.csv");
  }
  files.write("summary.json", out.to_json().dump(2) + "\n");
  return out;
}

}  // namespace spifit::scene
