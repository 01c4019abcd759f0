#include "cli/commands.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_card.hpp"
#include "forward/scenes/material_point_scene.hpp"
#include "forward/scenes/cone_scene.hpp"
#include "forward/scenes/forming_scene.hpp"
#include "forward/scenes/shell_benchmark_scene.hpp"
#include "reports/card_export.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <iostream>
#include <memory>

namespace spifit::cli {

namespace {
// r-values must be positive numbers; CLI11's PositiveNumber would print its whole range.
const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && v > 0 && std::isfinite(v)) return "";
      } catch (const std::exception&) {
      }
      return "must be a number > 0, got '" + text + "'";
    },
    "NUMBER > 0");
}  // namespace

void add_lankford_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { double r0 = 0, r45 = 0, r90 = 0; bool json = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("lankford", "Hill 1948 coefficients from Lankford r-values (thesis eq. C.3, G + H = 2, N = L = M)");
  cmd->add_option("--r0", o->r0, "r-value at 0 deg to RD")->required()->check(kPositive);
  cmd->add_option("--r45", o->r45, "r-value at 45 deg to RD")->required()->check(kPositive);
  cmd->add_option("--r90", o->r90, "r-value at 90 deg to RD")->required()->check(kPositive);
  cmd->add_flag("--json", o->json, "print JSON (keys F, G, H, N, L, M)");
  cmd->callback([o, &g, &exit_code] {
    const auto h = material::hill_from_lankford({o->r0, o->r45, o->r90});
    const auto a = material::abaqus_potential_from_hill(h);
    if (o->json) {
      nlohmann::json j{{"F", h.F}, {"G", h.G}, {"H", h.H}, {"N", h.N}, {"L", h.L}, {"M", h.M},
                       {"abaqus_potential", {{"R11", a.R11}, {"R22", a.R22}, {"R33", a.R33}, {"R12", a.R12}, {"R13", a.R13}, {"R23", a.R23}}}};
      std::cout << j.dump(2) << "\n";
    } else if (!g.quiet) {
      std::printf("Hill 1948 (thesis notation, G + H = 2, N = L = M) from r0 = %g, r45 = %g, r90 = %g:\n", o->r0, o->r45, o->r90);
      std::printf("  F = %.4f  G = %.4f  H = %.4f  N = L = M = %.4f\n", h.F, h.G, h.H, h.N);
      std::printf("Abaqus *POTENTIAL: R11 = %.4f  R22 = %.4f  R33 = %.4f  R12 = R13 = R23 = %.4f\n", a.R11, a.R22, a.R33, a.R12);
    }
    exit_code = 0;
  });
}

void add_material_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  auto* cmd = app.add_subcommand("material", "Inspect material cards");
  cmd->require_subcommand(1);
  auto card = std::make_shared<std::string>();
  auto* show = cmd->add_subcommand("show", "Summary of a card: parameters, initial yield stress, predicted r-values");
  show->add_option("CARD", *card, "material card (TOML)")->required();
  show->callback([card, &g, &exit_code] {
    const auto c = material::load_material_card(*card);
    if (!g.quiet) std::cout << material::describe_material_card(c);
    exit_code = 0;
  });

  struct ExportOpts { std::string card, format, out; bool force = false; };
  auto eo = std::make_shared<ExportOpts>();
  auto* exp = cmd->add_subcommand("export", "Write a card for another FE code (Abaqus, LS-DYNA, CalculiX); approximations are stated");
  exp->add_option("CARD", eo->card, "material card (TOML)")->required();
  exp->add_option("--format", eo->format, "abaqus | lsdyna | calculix")->required();
  exp->add_option("-o,--out", eo->out, "file to write (default: print to stdout)");
  exp->add_flag("--force", eo->force, "overwrite an existing file");
  exp->callback([eo, &g, &exit_code] {
    reports::ExportFormat f;
    if (!reports::export_format_from_string(eo->format, &f)) throw io::InputError("", "--format", eo->format, "unknown format (abaqus, lsdyna, calculix)");
    const auto c = material::load_material_card(eo->card);
    std::vector<std::string> notes;
    const std::string deck = reports::export_card(c, f, &notes);
    if (eo->out.empty()) {
      std::cout << deck;
    } else {
      if (std::filesystem::exists(eo->out) && !eo->force) throw io::InputError("", "--out", eo->out, "file exists; pass --force to overwrite");
      std::ofstream(eo->out) << deck;
      if (!g.quiet) {
        std::cout << "wrote " << eo->out << " (" << reports::to_string(f) << ")\n";
        for (const auto& n : notes) std::cout << "  note: " << n << "\n";
      }
    }
    exit_code = 0;
  });
}

void add_run_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string scene, out; bool force = false, resume = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("run", "Run a scene file and write DIR/summary.json (+ DIR/curve.csv for material points; increments.csv and vtu/ for shell benchmarks; force.csv and vtu/ for forming and cone scenes)");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_option("--out", o->out, "output directory")->required();
  auto* force = cmd->add_flag("--force", o->force, "replace an existing output directory");
  cmd->add_flag("--resume", o->resume, "continue the run in DIR from its last checkpoint (cone scenes)")->excludes(force);
  cmd->callback([o, &g, &exit_code] {
    const std::string kind = scene::scene_kind(o->scene);
    if (o->resume && !scene::is_cone_kind(kind))
      throw io::InputError(o->scene, "--resume", "", "not supported for scene kind " + kind + " (only cone scenes write checkpoints)");
    if (scene::is_forming_kind(kind)) {
      const auto fs = scene::read_forming_scene(o->scene);  // input errors before touching --out
      std::vector<std::string> inputs{fs.file, fs.card.file};
      if (!fs.gcode.empty()) inputs.push_back(fs.gcode);
      const auto dir = io::OutputDirectory::prepare(o->out, o->force, inputs);
      const auto rep = scene::run_forming_scene(fs, dir, g.verbose);
      const auto& s = rep.summary;
      if (!rep.ok) {
        std::cerr << "spifit: " << fs.name << " failed: " << s.value("message", std::string("?")) << "\n";
        exit_code = 1;
        return;
      }
      if (!g.quiet) {
        const auto& pk = s["peak_force"];
        std::printf("%-16s %-12s peak force (%.2f, %.2f, %.2f) N, max penetration %.4f mm  (%d elements, %d increments, %d iterations, %.2f s)\n",
                    fs.name.c_str(), kind.c_str(), pk[0].get<double>(), pk[1].get<double>(), pk[2].get<double>(),
                    s["max_penetration"].get<double>(), s["model"]["elements"].get<int>(), s["increments"].get<int>(),
                    s["newton_iterations"].get<int>(), s["wall_seconds"].get<double>());
        for (const auto& w : s["warnings"]) std::printf("  warning: %s\n", w.get<std::string>().c_str());
      }
      exit_code = 0;
      return;
    }
    if (scene::is_cone_kind(kind)) {
      const auto cs = scene::read_cone_scene(o->scene);  // input errors before touching --out
      const auto dir = o->resume ? io::OutputDirectory::existing(o->out) : io::OutputDirectory::prepare(o->out, o->force, {cs.file, cs.card.file});
      scene::ConeRunOptions ro;
      ro.progress = g.verbose;
      ro.resume = o->resume;  // the checkpoint is checked before any output is rewritten
      const auto rep = scene::run_cone_scene(cs, dir, ro);
      const auto& s = rep.summary;
      if (!rep.ok) {
        std::cerr << "spifit: " << cs.name << " failed: " << s.value("message", std::string("?")) << "\n";
        exit_code = 1;
        return;
      }
      if (!g.quiet) {
        const auto& pk = s["peak_force"];
        const auto& fp = s["final_polar_force"];
        std::printf("%-16s %-12s peak force (%.2f, %.2f, %.2f) N, final (Fr, Ftheta, Fz) (%.2f, %.2f, %.2f) N, %d/%d contours  (%d elements, %d increments, %d iterations, %.2f s)\n",
                    cs.name.c_str(), kind.c_str(), pk[0].get<double>(), pk[1].get<double>(), pk[2].get<double>(), fp[0].get<double>(),
                    fp[1].get<double>(), fp[2].get<double>(), s["contours_completed"].get<int>(), s["contours_total"].get<int>(),
                    s["model"]["elements"].get<int>(), s["increments"].get<int>(), s["newton_iterations"].get<int>(),
                    s["wall_seconds"].get<double>());
        for (const auto& w : s["warnings"]) std::printf("  warning: %s\n", w.get<std::string>().c_str());
      }
      exit_code = 0;
      return;
    }
    if (kind == "shell_benchmark") {
      const auto sb = scene::read_shell_benchmark_scene(o->scene);  // input errors before touching --out
      const auto dir = io::OutputDirectory::prepare(o->out, o->force, {sb.file});
      const auto rep = scene::run_shell_benchmark_scene(sb, dir, g.verbose);
      const auto& s = rep.summary;
      if (!rep.ok) {
        std::cerr << "spifit: " << sb.name << " failed: " << s.value("message", std::string("?")) << "\n";
        exit_code = 1;
        return;
      }
      if (!g.quiet) {
        std::printf("%-28s %-26s value %.6g  reference %.6g  error %+.3f %%  (%d elements, %d increments, %d iterations, %.3f s)\n",
                    sb.name.c_str(), s["benchmark"].get<std::string>().c_str(), s["value"].get<double>(),
                    s["reference"].get<double>(), 100.0 * s["relative_error"].get<double>(), s["mesh"]["elements"].get<int>(),
                    s["solver"]["increments"].get<int>(), s["solver"]["iterations"].get<int>(), s["wall_seconds"].get<double>());
        for (const auto& w : s["warnings"]) std::printf("  warning: %s\n", w.get<std::string>().c_str());
      }
      exit_code = 0;
      return;
    }
    const auto scene = scene::read_scene_file(o->scene);  // input errors before touching --out
    const auto dir = io::OutputDirectory::prepare(o->out, o->force, {scene.file, scene.card.file});
    const auto rep = scene::run_material_point_scene(scene, dir);
    const auto& s = rep.summary;
    if (!rep.ok) {
      std::cerr << "spifit: " << scene.name << " failed: " << s.value("message", std::string("?")) << "\n";
      exit_code = 1;
      return;
    }
    if (!g.quiet) {
      std::printf("%-16s %-12s %-14s", scene.name.c_str(), s["kind"].get<std::string>().c_str(), scene.card.name.c_str());
      if (s.contains("r_value") && !s["r_value"].is_null()) std::printf("  r(%.2f) = %.4f", s["r_value_strain"].get<double>(), s["r_value"].get<double>());
      if (s.contains("initial_yield_stress")) std::printf("  sigma_y0 = %.3f", s["initial_yield_stress"].get<double>());
      if (s.contains("yield_stress") && !s["yield_stress"].is_null()) std::printf("  sigma_0.2 = %.3f", s["yield_stress"].get<double>());
      if (s.contains("reverse_yield_stress")) std::printf("  reverse yield = %.3f", s["reverse_yield_stress"].get<double>());
      std::printf("  final stress = %.3f MPa at strain %.3f  (%.2f ms, %d increments)\n", s["final_stress"].get<double>(),
                  s["final_strain"].get<double>(), 1e3 * s["wall_seconds"].get<double>(), s["increments"].get<int>());
      if (g.verbose) std::printf("  -> %s/summary.json, %s/curve.csv\n", o->out.c_str(), o->out.c_str());
    }
    exit_code = 0;
  });
}

}  // namespace spifit::cli
