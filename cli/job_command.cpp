// `spifit job`: not for people (hidden from --help). A worker rank of an MPI fit or sweep starts
// one per forward run (cli/job_process.hpp): the job's bytes on stdin, the answer's on stdout.
#include "cli/commands.hpp"
#include "inverse/fit/fe_evaluation_worker.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/sweeps/sweep.hpp"

#include <cstdio>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>

namespace spifit::cli {

void add_job_command(CLI::App& app, const GlobalOptions&, int& exit_code) {
  struct Opts { std::string fit, sweep, out, jacobian; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("job", "");  // an empty description hides it from --help
  cmd->group("");
  auto* fit = cmd->add_option("--fit", o->fit, "fit file whose FE evaluation the job is");
  cmd->add_option("--sweep", o->sweep, "sweep file whose point the job is")->excludes(fit);
  cmd->add_option("--out", o->out, "the sweep's output directory");
  cmd->add_option("--jacobian", o->jacobian, "the fit's --jacobian");
  cmd->callback([o, &exit_code] {
    const std::string job((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    std::string answer;
    if (!o->fit.empty()) {
      const auto problem = inverse::read_fit_file(o->fit, o->jacobian);
      if (!problem.scene_runs) throw io::InputError(o->fit, "experiment", "", "no FE experiment: nothing to run in a job");
      answer = inverse::fe_evaluation_handler(problem)(job);
    } else if (!o->sweep.empty()) {
      const auto spec = inverse::read_sweep_file(o->sweep);
      answer = inverse::sweep_point_handler(spec, o->out)(job);
    } else {
      throw io::InputError("", "job", "", "needs --fit or --sweep");
    }
    std::fwrite(answer.data(), 1, answer.size(), stdout);
    std::fflush(stdout);
    exit_code = 0;
  });
}

}  // namespace spifit::cli
