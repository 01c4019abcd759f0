// `spifit fit`: a fit file in, fit.json, the card, its exports and the report out (inverse/fit/run_fit.hpp).
#include "cli/commands.hpp"

#include "cli/cli_errors.hpp"
#include "cli/command_support.hpp"
#include "cli/fit_progress_lines.hpp"
#include "cli/job_process.hpp"
#include "cli/mpi_session.hpp"
#include "cli/run_signals.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/run_status.hpp"
#include "inverse/fit/fit_algorithms.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_output.hpp"
#include "inverse/fit/run_fit.hpp"
#include "inverse/runs/evaluation_cache.hpp"
#include "inverse/runs/fe_evaluation_job.hpp"
#include "reports/card_export.hpp"
#include "reports/fit_report.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace spifit::cli {

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

std::string join(const std::vector<std::string>& texts, const std::string& sep) {
  std::string out;
  for (const auto& t : texts) out += (out.empty() ? "" : sep) + t;
  return out;
}

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
void serve_fit_jobs(const inverse::FitProblem& problem, const GlobalOptions& g, const std::string& fit_file, const std::string& jacobian) {
  if (!problem.scene_runs) return;
  const double limit = problem.settings.run_time_limit;
  std::vector<std::string> args{"job", "--fit", fit_file};
  if (!jacobian.empty()) args.insert(args.end(), {"--jacobian", jacobian});
  mpi::serve(jobs_in_child_processes(job_args(g, args), limit > 0 ? 2.5 * limit + 60.0 : 0.0,
                                     [](const std::string&, const std::string& why) { return inverse::failed_fe_answer(why); },
                                     note_on_stderr));
}

}  // namespace

void add_fit_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string file, out, algorithm, jacobian; bool force = false, resume = false; unsigned seed = 42; int multistart = 0; };
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
  cmd->add_option("--jacobian", o->jacobian,
                  "FE experiments' Jacobian, overriding [fit] jacobian: exact (through runs with sensitivities) or central (differences of whole runs)")
      ->check(CLI::IsMember({"exact", "central"}));
  cmd->callback([o, &g, &exit_code] {
    if (!o->algorithm.empty() && !inverse::is_fit_algorithm(o->algorithm)) {
      throw io::InputError("", "--algorithm", o->algorithm, "unknown algorithm (known: " + inverse::fit_algorithm_names() + ")");
    }
    const auto problem = inverse::read_fit_file(o->file, o->jacobian);
    if (mpi::is_worker()) {  // another rank of an MPI job: the FE evaluations rank 0 hands out
      serve_fit_jobs(problem, g, o->file, o->jacobian);
      exit_code = 0;
      return;
    }
    if (!g.quiet && inverse::is_nlopt_algorithm(o->algorithm) && problem.settings.offset_tolerance > 0.0)
      std::fprintf(stderr,
                   "note: %s stops on its own tolerances; offset_tolerance = %g stops Ceres's algorithms only and is left out (the fit still "
                   "checks its convergence at the solution)\n",
                   o->algorithm.c_str(), problem.settings.offset_tolerance);
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
      nlohmann::json j = heartbeat.ended();
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
    const auto report = reports::render_fit_report_from_record(dir.path(), inverse::fit_record(problem, result));
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

}  // namespace spifit::cli
