#include "cli/commands.hpp"

#include "cli/cli_errors.hpp"
#include "cli/progress_meter.hpp"
#include "cli/run_signals.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_card.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/sensitivity_brief.hpp"
#include "forward/scenes/common/sensitivity_check.hpp"
#include "forward/scenes/sensitivity_refusal.hpp"
#include "forward/scenes/input_reference.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "reports/card_export.hpp"
#include "reports/run_report.hpp"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

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

namespace {

// What `run` prints of an FE run's progress: every line with --verbose; without it (unless
// --quiet) the progress meter, whose last line *meter ends.
scene::ProgressSink progress_sink(const GlobalOptions& g, std::shared_ptr<ProgressMeter>* meter) {
  if (g.verbose) {
    return [](const scene::ProgressEvent& e) {
      if (!e.text.empty()) std::fprintf(stderr, "  %s\n", e.text.c_str());
    };
  }
  if (g.quiet) return {};
  auto m = std::make_shared<ProgressMeter>(::isatty(STDERR_FILENO) != 0);
  *meter = m;
  const auto t0 = std::chrono::steady_clock::now();
  return [m, t0](const scene::ProgressEvent& e) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (const auto text = m->update(e.fraction, elapsed, e.load)) std::fputs(text->c_str(), stderr);
  };
}

// FE runs: report.md and report.html with plots, of a failed or interrupted run too (what it
// did so far). A report that cannot be written is a warning, never a failed run.
void write_run_report(const io::OutputDirectory& dir) {
  if (!reports::is_fe_run_directory(dir.path())) return;
  try {
    const auto report = reports::render_run_report(dir.path());
    dir.record();  // report.md, report.html, plots/ in the manifest
    for (const auto& w : report.warnings) std::cerr << "spifit: warning: " << w << "\n";
  } catch (const std::exception& e) {
    std::cerr << "spifit: warning: no run report: " << e.what() << "\n";
  }
}

// Before the output directory is touched: the kind, friction, the names against the card, and the
// model's own refusals (sensitivity_refusal.hpp).
void refuse_sensitivities_early(const scene::Scene& scene, const std::vector<std::string>& names) {
  if (const auto r = scene::sensitivity_refusal(scene, names)) {
    const std::string why = r->key == "--sensitivities" ? r->why : "--sensitivities: " + r->why;
    throw io::InputError(scene.file(), r->key, r->value, why);
  }
}

}  // namespace

void add_run_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string scene, out; bool force = false, resume = false; std::vector<std::string> sensitivities; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("run", "Run a scene file and write DIR/summary.json and the scene's outputs (curve.csv for material points; "
                                        "increments.csv and vtu/ for shell benchmarks; force.csv, energies.csv, sections and vtu/ for FE scenes)");
  cmd->add_option("SCENE", o->scene, "scene file (TOML)")->required();
  cmd->add_option("--out", o->out, "output directory")->required();
  auto* force = cmd->add_flag("--force", o->force, "replace an existing output directory");
  cmd->add_flag("--resume", o->resume, "continue the run in DIR from its last checkpoint (FE scenes)")->excludes(force);
  cmd->add_option("--sensitivities", o->sensitivities,
                  "material parameters, contact.penalty and contact.friction, comma-separated (e.g. swift.K,elastic.E): write the tool force's exact derivatives "
                  "with respect to them to DIR/sensitivities.csv (implicit FE scenes: indent, indent_line, line and cone); with --resume, "
                  "the parameters the run started with")
      ->delimiter(',');
  cmd->callback([o, &g, &exit_code] {
    const auto scene = scene::read_scene(o->scene);  // input errors before touching --out
    if (!g.quiet)
      for (const auto& w : scene->input_warnings()) std::cerr << "spifit: warning: " << o->scene << ": " << w << "\n";
    const scene::SceneKind* kind = scene::find_scene_kind(scene->kind());
    if (o->resume && !kind->resumable)
      throw io::InputError(o->scene, "--resume", "", "not supported for scene kind " + scene->kind() + " (it writes no checkpoints)");
    if (!o->sensitivities.empty()) refuse_sensitivities_early(*scene, o->sensitivities);
    const auto dir = o->resume ? existing_output(o->out, o->scene, g.quiet) : prepare_output(o->out, o->force, scene->input_files(), g.quiet);
    scene::RunControl control;
    control.resume = o->resume;  // the checkpoint is checked before any output is rewritten
    control.sensitivities = o->sensitivities;
    std::shared_ptr<ProgressMeter> meter;
    control.progress = progress_sink(g, &meter);
    // SIGINT/SIGTERM end an FE run at the end of an increment, with a checkpoint to resume from;
    // the other kinds take seconds and end as they would without spifit's handler.
    std::optional<InterruptHandlers> handlers;
    if (kind->resumable) {
      handlers.emplace();
      control.interrupt = &interrupt_signal();
    }
    const auto result = scene->run(scene::RunFiles(dir), control);
    handlers.reset();
    if (meter)
      if (const auto end = meter->finish()) std::fputs(end->c_str(), stderr);
    write_run_report(dir);
    if (result->status == scene::RunStatus::interrupted) {
      const int sig = interrupt_signal().load();
      std::cerr << "spifit: " << scene->name() << " " << result->message << "; resume with: spifit run " << o->scene << " --out " << o->out
                << " --resume\n";
      exit_code = interrupted_exit_code(sig);
      return;
    }
    if (!result->ok()) {
      std::cerr << "spifit: " << scene->name() << " failed: " << result->message << "\n";
      exit_code = 1;
      return;
    }
    if (!g.quiet) {
      std::printf("%s\n", result->brief_report().c_str());
      std::printf("%s", scene::sensitivity_brief(*result).c_str());
      for (const auto& w : result->warnings) std::printf("  warning: %s\n", w.c_str());
    }
    exit_code = 0;
  });
}

void add_check_sensitivities_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string scene; std::vector<std::string> names; double relative_step = 1e-4, tolerance = 0.0; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("check-sensitivities",
                                 "Compare a scene's exact tool-force derivatives (run --sensitivities) with central differences of whole runs "
                                 "(steps h and h/4); exit 1 when one lies outside the central differences' own spread");
  cmd->add_option("SCENE", o->scene, "scene file (TOML): an implicit indent, indent_line, line or cone scene")->required();
  cmd->add_option("--sensitivities", o->names, "material parameters, contact.penalty and contact.friction, comma-separated (e.g. swift.K,elastic.E)")->delimiter(',')->required();
  cmd->add_option("--relative-step", o->relative_step, "h as a fraction of each parameter's value (default 1e-4)")->check(CLI::Range(1e-12, 0.1));
  cmd->add_option("--tolerance", o->tolerance, "force and displacement tolerance of every run's Newton solver instead of the scene's (e.g. 1e-10 with friction; default 0: the scene's)")
      ->check(CLI::Range(0.0, 1e-3));
  cmd->callback([o, &g, &exit_code] {
    const auto scene = scene::read_scene(o->scene);
    refuse_sensitivities_early(*scene, o->names);
    std::string joined;
    for (const auto& n : o->names) joined += (joined.empty() ? "" : ",") + n;
    scene::SensitivityCheck c;
    try {
      c = scene::check_sensitivities(*scene, o->names, o->relative_step, o->tolerance, [&g](const std::string& what) {
        if (!g.quiet) std::cerr << "spifit: running " << what << "\n";
      });
    } catch (const std::invalid_argument& e) {
      throw io::InputError(o->scene, "--sensitivities", joined, e.what());
    }
    std::printf("%s", scene::format_sensitivity_check(c).c_str());
    exit_code = c.agrees() ? 0 : 1;
  });
}

void add_inputs_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string kind; bool markdown = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("inputs", "List the scene kinds, or one kind's keys (unit, valid values, meaning) and observables");
  cmd->add_option("KIND", o->kind, "a scene kind (e.g. cone); none: every kind");
  cmd->add_flag("--markdown", o->markdown, "print the whole reference as Markdown (docs/reference/input-reference.md)");
  cmd->callback([o, &g, &exit_code] {
    exit_code = 0;
    if (o->markdown) {
      std::cout << scene::input_reference_markdown();
      return;
    }
    if (o->kind.empty()) {
      if (g.quiet) return;
      for (const auto& k : scene::scene_kinds())
        std::printf("%-16s %-16s %s%s\n", k.name.c_str(), k.family.c_str(), k.doc.c_str(), k.resumable ? " [resumable]" : "");
      return;
    }
    const scene::SceneKind* k = scene::find_scene_kind(o->kind);
    if (!k) throw io::InputError("", "KIND", o->kind, "unknown scene kind (known: " + scene::scene_kind_names() + ")");
    if (!g.quiet) std::cout << scene::kind_reference_markdown(*k);
  });
}

}  // namespace spifit::cli
