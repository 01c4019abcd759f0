// `spifit fit` and `spifit synth`: thin wrappers over inverse/.
#include "cli/commands.hpp"
#include "cli/cli_errors.hpp"
#include "cli/fit_progress_lines.hpp"
#include "cli/job_process.hpp"
#include "cli/mpi_session.hpp"
#include "cli/run_signals.hpp"

#include "forward/material/material_inputs.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/run_status.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/fit/run_fit.hpp"
#include "inverse/fit/fit_algorithms.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/runs/evaluation_cache.hpp"
#include "inverse/runs/fe_evaluation_job.hpp"
#include "inverse/fit/fit_output.hpp"
#include "inverse/sweeps/sweep.hpp"
#include "inverse/experiments/synthetic.hpp"
#include "reports/card_export.hpp"
#include "reports/fit_report.hpp"
#include "reports/run_report.hpp"
#include "reports/sweep_directory.hpp"
#include "reports/sweep_report.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

namespace spifit::cli {

namespace {

// Runs f; an exception ends the watch and leaves summary.json with status "failed" and the
// exception's message (not "running" with a heartbeat that stops) before it goes on.
template <typename F>
auto failed_on_error(scene::RunHeartbeat& heartbeat, RunWatch& watch, F f) {
  try {
    return f();
  } catch (const std::exception& e) {
    watch.stop();
    nlohmann::json j = heartbeat.running();
    for (const char* k : {"pid", "host", "heartbeat", "heartbeat_interval"}) j.erase(k);
    j["status"] = scene::to_string(scene::RunStatus::failed);
    j["message"] = e.what();
    heartbeat.finish(j);
    throw;
  }
}

}  // namespace

namespace {

// The fitted card for production FE codes (approximations stated in each deck): DIR/exports/
// with notes.json; a deck that cannot be written is a note, not a failed fit. suffix: the end of
// the deck names ("_NOT_USABLE" for a fit that is not usable).
void write_card_exports(const material::MaterialCard& card, const std::string& suffix, const io::OutputDirectory& dir) {
  nlohmann::json export_notes = nlohmann::json::object();
  for (auto f : {reports::ExportFormat::abaqus, reports::ExportFormat::lsdyna, reports::ExportFormat::calculix}) {
    std::vector<std::string> notes;
    const std::string name = "exports/card_" + reports::to_string(f) + suffix + reports::default_extension(f);
    try {
      dir.write_file(name, reports::export_card(card, f, &notes));
      export_notes[name] = notes;
    } catch (const std::exception& e) {
      export_notes[name] = std::vector<std::string>{std::string("export failed: ") + e.what()};
    }
  }
  dir.write_file("exports/notes.json", export_notes.dump(2) + "\n");
}

}  // namespace

namespace {

std::string join(const std::vector<std::string>& texts, const std::string& sep) {
  std::string out;
  for (const auto& t : texts) out += (out.empty() ? "" : sep) + t;
  return out;
}

// The command line of a worker rank's job process: quiet, the rank's --threads.
std::vector<std::string> job_args(const GlobalOptions& g, std::vector<std::string> command) {
  std::vector<std::string> args{"-q"};
  if (g.threads > 0) args.insert(args.end(), {"--threads", std::to_string(g.threads)});
  args.insert(args.end(), command.begin(), command.end());
  return args;
}

void note_on_stderr(const std::string& why) { std::cerr << "spifit: rank " << mpi::rank() << ": " << why << "\n"; }

// The FE runs of a fit on rank 0 (or in one process): their evaluations kept as they finish
// (DIR/runs/evaluations.jsonl) for --resume, and the workers of an MPI job.
void prepare_fe_runs(const inverse::FitProblem& problem, const io::OutputDirectory& dir, bool resume, bool quiet) {
  auto cache = std::make_shared<inverse::EvaluationCache>(dir.path() / "runs" / "evaluations.jsonl",
                                                         inverse::files_signature(problem.input_files), resume);
  if (resume && !quiet) std::cout << "resuming: " << cache->loaded() << " FE evaluations read back\n";
  problem.scene_runs->keep_evaluations(std::move(cache));
  dir.record();  // runs/ in the manifest
  if (auto pool = mpi::pool()) {
    problem.scene_runs->use_pool(pool);
    if (!quiet) std::cout << "MPI: FE evaluations on " << pool->workers() << " worker rank(s)\n";
  }
}

// A worker rank of an MPI fit: answers FE evaluations, each in a process of its own, until rank
// 0 stops it. A job may hold a run and its retry with half the increment: its process is stopped
// after 2.5 run time limits and a minute.
void serve_fit_jobs(const inverse::FitProblem& problem, const GlobalOptions& g, const std::string& fit_file) {
  if (!problem.scene_runs) return;
  const double limit = problem.settings.run_time_limit;
  mpi::serve(jobs_in_child_processes(job_args(g, {"job", "--fit", fit_file}), limit > 0 ? 2.5 * limit + 60.0 : 0.0,
                                     [](const std::string&, const std::string& why) { return inverse::failed_fe_answer(why); },
                                     note_on_stderr));
}

}  // namespace

void add_fit_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string file, out, algorithm; bool force = false, resume = false; unsigned seed = 42; int multistart = 0; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("fit", "Identify material parameters: fit a card to the experiments of a fit file (Ceres)");
  cmd->add_option("FIT", o->file, "fit file (TOML)")->required();
  cmd->add_option("--out", o->out, "output directory (fit.json, card.toml, experiments/*.csv)")->required();
  cmd->add_option("--algorithm", o->algorithm, "override the fit file: " + inverse::fit_algorithm_names());
  cmd->add_flag("--force", o->force, "replace an existing spifit output directory");
  cmd->add_flag("--resume", o->resume, "continue a killed fit in its output directory: the FE evaluations it finished are read back, not run")
      ->excludes("--force");
  cmd->add_option("--seed", o->seed, "seed of NLopt's stochastic algorithms and of multi-start draws (default 42)");
  cmd->add_option("--multistart", o->multistart, "number of starts (overrides [fit] multistart)")->check(CLI::Range(1, 10000));
  cmd->callback([o, &g, &exit_code] {
    if (!o->algorithm.empty() && !inverse::is_fit_algorithm(o->algorithm)) {
      throw io::InputError("", "--algorithm", o->algorithm, "unknown algorithm (known: " + inverse::fit_algorithm_names() + ")");
    }
    const auto problem = inverse::read_fit_file(o->file);
    if (mpi::is_worker()) {  // another rank of an MPI job: the FE evaluations rank 0 hands out
      serve_fit_jobs(problem, g, o->file);
      exit_code = 0;
      return;
    }
    const auto dir = o->resume ? existing_output(o->out, o->file, g.quiet) : prepare_output(o->out, o->force, problem.input_files, g.quiet);
    if (problem.scene_runs) {
      prepare_fe_runs(problem, dir, o->resume, g.quiet);
    } else if (o->resume) {
      throw io::InputError(o->file, "experiment", "", "--resume continues fits with FE experiments (the others take seconds)");
    }
    // The running summary with pid, host and a heartbeat; SIGINT/SIGTERM end the fit at once with
    // status "interrupted", the FE evaluations that finished kept for --resume.
    scene::RunHeartbeat heartbeat(scene::RunFiles(dir), {{"kind", "fit"}, {"fit", problem.name}, {"fit_file", o->file}});
    const auto runs = problem.scene_runs;
    // Its iterations and FE runs: lines on stderr (unless --quiet) and the running summary.
    auto lines = std::make_shared<FitProgressLines>(::isatty(STDERR_FILENO) != 0);
    auto print_lock = std::make_shared<std::mutex>();
    const bool quiet = g.quiet;
    auto fit_progress = std::make_shared<inverse::FitProgress>([lines, print_lock, quiet](const inverse::FitProgressEvent& e) {
      if (quiet) return;
      std::lock_guard<std::mutex> lock(*print_lock);
      if (const auto text = lines->update(e)) std::fputs(text->c_str(), stderr);
    });
    auto progress = [fit_progress] { return fit_progress_json(fit_progress->snapshot()); };
    RunWatch watch(heartbeat, progress, [&heartbeat, runs, progress, o](int sig) {
      nlohmann::json j = heartbeat.running();
      for (const char* k : {"pid", "host", "heartbeat", "heartbeat_interval"}) j.erase(k);
      j["status"] = scene::to_string(scene::RunStatus::interrupted);
      j["progress"] = progress();
      j["message"] = "interrupted by " + signal_name(sig) +
                     (runs ? "; the FE evaluations that finished are kept in runs/evaluations.jsonl: resume with spifit fit " + o->file + " --out " +
                                 o->out + " --resume"
                           : " (a fit of material points takes seconds and does not resume: run it again with --force)");
      return j;
    });
    heartbeat.write();  // once the signals are handled
    // Under MPI too Ceres gets --threads threads, as in one process (fits with other thread
    // counts agree to about 1e-10, not to the bit); the FE evaluations of a Jacobian go to the
    // workers all at once (parallel_evaluations).
    const int threads = g.threads > 0 ? g.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const auto result =
        failed_on_error(heartbeat, watch, [&] { return inverse::run_fit(problem, {o->algorithm, threads, o->seed, o->multistart, fit_progress}); });
    {
      std::lock_guard<std::mutex> lock(*print_lock);
      if (const auto end = lines->finish(); end && !g.quiet) std::fputs(end->c_str(), stderr);
    }
    const auto card = inverse::write_fit_outputs(problem, result, dir);
    const std::string suffix = inverse::fitted_file_suffix(result.usable);
    write_card_exports(card, suffix, dir);
    // Report for people: report.md, report.html, plots/*.svg (gnuplot; without it, no plots).
    const auto report = reports::render_fit_report(dir.path(), {});
    dir.record();  // report.md, report.html, plots/ in the manifest
    for (const auto& w : report.warnings) std::cerr << "spifit: warning: " << w << "\n";
    watch.stop();  // the final summary is this one
    heartbeat.stop();
    const std::string card_file = o->out + "/card" + suffix + ".toml";
    nlohmann::json summary{{"status", result.usable ? "ok" : "failed"},
                           {"kind", "fit"},
                           {"fit", problem.name},
                           {"fit_file", o->file},
                           {"wall_seconds", result.wall_seconds},
                           {"termination", result.termination}};
    if (!result.usable) summary["message"] = "the fit's result is not usable: " + join(result.not_usable, "; ");
    dir.write_file("summary.json", summary.dump(2) + "\n");
    if (!g.quiet) {
      std::cout << inverse::fit_table(problem, result);
      // The report's warnings and notes, as its red and yellow boxes list them.
      for (const auto& f : report.findings) std::cout << "WARNING: " << f << "\n";
      for (const auto& n : report.notes) std::cout << "NOTE: " << n << "\n";
      if (result.usable) std::cout << "card: " << card_file << " (report: " << o->out << "/report.html)\n";
    }
    std::cout.flush();
    if (!result.usable) {
      // The reasons are among the warnings printed above; with --quiet, here.
      std::cerr << "spifit: fit " << problem.name << ": the result is NOT USABLE";
      if (g.quiet)
        for (const auto& why : result.not_usable) std::cerr << "\n  - " << why;
      std::cerr << "\n  its card is written as " << card_file << "; do not use it as a material card (report: " << o->out << "/report.html)\n";
      exit_code = 1;
      return;
    }
    exit_code = 0;
  });
}

namespace {

// --set NAME=VALUE on a scene: io::InputError naming --set and the text when the name is not an
// input of the scene or the value is not one it can run with.
void set_scene_input(scene::Scene& sc, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw io::InputError("", "--set", assignment, "expected NAME=VALUE");
  const std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  double v = 0.0;
  try {
    std::size_t used = 0;
    v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw io::InputError("", "--set", assignment, "the value is not a number");
  }
  std::string why;
  try {
    why = sc.set_input(name, v);
  } catch (const std::invalid_argument& e) {
    why = e.what();
  }
  if (!why.empty()) throw io::InputError(sc.file(), "--set", assignment, why);
}

}  // namespace

void add_synth_command(CLI::App& app, const GlobalOptions& g, int& exit_code, const std::string& command_line) {
  struct Opts { std::string scene, out, material, section, contour_means; std::vector<std::string> set; inverse::SyntheticOptions syn; bool force = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("synth", "Write a SYNTHETIC measurement (twin experiment): a scene's curve with seeded noise");
  cmd->add_option("SCENE", o->scene, "scene file (TOML): a material point, or an FE scene with a tool")->required();
  cmd->add_option("--out", o->out, "CSV file to write")->required();
  cmd->add_option("--material", o->material, "generating card (default: the scene's)");
  cmd->add_option("--section", o->section, "a forming scene's section y = 0 at this path point instead of the tool force (x: x or x0; y: z or thickness)");
  cmd->add_option("--contour-means", o->contour_means, "a cone's central-third contour means of this component or ratio (fr, ftheta, fz, fx, fy, ftheta_over_fz, fr_over_fz) against the contour");
  cmd->add_option("--set", o->set, "NAME=VALUE: a named input of an FE scene for this run (e.g. contact.friction=0.05); repeatable");
  cmd->add_option("--x", o->syn.x, "abscissa column: strain, cumulative_strain, increment (material point; default strain); depth, travel, time (FE; default depth)");
  cmd->add_option("--y", o->syn.y, "response column: stress, eps_ww, eps_zz, ... (material point; default stress); fx, fy, fz, fr, ftheta (FE; default fz)");
  cmd->add_option("--noise", o->syn.noise, "standard deviation of the Gaussian noise on y (units of y)");
  cmd->add_option("--seed", o->syn.seed, "random seed");
  cmd->add_option("--every", o->syn.every, "keep every k-th increment");
  cmd->add_flag("--force", o->force, "overwrite an existing file");
  cmd->callback([o, &g, &exit_code, command_line, cmd] {
    const std::string kind = scene::scene_kind_of_file(o->scene);
    const scene::SceneKind* k = scene::find_scene_kind(kind);
    if (!k) (void)scene::read_scene(o->scene);  // names the unknown kind and the known ones
    if (std::filesystem::exists(o->out) && !o->force) throw io::InputError("", "--out", o->out, "file exists; pass --force to overwrite");
    o->syn.command = command_line;
    const bool fe = !k->jets;
    if (fe) {
      if (cmd->count("--x") == 0) o->syn.x = o->section.empty() ? "depth" : "x";
      if (cmd->count("--y") == 0) o->syn.y = o->section.empty() ? "fz" : "z";
    } else if (!o->section.empty()) {
      throw io::InputError("", "--section", o->section, "only for forming scenes (indent, indent_line, line)");
    }
    std::string card_name;
    const std::string csv = with_option_names({{"x", "--x"}, {"y", "--y"}, {"every", "--every"}, {"noise", "--noise"}}, [&] {
      if (!fe) {
        if (!o->set.empty()) throw io::InputError("", "--set", o->set.front(), "only for FE scenes (a material-point scene's inputs are its file's)");
        // With --material the scene's own card (or the default one) is not needed.
        scene::MaterialPointScene scene;
        try {
          scene = scene::read_material_point_scene(o->scene, o->material.empty() ? scene::AbsentMaterial::default_card : scene::AbsentMaterial::no_card);
        } catch (const io::InputError& e) {
          throw scene::with_kind_hint(e, o->scene, kind);  // [contact] in a file of kind tensile: is the kind right?
        }
        if (!o->material.empty()) scene.card = material::load_material_card(o->material);
        card_name = scene.card.name;
        return inverse::synthetic_measurement_csv(scene, o->syn);
      }
      auto scene = scene::read_scene(o->scene);
      if (!scene->tool_centre_path() || !scene->card())
        throw io::InputError(o->scene, "scene.kind", kind,
                             std::string("a scene of this kind has no ") + (scene->tool_centre_path() ? "material card" : "tool") +
                                 ": synth writes a material-point curve or the tool force (or a section) of an FE scene with a tool and a card");
      if (!o->material.empty()) *scene->card() = material::load_material_card(o->material);
      for (const std::string& a : o->set) set_scene_input(*scene, a);
      card_name = scene->card()->name;
      if (!o->contour_means.empty()) {
        o->syn.y = o->contour_means;
        return inverse::synthetic_contour_means_csv(*scene, o->syn);
      }
      return o->section.empty() ? inverse::synthetic_force_curve_csv(*scene, o->syn) : inverse::synthetic_section_csv(*scene, o->section, o->syn);
    });
    const std::string tmp = o->out + ".tmp";
    {
      std::ofstream f(tmp, std::ios::trunc);
      if (!f) throw io::InputError("", "--out", o->out, "cannot write");
      f << csv;
    }
    std::filesystem::rename(tmp, o->out);
    if (!g.quiet) std::cout << "wrote " << o->out << " (synthetic, card " << card_name << ", noise " << o->syn.noise << ", seed " << o->syn.seed << ")\n";
    exit_code = 0;
  });
}

}  // namespace spifit::cli

namespace spifit::cli {

void add_report_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string dir; bool no_plots = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("report", "Re-render report.md, report.html and plots of a fit's, a sweep's or an FE run's output directory (also a partial run)");
  cmd->add_option("DIR", o->dir, "output directory of spifit fit, spifit sweep or spifit run (indent, indent_line, line, cone)")->required();
  cmd->add_flag("--no-plots", o->no_plots, "skip the gnuplot plots");
  cmd->callback([o, &g, &exit_code] {
    reports::ReportOptions ro;
    ro.plots = !o->no_plots;
    // Opened before rendering: what is there and not in its manifest stays out of it. No lock:
    // a run still going (or killed) is reported as far as it got; the report's files are written
    // atomically and the run's own report at its end replaces them.
    std::optional<io::OutputDirectory> dir;
    if (std::filesystem::is_directory(o->dir)) dir = io::OutputDirectory::existing(o->dir, io::OutputDirectory::Locking::none);
    if (!std::filesystem::exists(std::filesystem::path(o->dir) / "fit.json") && reports::is_sweep_directory(o->dir)) {
      const auto r = reports::rerender_sweep_report(o->dir, ro.plots);
      if (dir) dir->record();
      for (const auto& w : r.warnings) std::cerr << "spifit: warning: " << w << "\n";
      if (!g.quiet) std::cout << "wrote " << r.markdown.string() << " and " << r.html.string() << "\n";
      exit_code = 0;
      return;
    }
    if (!std::filesystem::exists(std::filesystem::path(o->dir) / "fit.json") && reports::is_fe_run_directory(o->dir)) {
      const auto r = reports::render_run_report(o->dir, ro);
      if (dir) dir->record();
      for (const auto& w : r.warnings) std::cerr << "spifit: warning: " << w << "\n";
      if (!g.quiet) std::cout << "wrote " << r.markdown.string() << ", " << r.html.string() << " and " << r.plots.size() << " plots\n";
      exit_code = 0;
      return;
    }
    const auto r = reports::render_fit_report(o->dir, ro);
    if (dir) dir->record();  // plots/ when the fit had none
    for (const auto& w : r.warnings) std::cerr << "spifit: warning: " << w << "\n";
    if (!g.quiet) std::cout << "wrote " << r.markdown.string() << ", " << r.html.string() << " and " << r.plots.size() << " plots\n";
    exit_code = 0;
  });
}

namespace {

reports::SweepTable sweep_table(const inverse::SweepSpec& spec, const inverse::SweepResult& r) {
  reports::SweepTable table;
  // Units from the scene kind's inputs and observables, and the card's parameters.
  std::vector<io::InputInfo> infos = spec.kind ? spec.kind->inputs : std::vector<io::InputInfo>{};
  for (const auto& m : material::material_input_infos()) infos.push_back(m);
  for (const auto& in : spec.inputs) {
    table.inputs.push_back(in.name);
    std::string unit;
    for (const auto& info : infos)
      if (info.name == in.name) unit = info.unit;
    table.input_units.push_back(unit);
  }
  table.metrics = spec.metrics;
  for (const auto& m : spec.metrics) {
    const scene::Observable* ob = spec.kind ? spec.kind->find_observable(m) : nullptr;
    table.metric_units.push_back(ob ? ob->unit : "");
  }
  for (const auto& p : r.points) {
    table.input_values.push_back(p.inputs);
    table.metric_values.push_back(p.metrics);
    table.wall_seconds.push_back(p.wall_seconds);
    table.ok.push_back(p.ok);
  }
  return table;
}

}  // namespace

void add_sweep_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string file, out; bool force = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("sweep", "Run a scene over a grid of inputs: DIR/sweep.csv, DIR/sensitivities.csv (FE scenes: DIR/points/NNN/)");
  cmd->add_option("SWEEP", o->file, "sweep file (TOML)")->required();
  cmd->add_option("--out", o->out, "output directory")->required();
  cmd->add_flag("--force", o->force, "replace an existing spifit output directory");
  cmd->callback([o, &g, &exit_code] {
    const auto spec = inverse::read_sweep_file(o->file);
    if (mpi::is_worker()) {  // another rank of an MPI job: the points rank 0 hands out, each in a process of its own
      if (!spec.kind->parallel_sweeps)
        mpi::serve(jobs_in_child_processes(
            job_args(g, {"job", "--sweep", o->file, "--out", o->out}), 0.0,
            [&spec](const std::string& job, const std::string& why) { return inverse::failed_point_answer(spec, job, why); }, note_on_stderr));
      exit_code = 0;
      return;
    }
    const auto dir = prepare_output(o->out, o->force, inverse::sweep_input_files(spec), g.quiet);
    // The running summary with pid, host and a heartbeat; SIGINT/SIGTERM end the sweep at once
    // with status "interrupted" (the points that finished are in DIR/points/).
    scene::RunHeartbeat heartbeat(scene::RunFiles(dir), {{"kind", "sweep"}, {"sweep", spec.name}, {"sweep_file", o->file}});
    auto done = std::make_shared<std::atomic<long>>(0);
    auto progress = [done] { return nlohmann::json{{"runs_done", done->load()}}; };
    RunWatch watch(heartbeat, progress, [&heartbeat, progress](int sig) {
      nlohmann::json j = heartbeat.running();
      for (const char* k : {"pid", "host", "heartbeat", "heartbeat_interval"}) j.erase(k);
      j["status"] = scene::to_string(scene::RunStatus::interrupted);
      j["progress"] = progress();
      j["message"] = "interrupted by " + signal_name(sig) + " (a sweep does not resume: run it again with --force)";
      return j;
    });
    heartbeat.write();  // once the signals are handled
    inverse::SweepRunOptions ro;
    ro.threads = g.threads > 0 ? g.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    ro.out = &dir;
    const auto pool = spec.kind->parallel_sweeps ? nullptr : mpi::pool();  // material points: milliseconds, here
    ro.pool = pool.get();
    const bool quiet = g.quiet;
    ro.progress = [done, quiet](const scene::ProgressEvent& e) {
      ++*done;  // one event per forward run (serial sweeps)
      if (!quiet) std::fprintf(stderr, "%s\n", e.text.c_str());
    };
    const auto r = failed_on_error(heartbeat, watch, [&] { return inverse::run_sweep(spec, ro); });
    dir.write_file("sweep.csv", inverse::sweep_csv(spec, r));
    if (spec.sensitivities) dir.write_file("sensitivities.csv", inverse::sensitivities_csv(r));
    std::vector<std::string> messages;
    for (const auto& p : r.points) messages.push_back(p.message);
    const reports::SweepTable table = sweep_table(spec, r);
    for (const auto& w : reports::render_sweep_report(dir.path(), spec.name, table, messages).warnings)
      std::cerr << "spifit: warning: " << w << "\n";
    dir.record();  // report.md, report.html, plots/ in the manifest
    int failed = 0;
    for (const auto& p : r.points) failed += p.ok ? 0 : 1;
    watch.stop();  // the final summary is this one
    heartbeat.stop();
    // The table's description and the failures' messages: what `spifit report DIR` reads back.
    dir.write_file("summary.json", nlohmann::json{{"status", "ok"}, {"kind", "sweep"}, {"sweep", spec.name}, {"points", r.points.size()},
                                                  {"failed_points", failed}, {"wall_seconds", r.wall_seconds},
                                                  {"inputs", table.inputs}, {"input_units", table.input_units},
                                                  {"metrics", table.metrics}, {"metric_units", table.metric_units},
                                                  {"messages", messages}}
                                       .dump(2) + "\n");
    if (!g.quiet) {
      std::printf("sweep %s: %zu points (%d failed) in %.3f s -> %s/sweep.csv\n", spec.name.c_str(), r.points.size(), failed, r.wall_seconds,
                  o->out.c_str());
      for (const auto& s : r.sensitivities)
        std::printf("  d ln(%s) / d ln(%s) = %.4g  at %s = %.6g\n", s.metric.c_str(), s.input.c_str(), s.value, s.input.c_str(), s.base_input);
    }
    exit_code = 0;
  });
}

}  // namespace spifit::cli
