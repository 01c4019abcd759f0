// `spifit sweep`: a scene over a grid of inputs (inverse/sweeps/sweep.hpp), over MPI ranks too.
#include "cli/commands.hpp"

#include "cli/cli_errors.hpp"
#include "cli/command_support.hpp"
#include "cli/job_process.hpp"
#include "cli/mpi_session.hpp"
#include "cli/run_signals.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/scenes/common/run_status.hpp"
#include "inverse/sweeps/sweep.hpp"
#include "reports/sweep_report.hpp"

#include <atomic>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

namespace spifit::cli {

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
      nlohmann::json j = heartbeat.ended();
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
